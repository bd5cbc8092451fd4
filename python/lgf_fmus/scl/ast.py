"""The syntax tree of an SCL source (docs/scl.md §3): every node carries the place it was read
from (file:line:col), so that a check names the construct where the user wrote it. The parser
(parser.py) builds it, checks.py annotates the expressions with their S7 types, cgen.py reads
it."""

from __future__ import annotations

import enum
from dataclasses import dataclass, field, fields

from .diagnostics import SclError  # noqa: F401  (the error of every stage, docs/scl.md §5)


@dataclass(frozen=True)
class Loc:
    file: str
    line: int
    column: int

    def __str__(self) -> str:
        return f"{self.file}:{self.line}:{self.column}"


@dataclass
class Node:
    loc: Loc


class Section(str, enum.Enum):
    """Where a declaration stands (docs/scl.md §2, §4)."""

    INPUT = "VAR_INPUT"
    OUTPUT = "VAR_OUTPUT"
    IN_OUT = "VAR_IN_OUT"
    STATIC = "VAR"
    RETAIN = "VAR RETAIN"
    NON_RETAIN = "VAR NON_RETAIN"
    TEMP = "VAR_TEMP"
    CONSTANT = "VAR CONSTANT"
    MEMBER = "STRUCT"  # a member of a STRUCT, a UDT or a global DB
    RETURN = "RETURN"  # an FC's return value, the variable of its name

    def __str__(self) -> str:
        return self.value

    __format__ = str.__format__

    @property
    def static(self) -> bool:
        """A static: instance data, kept from call to call (in the FMU state)."""
        return self in (Section.STATIC, Section.RETAIN, Section.NON_RETAIN)

    @property
    def interface(self) -> bool:
        """An input, output or in/out: the block's parameters (the FMU's variables)."""
        return self in (Section.INPUT, Section.OUTPUT, Section.IN_OUT)

    @property
    def in_struct(self) -> bool:
        """A field of the block's C struct: its interface and its statics."""
        return self.interface or self.static

    @property
    def local(self) -> bool:
        """A C local of the call: it starts again in every call."""
        return self in (Section.TEMP, Section.CONSTANT)


# Declarations


@dataclass
class VarDecl(Node):
    name: str
    type_name: str
    type_loc: Loc
    init: Expr | None
    section: Section | str  # the parser's "" until the section around it is known
    comment: str = ""
    type: object = None  # checks.py: a types.Elementary, FbType, ArrayType or StructType
    # checks.py: the initial value checked against the type: a Literal of it, for an ARRAY a
    # list of one per element (None: the element's default), for a STRUCT a dict of members
    start: object = field(default=None, init=False)
    type_ref: object = None  # ArrayTypeRef or StructTypeRef; None: the named type type_name
    db: bool = False  # a DB of the program, held as a static of the FMU's FB (docs/scl.md §3.9)
    db_starts: list = field(default_factory=list)  # an instance DB's (member, start) (§3.9)
    calling_ob: bool = False  # an OB_CYCLIC input the FMU's cycleTime plays (docs/scl.md §4)
    # its attribute pragma, lower-case names: {"s7_setpoint": "True"} (docs/scl.md §3.9)
    attributes: dict = field(default_factory=dict)

    @property
    def setpoint(self) -> bool:
        """TIA's "Setpoint" of a member ({ S7_SetPoint := 'True'}), unless not "Writable from
        HMI/OPC UA" ({ ExternalWritable := 'False'}): in a global DB, a tunable parameter
        (docs/scl.md §3.9 [S7-DB-SETPOINT])."""
        marks = {k: v.lower() for k, v in self.attributes.items()}
        return marks.get("s7_setpoint") == "true" and marks.get("externalwritable") != "false"


@dataclass
class ArrayTypeRef(Node):
    """ARRAY[lo..hi, ...] OF element; a dimension None is [*] (docs/scl.md §3.1)."""

    dims: list[tuple[int, int] | None]
    element: object  # (name, loc), ArrayTypeRef or StructTypeRef


@dataclass
class SizedTypeRef(Node):
    """STRING[20], WSTRING[#LEN]: a named type with its length, an integer or the #NAME of a
    constant of the block (docs/scl.md §3.1)."""

    name: str
    size: int | str


@dataclass
class StructTypeRef(Node):
    """STRUCT members END_STRUCT, anonymous in a declaration or the body of a TYPE."""

    members: list[VarDecl]


@dataclass
class DataBlock(Node):
    """DATA_BLOCK "Name" ... BEGIN ... END_DATA_BLOCK (docs/scl.md §3.9): an instance DB of an
    FB (of_type its name, e.g. "Motor" or IEC_TIMER) or a global DB (its VAR declarations)."""

    name: str
    headers: dict[str, str]
    of_type: str | None
    decls: list[VarDecl]
    values: list  # the assignments between BEGIN and END_DATA_BLOCK
    kind: str = "DATA_BLOCK"


@dataclass
class TypeDecl(Node):
    """TYPE "Name" ... STRUCT ... END_STRUCT; END_TYPE: a UDT (docs/scl.md §2)."""

    name: str
    headers: dict[str, str]
    struct: StructTypeRef
    type: object = None  # checks.py: its types.StructType
    kind: str = "TYPE"


@dataclass
class ArrayInit(Node):
    """An initial value [1.0, 2.0, 3(0.0)]: items of (count, value); value None is 3()."""

    items: list[tuple[int, object]]


@dataclass
class StructInit(Node):
    """An initial value (member := value, ...) of a STRUCT or UDT element."""

    members: list[tuple[str, Loc, object]]


@dataclass
class Block(Node):
    kind: str  # FUNCTION_BLOCK, FUNCTION or ORGANIZATION_BLOCK (to the checks an FC : Void)
    name: str
    headers: dict[str, str]
    decls: list[VarDecl]
    body: list[Stmt]
    comment: str = ""
    return_type: str | None = None


# Expressions


@dataclass
class Expr(Node):
    type: object = field(default=None, init=False)  # set by checks.py


@dataclass
class Literal(Expr):
    kind: str  # int, real, bool, time, typed (text as written, with its type prefix)
    text: str
    value: object = None
    type_prefix: str | None = None


@dataclass
class Index(Node):
    """[i, j] after a name: the run-time indices of an ARRAY (docs/scl.md §3.8)."""

    exprs: list[Expr]


@dataclass
class Bit(Node):
    """.%X15 after a name: one bit of a bit string or integer; with width 8, 16 or 32 the
    slice .%B1, .%W1 or .%D1: its byte, word or double word number 1, counted from the least
    significant (docs/scl.md §3.8)."""

    number: int
    width: int = 1


@dataclass
class VarRef(Expr):
    name: str
    members: list  # member names (str), Index and Bit, as written
    local: bool  # written #name
    decl: VarDecl | None = field(default=None, init=False)
    quoted: bool = False  # written "name": a DB of the sources, never a local (docs/scl.md §3.9)
    tag: str | None = field(default=None, init=False)  # the PLC tag it names (docs/scl.md §3.12)
    # the checks' reading of the selectors (None: an FB instance's member): each step
    # ("member", name), ("index", [exprs], ArrayType) or ("bit", shift, type, width): the bits
    # shift .. shift + width - 1 of a variable of the type, a .%X bit (width 1) or a slice
    path: list | None = field(default=None, init=False)


@dataclass
class Binary(Expr):
    op: str
    left: Expr
    right: Expr
    operand_type: object = field(default=None, init=False)  # the type the operation runs in


@dataclass
class Unary(Expr):
    op: str
    operand: Expr


@dataclass
class Argument(Node):
    name: str | None  # None: positional
    value: Expr | None  # IN := value
    target: VarRef | None = None  # OUT => target


@dataclass
class Call(Expr):
    callee: str
    local: bool  # #inst(...): an instance of the FB
    args: list[Argument]
    quoted: bool = False  # "Fc"(...): a block of the sources, never a local name
    method: str | None = None  # "Timer_DB".TON(...): the timer an IEC_TIMER DB runs
    index: Index | None = None  # #axes[#i](...): the element of an ARRAY of instances
    # what the checks found the call to be: a built-in, an FC or an FB instance's call
    builtin: object = field(default=None, init=False)  # builtins.Builtin of a system function
    operand: object = field(default=None, init=False)  # the type a built-in computes in
    resolved: object = field(default=None, init=False)  # the built-in's record of its arguments
    unit: object = field(default=None, init=False)  # a user FC's checks.Checker
    instance: VarRef | None = field(default=None, init=False)  # an FB instance's call: the FB
    fb: object = field(default=None, init=False)  # and its types.FbType
    # an FC's: the input values in declaration order, the output targets (None: not given);
    # an instance's: (name, value) of the inputs given, (name, target) of the outputs
    inputs: list = field(default_factory=list, init=False)
    outputs: list = field(default_factory=list, init=False)
    # the parameters passed by reference (in/outs, an FC's ARRAY[*]): (VarDecl, VarRef)
    references: list = field(default_factory=list, init=False)


# Statements


@dataclass
class Stmt(Node):
    pass


@dataclass
class Assign(Stmt):
    target: VarRef
    value: Expr
    op: str = ":="  # or +=, -=, *=, /=
    # x op= e: the checks' `x op e`, which lower.py makes the value (then op is :=)
    operation: Binary | None = field(default=None, init=False)


@dataclass
class CallStmt(Stmt):
    call: Call


@dataclass
class If(Stmt):
    branches: list[tuple[Expr, list[Stmt]]]
    otherwise: list[Stmt] | None


@dataclass
class Case(Stmt):
    selector: Expr
    branches: list[tuple[list[tuple[int, int]], list[Stmt]]]  # labels as (low, high)
    otherwise: list[Stmt] | None


@dataclass
class For(Stmt):
    variable: VarRef
    start: Expr
    end: Expr
    step: Expr | None
    body: list[Stmt]


@dataclass
class While(Stmt):
    condition: Expr
    body: list[Stmt]


@dataclass
class Repeat(Stmt):
    body: list[Stmt]
    condition: Expr


@dataclass
class Jump(Stmt):
    kind: str  # EXIT, CONTINUE, RETURN


@dataclass
class Goto(Stmt):
    label: str
    backward: bool = False  # the label stands before it: a loop (the cycle watchdog counts it)


@dataclass
class Label(Stmt):
    name: str
    used: bool = False  # some GOTO jumps to it (the C declares no label nothing jumps to)


@dataclass
class Region(Stmt):
    title: str
    body: list[Stmt]


def nodes(tree):
    """Every node of a syntax tree (a node or a list of them), depth first; not the
    declarations that checks.py links to (VarRef.decl) nor the nodes it adds."""
    if isinstance(tree, (list, tuple)):
        for item in tree:
            yield from nodes(item)
    elif isinstance(tree, Node):
        yield tree
        for f in fields(tree):
            if f.init and f.name != "loc":
                yield from nodes(getattr(tree, f.name))
