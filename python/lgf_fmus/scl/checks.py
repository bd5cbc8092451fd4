"""The checks between parsing and C generation (docs/scl.md §3, §5): every name is declared,
every expression has an S7 type, every conversion is one S7 makes implicitly or one the program
writes, every construct is one the subset supports. Each refusal is an SclError at the
construct's file:line:col, before any C is generated. Annotates the tree in place: VarRef.decl,
Expr.type (an untyped literal takes its context's type), Binary.operand_type."""

from __future__ import annotations

import math
import re

from . import ast as A
from . import builtins, unsupported
from . import types as T
from .diagnostics import Code, Diagnostics, SclError, Silent, refuse

STATIC_SECTIONS = ("VAR", "VAR RETAIN", "VAR NON_RETAIN")
C_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*\Z")
ARITHMETIC = {"+", "-", "*", "/", "MOD"}
TIMERS = ("TON", "TOF", "TP")  # what an IEC_TIMER DB runs
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


_err = refuse  # docs/scl.md §5


# the longest name TIA Portal gives a block, a type or a variable
NAME_LIMIT = 128


def _identifier(node, name: str, message: str):
    """Refuses a name the C cannot hold as an identifier (message), or a longer one than TIA's."""
    if len(name) > NAME_LIMIT:
        _err(
            Code.NAME,
            node,
            f'"{name[:20]}...": a name of {len(name)} characters (TIA: {NAME_LIMIT} at most)',
        )
    if not C_IDENTIFIER.match(name):
        _err(Code.NAME, node, message)


class Program:
    """The blocks of the sources, checked on demand: an FB is checked before the first block that
    declares an instance of it, an FC before the first call of it, so they may stand in any
    order and in any file; a block reached again while its own check runs is a recursion, which
    S7 does not allow (docs/scl.md §3.6)."""

    def __init__(
        self,
        blocks: dict,
        core_vars: set[str],
        core_fields: set[str],
        udts=None,
        dbs=None,
        diagnostics: Diagnostics | None = None,
    ):
        self.diagnostics = diagnostics or Diagnostics({})  # every error, reported as found
        self.blocks = blocks  # lower-case name -> A.Block
        self.udts = udts or {}  # lower-case name -> A.TypeDecl
        self.dbs = dbs or {}  # lower-case name -> A.DataBlock
        self.db_statics: dict[str, A.VarDecl] = {}  # the DBs the FMU's FB uses, as its statics
        self.timer_dbs: dict[str, set[str]] | None = None  # DB -> the timers run on it
        # every STRUCT and UDT of the program, inner ones first (one typedef each in block.h)
        self.structs: list[T.StructType] = []
        self.resolving: list[str] = []  # the UDTs being resolved: one met again contains itself
        self.top = None  # the A.Block of the FB compiled into the FMU
        self.top_checker = None
        self.core_vars = core_vars
        self.core_fields = core_fields
        self.checked: dict[str, Checker] = {}
        self.active: list[A.Block] = []
        self.order: list[Checker] = []  # callees before their callers
        self.uses_date = False  # RD_SYS_T or RD_LOC_T: the parameter startDateAndTime
        self.uses_local = False  # RD_LOC_T: the parameter localTimeOffset

    def unit(self, name: str, node) -> Checker | None:
        key = name.lower()
        if key in self.checked:
            return self.checked[key]
        block = self.blocks.get(key)
        if block is None:
            return None
        if block in self.active:
            chain = " -> ".join(b.name for b in self.active[self.active.index(block) :])
            _err(
                Code.RECURSION,
                node,
                f"{block.name} calls itself ({chain} -> {block.name}): S7 has no recursion",
            )
        self.active.append(block)
        checker = Checker(block, self)
        if block is self.top:
            self.top_checker = checker  # the holder of the DBs, checked last
        try:
            checker.run()  # its errors reported, the next declaration or statement checked
        finally:
            self.active.pop()
        self.checked[key] = checker
        self.order.append(checker)
        return checker


class Checker:
    def __init__(self, block: A.Block, program: Program):
        self.block = block
        self.program = program
        self.core_vars = program.core_vars
        self.core_fields = program.core_fields
        self.names: dict[str, A.VarDecl] = {}
        self.loops = 0
        self.fc = block.kind == "FUNCTION"
        self.return_type = None  # an FC's: an Elementary, or None for VOID
        self.fb_type = None  # an FB's instance type, for the blocks that declare one

    def attempt(self, check, *args) -> bool:
        """Runs one check (a declaration, a statement, a condition); an error it finds is
        reported and the checks go on with the next one (docs/scl.md §5)."""
        try:
            check(*args)
            return True
        except SclError as e:
            self.program.diagnostics.report(e)
            return False

    # Declarations (docs/scl.md §4)

    def declarations(self):
        for d in list(self.block.decls):
            if not self.attempt(self.declare, d):
                d.type = T.ERROR  # its uses end their statements without a second error
        if self.fc and not self.attempt(self.returns):
            self.return_type = T.ERROR

    def declare(self, d: A.VarDecl):
        key = d.name.lower()  # SCL names are case-insensitive
        if key in self.names:
            first = self.names[key].loc
            _err(
                Code.DUPLICATE, d, f"'{d.name}' is declared twice", [(first, "first declared here")]
            )
        _identifier(d, d.name, f'"{d.name}": only names of letters, digits and _ are supported')
        if key == "cycletime":
            _err(
                Code.RESERVED, d, "'cycleTime' is the FMU's own parameter (docs/behaviour.md §1.1)"
            )
        if key in ("en", "eno"):
            what = "output ENO" if key == "eno" else "input EN"
            _err(
                Code.RESERVED,
                d,
                f"'{d.name}': S7 gives every block its enable {what}; name it otherwise",
            )
        self.names[key] = d
        if self.fc and d.section in STATIC_SECTIONS:
            _err(
                Code.DECLARATION,
                d,
                f"the FUNCTION {self.block.name} has no instance data, so no statics: "
                f"declare '{d.name}' in VAR_TEMP, or make the block a FUNCTION_BLOCK",
            )
        if d.section == "VAR_IN_OUT" and self.block is not self.program.top:
            _err(
                Code.UNSUPPORTED,
                d,
                f"VAR_IN_OUT '{d.name}' of {self.block.name}: only the FB compiled into the "
                "FMU has in/outs yet, not an FC or an FB it uses (docs/scl.md §6)",
            )
        t = d.type = self.resolve(d)
        if d.type_ref is None and d.type_name.upper() in T.OB_NUMBERS:
            self.calling_ob(d)
        if isinstance(t, T.FbType):
            if d.section not in STATIC_SECTIONS:
                _err(
                    Code.DECLARATION,
                    d,
                    f"the {t.name} instance '{d.name}' must be a static (VAR): it keeps"
                    " its state from call to call",
                )
            if d.init is not None:
                _err(
                    Code.INITIAL, d.init, f"the {t.name} instance '{d.name}' takes no initial value"
                )
            return
        if t is T.DTL:
            if d.section not in STATIC_SECTIONS + ("VAR_TEMP",):
                _err(
                    Code.DECLARATION,
                    d,
                    f"the DTL '{d.name}': only a static or a VAR_TEMP can be a DTL (the "
                    "core has no FMI variable of a structure)",
                )
            if d.init is not None:
                _err(
                    Code.INITIAL,
                    d.init,
                    f"the DTL '{d.name}' takes no initial value (it starts at "
                    "DTL#1970-01-01-00:00:00)",
                )
            return
        if d.section == "VAR_IN_OUT":
            self.in_out(d, t)
        elif isinstance(t, T.ArrayType) and t.dims is None:
            _err(
                Code.DECLARATION,
                A.Node(d.type_loc),
                f"'{d.name}': ARRAY[*] is only a VAR_IN_OUT's type",
            )
        if (
            d.section in ("VAR_INPUT", "VAR_OUTPUT")
            and self.block is not self.program.top
            and not isinstance(t, T.Elementary)
        ):
            _err(
                Code.UNSUPPORTED,
                A.Node(d.type_loc),
                f"the {t} {d.section} '{d.name}' of {self.block.name}: the inputs and "
                "outputs of an FC or of an FB's instance are elementary yet (docs/scl.md §6)",
            )
        for leaf in leaves(t):
            self.storable(d, leaf)
        if d.init is not None:
            d.init = self.initial(d.init, t, f"the initial value of '{d.name}'")
        elif d.section == "VAR CONSTANT":
            _err(Code.INITIAL, d, f"the constant '{d.name}' needs a value")

    def calling_ob(self, d: A.VarDecl):
        """An input of an OB number (OB_CYCLIC: the LGF CI blocks' callOB) in the FB compiled
        into the FMU is no FMI variable: the parameter cycleTime plays the calling OB
        (docs/behaviour.md §1.1). It is a temporary holding its initial value, or 30 (OB30),
        in every call, as if the caller passed the same OB each time (docs/scl.md §4)."""
        if d.section != "VAR_INPUT" or self.block is not self.program.top:
            return
        d.section, d.calling_ob = "VAR_TEMP", True
        if d.init is None:
            d.init = A.Literal(d.loc, "int", "30", 30)

    def eno(self, ref: A.VarRef) -> A.VarDecl:
        """ENO, the enable output every block has: a BOOL temporary that starts TRUE and that
        the block may set; the FMU has no EN/ENO, so nothing reads it (docs/scl.md §3.4)."""
        d = A.VarDecl(ref.loc, "ENO", "BOOL", ref.loc, None, "VAR_TEMP")
        d.type = T.BOOL
        d.init = self.initial(A.Literal(ref.loc, "bool", "TRUE", True, "BOOL"), T.BOOL, "ENO")
        self.block.decls.append(d)
        self.names["eno"] = d
        return d

    # DBs (docs/scl.md §3.9)

    def global_db(self, name: str, node, method: str | None = None) -> A.VarDecl:
        """The DB `name` of the sources as the FMU holds it: a static of the FB compiled into
        the FMU (in its state, among its locals), made at its first use by any block of the
        program, which reaches it through the call's context. An instance DB of an
        FB ("Motor_DB"(...), "Motor_DB".Q), of an IEC timer ("T_DB".TON(...), which needs no
        DATA_BLOCK: the call names the timer) or a global DB ("Data".x)."""
        key = name.lower()
        d = self.program.db_statics.get(key)
        if d is None:
            top = self.program.top_checker
            try:
                d = top.db_static(name, self.program.dbs.get(key), node)
            except SclError:  # reported once: its other uses end without an error
                poisoned = A.VarDecl(node.loc, name, "", node.loc, None, "VAR", db=True)
                poisoned.type = T.ERROR
                self.program.db_statics[key] = poisoned
                raise
            self.program.db_statics[key] = d
        if d.type is T.ERROR:
            raise Silent()
        timer = d.type_name.upper() in TIMERS
        if method is not None and (not timer or d.type_name.upper() != method):
            what = f"an IEC_TIMER DB of {d.type_name}" if timer else f"the DB of {d.type_name}"
            _err(Code.DB, node, f'"{name}".{method}(...): "{name}" is {what}')
        if method is None and timer and isinstance(node, A.Call):
            _err(
                Code.DB,
                node,
                f'"{name}" is an IEC_TIMER DB: call it as "{name}".{d.type_name}(...)',
            )
        return d

    def is_db(self, name: str) -> bool:
        """A DB of the sources, or one a block runs an IEC timer on ("T_DB".TON(...))."""
        key = name.lower()
        return key in self.program.dbs or bool(self.timers_on(name))

    def timers_on(self, name: str) -> set[str]:
        """The timers the program's blocks run on the DB `name` ("T_DB".TON(...))."""
        if self.program.timer_dbs is None:  # the whole program's, found once
            self.program.timer_dbs = {}
            for block in self.program.blocks.values():
                for n in A.nodes(block.body):
                    if isinstance(n, A.Call) and n.method:
                        self.program.timer_dbs.setdefault(n.callee.lower(), set()).add(n.method)
        return self.program.timer_dbs.get(name.lower(), set())

    def db_static(self, name: str, db: A.DataBlock | None, node) -> A.VarDecl:
        loc = db.loc if db is not None else node.loc
        d = A.VarDecl(loc, name, "", loc, None, "VAR", comment=f'the DB "{name}"', db=True)
        of = db.of_type if db is not None else "IEC_TIMER"
        if of is not None and of.upper() == "IEC_TIMER":
            d.type_name = self.timer_of(name, node if db is None else db)
        elif of is not None:
            if self.program.blocks.get(of.lower()) is None:
                _err(
                    Code.DB,
                    db,
                    f'the DB "{name}" is an instance of {of}, which is no FB of the sources',
                )
            d.type_name = of
            if db.values:
                _err(
                    Code.UNSUPPORTED,
                    db.values[0],
                    f'the instance DB "{name}": start values are not supported',
                )
        else:
            members = {m.name.lower(): m for m in db.decls}
            for value in db.values:  # BEGIN name := value; a member's start value
                m = members.get(value.target.name.lower())
                if m is None or value.target.members:
                    _err(Code.DB, value, f"the DB \"{name}\" has no member '{value.target.name}'")
                m.init = value.value
            for m in db.decls:
                m.section = "STRUCT"
            d.type_ref = A.StructTypeRef(loc, db.decls)
        self.block.decls.append(d)
        self.declare(d)
        return d

    def timer_of(self, name: str, node) -> str:
        """TON, TOF or TP: the one timer that the program runs on the IEC_TIMER DB `name` (a DB
        without a DATA_BLOCK in the sources is one, if a block runs a timer on it)."""
        used = self.timers_on(name)
        if len(used) != 1 or not used <= set(TIMERS):
            _err(
                Code.DB,
                node,
                f'the IEC_TIMER DB "{name}" must run one timer, "{name}".TON/TOF/TP(...), '
                f"not {', '.join(sorted(used)) or 'none'}",
            )
        return next(iter(used))

    def user_fb(self, name: str, loc):
        """The instance type of the user FUNCTION_BLOCK name (checked first), or None for no
        block of that name."""
        block = self.program.blocks.get(name.lower())
        if block is None:
            return None
        if block.kind != "FUNCTION_BLOCK":
            _err(
                Code.INSTANCE,
                A.Node(loc),
                f'{block.name} is a FUNCTION: it has no instance; call it as "{block.name}"(...)',
            )
        return self.program.unit(block.name, A.Node(loc)).instance_type()

    def instance_type(self) -> T.FbType:
        if self.fb_type is None:
            sections = {"VAR_INPUT": {}, "VAR_OUTPUT": {}}
            for d in self.block.decls:
                if d.section in sections:
                    sections[d.section][d.name.upper()] = d.type
            self.fb_type = T.FbType(
                self.block.name,
                "",
                sections["VAR_INPUT"],
                sections["VAR_OUTPUT"],
                timed=True,
                block=self,
            )
        return self.fb_type

    def returns(self):
        """An FC's return value: a variable of the FC's own name (#Fc := ...)."""
        name = self.block.return_type
        if name.upper() == "VOID":
            return
        t = T.lookup(name)
        if not isinstance(t, T.Elementary) or t.var not in self.core_vars:
            _err(
                Code.UNSUPPORTED,
                self.block,
                f"the FUNCTION {self.block.name} : {name}: unsupported return type",
            )
        self.return_type = t
        key = self.block.name.lower()
        if key in self.names:
            _err(
                Code.RESERVED,
                self.names[key],
                f"'{self.names[key].name}' is the name of its FUNCTION",
            )
        d = A.VarDecl(self.block.loc, self.block.name, name, self.block.loc, None, "RETURN")
        d.type = t
        self.names[key] = d

    def in_out(self, d: A.VarDecl, t):
        """VAR_IN_OUT (docs/scl.md §4): an elementary one (a STRUCT, a fixed ARRAY) is an FMI
        input and the output <name>_out on the same data (each member and element); an ARRAY[*]
        the table of tunable parameters name[i] with its size numberOf<Name>, a fixed
        parameter."""
        if not isinstance(t, T.ArrayType) or t.dims is not None:
            out = d.name + "_out"
            if any(x.name.lower() == out.lower() for x in self.block.decls):
                _err(
                    Code.RESERVED,
                    d,
                    f"VAR_IN_OUT '{d.name}': its output '{out}' is declared as well",
                )
            return
        count = T.table_count(d.name)
        if any(
            x.name.lower() == count.lower()
            or x is not d
            and x.section == "VAR_IN_OUT"
            and T.table_count(x.name).lower() == count.lower()
            for x in self.block.decls
        ):
            _err(
                Code.RESERVED,
                d,
                f"VAR_IN_OUT '{d.name}': '{count}', the size of its table, is declared as well",
            )

    def storable(self, d: A.VarDecl, t):
        """Whether the core can hold t as the FMI variable or static of d (src/core/model.h)."""
        if isinstance(t, T.FbType):
            _err(
                Code.UNSUPPORTED,
                A.Node(d.type_loc),
                f"'{d.name}': an ARRAY or STRUCT of {t.name} instances",
            )
        if d.section in ("VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT") and t.var not in self.core_vars:
            why = (
                f"the core has no FMI variable of type {t.name} yet ({t.var} in src/core/model.h)"
                if t.var
                else f"FMI 2.0 and the core have no {t.bits}-bit integer variable; keep it"
                " a static or a temporary (docs/scl.md §3.1)"
            )
            _err(Code.DECLARATION, A.Node(d.type_loc), f"{t.name} {d.section} '{d.name}': {why}")
        if d.section in STATIC_SECTIONS and t.field not in self.core_fields:
            _err(
                Code.UNSUPPORTED,
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
            if element is T.DTL:
                _err(
                    Code.UNSUPPORTED,
                    ref,
                    f"'{owner}': an ARRAY of DTLs is not supported yet (docs/scl.md §6)",
                )
            if isinstance(element, T.ArrayType):
                _err(
                    Code.UNSUPPORTED,
                    ref,
                    f"'{owner}': an ARRAY of ARRAYs; write ARRAY[a..b, c..d] OF ...",
                )
            if None in ref.dims:
                if len(ref.dims) > 1:
                    _err(
                        Code.UNSUPPORTED,
                        ref,
                        f"'{owner}': ARRAY[*] of one dimension only is supported",
                    )
                return T.ArrayType(element, None)
            for lo, hi in ref.dims:
                if lo > hi:
                    _err(
                        Code.RANGE,
                        ref,
                        f"'{owner}': ARRAY[{lo}..{hi}]: the low bound is above the high",
                    )
                if not T.fits(lo, T.DINT) or not T.fits(hi, T.DINT):
                    _err(Code.RANGE, ref, f"'{owner}': ARRAY bounds are DINTs")
            array = T.ArrayType(element, tuple(ref.dims))
            if math.prod(array.sizes) > ARRAY_LIMIT:
                _err(Code.RANGE, ref, f"'{owner}': {array} has more than {ARRAY_LIMIT} elements")
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
                _err(Code.UNSUPPORTED, A.Node(loc), unsupported.type_message(name))
            _err(
                Code.UNDECLARED,
                A.Node(loc),
                f"unknown or unsupported data type '{name}' of '{owner}' (docs/scl.md §3.1)",
            )
        return t

    def udt(self, decl: A.TypeDecl, loc):
        if decl.type is T.ERROR:
            raise Silent()
        if decl.type is not None:
            return decl.type
        if decl.name.lower() in self.program.resolving:
            _err(Code.RECURSION, A.Node(loc), f'the UDT "{decl.name}" contains itself')
        self.program.resolving.append(decl.name.lower())
        try:
            _identifier(
                decl,
                decl.name,
                f'"{decl.name}": only UDT names of letters, digits and _ are supported',
            )
            decl.type = self.struct(decl.struct, decl.name, decl.name)
        except SclError:
            decl.type = T.ERROR  # reported once, here: its other uses end without an error
            raise
        finally:
            self.program.resolving.pop()
        return decl.type

    def struct(self, ref: A.StructTypeRef, name: str | None, owner: str):
        members = {}
        for m in ref.members:
            if m.name.lower() in (k.lower() for k in members):
                first = next(x for x in ref.members if x.name.lower() == m.name.lower()).loc
                _err(
                    Code.DUPLICATE,
                    m,
                    f"'{owner}' has two members '{m.name}'",
                    [(first, "first declared here")],
                )
            _identifier(m, m.name, f'"{m.name}": only names of letters, digits and _ are supported')
            t = self.type_of(m.type_ref or (m.type_name, m.type_loc), f"{owner}.{m.name}")
            if isinstance(t, T.FbType):
                _err(
                    Code.UNSUPPORTED,
                    A.Node(m.type_loc),
                    f"'{owner}.{m.name}': an FB instance in a STRUCT",
                )
            if t is T.DTL:
                _err(
                    Code.UNSUPPORTED,
                    A.Node(m.type_loc),
                    f"'{owner}.{m.name}': a DTL in a STRUCT is not supported",
                )
            if isinstance(t, T.ArrayType) and t.dims is None:
                _err(
                    Code.DECLARATION,
                    A.Node(m.type_loc),
                    f"'{owner}.{m.name}': ARRAY[*] in a STRUCT",
                )
            init = None
            if m.init is not None:
                init = self.initial(m.init, t, f"the initial value of '{owner}.{m.name}'")
            members[m.name] = (t, init)
        tag = (name or owner).lower().replace(".", "_")
        structs = self.program.structs
        c = f"scl_{self.block.name.lower()}_{tag}_{len(structs)}"
        t = T.StructType(name, c, members)
        structs.append(t)
        return t

    def initial(self, e, t, what: str):
        """An initial value, checked against t: a Literal for an elementary t, a list of one
        per element (None: the element's default) for an ARRAY, a dict of members for a
        STRUCT (docs/scl.md §3.8)."""
        if isinstance(t, T.ArrayType):
            if not isinstance(e, A.ArrayInit):
                _err(Code.INITIAL, e, f"{what}: an ARRAY takes [value, count(value), ...]")
            values = []
            for count, item in e.items:
                if count < 1:
                    _err(Code.INITIAL, e, f"{what}: a repetition count must be 1 or more")
                value = None if item is None else self.initial(item, t.element, what)
                values += [value] * count
            if t.dims is not None and len(values) > math.prod(t.sizes):
                _err(
                    Code.INITIAL,
                    e,
                    f"{what}: {len(values)} values for the {math.prod(t.sizes)} of {t}",
                )
            if t.dims is None and len(values) > T.TABLE_CAPACITY:
                _err(
                    Code.INITIAL,
                    e,
                    f"{what}: {len(values)} values, the table holds {T.TABLE_CAPACITY}",
                )
            return values
        if isinstance(t, T.StructType):
            if not isinstance(e, A.StructInit):
                _err(Code.INITIAL, e, f"{what}: a {t} takes (member := value, ...)")
            values = {}
            for name, loc, value in e.members:
                key = t.member(name)
                if key is None:
                    _err(Code.INITIAL, A.Node(loc), f"{what}: {t} has no member '{name}'")
                if key in values:
                    _err(Code.INITIAL, A.Node(loc), f"{what}: '{name}' is given twice")
                values[key] = self.initial(value, t.members[key][0], what)
            return values
        if isinstance(e, (A.ArrayInit, A.StructInit)) or not isinstance(t, T.Elementary):
            _err(Code.INITIAL, e, f"{what}: {t} takes a literal")
        return self.constant(e, t, what)

    def constant(self, e: A.Expr, t: T.Elementary, what: str) -> A.Expr:
        e = self.fold(e)
        if not isinstance(e, A.Literal):
            _err(Code.INITIAL, e, f"{what} must be a literal")
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
            self.attempt(self.statement, s)

    def statement(self, s: A.Stmt):
        if isinstance(s, A.Assign):
            self.assign(s)
        elif isinstance(s, A.CallStmt):
            self.call_statement(s.call)
        elif isinstance(s, A.If):
            for condition, body in s.branches:
                self.attempt(self.condition, condition, "IF")
                self.statements(body)
            self.statements(s.otherwise or [])
        elif isinstance(s, A.Case):
            self.attempt(self.case_labels, s)
            for _, body in s.branches:
                self.statements(body)
            self.statements(s.otherwise or [])
        elif isinstance(s, A.For):
            self.attempt(self.for_header, s)
            self.loop(s.body)
        elif isinstance(s, A.While):
            self.attempt(self.condition, s.condition, "WHILE")
            self.loop(s.body)
        elif isinstance(s, A.Repeat):
            self.loop(s.body)
            self.attempt(self.condition, s.condition, "UNTIL")
        elif isinstance(s, A.Jump):
            if s.kind != "RETURN" and not self.loops:
                _err(Code.STATEMENT, s, f"{s.kind} outside FOR, WHILE or REPEAT")
        elif isinstance(s, A.Region):
            self.statements(s.body)

    def case_labels(self, s: A.Case):
        """The selector and the labels of a CASE: an integer or bit string, literal labels of its
        range, no two overlapping."""
        t = self.expr(s.selector)
        if isinstance(t, T.Untyped):
            self.coerce(s.selector, T.DINT, "the CASE selector")
            t = T.DINT
        if not isinstance(t, T.Elementary) or t.kind not in ("int", "bits"):
            _err(
                Code.OPERAND,
                s.selector,
                f"the CASE selector must be an integer or bit string, not {t}",
            )
        seen = []
        for labels, _ in s.branches:
            for low, high in labels:
                if not (T.fits(low, t) and T.fits(high, t)) or low > high:
                    _err(Code.RANGE, s, f"the CASE label {low}..{high} is not a range of {t}")
                for other in seen:
                    if low <= other[1] and other[0] <= high:
                        _err(
                            Code.DUPLICATE,
                            s,
                            f"the CASE label {low}..{high} overlaps {other[0]}..{other[1]}",
                        )
                seen.append((low, high))

    def for_header(self, s: A.For):
        t = self.variable(s.variable, write=True)
        if s.variable.members:
            _err(Code.STATEMENT, s.variable, "the FOR variable must be a plain variable")
        if not isinstance(t, T.Elementary) or t.kind != "int" or not t.signed or t.bits > 32:
            _err(Code.OPERAND, s.variable, f"the FOR variable must be a SINT, INT or DINT, not {t}")
        for part, what in ((s.start, "start"), (s.end, "end"), (s.step, "BY")):
            if part is not None:
                self.expr(part)
                self.coerce(part, t, f"the FOR {what} value")

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
        if ref.quoted and self.is_db(ref.name):
            d = self.global_db(ref.name, ref)
        if d is None and ref.name.upper() == "ENO":
            d = self.eno(ref)
        if d is None:
            _err(Code.UNDECLARED, ref, f"'{ref.name}' is not declared in {self.block.name}")
        return d

    def variable(self, ref: A.VarRef, write=False):
        d = ref.decl = self.decl(ref)
        if d.type is T.ERROR:
            raise Silent()
        if isinstance(d.type, T.FbType):
            fb = d.type
            if not ref.members:
                _err(
                    Code.INSTANCE,
                    ref,
                    f"the {fb.name} instance '{d.name}' is not a value: use "
                    f"#{d.name}.{next(iter(fb.outputs), '<output>')}",
                )
            if len(ref.members) > 1 or not isinstance(ref.members[0], str):
                _err(Code.SELECTOR, ref, f"'{d.name}': {fb.name} has members .Q, .IN, ... only")
            member = ref.members[0].upper()
            if fb.block is not None and member not in fb.inputs and member not in fb.outputs:
                _err(
                    Code.SELECTOR,
                    ref,
                    f"{fb.name} has no input or output '{ref.members[0]}' (the statics of an "
                    "instance are its own)",
                )
            if member in fb.outputs:
                if write:
                    _err(
                        Code.READ_ONLY,
                        ref,
                        f"'{d.name}.{ref.members[0]}' is an output of {fb.name}: "
                        "only the instance writes it",
                    )
                ref.type = fb.outputs[member]
            elif member in fb.inputs:
                ref.type = fb.inputs[member]
            else:
                _err(Code.SELECTOR, ref, f"{fb.name} has no member '{ref.members[0]}'")
            ref.members = [member]
            return ref.type
        if d.type is T.DTL:
            if len(ref.members) != 1 or ref.members[0].upper() not in T.DTL_MEMBERS:
                if not ref.members:
                    _err(
                        Code.SELECTOR,
                        ref,
                        f"the DTL '{d.name}' is not a value: use #{d.name}.YEAR, ...",
                    )
                _err(
                    Code.SELECTOR,
                    ref,
                    f"a DTL has no member '{'.'.join(ref.members)}' ({', '.join(T.DTL_MEMBERS)})",
                )
            ref.members = [ref.members[0].upper()]
            ref.type = T.DTL_MEMBERS[ref.members[0]]
            return ref.type
        if write and d.section == "VAR CONSTANT":
            _err(Code.READ_ONLY, ref, f"'{d.name}' is a constant")
        if write and (d.section == "VAR_INPUT" or d.calling_ob):
            _err(
                Code.READ_ONLY,
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
                    _err(Code.SELECTOR, ref, f"'{name}' is a {t}: it has no member '{sel}'")
                ref.path.append(("member", key))
                t, name = t.members[key][0], f"{name}.{key}"
            elif isinstance(sel, A.Index):
                if not isinstance(t, T.ArrayType):
                    _err(Code.SELECTOR, sel, f"'{name}' is a {t}, not an ARRAY: it takes no index")
                rank = 1 if t.dims is None else len(t.dims)
                if len(sel.exprs) != rank:
                    given = len(sel.exprs)
                    _err(
                        Code.SELECTOR,
                        sel,
                        f"'{name}' is an {t}: it takes {rank} index(es), not {given}",
                    )
                for i, e in enumerate(sel.exprs):
                    it = self.expr(e)
                    if isinstance(it, T.Untyped):
                        self.coerce(e, T.DINT, f"the index of '{name}'")
                    elif not isinstance(it, T.Elementary) or it.kind != "int" or it.bits > 32:
                        _err(
                            Code.OPERAND,
                            e,
                            f"the index of '{name}' must be an integer of up to 32 bits, not {it}",
                        )
                    if isinstance(e, A.Literal) and t.dims is not None:
                        lo, hi = t.dims[i]
                        if not lo <= e.value <= hi:
                            _err(
                                Code.RANGE, e, f"the index {e.value} is outside {name}'s {lo}..{hi}"
                            )
                ref.path.append(("index", sel.exprs, t))
                t, name = t.element, f"{name}[..]"
            else:
                if not isinstance(t, T.Elementary) or t.kind not in ("int", "bits"):
                    _err(
                        Code.SELECTOR,
                        sel,
                        f"'{name}' is a {t}: bit access .%X is on a bit string or integer",
                    )
                if sel.number >= t.bits:
                    _err(Code.RANGE, sel, f"'{name}' is a {t}: its bits are %X0 to %X{t.bits - 1}")
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
        if e.type is T.ERROR:  # a call of an FC whose return type was refused
            raise Silent()
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
            _err(Code.LITERAL, e, f"{e.text}: unknown literal type {e.type_prefix}")
        if e.kind == "real" and t.kind != "real":
            _err(Code.LITERAL, e, f"{e.text}: a {t} literal must be a whole number")
        if e.kind == "int" and t.kind in ("int", "bits") and not T.fits(e.value, t):
            _err(Code.RANGE, e, f"{e.text} does not fit {t} ({t.low} to {t.high})")
        if t.kind == "real" and abs(float(e.value)) > T.REAL_MAX[t.name]:
            _err(Code.RANGE, e, f"{e.text} is beyond the largest {t}")
        if t.kind == "time":
            _err(Code.LITERAL, e, f"{e.text}: write a TIME as T#...")
        return t

    def coerce(self, e: A.Expr, t, what: str):
        """Gives an untyped literal (or an expression of them) the type t, or checks that e's
        type converts to t implicitly (docs/scl.md §3.2)."""
        if t is T.ERROR or e.type is T.ERROR:
            raise Silent()
        if isinstance(e.type, T.Untyped) and not isinstance(t, T.Elementary):
            _err(Code.CONVERSION, e, f"{what}: {e.type} is no {t}")
        if isinstance(e.type, T.Untyped):
            if t.kind == "bool" or t.kind == "time" or (e.type.kind == "real" and t.kind != "real"):
                _err(Code.CONVERSION, e, f"{what}: {e.type} is no {t}")
            self.settle(e, t, what)
            return
        if not T.implicit(e.type, t):
            both = isinstance(e.type, T.Elementary) and isinstance(t, T.Elementary)
            hint = f"; write {e.type}_TO_{t}(...)" if both else ""
            _err(Code.CONVERSION, e, f"{what}: S7 converts no {e.type} to {t} implicitly{hint}")

    def settle(self, e, t, what):
        if isinstance(e, A.Literal):
            if e.kind == "int" and t.kind in ("int", "bits") and not T.fits(e.value, t):
                _err(Code.RANGE, e, f"{what}: {e.text} does not fit {t} ({t.low} to {t.high})")
            if t.kind == "real" and abs(float(e.value)) > T.REAL_MAX[t.name]:
                _err(Code.RANGE, e, f"{what}: {e.text} is beyond the largest {t}")
            e.type = t
        elif isinstance(e, A.Unary):
            self.settle(e.operand, t, what)
            e.type = t
        elif isinstance(e, A.Binary):
            self.settle(e.left, t, what)
            self.settle(e.right, t, what)
            e.operand_type = t
            e.type = T.BOOL if e.op in COMPARISON else t
        elif isinstance(e, A.Call) and e.builtin is not None and e.builtin.settle is not None:
            e.builtin.settle(self, e, t, what)
        else:
            e.type = t

    def unary(self, e: A.Unary):
        t = self.expr(e.operand)
        if e.op == "NOT":
            if isinstance(t, T.Untyped) or t.kind not in ("bool", "bits"):
                _err(Code.OPERAND, e, f"NOT needs a BOOL or a bit string, not {t}")
        elif isinstance(t, T.Elementary) and (
            t.kind not in ("int", "real", "time") or not t.signed
        ):
            _err(Code.OPERAND, e, f"unary minus needs a signed number or TIME, not {t}")
        e.type = t

    def binary(self, e: A.Binary):
        a, b = self.expr(e.left), self.expr(e.right)
        op = e.op
        if op == "&":
            op = e.op = "AND"
        if op == "**":
            return self.power(e, a, b)
        if isinstance(a, T.Untyped) and isinstance(b, T.Untyped):
            if op in LOGIC or op == "MOD" and "real" in (a.kind, b.kind):
                _err(Code.OPERAND, e, f"{op} of two untyped literals: give one a type (INT#..)")
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
            _err(
                Code.OPERAND, e, f"{a} {op} {b}: {tt} takes + and - of {tt}, * and / by an integer"
            )
        if isinstance(a, T.Untyped):
            self.coerce(e.left, b, f"the {op} operand")
            a = b
        elif isinstance(b, T.Untyped):
            self.coerce(e.right, a, f"the {op} operand")
            b = a
        t = T.common(a, b)
        if t is None:
            _err(
                Code.CONVERSION,
                e,
                f"{a} {op} {b}: S7 converts neither operand to the other's type implicitly;"
                " convert one with *_TO_*",
            )
        e.operand_type = t
        if op in ARITHMETIC:
            if t.kind not in ("int", "real"):
                _err(Code.OPERAND, e, f"{op} needs numbers, not {t}")
            if op == "MOD" and t.kind != "int":
                _err(Code.OPERAND, e, f"MOD needs integers, not {t}")
            e.type = t
        elif op in COMPARISON:
            if t.kind == "bool" and op not in ("=", "<>"):
                _err(Code.OPERAND, e, f"BOOL values compare with = and <> only, not {op}")
            e.type = T.BOOL
        else:
            if t.kind not in ("bool", "bits"):
                _err(Code.OPERAND, e, f"{op} needs BOOL or bit strings, not {t}")
            e.type = t

    def power(self, e: A.Binary, a, b):
        """a ** b, S7's EXPT (docs/scl.md §3.5): a REAL or LREAL base, an integer or real
        exponent; the result has the base's type, or LREAL where either is an LREAL."""
        if isinstance(a, T.Untyped):
            a = T.LREAL if not isinstance(b, T.Elementary) or b.kind != "real" else b
            self.coerce(e.left, a, "the base of **")
        if not isinstance(a, T.Elementary) or a.kind != "real":
            _err(
                Code.OPERAND,
                e,
                f"** needs a REAL or LREAL base, not {a}; convert it with *_TO_REAL",
            )
        if isinstance(b, T.Untyped):
            b = a if b.kind == "real" else T.DINT
            self.coerce(e.right, b, "the exponent of **")
        if b.kind == "real":
            e.type = e.operand_type = T.common(a, b)
        elif b.kind == "int" and T.implicit(b, T.LREAL):
            e.type = e.operand_type = a
        else:
            _err(Code.OPERAND, e, f"the exponent of ** must be a number, not {b}")
        return e.type

    # Calls (docs/scl.md §3.5, §3.6)

    def arguments(self, call: A.Call, names: list[str], positional_ok=True) -> dict:
        given = {}
        for i, arg in enumerate(call.args):
            if arg.target is not None:
                _err(Code.PARAMETER, arg, f"{call.callee} has no output '{arg.name}'")
            name = arg.name.upper() if arg.name else None
            if name is None:
                if not positional_ok or i >= len(names) or any(a.name for a in call.args):
                    _err(
                        Code.PARAMETER,
                        arg,
                        f"{call.callee}: name the arguments ({', '.join(names)} := ...)",
                    )
                name = names[i]
            if name not in names:
                _err(
                    Code.PARAMETER,
                    arg,
                    f"{call.callee} has no input '{arg.name}' (it takes {', '.join(names)})",
                )
            if name in given:
                _err(Code.PARAMETER, arg, f"{call.callee}: '{name}' is given twice")
            given[name] = arg.value
        missing = [n for n in names if n not in given]
        if missing:
            _err(Code.PARAMETER, call, f"{call.callee} needs {', '.join(missing)}")
        return given

    def call(self, c: A.Call):
        """A call as a value: of a user FC, else of a built-in (builtins/, its entry's check)."""
        d = None if c.quoted else self.names.get(c.callee.lower())
        if c.local or (d is not None and isinstance(d.type, T.FbType)):
            _err(
                Code.STATEMENT, c, f"the instance call #{c.callee}(...) is a statement, not a value"
            )
        unit = self.user_unit(c)
        if unit is not None:
            return self.fc_call(c, unit, statement=False)
        c.builtin = builtins.lookup(c.callee)
        if c.builtin is None:
            message = unsupported.function_message(c.callee)
            if message:
                _err(Code.UNSUPPORTED, c, message)
            _err(
                Code.UNDECLARED,
                c,
                f"unknown or unsupported function '{c.callee}' (docs/scl.md §3.5)",
            )
        c.type = c.builtin.check(self, c)
        return c.type

    def user_unit(self, c: A.Call):
        """The checked FC that c calls, None where no block of the sources has its name."""
        block = self.program.blocks.get(c.callee.lower())
        if block is None:
            return None
        if block.kind == "FUNCTION_BLOCK":
            _err(
                Code.INSTANCE,
                c,
                f"{block.name} is a FUNCTION_BLOCK: declare an instance of it in VAR "
                f'(#inst : "{block.name}";) and call #inst(...)',
            )
        return self.program.unit(block.name, c)

    def fc_call(self, c: A.Call, unit, statement: bool):
        """A call of a user FC (docs/scl.md §3.6): every input given, by name or in the order of
        their declaration; outputs by name (=>), each to a variable of the output's type."""
        fc = unit.block
        ins = [d for d in fc.decls if d.section == "VAR_INPUT"]
        outs = {d.name.upper(): d for d in fc.decls if d.section == "VAR_OUTPUT"}
        in_names = [d.name.upper() for d in ins]
        listed = ", ".join(d.name for d in ins) or "none"
        values, targets = {}, {}
        positional = [a for a in c.args if a.name is None]
        if positional and len(positional) != len(c.args):
            _err(
                Code.PARAMETER, c, f'"{fc.name}": name every parameter (a := ..., b => ...) or none'
            )
        if positional:
            if len(positional) != len(ins):
                _err(
                    Code.PARAMETER,
                    c,
                    f'"{fc.name}" takes {len(ins)} inputs ({listed}), not {len(positional)}',
                )
            values = dict(zip(in_names, (a.value for a in positional)))
        for arg in c.args if not positional else []:
            key = arg.name.upper()
            if key in values or key in targets:
                _err(Code.PARAMETER, arg, f"\"{fc.name}\": '{arg.name}' is given twice")
            if arg.target is None:
                if key not in in_names:
                    _err(
                        Code.PARAMETER,
                        arg,
                        f"\"{fc.name}\" has no input '{arg.name}' (inputs: {listed})",
                    )
                values[key] = arg.value
            else:
                if key not in outs:
                    _err(
                        Code.PARAMETER,
                        arg,
                        f"\"{fc.name}\" has no output '{arg.name}' "
                        f"(outputs: {', '.join(d.name for d in outs.values()) or 'none'})",
                    )
                targets[key] = arg.target
        missing = [d.name for d in ins if d.name.upper() not in values]
        if missing:
            _err(
                Code.PARAMETER,
                c,
                f'"{fc.name}" needs {", ".join(missing)}: an FC has no instance data, so '
                "every input is given in every call",
            )
        for d in ins:
            v = values[d.name.upper()]
            self.expr(v)
            self.coerce(v, d.type, f'"{fc.name}"\'s input {d.name}')
        for key, target in targets.items():
            t = self.variable(target, write=True)
            if any(step[0] == "bit" for step in target.path):
                _err(
                    Code.PARAMETER,
                    target,
                    f'"{fc.name}"\'s output {outs[key].name} goes to a variable, member or '
                    "element, not to a bit (.%X): assign it through a VAR_TEMP",
                )
            if t != outs[key].type:
                _err(
                    Code.PARAMETER,
                    target,
                    f'"{fc.name}"\'s output {outs[key].name} is a {outs[key].type}; '
                    f"'{target.name}' is a {t} (an FC's output goes to a variable of its type)",
                )
        if unit.return_type is None and not statement:
            _err(
                Code.STATEMENT,
                c,
                f'"{fc.name}" is a FUNCTION : Void, it has no value: call it as a statement',
            )
        c.unit = unit
        c.inputs = [values[n] for n in in_names]
        c.outputs = [targets.get(key) for key in outs]
        c.type = unit.return_type
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
                _err(
                    Code.CONVERSION,
                    c,
                    f"{c.callee}: {t} and {other} have no common type; convert with *_TO_*",
                )
            t = u
        for v in values:
            self.coerce(v, t, f"{c.callee}'s argument")
        return t

    def call_statement(self, c: A.Call):
        d = None if c.quoted else self.names.get(c.callee.lower())
        if c.method is not None or c.quoted and self.is_db(c.callee):
            d = self.global_db(c.callee, c, c.method)
        if d is not None and not c.local and not isinstance(d.type, T.FbType):
            d = None  # SHL(...) in a block with a variable shl: the function
        if d is None or d.section == "RETURN":
            if c.local and d is None:
                _err(Code.UNDECLARED, c, f"'{c.callee}' is not declared in {self.block.name}")
            unit = self.user_unit(c)
            if unit is not None:
                self.fc_call(c, unit, statement=True)
                return
            self.call(c)  # a function whose value is dropped, e.g. QRY_CINT(...)
            return
        if not isinstance(d.type, T.FbType):
            _err(Code.INSTANCE, c, f"'{d.name}' is a {d.type}, not an FB instance")
        fb = d.type
        c.instance = A.VarRef(c.loc, d.name, [], True)
        c.instance.decl = d
        c.fb = fb
        seen = set()
        for arg in c.args:
            if arg.name is None:
                _err(Code.PARAMETER, arg, f"{fb.name} '{d.name}': name the parameters (IN := ...)")
            name = arg.name.upper()
            if name in seen:
                _err(Code.PARAMETER, arg, f"'{name}' is given twice")
            seen.add(name)
            if arg.target is None:
                if name not in fb.inputs:
                    _err(
                        Code.PARAMETER,
                        arg,
                        f"{fb.name} has no input '{arg.name}' ({', '.join(fb.inputs)})",
                    )
                self.expr(arg.value)
                self.coerce(arg.value, fb.inputs[name], f"{fb.name}'s {name}")
                c.inputs.append((name, arg.value))
            else:
                if name not in fb.outputs:
                    _err(
                        Code.PARAMETER,
                        arg,
                        f"{fb.name} has no output '{arg.name}' ({', '.join(fb.outputs)})",
                    )
                t = self.variable(arg.target, write=True)
                if not T.implicit(fb.outputs[name], t):
                    _err(
                        Code.PARAMETER,
                        arg,
                        f"{fb.name}'s {name} is a {fb.outputs[name]}, '{arg.target.name}' a {t}",
                    )
                c.outputs.append((name, arg.target))
        c.type = None

    def run(self):
        self.attempt(
            _identifier,
            self.block,
            self.block.name,
            f'"{self.block.name}": only names of letters, digits and _ are supported',
        )
        self.declarations()
        self.statements(self.block.body)


# The date and time parameters of an FMU whose program reads the clock (docs/scl.md §3.6)
DATE_PARAMETERS = ("startDateAndTime", "localTimeOffset")


def check(
    block: A.Block,
    blocks: dict,
    core_vars: set[str],
    core_fields: set[str],
    udts=None,
    dbs=None,
    diagnostics: Diagnostics | None = None,
) -> Checker:
    """Checks the FB `block` and every FB and FC it uses, of the blocks of the sources (by
    lower-case name); the Checker of `block`, with the program as its `program`. Raises an
    SclError of every error found (docs/scl.md §5)."""
    if block.kind != "FUNCTION_BLOCK":
        _err(Code.PROGRAM, block, f"{block.name}: only a FUNCTION_BLOCK becomes an FMU")
    _identifier(
        block,
        block.name,
        f'"{block.name}": the FB\'s name becomes the modelIdentifier and must be '
        "letters, digits and _",
    )
    program = Program(blocks, core_vars, core_fields, udts, dbs, diagnostics)
    program.top = block
    checker = program.unit(block.name, block)
    used = DATE_PARAMETERS[: (program.uses_date) + (program.uses_local)]
    for name in used:
        d = checker.names.get(name.lower())
        if d is not None:
            checker.attempt(
                _err,
                Code.RESERVED,
                d,
                f"'{name}' is the FMU's own parameter of RD_SYS_T/RD_LOC_T (docs/scl.md §3.6)",
            )
    program.diagnostics.check()
    return checker
