"""The checks between parsing and C generation (docs/scl.md §3, §5): every name is declared,
every expression has an S7 type, every conversion is one S7 makes implicitly or one the program
writes, every construct is one the subset supports. Each refusal is an SclError at the
construct's file:line:col, before any C is generated; after one the checks go on with the next
declaration or statement, so that every error of the program is reported (§5).

The checks of a block are passes in a fixed order, each a concern of its own and a file:

    check_symbols.py      symbols and declarations: names, sections, the names statements use
    check_types.py        types and constants: each declaration's type, the UDTs, start values
    check_statements.py   statements and flow, typing each expression with
    check_expressions.py  expressions and conversions, the calls (builtins.py: the built-ins)
    check_inout.py        the calls of FCs, the arguments passed by reference (in/outs)

The program's blocks are checked on demand (Program.unit), callees before callers. The checks
annotate the tree (declared fields: VarRef.decl and .path, Expr.type, Binary.operand_type,
VarDecl.type and .start, Assign.operation, the Call's fields); lower.py then rewrites what the
C generation takes simpler, once every check has passed."""

from __future__ import annotations

from . import ast as A
from . import types as T
from .check_expressions import Expressions
from .check_inout import InOuts
from .check_statements import Statements
from .check_symbols import DATE_PARAMETERS, Symbols, c_name, identifier
from .check_types import Types
from .cnames import block_prefix
from .diagnostics import Code, Diagnostics, SclError, refuse


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
        iec_check: bool = False,
        auto_eno: bool = False,
    ):
        # TIA Portal's block property "IEC check": off by default, as in TIA, with its implicit
        # conversions between integers and bit strings; on, only the widening ones (§3.2)
        self.iec_check = iec_check
        # TIA's block property "Set ENO automatically", off by default as in TIA (§3.4)
        self.auto_eno = auto_eno
        self.diagnostics = diagnostics or Diagnostics({})  # every error, reported as found
        self.blocks = blocks  # lower-case name -> A.Block
        self.udts = udts or {}  # lower-case name -> A.TypeDecl
        self.dbs = dbs or {}  # lower-case name -> A.DataBlock
        self.db_statics: dict[str, A.VarDecl] = {}  # the DBs the FMU's FB uses, as its statics
        self.timer_dbs: dict[str, set[str]] | None = None  # DB -> the timers run on it
        # what the blocks write of a DB: (its name, member, member, ...) in lower case, up to
        # the first index; a setpoint written stays a local (docs/scl.md §3.9)
        self.db_writes: set[tuple[str, ...]] = set()
        # every STRUCT and UDT of the program, inner ones first (one typedef each in block.h)
        self.structs: list[T.StructType] = []
        self.resolving: list[str] = []  # the UDTs being resolved: one met again contains itself
        self.top = None  # the A.Block of the FB compiled into the FMU
        self.top_checker = None
        self.core_vars = core_vars
        self.core_fields = core_fields
        self.checked: dict[str, Checker] = {}
        self.prefixes: dict[str, A.Block] = {}  # the blocks' C names (check_symbols.c_name)
        self.active: list[A.Block] = []
        self.order: list[Checker] = []  # callees before their callers
        self.uses_date = False  # RD_SYS_T or RD_LOC_T: the parameter startDateAndTime
        self.uses_local = False  # RD_LOC_T: the parameter localTimeOffset
        self.has_loop = False  # a FOR, WHILE or REPEAT, found by the C generation: the watchdog
        self.schedule = None  # a program's (program.Schedule): the top FB runs its OBs

    def unit(self, name: str, node) -> Checker | None:
        key = name.lower()
        if key in self.checked:
            return self.checked[key]
        block = self.blocks.get(key)
        if block is None:
            return None
        if block in self.active:
            chain = " -> ".join(b.name for b in self.active[self.active.index(block) :])
            refuse(
                Code.RECURSION,
                node,
                f"{block.name} calls itself ({chain} -> {block.name}): S7 has no recursion",
            )
        # the C prefix of its functions, which no other block's may be (docs/scl.md §2)
        c_name(block, block.name, block_prefix(block), self.prefixes)
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


class Checker(Symbols, Types, Statements, Expressions, InOuts):
    """The checks of one block: its passes (the mixins, one file each) over its declarations
    and its statements."""

    def __init__(self, block: A.Block, program: Program):
        self.block = block
        self.program = program
        self.core_vars = program.core_vars
        self.core_fields = program.core_fields
        self.names: dict[str, A.VarDecl] = {}
        self.c_names: dict[str, A.VarDecl] = {}  # C name -> declaration (check_symbols.c_name)
        self.loops = 0
        self.fc = block.kind in ("FUNCTION", "ORGANIZATION_BLOCK")  # an OB: an FC : Void
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

    def run(self):
        self.attempt(identifier, self.block, self.block.name)
        self.symbols()  # check_symbols.py: every declaration's name and section
        self.types()  # check_types.py: every declaration's type and start value
        self.statements(self.block.body)  # check_statements.py, check_expressions.py
        self.jumps(self.block.body)  # check_statements.py: GOTO and its labels


def check(block: A.Block, program: Program, schedule=None) -> Checker:
    """Checks the FB `block` and every FB and FC it uses, of the program's blocks (its sources,
    with their options: TIA's "IEC check" and "Set ENO automatically" of every block, docs/scl.md
    §3.2 and §3.4); the Checker of `block`, with the program as its `program`. Raises an SclError
    of every error found (docs/scl.md §5)."""
    if block.kind != "FUNCTION_BLOCK":
        whole = " (an OB: compile the program with --program, docs/scl.md §3.10)"
        refuse(
            Code.PROGRAM,
            block,
            f"{block.name}: only a FUNCTION_BLOCK becomes an FMU"
            + (whole if block.kind == "ORGANIZATION_BLOCK" else ""),
        )
    program.top = block
    program.schedule = schedule
    checker = program.unit(block.name, block)
    used = DATE_PARAMETERS[: (program.uses_date) + (program.uses_local)]
    for name in used:
        d = checker.names.get(name.lower())
        if d is not None:
            checker.attempt(
                refuse,
                Code.RESERVED,
                d,
                f"'{name}' is the FMU's own parameter of RD_SYS_T/RD_LOC_T (docs/scl.md §3.6)",
            )
    d = checker.names.get("maxcycletime")
    if d is not None:
        checker.attempt(
            refuse,
            Code.RESERVED,
            d,
            "'maxCycleTime' is the FMU's own parameter of the cycle watchdog (docs/scl.md §4)",
        )
    program.diagnostics.check()
    return checker
