"""The checks between parsing and C generation (docs/scl.md §3, §5): every name is declared,
every expression has an S7 type, every conversion is one S7 makes implicitly or one the program
writes, every construct is one the subset supports. Each refusal is an SclError at the
construct's file:line:col, before any C is generated. Annotates the tree in place: VarRef.decl,
Expr.type (an untyped literal takes its context's type), Binary.operand_type."""

from __future__ import annotations

import math
import re

from . import ast as A
from . import types as T

SECTIONS_IN_STRUCT = ("VAR_INPUT", "VAR_OUTPUT", "VAR", "VAR RETAIN", "VAR NON_RETAIN")
STATIC_SECTIONS = ("VAR", "VAR RETAIN", "VAR NON_RETAIN")
C_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")
CONVERSION = re.compile(r"([A-Z]+)_TO_([A-Z]+)\Z")
ARITHMETIC = {"+", "-", "*", "/", "MOD"}
COMPARISON = {"=", "<>", "<", ">", "<=", ">="}
LOGIC = {"AND", "&", "OR", "XOR"}
# the elements an ARRAY may have: the FMU's state and its tables stay small
ARRAY_LIMIT = 65536


def leaves(t):
    """The elementary types (or FB types) an ARRAY or STRUCT is made of."""
    if isinstance(t, T.ArrayType):
        return leaves(t.element)
    if isinstance(t, T.StructType):
        return [leaf for m, _ in t.members.values() for leaf in leaves(m)]
    return [t]


def _err(node, message):
    raise A.SclError(node.loc if node is not None else None, message)


class Checker:
    def __init__(self, block: A.Block, core_vars: set[str], core_fields: set[str], udts=None):
        self.block = block
        self.udts = udts or {}  # lower-case name -> A.TypeDecl
        self.structs: list[T.StructType] = []  # every STRUCT and UDT used, inner ones first
        self.resolving: list[str] = []
        self.core_vars = core_vars
        self.core_fields = core_fields
        self.names: dict[str, A.VarDecl] = {}
        self.loops = 0
        self.uses_qry_cint = False

    # Declarations (docs/scl.md §4)

    def declarations(self):
        for d in self.block.decls:
            key = d.name.lower()  # SCL names are case-insensitive
            if key in self.names:
                _err(d, f"'{d.name}' is declared twice (first at {self.names[key].loc})")
            if not C_IDENTIFIER.match(d.name):
                _err(d, f'"{d.name}": only names of letters, digits and _ are supported')
            if key == "cycletime":
                _err(d, "'cycleTime' is the FMU's own parameter (docs/behaviour.md §1.1)")
            self.names[key] = d
            t = d.type = self.resolve(d)
            if isinstance(t, T.FbType):
                if d.section not in STATIC_SECTIONS:
                    _err(
                        d,
                        f"the {t.name} instance '{d.name}' must be a static (VAR): it keeps"
                        " its state from call to call",
                    )
                if d.init is not None:
                    _err(d.init, f"the {t.name} instance '{d.name}' takes no initial value")
                continue
            if d.section == "VAR_IN_OUT":
                self.in_out(d, t)
            elif isinstance(t, T.ArrayType) and t.dims is None:
                _err(A.Node(d.type_loc), f"'{d.name}': ARRAY[*] is only a VAR_IN_OUT's type")
            for leaf in leaves(t):
                self.storable(d, leaf)
            if d.init is not None:
                d.init = self.initial(d.init, t, f"the initial value of '{d.name}'")
            elif d.section == "VAR CONSTANT":
                _err(d, f"the constant '{d.name}' needs a value")

    def in_out(self, d: A.VarDecl, t):
        """VAR_IN_OUT (docs/scl.md §4): an elementary one (a STRUCT, a fixed ARRAY) is an FMI
        input and the output <name>_out on the same data (each member and element); an ARRAY[*]
        the table of tunable parameters name[i] with its size numberOf<Name>, a fixed
        parameter."""
        if not isinstance(t, T.ArrayType) or t.dims is not None:
            out = d.name + "_out"
            if any(x.name.lower() == out.lower() for x in self.block.decls):
                _err(d, f"VAR_IN_OUT '{d.name}': its output '{out}' is declared as well")
            return
        count = T.table_count(d.name)
        if any(
            x.name.lower() == count.lower()
            or x is not d
            and x.section == "VAR_IN_OUT"
            and T.table_count(x.name).lower() == count.lower()
            for x in self.block.decls
        ):
            _err(d, f"VAR_IN_OUT '{d.name}': '{count}', the size of its table, is declared as well")

    def storable(self, d: A.VarDecl, t):
        """Whether the core can hold t as the FMI variable or static of d (src/core/model.h)."""
        if isinstance(t, T.FbType):
            _err(A.Node(d.type_loc), f"'{d.name}': an ARRAY or STRUCT of {t.name} instances")
        if d.section in ("VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT") and t.var not in self.core_vars:
            why = (
                f"the core has no FMI variable of type {t.name} yet ({t.var} in src/core/model.h)"
                if t.var
                else f"FMI 2.0 and the core have no {t.bits}-bit integer variable; keep it"
                " a static or a temporary (docs/scl.md §3.1)"
            )
            _err(A.Node(d.type_loc), f"{t.name} {d.section} '{d.name}': {why}")
        if d.section in STATIC_SECTIONS and t.field not in self.core_fields:
            _err(
                A.Node(d.type_loc),
                f"{t.name} static '{d.name}': the core cannot keep a "
                f"{t.name} in an FMU state yet ({t.field} in src/core/model.h)",
            )

    # Types (docs/scl.md §3.1, §3.8)

    def resolve(self, d: A.VarDecl):
        return self.type_of(d.type_ref or (d.type_name, d.type_loc), d.name)

    def type_of(self, ref, owner: str):
        if isinstance(ref, A.ArrayTypeRef):
            element = self.type_of(ref.element, owner)
            if isinstance(element, T.ArrayType):
                _err(ref, f"'{owner}': an ARRAY of ARRAYs; write ARRAY[a..b, c..d] OF ...")
            if None in ref.dims:
                if len(ref.dims) > 1:
                    _err(ref, f"'{owner}': ARRAY[*] of one dimension only is supported")
                return T.ArrayType(element, None)
            for lo, hi in ref.dims:
                if lo > hi:
                    _err(ref, f"'{owner}': ARRAY[{lo}..{hi}]: the low bound is above the high")
                if not T.fits(lo, T.DINT) or not T.fits(hi, T.DINT):
                    _err(ref, f"'{owner}': ARRAY bounds are DINTs")
            array = T.ArrayType(element, tuple(ref.dims))
            if math.prod(array.sizes) > ARRAY_LIMIT:
                _err(ref, f"'{owner}': {array} has more than {ARRAY_LIMIT} elements")
            return array
        if isinstance(ref, A.StructTypeRef):
            return self.struct(ref, None, owner)
        name, loc = ref
        t = T.lookup(name)
        if t is None and name.lower() in self.udts:
            t = self.udt(self.udts[name.lower()], loc)
        if t is None:
            _err(
                A.Node(loc),
                f"unknown or unsupported data type '{name}' of '{owner}' (docs/scl.md §3.1)",
            )
        return t

    def udt(self, decl: A.TypeDecl, loc):
        if decl.type is not None:
            return decl.type
        if decl.name.lower() in self.resolving:
            _err(A.Node(loc), f'the UDT "{decl.name}" contains itself')
        if not C_IDENTIFIER.match(decl.name):
            _err(decl, f'"{decl.name}": only UDT names of letters, digits and _ are supported')
        self.resolving.append(decl.name.lower())
        decl.type = self.struct(decl.struct, decl.name, decl.name)
        self.resolving.pop()
        return decl.type

    def struct(self, ref: A.StructTypeRef, name: str | None, owner: str):
        members = {}
        for m in ref.members:
            if m.name.lower() in (k.lower() for k in members):
                _err(m, f"'{owner}' has two members '{m.name}'")
            if not C_IDENTIFIER.match(m.name):
                _err(m, f'"{m.name}": only names of letters, digits and _ are supported')
            t = self.type_of(m.type_ref or (m.type_name, m.type_loc), f"{owner}.{m.name}")
            if isinstance(t, T.FbType):
                _err(A.Node(m.type_loc), f"'{owner}.{m.name}': an FB instance in a STRUCT")
            if isinstance(t, T.ArrayType) and t.dims is None:
                _err(A.Node(m.type_loc), f"'{owner}.{m.name}': ARRAY[*] in a STRUCT")
            init = None
            if m.init is not None:
                init = self.initial(m.init, t, f"the initial value of '{owner}.{m.name}'")
            members[m.name] = (t, init)
        tag = (name or owner).lower().replace(".", "_")
        c = f"scl_{self.block.name.lower()}_{tag}_{len(self.structs)}"
        t = T.StructType(name, c, members)
        self.structs.append(t)
        return t

    def initial(self, e, t, what: str):
        """An initial value, checked against t: a Literal for an elementary t, a list of one
        per element (None: the element's default) for an ARRAY, a dict of members for a
        STRUCT (docs/scl.md §3.8)."""
        if isinstance(t, T.ArrayType):
            if not isinstance(e, A.ArrayInit):
                _err(e, f"{what}: an ARRAY takes [value, count(value), ...]")
            values = []
            for count, item in e.items:
                if count < 1:
                    _err(e, f"{what}: a repetition count must be 1 or more")
                value = None if item is None else self.initial(item, t.element, what)
                values += [value] * count
            if t.dims is not None and len(values) > math.prod(t.sizes):
                _err(e, f"{what}: {len(values)} values for the {math.prod(t.sizes)} of {t}")
            if t.dims is None and len(values) > T.TABLE_CAPACITY:
                _err(e, f"{what}: {len(values)} values, the table holds {T.TABLE_CAPACITY}")
            return values
        if isinstance(t, T.StructType):
            if not isinstance(e, A.StructInit):
                _err(e, f"{what}: a {t} takes (member := value, ...)")
            values = {}
            for name, loc, value in e.members:
                key = t.member(name)
                if key is None:
                    _err(A.Node(loc), f"{what}: {t} has no member '{name}'")
                if key in values:
                    _err(A.Node(loc), f"{what}: '{name}' is given twice")
                values[key] = self.initial(value, t.members[key][0], what)
            return values
        if isinstance(e, (A.ArrayInit, A.StructInit)) or not isinstance(t, T.Elementary):
            _err(e, f"{what}: {t} takes a literal")
        return self.constant(e, t, what)

    def constant(self, e: A.Expr, t: T.Elementary, what: str) -> A.Expr:
        e = self.fold(e)
        if not isinstance(e, A.Literal):
            _err(e, f"{what} must be a literal")
        self.expr(e)
        self.coerce(e, t, what)
        return e

    def fold(self, e):
        """-literal is a literal: -32768 is an INT."""
        if isinstance(e, A.Unary) and e.op == "-" and isinstance(e.operand, A.Literal):
            lit = self.fold(e.operand)
            if lit.kind in ("int", "real", "time"):
                return A.Literal(e.loc, lit.kind, "-" + lit.text, -lit.value, lit.type_prefix)
        return e

    # Statements

    def statements(self, body: list[A.Stmt]):
        for s in body:
            self.statement(s)

    def statement(self, s: A.Stmt):
        if isinstance(s, A.Assign):
            self.assign(s)
        elif isinstance(s, A.CallStmt):
            self.call_statement(s.call)
        elif isinstance(s, A.If):
            for condition, body in s.branches:
                self.condition(condition, "IF")
                self.statements(body)
            self.statements(s.otherwise or [])
        elif isinstance(s, A.Case):
            t = self.expr(s.selector)
            if isinstance(t, T.Untyped):
                self.coerce(s.selector, T.DINT, "the CASE selector")
                t = T.DINT
            if not isinstance(t, T.Elementary) or t.kind not in ("int", "bits"):
                _err(s.selector, f"the CASE selector must be an integer or bit string, not {t}")
            seen = []
            for labels, body in s.branches:
                for low, high in labels:
                    if not (T.fits(low, t) and T.fits(high, t)) or low > high:
                        _err(s, f"the CASE label {low}..{high} is not a range of {t}")
                    for other in seen:
                        if low <= other[1] and other[0] <= high:
                            _err(s, f"the CASE label {low}..{high} overlaps {other[0]}..{other[1]}")
                    seen.append((low, high))
                self.statements(body)
            self.statements(s.otherwise or [])
        elif isinstance(s, A.For):
            t = self.variable(s.variable, write=True)
            if s.variable.members:
                _err(s.variable, "the FOR variable must be a plain variable")
            if not isinstance(t, T.Elementary) or t.kind != "int" or not t.signed or t.bits > 32:
                _err(s.variable, f"the FOR variable must be a SINT, INT or DINT, not {t}")
            for part, what in ((s.start, "start"), (s.end, "end"), (s.step, "BY")):
                if part is not None:
                    self.expr(part)
                    self.coerce(part, t, f"the FOR {what} value")
            self.loop(s.body)
        elif isinstance(s, A.While):
            self.condition(s.condition, "WHILE")
            self.loop(s.body)
        elif isinstance(s, A.Repeat):
            self.loop(s.body)
            self.condition(s.condition, "UNTIL")
        elif isinstance(s, A.Jump):
            if s.kind != "RETURN" and not self.loops:
                _err(s, f"{s.kind} outside FOR, WHILE or REPEAT")
        elif isinstance(s, A.Region):
            self.statements(s.body)

    def loop(self, body):
        self.loops += 1
        self.statements(body)
        self.loops -= 1

    def condition(self, e, what):
        self.expr(e)
        self.coerce(e, T.BOOL, f"the {what} condition")

    def assign(self, s: A.Assign):
        t = self.variable(s.target, write=True)
        if s.op != ":=":
            s.value = A.Binary(s.loc, s.op[0], s.target, s.value)
            s.op = ":="
        self.expr(s.value)
        self.coerce(s.value, t, f"the assignment to '{s.target.name}'")

    # Names

    def decl(self, ref: A.VarRef) -> A.VarDecl:
        d = self.names.get(ref.name.lower())
        if d is None:
            _err(ref, f"'{ref.name}' is not declared in {self.block.name}")
        return d

    def variable(self, ref: A.VarRef, write=False):
        d = ref.decl = self.decl(ref)
        if isinstance(d.type, T.FbType):
            fb = d.type
            if not ref.members:
                _err(
                    ref,
                    f"the {fb.name} instance '{d.name}' is not a value: use "
                    f"#{d.name}.{next(iter(fb.outputs))}",
                )
            if len(ref.members) > 1 or not isinstance(ref.members[0], str):
                _err(ref, f"'{d.name}': {fb.name} has members .Q, .IN, ... only")
            member = ref.members[0].upper()
            if member in fb.outputs:
                if write:
                    _err(
                        ref,
                        f"'{d.name}.{ref.members[0]}' is an output of {fb.name}: "
                        "only the instance writes it",
                    )
                ref.type = fb.outputs[member]
            elif member in fb.inputs:
                ref.type = fb.inputs[member]
            else:
                _err(ref, f"{fb.name} has no member '{ref.members[0]}'")
            ref.members = [member]
            return ref.type
        if write and d.section == "VAR CONSTANT":
            _err(ref, f"'{d.name}' is a constant")
        if write and d.section == "VAR_INPUT":
            _err(
                ref,
                f"'{d.name}' is an input, set by the importer at every call; assign a "
                "static instead (docs/scl.md §4)",
            )
        ref.type = self.selectors(ref, d.type, d.name)
        return ref.type

    def selectors(self, ref: A.VarRef, t, name: str):
        """The type of name.member[i, j].%X3 ...; annotates the ref's path for cgen.py:
        ("member", name), ("index", [exprs], ArrayType), ("bit", number, type)
        (docs/scl.md §3.8)."""
        ref.path = []
        for sel in ref.members:
            if isinstance(sel, str):
                key = t.member(sel) if isinstance(t, T.StructType) else None
                if key is None:
                    _err(ref, f"'{name}' is a {t}: it has no member '{sel}'")
                ref.path.append(("member", key))
                t, name = t.members[key][0], f"{name}.{key}"
            elif isinstance(sel, A.Index):
                if not isinstance(t, T.ArrayType):
                    _err(sel, f"'{name}' is a {t}, not an ARRAY: it takes no index")
                rank = 1 if t.dims is None else len(t.dims)
                if len(sel.exprs) != rank:
                    given = len(sel.exprs)
                    _err(sel, f"'{name}' is an {t}: it takes {rank} index(es), not {given}")
                for i, e in enumerate(sel.exprs):
                    it = self.expr(e)
                    if isinstance(it, T.Untyped):
                        self.coerce(e, T.DINT, f"the index of '{name}'")
                    elif not isinstance(it, T.Elementary) or it.kind != "int" or it.bits > 32:
                        _err(
                            e,
                            f"the index of '{name}' must be an integer of up to 32 bits, not {it}",
                        )
                    if isinstance(e, A.Literal) and t.dims is not None:
                        lo, hi = t.dims[i]
                        if not lo <= e.value <= hi:
                            _err(e, f"the index {e.value} is outside {name}'s {lo}..{hi}")
                ref.path.append(("index", sel.exprs, t))
                t, name = t.element, f"{name}[..]"
            else:
                if not isinstance(t, T.Elementary) or t.kind not in ("int", "bits"):
                    _err(sel, f"'{name}' is a {t}: bit access .%X is on a bit string or integer")
                if sel.number >= t.bits:
                    _err(sel, f"'{name}' is a {t}: its bits are %X0 to %X{t.bits - 1}")
                ref.path.append(("bit", sel.number, t))
                t, name = T.BOOL, f"{name}.%X{sel.number}"
        return t

    # Expressions (docs/scl.md §3.2-3.5)

    def expr(self, e: A.Expr):
        if isinstance(e, A.Literal):
            e.type = self.literal_type(e)
        elif isinstance(e, A.VarRef):
            self.variable(e)
        elif isinstance(e, A.Unary):
            self.unary(e)
        elif isinstance(e, A.Binary):
            self.binary(e)
        elif isinstance(e, A.Call):
            self.call(e)
        return e.type

    def literal_type(self, e: A.Literal):
        if e.kind == "bool":
            return T.BOOL
        if e.kind == "time":
            return T.LTIME if e.type_prefix == "LTIME" else T.TIME
        if e.type_prefix is None:
            return T.ANY_INT if e.kind == "int" else T.ANY_REAL
        t = T.lookup(e.type_prefix)
        if not isinstance(t, T.Elementary) or t.kind == "bool":
            _err(e, f"{e.text}: unknown literal type {e.type_prefix}")
        if e.kind == "real" and t.kind != "real":
            _err(e, f"{e.text}: a {t} literal must be a whole number")
        if e.kind == "int" and t.kind in ("int", "bits") and not T.fits(e.value, t):
            _err(e, f"{e.text} does not fit {t} ({t.low} to {t.high})")
        if t.kind == "real" and abs(float(e.value)) > T.REAL_MAX[t.name]:
            _err(e, f"{e.text} is beyond the largest {t}")
        if t.kind == "time":
            _err(e, f"{e.text}: write a TIME as T#...")
        return t

    def coerce(self, e: A.Expr, t, what: str):
        """Gives an untyped literal (or an expression of them) the type t, or checks that e's
        type converts to t implicitly (docs/scl.md §3.2)."""
        if isinstance(e.type, T.Untyped) and not isinstance(t, T.Elementary):
            _err(e, f"{what}: {e.type} is not a {t}")
        if isinstance(e.type, T.Untyped):
            if t.kind == "bool" or t.kind == "time" or (e.type.kind == "real" and t.kind != "real"):
                _err(e, f"{what}: {e.type} is not a {t}")
            self.settle(e, t, what)
            return
        if not T.implicit(e.type, t):
            hint = f"; write {e.type}_TO_{t}(...)" if isinstance(e.type, T.Elementary) else ""
            _err(e, f"{what}: S7 converts no {e.type} to {t} implicitly{hint}")

    def settle(self, e, t, what):
        if isinstance(e, A.Literal):
            if e.kind == "int" and t.kind in ("int", "bits") and not T.fits(e.value, t):
                _err(e, f"{what}: {e.text} does not fit {t} ({t.low} to {t.high})")
            if t.kind == "real" and abs(float(e.value)) > T.REAL_MAX[t.name]:
                _err(e, f"{what}: {e.text} is beyond the largest {t}")
            e.type = t
        elif isinstance(e, A.Unary):
            self.settle(e.operand, t, what)
            e.type = t
        elif isinstance(e, A.Binary):
            self.settle(e.left, t, what)
            self.settle(e.right, t, what)
            e.operand_type = t
            e.type = T.BOOL if e.op in COMPARISON else t
        else:
            e.type = t

    def unary(self, e: A.Unary):
        t = self.expr(e.operand)
        if e.op == "NOT":
            if isinstance(t, T.Untyped) or t.kind not in ("bool", "bits"):
                _err(e, f"NOT needs a BOOL or a bit string, not {t}")
        elif isinstance(t, T.Elementary) and (
            t.kind not in ("int", "real", "time") or not t.signed
        ):
            _err(e, f"unary minus needs a signed number or TIME, not {t}")
        e.type = t

    def binary(self, e: A.Binary):
        a, b = self.expr(e.left), self.expr(e.right)
        op = e.op
        if op == "&":
            op = e.op = "AND"
        if isinstance(a, T.Untyped) and isinstance(b, T.Untyped):
            if op in LOGIC or op == "MOD" and "real" in (a.kind, b.kind):
                _err(e, f"{op} of two untyped literals: give one a type (INT#..)")
            kind = "real" if "real" in (a.kind, b.kind) else "int"
            e.type = T.BOOL if op in COMPARISON else T.Untyped(kind)
            e.operand_type = T.Untyped(kind)
            return
        # TIME arithmetic: TIME ± TIME, TIME * integer, TIME / integer (docs/scl.md §3.4)
        timed = [x for x in (a, b) if isinstance(x, T.Elementary) and x.kind == "time"]
        if timed and op in ARITHMETIC:
            tt = timed[0]
            count = T.LINT if tt == T.LTIME else T.DINT  # what a TIME (LTIME) counts in
            if op in ("+", "-") and a == b == tt:
                e.operand_type = e.type = tt
                return
            if op in ("*", "/") and a == tt:
                if isinstance(b, T.Untyped):
                    self.coerce(e.right, count, f"the {op} operand")
                    b = count
                if b.kind == "int" and T.implicit(b, count):
                    e.operand_type = e.type = tt
                    return
            _err(e, f"{a} {op} {b}: {tt} takes + and - of {tt}, * and / by an integer")
        if isinstance(a, T.Untyped):
            self.coerce(e.left, b, f"the {op} operand")
            a = b
        elif isinstance(b, T.Untyped):
            self.coerce(e.right, a, f"the {op} operand")
            b = a
        t = T.common(a, b)
        if t is None:
            _err(
                e,
                f"{a} {op} {b}: S7 converts neither operand to the other's type implicitly;"
                " convert one with *_TO_*",
            )
        e.operand_type = t
        if op in ARITHMETIC:
            if t.kind not in ("int", "real"):
                _err(e, f"{op} needs numbers, not {t}")
            if op == "MOD" and t.kind != "int":
                _err(e, f"MOD needs integers, not {t}")
            e.type = t
        elif op in COMPARISON:
            if t.kind == "bool" and op not in ("=", "<>"):
                _err(e, f"BOOL values compare with = and <> only, not {op}")
            e.type = T.BOOL
        else:
            if t.kind not in ("bool", "bits"):
                _err(e, f"{op} needs BOOL or bit strings, not {t}")
            e.type = t

    # Calls (docs/scl.md §3.5, §3.6)

    def arguments(self, call: A.Call, names: list[str], positional_ok=True) -> dict:
        given = {}
        for i, arg in enumerate(call.args):
            if arg.target is not None:
                _err(arg, f"{call.callee} has no output '{arg.name}'")
            name = arg.name.upper() if arg.name else None
            if name is None:
                if not positional_ok or i >= len(names) or any(a.name for a in call.args):
                    _err(arg, f"{call.callee}: name the arguments ({', '.join(names)} := ...)")
                name = names[i]
            if name not in names:
                _err(arg, f"{call.callee} has no input '{arg.name}' (it takes {', '.join(names)})")
            if name in given:
                _err(arg, f"{call.callee}: '{name}' is given twice")
            given[name] = arg.value
        missing = [n for n in names if n not in given]
        if missing:
            _err(call, f"{call.callee} needs {', '.join(missing)}")
        return given

    def call(self, c: A.Call):
        name = c.callee.upper()
        if c.local or self.names.get(c.callee.lower()):
            _err(c, f"the instance call #{c.callee}(...) is a statement, not a value")
        m = CONVERSION.match(name)
        if m:
            return self.conversion(c, m.group(1), m.group(2))
        if name == "QRY_CINT":
            return self.qry_cint(c)
        if name in ("LOWER_BOUND", "UPPER_BOUND"):
            return self.bound(c, name)
        shapes = {
            "ABS": ["IN"],
            "SQRT": ["IN"],
            "SIN": ["IN"],
            "COS": ["IN"],
            "TRUNC": ["IN"],
            "LIMIT": ["MN", "IN", "MX"],
            "SEL": ["G", "IN0", "IN1"],
        }
        if name in ("MIN", "MAX"):
            count = max(2, len(c.args))
            shapes[name] = [f"IN{i}" for i in range(1, count + 1)]
        if name not in shapes:
            _err(c, f"unknown or unsupported function '{c.callee}' (docs/scl.md §3.5)")
        args = self.arguments(c, shapes[name])
        c.args = [A.Argument(c.loc, n, args[n]) for n in shapes[name]]
        values = [a.value for a in c.args]
        for v in values:
            self.expr(v)
        if name == "SEL":
            self.coerce(values[0], T.BOOL, "SEL's G")
            values = values[1:]
        t = self.unify(c, values)
        if name in ("SIN", "COS"):
            if isinstance(t, T.Untyped):
                t = T.REAL
                self.coerce(values[0], t, f"{name}'s IN")
            if t != T.REAL:
                _err(c, f"{name} of {t}: only {name} of a REAL is supported yet (docs/scl.md §3.5)")
        elif name in ("SQRT", "TRUNC"):
            if isinstance(t, T.Untyped):
                t = T.LREAL
                self.coerce(values[0], t, f"{name}'s IN")
            if t.kind != "real":
                _err(c, f"{name} needs a REAL or LREAL, not {t}")
        elif name != "SEL" and (isinstance(t, T.Untyped) or t.kind not in ("int", "real")):
            if isinstance(t, T.Untyped):
                t = T.DINT if t.kind == "int" else T.LREAL
                for v in values:
                    self.coerce(v, t, f"{name}'s argument")
            else:
                _err(c, f"{name} needs numbers, not {t}")
        if name == "ABS" and t.kind == "int" and not t.signed:
            _err(c, f"ABS of an unsigned {t}")
        c.type = T.DINT if name == "TRUNC" else t
        c.operand = t
        return c.type

    def unify(self, c, values):
        typed = [v.type for v in values if isinstance(v.type, T.Elementary)]
        if not typed:
            kinds = {v.type.kind for v in values}
            return T.Untyped("real" if "real" in kinds else "int")
        t = typed[0]
        for other in typed[1:]:
            u = T.common(t, other)
            if u is None:
                _err(c, f"{c.callee}: {t} and {other} have no common type; convert with *_TO_*")
            t = u
        for v in values:
            self.coerce(v, t, f"{c.callee}'s argument")
        return t

    def conversion(self, c: A.Call, source: str, target: str):
        s, t = T.lookup(source), T.lookup(target)
        if not isinstance(s, T.Elementary) or not isinstance(t, T.Elementary) or s == t:
            _err(c, f"unknown conversion {c.callee}")
        kinds = {s.kind, t.kind}
        if "real" in kinds and kinds & {"bool", "time", "bits"}:
            _err(c, f"{c.callee}: S7 has no conversion between {s} and {t}")
        if "bool" in kinds and "time" in kinds:
            _err(c, f"{c.callee}: S7 has no conversion between {s} and {t}")
        args = self.arguments(c, ["IN"])
        value = args["IN"]
        self.expr(value)
        self.coerce(value, s, f"{c.callee}'s argument")
        c.args = [A.Argument(c.loc, "IN", value)]
        c.conversion = (s, t)
        c.type = t
        return t

    def bound(self, c: A.Call, name: str):
        """LOWER_BOUND(ARR := a, DIM := n), UPPER_BOUND: a bound of an ARRAY as a DINT; of an
        ARRAY[*] of the FMU 0 and numberOf<Name> - 1 (docs/scl.md §3.8)."""
        args = self.arguments(c, ["ARR", "DIM"])
        arr, dim = args["ARR"], self.fold(args["DIM"])
        if not isinstance(arr, A.VarRef):
            _err(arr, f"{name}'s ARR must be an ARRAY variable")
        t = self.expr(arr)
        if not isinstance(t, T.ArrayType):
            _err(arr, f"{name}'s ARR must be an ARRAY, not {t}")
        rank = 1 if t.dims is None else len(t.dims)
        if not isinstance(dim, A.Literal) or dim.kind != "int" or not 1 <= dim.value <= rank:
            _err(dim, f"{name}'s DIM must be a literal from 1 to {rank}")
        self.expr(dim)
        self.coerce(dim, T.UDINT, f"{name}'s DIM")
        c.bound = (arr, dim.value)
        c.type = T.DINT
        return c.type

    def qry_cint(self, c: A.Call):
        """QRY_CINT answers the period of the calling cyclic-interrupt OB: the FMU's cycleTime
        (docs/behaviour.md §1.1)."""
        self.uses_qry_cint = True
        outputs = {"CYCLE": T.UDINT, "PHASE": T.UDINT, "STATUS": T.ELEMENTARY["DWORD"]}
        c.outputs = {}
        for arg in c.args:
            name = (arg.name or "").upper()
            if arg.target is not None:
                if name not in outputs:
                    _err(arg, f"QRY_CINT has no output '{arg.name}' (CYCLE, PHASE, STATUS)")
                t = self.variable(arg.target, write=True)
                if any(not isinstance(m, str) for m in arg.target.members):
                    _err(arg, f"QRY_CINT's {name} goes to a variable or member, not to an element")
                if t != outputs[name]:
                    _err(
                        arg, f"QRY_CINT's {name} is a {outputs[name]}; '{arg.target.name}' is a {t}"
                    )
                c.outputs[name] = arg.target
            elif name == "OB_NR":
                t = self.expr(arg.value)
                if isinstance(t, T.Untyped):
                    self.coerce(arg.value, T.INT, "OB_NR")
                elif t.kind != "int":
                    _err(arg, f"QRY_CINT's OB_NR is a number, not {t}")
            else:
                _err(arg, "QRY_CINT takes OB_NR := and CYCLE =>, PHASE =>, STATUS =>")
        c.type = T.INT
        return c.type

    def call_statement(self, c: A.Call):
        d = self.names.get(c.callee.lower())
        if d is None:
            if c.local:
                _err(c, f"'{c.callee}' is not declared in {self.block.name}")
            self.call(c)  # a function whose value is dropped, e.g. QRY_CINT(...)
            return
        if not isinstance(d.type, T.FbType):
            _err(c, f"'{d.name}' is a {d.type}, not an FB instance")
        fb = d.type
        c.instance = A.VarRef(c.loc, d.name, [], True)
        c.instance.decl = d
        c.fb = fb
        c.ins, c.outs = [], []
        seen = set()
        for arg in c.args:
            if arg.name is None:
                _err(arg, f"{fb.name} '{d.name}': name the parameters (IN := ...)")
            name = arg.name.upper()
            if name in seen:
                _err(arg, f"'{name}' is given twice")
            seen.add(name)
            if arg.target is None:
                if name not in fb.inputs:
                    _err(arg, f"{fb.name} has no input '{arg.name}' ({', '.join(fb.inputs)})")
                self.expr(arg.value)
                self.coerce(arg.value, fb.inputs[name], f"{fb.name}'s {name}")
                c.ins.append((name, arg.value))
            else:
                if name not in fb.outputs:
                    _err(arg, f"{fb.name} has no output '{arg.name}' ({', '.join(fb.outputs)})")
                t = self.variable(arg.target, write=True)
                if not T.implicit(fb.outputs[name], t):
                    _err(
                        arg,
                        f"{fb.name}'s {name} is a {fb.outputs[name]}, '{arg.target.name}' a {t}",
                    )
                c.outs.append((name, arg.target))
        c.type = None

    def run(self):
        self.declarations()
        self.statements(self.block.body)


def check(block: A.Block, core_vars: set[str], core_fields: set[str], udts=None) -> Checker:
    if block.kind != "FUNCTION_BLOCK":
        _err(block, f"{block.name}: only a FUNCTION_BLOCK becomes an FMU")
    if not C_IDENTIFIER.match(block.name):
        _err(
            block,
            f'"{block.name}": the FB\'s name becomes the modelIdentifier and must be '
            "letters, digits and _",
        )
    checker = Checker(block, core_vars, core_fields, udts)
    checker.run()
    return checker
