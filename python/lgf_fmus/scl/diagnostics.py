"""What the compiler says about a source it refuses (docs/scl.md §5): every error of the
program, up to LIMIT, each `file:line:col: error E0nn: message` with its source line and a
caret under the place, and notes at the related places ("first declared here"). The codes are
the table of docs/scl.md §5 (tests/scl/test_diagnostics.py keeps the two equal)."""

from __future__ import annotations

import enum
import re
from dataclasses import dataclass, field

# the errors reported at most: after them the compiler stops
LIMIT = 50


class Code(enum.Enum):
    """An error's code and what it says in general (docs/scl.md §5)."""

    SYNTAX = ("E001", "the text is no SCL: a token or character that cannot stand there")
    UNSUPPORTED = ("E002", "a construct of S7 outside the subset the compiler takes (§6)")
    UNDECLARED = ("E003", "a name no declaration, type, block, DB or function has")
    DUPLICATE = ("E004", "a name, member, parameter or CASE label given twice")
    RESERVED = ("E005", "a name that S7 or the FMU already gives to something else")
    CONVERSION = ("E006", "a conversion S7 does not make implicitly, or at all (§3.2)")
    RANGE = ("E007", "a literal, bound, index or bit beyond its type's range")
    OPERAND = ("E008", "an operand or argument of a type the operation does not take")
    SELECTOR = ("E009", "a member, index or bit access the variable does not have")
    PARAMETER = ("E010", "a call's parameters: missing, unknown, or of the wrong kind")
    INSTANCE = ("E011", "an FB instance or an FC used as the other, or as a value")
    READ_ONLY = ("E012", "a write to an input, a constant or an instance's output")
    STATEMENT = ("E013", "a statement where it cannot stand, or used as a value")
    DECLARATION = ("E014", "a declaration in a section or of a type where it cannot stand")
    INITIAL = ("E015", "an initial value that does not fit its declaration")
    RECURSION = ("E016", "a block that calls itself, or a UDT that contains itself")
    DB = ("E017", "a DB used against its kind (§3.9)")
    NAME = ("E018", "a name the FMU cannot carry (characters, length)")
    PROGRAM = ("E019", "the program as a whole: the block to compile, the sources")
    LITERAL = ("E020", "a literal of a form its type does not take")

    @property
    def number(self) -> str:
        return self.value[0]

    @property
    def summary(self) -> str:
        return self.value[1]


@dataclass(frozen=True)
class Note:
    loc: object  # ast.Loc
    message: str


@dataclass
class Diagnostic:
    loc: object  # ast.Loc, or None for the program as a whole
    message: str
    code: Code | None = None
    notes: list[Note] = field(default_factory=list)

    def head(self) -> str:
        """file:line:col: error E0nn: message."""
        code = f" {self.code.number}" if self.code is not None else ""
        where = f"{self.loc}: " if self.loc is not None else ""
        return f"{where}error{code}: {self.message}"


class SclError(Exception):
    """A source the compiler refuses (docs/scl.md §5): one or more Diagnostics. `loc`,
    `message` and `code` are the first one's; str() is all of them, each with its source
    line and a caret where the sources are known."""

    def __init__(self, loc, message: str, code: Code | None = None, notes=()):
        notes = [n if isinstance(n, Note) else Note(*n) for n in notes]
        self.diagnostics = [Diagnostic(loc, message, code, notes)]
        self.sources: dict[str, str] = {}
        super().__init__(message)

    @classmethod
    def of(cls, diagnostics: list[Diagnostic], sources: dict[str, str]) -> SclError:
        error = cls.__new__(cls)
        Exception.__init__(error, diagnostics[0].message)
        error.diagnostics = list(diagnostics)
        error.sources = dict(sources)
        return error

    @property
    def loc(self):
        return self.diagnostics[0].loc

    @property
    def message(self) -> str:
        return self.diagnostics[0].message

    @property
    def code(self) -> Code | None:
        return self.diagnostics[0].code

    def __str__(self) -> str:
        return render(self.diagnostics, self.sources)


def refuse(code: Code, node, message: str, notes=()):
    """Refuses the construct at node (an ast node, or None for the program): an error of the
    code, notes as (loc, text) of related places."""
    raise SclError(node.loc if node is not None else None, message, code, notes)


class Silent(SclError):
    """An error whose cause is reported already (a declaration refused before, used here):
    it ends the statement without a second report."""

    def __init__(self):
        super().__init__(None, "an error reported before")


class Diagnostics:
    """The errors of one compile, collected as the checks go on; at LIMIT it stops."""

    def __init__(self, sources: dict[str, str]):
        self.sources = sources
        self.found: list[Diagnostic] = []

    def report(self, error: SclError):
        if isinstance(error, Silent):
            return
        self.found += error.diagnostics
        if len(self.found) >= LIMIT:
            stop = Diagnostic(None, f"stopped after {LIMIT} errors")
            raise SclError.of(self.found[:LIMIT] + [stop], self.sources)

    def check(self):
        """Raises every error found so far, if any."""
        if self.found:
            raise SclError.of(self.found, self.sources)


_UNPRINTABLE = re.compile("[\u0000-\u0008\u000a-\u001f\u007f-\u009f\u2028\u2029]")


def _excerpt(loc, sources: dict[str, str]) -> list[str]:
    """The source line of loc and a caret under its column; none where the source is unknown."""
    text = sources.get(getattr(loc, "file", None))
    if text is None or loc.line < 1:
        return []
    lines = text.splitlines()
    if loc.line > len(lines):
        return []
    line = _UNPRINTABLE.sub("?", lines[loc.line - 1])
    if len(line) > 200:  # a very long line: the part around the place
        start = max(0, loc.column - 100)
        line, column = line[start : start + 200], loc.column - start
    else:
        column = loc.column
    number = f"{loc.line:>4}"
    pad = "".join("\t" if c == "\t" else " " for c in line[: max(column - 1, 0)])
    return [f"{number} | {line}", f"{' ' * len(number)} | {pad}^"]


def render(diagnostics: list[Diagnostic], sources: dict[str, str]) -> str:
    out = []
    for d in diagnostics:
        out.append(d.head() if d.loc is not None or d.code is not None else d.message)
        out += _excerpt(d.loc, sources) if d.loc is not None else []
        for note in d.notes:
            out.append(f"{note.loc}: note: {note.message}")
            out += _excerpt(note.loc, sources)
    errors = sum(d.loc is not None for d in diagnostics)
    if errors > 1:
        out.append(f"{errors} errors")
    return "\n".join(out)
