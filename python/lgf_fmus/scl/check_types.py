"""The checks' second pass (docs/scl.md §3.1, §3.8, §4): types and constants. Every
declaration's type (elementary, ARRAY, STRUCT, UDT, an FB instance, DTL) where it stands and as
the core can hold it; the UDTs of the program (none containing itself); every initial value and
constant against its type, folded to a literal (Decl.start)."""

from __future__ import annotations

import copy
import math
import re

from . import ast as A
from . import types as T
from . import unsupported
from .check_symbols import c_name
from .check_symbols import identifier as name_check
from .cnames import field, identifier
from .diagnostics import Code, SclError, Silent, refuse
from .lower import fold

# the elements an ARRAY may have: the FMU's state and its tables stay small
ARRAY_LIMIT = 65536


def elementary_leaves(t):
    """The elementary types (or FB types) an ARRAY or STRUCT is made of."""
    if isinstance(t, T.ArrayType):
        return elementary_leaves(t.element)
    if isinstance(t, T.StructType):
        return [leaf for m, _ in t.members.values() for leaf in elementary_leaves(m)]
    return [t]


class Types:
    """The pass over a block's declarations that gives each its type and start value (a mixin
    of checks.Checker)."""

    def types(self):
        for d in list(self.block.decls):
            if d.type is None and not self.attempt(self.declare_type, d):
                d.type = T.ERROR  # its uses end their statements without a second error

    def declare_type(self, d: A.VarDecl):
        """The type of a declaration (docs/scl.md §3.1, §3.8, §4): one the core can hold where
        it stands, and its initial value checked against it (Decl.start)."""
        t = d.type = self.resolve(d)
        if isinstance(t, T.ArrayType) and isinstance(t.element, T.FbType):
            t = t.element  # an ARRAY of instances (docs/scl.md §3.7): a static, as an instance
            if d.type.dims is None:
                refuse(Code.DECLARATION, d, f"'{d.name}': an ARRAY[*] of {t.name} instances")
        if isinstance(t, T.FbType):
            if not d.section.static:
                refuse(
                    Code.DECLARATION,
                    d,
                    f"the {t.name} instance '{d.name}' must be a static (VAR): it keeps"
                    " its state from call to call",
                )
            if d.init is not None:
                refuse(
                    Code.INITIAL, d.init, f"the {t.name} instance '{d.name}' takes no initial value"
                )
            return
        top = self.block is self.program.top
        open_array = isinstance(t, T.ArrayType) and t.dims is None
        if d.section == A.Section.IN_OUT and top:
            self.in_out(d, t)
        elif open_array and d.section != A.Section.IN_OUT and not (self.fc and d.section.interface):
            refuse(
                Code.DECLARATION,
                A.Node(d.type_loc),
                f"'{d.name}': ARRAY[*] is only the type of a VAR_IN_OUT or of an FC's "
                "VAR_INPUT or VAR_OUTPUT (S7)",
            )
        if (
            d.section in (A.Section.INPUT, A.Section.OUTPUT)
            and not top
            and not open_array
            and not isinstance(t, (T.Elementary, T.StringType))
            and not (self.fc and isinstance(t, (T.ArrayType, T.StructType)))
            and t is not T.DTL  # a DTL is passed whole, as scl_dtl (docs/scl.md §3.7)
        ):
            refuse(
                Code.UNSUPPORTED,
                A.Node(d.type_loc),
                f"the {t} {d.section} '{d.name}' of {self.block.name}: the inputs and "
                "outputs of an FB's instance are elementary yet (docs/scl.md §6)",
            )
        for leaf in elementary_leaves(t):
            self.storable(d, leaf)
        if d.init is not None:
            d.start = self.initial(d.init, t, f"the initial value of '{d.name}'")
            if d.section.interface and self.block is self.program.top:
                self.xml_text(d, d.start)
        # a VAR CONSTANT without a value has its type's default, as TIA takes it (§2.1)

    def xml_text(self, d: A.VarDecl, start):
        """A string start value of the FMU's interface goes into modelDescription.xml, which
        carries no control character but tab, line feed and carriage return (XML 1.0)."""
        if isinstance(start, dict):
            start = list(start.values())
        if isinstance(start, list):
            for item in start:
                self.xml_text(d, item)
        elif isinstance(start, A.Literal) and start.kind == "string":
            bad = [c for c in start.value if c < 0x20 and c not in (0x09, 0x0A, 0x0D)]
            if bad:
                refuse(
                    Code.INITIAL,
                    start,
                    f"the start value of '{d.name}' holds the character ${bad[0]:02X}, which "
                    "modelDescription.xml cannot carry (XML 1.0 takes $T, $L and $R only)",
                )

    def in_out(self, d: A.VarDecl, t):
        """VAR_IN_OUT (docs/scl.md §4): an elementary one (a STRUCT, a fixed ARRAY) is an FMI
        input and the output <name>_out on the same data (each member and element); an ARRAY[*]
        the table of tunable parameters name[i] with its size numberOf<Name>, a fixed
        parameter."""
        if isinstance(t, T.ArrayType) and t.dims is None and t.rank > 1:
            refuse(
                Code.UNSUPPORTED,
                A.Node(d.type_loc),
                f"'{d.name}': an {t} in/out of the FB compiled into the FMU (a table of more "
                "than one dimension) is not supported yet (docs/scl.md §6)",
            )
        if not isinstance(t, T.ArrayType) or t.dims is not None:
            out = d.name + "_out"
            if any(x.name.lower() == out.lower() for x in self.block.decls):
                refuse(
                    Code.RESERVED,
                    d,
                    f"VAR_IN_OUT '{d.name}': its output '{out}' is declared as well",
                )
            return
        count = T.table_count(d.name)
        if any(
            x.name.lower() == count.lower()
            or x is not d
            and x.section == A.Section.IN_OUT
            and T.table_count(x.name).lower() == count.lower()
            for x in self.block.decls
        ):
            refuse(
                Code.RESERVED,
                d,
                f"VAR_IN_OUT '{d.name}': '{count}', the size of its table, is declared as well",
            )

    def storable(self, d: A.VarDecl, t):
        """Whether the core can hold t as the FMI variable or static of d (src/core/model.h); an
        FC's parameters are none of them (passed by value or by reference, docs/scl.md §3.7)."""
        if d.section.interface and t.var not in self.core_vars and self.block.kind != "FUNCTION":
            why = (
                f"the core has no FMI variable of type {t.name} yet ({t.var} in src/core/model.h)"
                if t.var
                else f"FMI 2.0 and the core have no {t.bits}-bit integer variable; keep it"
                " a static or a temporary (docs/scl.md §3.1)"
            )
            refuse(Code.DECLARATION, A.Node(d.type_loc), f"{t.name} {d.section} '{d.name}': {why}")
        if d.section.static and t.field not in self.core_fields:
            refuse(
                Code.UNSUPPORTED,
                A.Node(d.type_loc),
                f"{t.name} static '{d.name}': the core cannot keep a "
                f"{t.name} in an FMU state yet ({t.field} in src/core/model.h)",
            )

    def resolve(self, d: A.VarDecl):
        if d.type_ref is None and d.type_name.upper() == "IEC_TIMER":
            d.type_name = self.timer_run_on(d)
        return self.type_of(d.type_ref or (d.type_name, d.type_loc), d.name)

    def timer_run_on(self, d: A.VarDecl) -> str:
        """TON, TOF or TP: the timer the block runs on its IEC_TIMER static `d`
        (#inst.TON(...), as TIA writes a multi-instance of IEC_TIMER, docs/scl.md §3.6)."""
        used = {
            n.method
            for n in A.nodes(self.block.body)
            if isinstance(n, A.Call) and n.local and n.method and n.callee.lower() == d.name.lower()
        }
        if len(used) != 1 or not used <= {"TON", "TOF", "TP"}:
            refuse(
                Code.INSTANCE,
                d,
                f"the IEC_TIMER '{d.name}' must run one timer, #{d.name}.TON/TOF/TP(...), "
                f"not {', '.join(sorted(used)) or 'none'}",
            )
        return next(iter(used))

    def type_of(self, ref, owner: str):
        if isinstance(ref, A.SizedTypeRef):
            return self.sized(ref, owner)
        if isinstance(ref, A.ArrayTypeRef):
            element = self.type_of(ref.element, owner)
            if isinstance(element, T.ArrayType):
                refuse(
                    Code.UNSUPPORTED,
                    ref,
                    f"'{owner}': an ARRAY of ARRAYs; write ARRAY[a..b, c..d] OF ...",
                )
            if None in ref.dims:
                if any(d is not None for d in ref.dims):  # S7: * in every dimension or none
                    refuse(
                        Code.DECLARATION,
                        ref,
                        f"'{owner}': ARRAY[*] has * in every dimension, no bounds",
                    )
                return T.ArrayType(element, None, len(ref.dims))
            for lo, hi in ref.dims:
                if lo > hi:
                    refuse(
                        Code.RANGE,
                        ref,
                        f"'{owner}': ARRAY[{lo}..{hi}]: the low bound is above the high",
                    )
                if not T.fits(lo, T.DINT) or not T.fits(hi, T.DINT):
                    refuse(Code.RANGE, ref, f"'{owner}': ARRAY bounds are DINTs")
            array = T.ArrayType(element, tuple(ref.dims))
            if math.prod(array.sizes) > ARRAY_LIMIT:
                refuse(Code.RANGE, ref, f"'{owner}': {array} has more than {ARRAY_LIMIT} elements")
            return array
        if isinstance(ref, A.StructTypeRef):
            return self.struct(ref, None, owner)
        name, loc = ref
        t = T.lookup(name)
        if t is None and name.lower() in self.program.udts:
            t = self.udt(self.program.udts[name.lower()], loc)
        if t is None:
            t = self.user_fb(name, loc)
        if t is None:
            if unsupported.type_message(name):
                refuse(Code.UNSUPPORTED, A.Node(loc), unsupported.type_message(name))
            if name.lower() in self.names:  # a variable's name as a type (Symbols.names)
                refuse(
                    Code.UNDECLARED,
                    A.Node(loc),
                    f"'{name}', the data type of '{owner}', is a variable of the block, not a "
                    "data type: the source is not valid SCL (docs/scl.md §6)",
                )
            refuse(
                Code.UNDECLARED,
                A.Node(loc),
                f"unknown or unsupported data type '{name}' of '{owner}' (docs/scl.md §3.1)",
            )
        return t

    def sized(self, ref: A.SizedTypeRef, owner: str) -> T.StringType:
        """STRING[n], WSTRING[n], n 1 ... 254 or a constant of the block of that value
        (docs/scl.md §3.1 [S7-STRING])."""
        base = T.lookup(ref.name)
        if not isinstance(base, T.StringType):
            refuse(
                Code.UNDECLARED,
                ref,
                f"unknown or unsupported data type '{ref.name}[{ref.size}]' of '{owner}'",
            )
        size = ref.size
        if isinstance(size, str):
            d = self.names.get(size.lstrip("#").strip('"').lower()) if size[0] == "#" else None
            init = fold(d.init) if d is not None and d.init is not None else None
            if d is None or d.section != A.Section.CONSTANT or not isinstance(init, A.Literal):
                refuse(
                    Code.UNSUPPORTED,
                    ref,
                    f"'{owner}': the length of {base.name}[{size}] is an integer or a constant "
                    "of the block (VAR CONSTANT) with an integer value",
                )
            size = init.value
        if base.wide and isinstance(size, int) and T.STRING_MAX < size <= 16382:
            refuse(
                Code.UNSUPPORTED,
                ref,
                f"'{owner}': WSTRING[{size}]: a WSTRING of more than {T.STRING_MAX} characters "
                "is not supported yet (docs/scl.md §6)",
            )
        if not isinstance(size, int) or not 1 <= size <= (16382 if base.wide else T.STRING_MAX):
            refuse(
                Code.RANGE,
                ref,
                f"'{owner}': {base.name}[{size}]: a {base.name} holds 1 to "
                f"{16382 if base.wide else T.STRING_MAX} characters",
            )
        return T.StringType(base.wide, size)

    def udt(self, decl: A.TypeDecl, loc):
        if decl.type is T.ERROR:
            raise Silent()
        if decl.type is not None:
            return decl.type
        if decl.name.lower() in self.program.resolving:
            refuse(Code.RECURSION, A.Node(loc), f'the UDT "{decl.name}" contains itself')
        self.program.resolving.append(decl.name.lower())
        try:
            name_check(decl, decl.name)
            decl.type = self.struct(decl.struct, decl.name, decl.name)
        except SclError:
            decl.type = T.ERROR  # reported once, here: its other uses end without an error
            raise
        finally:
            self.program.resolving.pop()
        return decl.type

    def struct(self, ref: A.StructTypeRef, name: str | None, owner: str):
        members = {}
        c_names = {}  # the members' C names (check_symbols.c_name)
        for m in ref.members:
            if m.name.lower() in (k.lower() for k in members):
                first = next(x for x in ref.members if x.name.lower() == m.name.lower()).loc
                refuse(
                    Code.DUPLICATE,
                    m,
                    f"'{owner}' has two members '{m.name}'",
                    [(first, "first declared here")],
                )
            name_check(m, m.name)
            c_name(m, m.name, field(m.name), c_names)
            t = self.type_of(m.type_ref or (m.type_name, m.type_loc), f"{owner}.{m.name}")
            if any(isinstance(leaf, T.FbType) for leaf in elementary_leaves(t)):
                refuse(
                    Code.UNSUPPORTED,
                    A.Node(m.type_loc),
                    f"'{owner}.{m.name}': an FB instance in a STRUCT (docs/scl.md §6)",
                )
            if isinstance(t, T.ArrayType) and t.dims is None:
                refuse(
                    Code.DECLARATION,
                    A.Node(m.type_loc),
                    f"'{owner}.{m.name}': ARRAY[*] in a STRUCT",
                )
            init = None
            if m.init is not None:
                init = self.initial(m.init, t, f"the initial value of '{owner}.{m.name}'")
            members[m.name] = (t, init)
        # a C name of its own by its count; the names only make it readable
        tag = re.sub(r"[^a-z0-9_]", "_", (name or owner).lower())
        structs = self.program.structs
        c = f"scl_{identifier(self.block.name).lower()}_{tag}_{len(structs)}"
        comments = {m.name: m.comment for m in ref.members if m.comment}
        t = T.StructType(name, c, members, comments)
        t.setpoints = frozenset(m.name for m in ref.members if m.setpoint)
        structs.append(t)
        return t

    def initial(self, e, t, what: str):
        """An initial value, checked against t: a Literal for an elementary t, a list of one
        per element (None: the element's default) for an ARRAY, a dict of members for a
        STRUCT (docs/scl.md §3.8)."""
        if isinstance(t, T.ArrayType):
            if not isinstance(e, A.ArrayInit):
                refuse(Code.INITIAL, e, f"{what}: an ARRAY takes [value, count(value), ...]")
            values = []
            for count, item in e.items:
                if count < 1:
                    refuse(Code.INITIAL, e, f"{what}: a repetition count must be 1 or more")
                value = None if item is None else self.initial(item, t.element, what)
                values += [value] * count
            if t.dims is not None and len(values) > math.prod(t.sizes):
                refuse(
                    Code.INITIAL,
                    e,
                    f"{what}: {len(values)} values for the {math.prod(t.sizes)} of {t}",
                )
            if t.dims is None and len(values) > T.TABLE_CAPACITY:
                refuse(
                    Code.INITIAL,
                    e,
                    f"{what}: {len(values)} values, the table holds {T.TABLE_CAPACITY}",
                )
            return values
        if t is T.DTL and isinstance(e, A.Literal) and e.type_prefix == "DTL":
            return T.dtl_start(e.value)  # DTL#1990-01-01-00:00:00 (docs/scl.md §2.1)
        if isinstance(t, T.StructType):
            if not isinstance(e, A.StructInit):
                dtl = "DTL#... or " if t is T.DTL else ""
                refuse(Code.INITIAL, e, f"{what}: a {t} takes {dtl}(member := value, ...)")
            values = {}
            for position, (name, loc, value) in enumerate(e.members):
                if name is None:  # TIA's positional (#C, (), ()), docs/scl.md §2.1
                    if position >= len(t.members):
                        refuse(
                            Code.INITIAL,
                            A.Node(loc),
                            f"{what}: {len(e.members)} values for the {len(t.members)} of {t}",
                        )
                    if value is None:  # (): the member keeps its default
                        continue
                    name = list(t.members)[position]
                key = t.member(name)
                if key is None:
                    refuse(Code.INITIAL, A.Node(loc), f"{what}: {t} has no member '{name}'")
                if key in values:
                    refuse(Code.INITIAL, A.Node(loc), f"{what}: '{name}' is given twice")
                values[key] = self.initial(value, t.members[key][0], what)
            return values
        if isinstance(e, (A.ArrayInit, A.StructInit)) or not isinstance(
            t, (T.Elementary, T.StringType)
        ):
            refuse(Code.INITIAL, e, f"{what}: {t} takes a literal")
        return self.constant(e, t, what)

    def constant(self, e: A.Expr, t: T.Elementary, what: str) -> A.Expr:
        e = fold(e)
        if isinstance(e, A.VarRef) and not e.members:
            # a constant of the block (VAR CONSTANT := literal) as a start value, as TIA takes
            # it (LGF_StoreMinMax's := #LREAL_MAX): its literal, typed for this variable
            d = self.names.get(e.name.lower())
            if d is not None and d.section == A.Section.CONSTANT:
                init = fold(d.init) if d.init is not None else None
                if isinstance(init, A.Literal):
                    e = copy.copy(init)
                    e.type = None
        if not isinstance(e, A.Literal):
            refuse(Code.INITIAL, e, f"{what} must be a literal or a constant of the block")
        self.expr(e)
        self.coerce(e, t, what)
        return e
