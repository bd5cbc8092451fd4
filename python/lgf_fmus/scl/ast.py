"""The syntax tree of an SCL source (docs/scl.md §3): every node carries the place it was read
from (file:line:col), so that a check names the construct where the user wrote it. The parser
(parser.py) builds it, checks.py annotates the expressions with their S7 types, cgen.py reads
it."""

from __future__ import annotations

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


# Declarations


@dataclass
class VarDecl(Node):
    name: str
    type_name: str
    type_loc: Loc
    init: Expr | None
    section: str  # VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT, VAR, VAR_TEMP, VAR CONSTANT
    comment: str = ""
    type: object = None  # checks.py: a types.Elementary, FbType, ArrayType or StructType
    type_ref: object = None  # ArrayTypeRef or StructTypeRef; None: the named type type_name
    db: bool = False  # a DB of the program, held as a static of the FMU's FB (docs/scl.md §3.9)
    calling_ob: bool = False  # an OB_CYCLIC input the FMU's cycleTime plays (docs/scl.md §4)


@dataclass
class ArrayTypeRef(Node):
    """ARRAY[lo..hi, ...] OF element; a dimension None is [*] (docs/scl.md §3.1)."""

    dims: list[tuple[int, int] | None]
    element: object  # (name, loc), ArrayTypeRef or StructTypeRef


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
    kind: str  # FUNCTION_BLOCK or FUNCTION
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
    """.%X15 after a name: one bit of a bit string or integer (docs/scl.md §3.8)."""

    number: int


@dataclass
class VarRef(Expr):
    name: str
    members: list  # member names (str), Index and Bit, as written
    local: bool  # written #name
    decl: VarDecl | None = field(default=None, init=False)
    quoted: bool = False  # written "name": a DB of the sources, never a local (docs/scl.md §3.9)
    # the checks' reading of the selectors (None: an FB instance's or a DTL's member): each step
    # ("member", name), ("index", [exprs], ArrayType) or ("bit", number, type)
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


# Statements


@dataclass
class Stmt(Node):
    pass


@dataclass
class Assign(Stmt):
    target: VarRef
    value: Expr
    op: str = ":="  # or +=, -=, *=, /=


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
