"""What TIA Portal writes in an export besides the SCL of docs/scl.md §2 (docs/scl.md §2.1):
the parser's part of it, beside parser.py. S7's literals (B#16#.., C#.., the date and time
literals and character strings, read and refused by their type's name), a minus sign that
belongs to its number, T# beyond TIME's range, positional start values, the block's constants
as CASE labels and ARRAY bounds, the slices .%B0, .%W1, .%D0."""

from __future__ import annotations

import datetime
import re
from dataclasses import dataclass

from lark import v_args

from . import ast as A
from . import unsupported
from .diagnostics import Code
from .literals import characters
from .types import STRING_MAX

# the terminals of scl.lark this file reads, in an error message
WORDS = {
    "CONSTANT_NAME": "#constant",
    "END_REGION_LINE": "END_REGION",
    "DESCRIPTION_MARK": "(/**/)",
    "SLICE_ACCESS": "%B<byte>, %W<word> or %D<dword>",
    "TYPE_LABEL": "a data type",
}

# the slices .%B<n>, .%W<n>, .%D<n>: the width of their part (docs/scl.md §3.8)
# The system data types of S7 that are STRUCTs of elementary types (docs/scl.md §3.8 [S7-TADDR]),
# written as the UDTs they are, and known to every program whose sources do not define them
SYSTEM_TYPES_FILE = "S7 system data types"
SYSTEM_TYPES = """TYPE TADDR_Param
   STRUCT
      REM_IP_ADDR : Array[1..4] of USInt;  // the remote partner's IP address, its 4 octets
      REM_PORT_NR : UInt;  // the remote partner's port number
      RESERVED : Word;  // reserved: 0
   END_STRUCT;
END_TYPE
"""

SLICE_WIDTHS = {"B": 8, "W": 16, "D": 32}

# S7's short prefixes of the bit-string literals
BIT_STRING_PREFIXES = {"B": "BYTE", "W": "WORD", "DW": "DWORD", "LW": "LWORD"}

# the date and time literals by prefix, and their forms: refused by type (docs/scl.md §6)
DATE_KINDS = {
    "D": "DATE",
    "DATE": "DATE",
    "TOD": "TIME_OF_DAY",
    "TIME_OF_DAY": "TIME_OF_DAY",
    "LTOD": "LTOD",
    "LTIME_OF_DAY": "LTOD",
    "DT": "DATE_AND_TIME",
    "DATE_AND_TIME": "DATE_AND_TIME",
    "LDT": "LDT",
    "DATE_AND_LTIME": "LDT",
    "DTL": "DTL",
    "S5T": "S5TIME",
    "S5TIME": "S5TIME",
}
_DAY = r"(?P<y>[0-9]{4})-(?P<mo>[0-9]{1,2})-(?P<d>[0-9]{1,2})"
_CLOCK = r"(?P<h>[0-9]{1,2}):(?P<mi>[0-9]{1,2}):(?P<s>[0-9]{1,2})"
DATE_FORMS = {
    "DATE": (_DAY, "D#2024-01-31"),
    "TIME_OF_DAY": (_CLOCK + r"(\.[0-9]{1,3})?", "TOD#10:20:30.400"),
    "LTOD": (_CLOCK + r"(\.[0-9]{1,9})?", "LTOD#10:20:30.400365215"),
    "DATE_AND_TIME": (_DAY + "-" + _CLOCK + r"(\.[0-9]{1,3})?", "DT#2024-01-31-10:20:30.400"),
    "LDT": (_DAY + "-" + _CLOCK + r"(\.[0-9]{1,9})?", "LDT#2024-01-31-10:20:30.400365215"),
    "DTL": (_DAY + "-" + _CLOCK + r"(\.[0-9]{1,9})?", "DTL#2024-01-31-10:20:30.250"),
    "S5TIME": (r"(?i:(?:[0-9]+(?:h|ms|m|s))+)", "S5T#1h2m3s"),
}
# the types of these literals unsupported.TYPES does not name
_NOT_YET = {
    "S5TIME": "S5TIME is not supported yet (docs/scl.md §6)",
}

_DATE_RANGE = "D#1990-01-01 to D#2169-06-06"

# the TIME (ms, 32 bits) and LTIME (ns, 64 bits) ranges, as S7 writes their ends
TIME_RANGES = {
    "TIME": (-(2**31), 2**31 - 1, "T#-24d20h31m23s648ms to T#24d20h31m23s647ms"),
    "LTIME": (
        -(2**63),
        2**63 - 1,
        "LT#-106751d23h47m16s854ms775us808ns to LT#106751d23h47m16s854ms775us807ns",
    ),
}

# what may stand between a minus sign and the number it belongs to: blanks and comments
_BLANK = re.compile(r"\s+|//[^\n]*|\(\*.*?\*\)|/\*.*?\*/", re.S)


def _name(text: str) -> str:
    """#"x" or "x" -> x (as parser.py's)."""
    text = text[1:] if text.startswith("#") else text
    return text[1:-1] if text.startswith('"') else text


def _calendar(match: re.Match) -> bool:
    """A date and time literal's day and time of day exist (2023-02-29 does not)."""
    parts = match.groupdict()
    try:
        if parts.get("y") is not None:
            datetime.date(int(parts["y"]), int(parts["mo"]), int(parts["d"]))
        if parts.get("h") is not None:
            datetime.time(int(parts["h"]), int(parts["mi"]), int(parts["s"]))
    except ValueError:
        return False
    return True


def _date_value(match: re.Match, body: str) -> tuple:
    """(year, month, day, hour, minute, second, nanosecond) of a date and time literal; the
    digits after the point are a fraction of a second (.25 = 250000000 ns)."""
    parts = match.groupdict()
    fraction = body.replace("_", "").partition(".")[2] if parts.get("h") is not None else ""
    numbers = [int(parts.get(k) or 0) for k in ("y", "mo", "d", "h", "mi", "s")]
    return (*numbers, int((fraction + "000000000")[:9]))


@dataclass(frozen=True)
class _Constant:
    """#NAME where S7 takes a constant (a CASE label, an ARRAY bound), until the block's
    declarations give its value."""

    name: str
    loc: A.Loc


def constants_in_place(decls: list, body: list, errors: list):
    """The block's constants (VAR CONSTANT of an integer value, or none: 0) in the CASE labels
    and ARRAY bounds of its declarations and statements, as S7 takes them; another name there
    is an error, appended to errors."""
    declared = {d.name.lower() for d in decls if isinstance(d, A.VarDecl)}
    values = {}
    for d in decls:
        if isinstance(d, A.VarDecl) and d.section == A.Section.CONSTANT:
            if d.init is None:
                values[d.name.lower()] = 0
            elif isinstance(d.init, A.Literal) and d.init.kind == "int":
                values[d.name.lower()] = d.init.value

    def value(x, what):
        if not isinstance(x, _Constant):
            return x
        if x.name.lower() not in values:
            code = Code.OPERAND if x.name.lower() in declared else Code.UNDECLARED
            message = (
                f"#{x.name}: {what} is a literal or a constant of the block with an integer "
                "value (VAR CONSTANT)"
            )
            errors.extend(A.SclError(x.loc, message, code).diagnostics)
            return 0
        return values[x.name.lower()]

    for node in A.nodes([decls, body]):
        if isinstance(node, A.ArrayTypeRef):
            node.dims = [
                None if dim is None else tuple(value(x, "an ARRAY bound") for x in dim)
                for dim in node.dims
            ]
        elif isinstance(node, A.Case):
            node.branches = [
                ([tuple(value(x, "a CASE label") for x in label) for label in labels], body)
                for labels, body in node.branches
            ]


def time_ranges(tree, errors: list):
    """A T# or LT# literal beyond its type's range is refused (T#25d would wrap), once the
    sign is the literal's: T#-24d20h31m23s648ms and -T#24d20h31m23s648ms fit."""
    for literal in A.nodes(tree):
        if isinstance(literal, A.Literal) and literal.kind == "time":
            low, high, text = TIME_RANGES[literal.type_prefix]
            if not low <= literal.value <= high:
                message = f"{literal.text} is beyond the {literal.type_prefix} range ({text})"
                errors.extend(A.SclError(literal.loc, message, Code.RANGE).diagnostics)


class TiaSyntax:
    """The transformer methods of these constructs, for parser.py's _Builder (which has
    _loc, _literal, _error, text and starts)."""

    def signed(self, op, operand):
        """A minus sign before a number (blanks and comments between, no parenthesis) is the
        number's: -32768 is an INT, -2147483648 a DINT; -(32768) is the negation of 32768.
        The literal, or None where op is no sign of a literal."""
        if not (
            op.type == "MINUS"
            and isinstance(operand, A.Literal)
            and operand.kind in ("int", "real", "time")
            and not _BLANK.sub("", self.text[op.end_pos : self.starts[id(operand)]])
        ):
            return None
        kind, text, value, prefix = operand.kind, operand.text, operand.value, operand.type_prefix
        return A.Literal(self._loc(op), kind, "-" + text, -value, prefix)

    def count_literal(self, token):
        """C#500: S7's BCD count value, the WORD 16#0500 (C#0 to C#999)."""
        digits = str(token).split("#", 1)[1].replace("_", "")
        if not re.fullmatch(r"[0-9]{1,3}", digits):
            self._error(token, f"{token}: a count value is C#0 to C#999 (BCD)", Code.RANGE)
            digits = "0"
        return self._literal("int", token, int(digits, 16), "WORD")

    @staticmethod
    def bit_string_prefix(prefix):
        """B#16#FF, W#16#.., DW#16#.., LW#16#..: BYTE, WORD, DWORD, LWORD."""
        return BIT_STRING_PREFIXES.get(prefix, prefix)

    def date_literal(self, children):
        """D#, TOD#, LTOD#, DT#, LDT#, DTL#, S5T#: read, checked for their form, and refused
        by the name of their type, which the compiler does not support yet (§6)."""
        token = children[0]
        text = str(token)
        prefix, body = text.split("#", 1)
        kind = DATE_KINDS[prefix.upper()]
        form, example = DATE_FORMS[kind]
        match = re.fullmatch(form, body.replace("_", ""))
        if match is None or not _calendar(match):
            self._error(token, f"{text}: not a {kind} literal ({example})")
        elif kind in ("DTL", "DATE", "TIME_OF_DAY"):
            value = _date_value(match, body)
            if kind == "DATE":  # days since 1990-01-01, 16 bits: D#1990-01-01 .. D#2169-06-06
                value = (datetime.date(*value[:3]) - datetime.date(1990, 1, 1)).days
                if not 0 <= value <= 65535:
                    self._error(
                        token, f"{text} is beyond the DATE range ({_DATE_RANGE})", Code.RANGE
                    )
                    value = 0
            elif kind == "TIME_OF_DAY":  # ms since midnight
                value = ((value[3] * 60 + value[4]) * 60 + value[5]) * 1000 + value[6] // 10**6
            return self._literal("date", token, value, kind)
        else:
            message = unsupported.type_message(kind) or _NOT_YET[kind]
            self._error(token, f"{text}: {message}", Code.UNSUPPORTED)
        return self._literal("int", token, 0)  # in place of the literal refused

    def string_literal(self, children):
        """'text', STRING#'..', WSTRING#'..', CHAR#'a', WCHAR#'a' (docs/scl.md §3.1
        [S7-STRING-LIT]): the character codes, its $-escapes read (literals.characters)."""
        token = children[0]
        text = str(token)
        head, body = text.split("'", 1)
        prefix = head[:-1].upper() if head else None
        try:
            codes = characters(body[:-1], wide=prefix in ("WSTRING", "WCHAR"))
        except ValueError as e:
            self._error(token, f"{text}: {e}")
            codes = ()
        if len(codes) > STRING_MAX:
            self._error(token, f"{text}: a character string holds {STRING_MAX} characters at most")
        return self._literal("string", token, codes, prefix)

    @v_args(meta=True)
    def slice(self, meta, children):
        """.%B0, .%W1, .%D0: a byte, word or double word of a bit string or integer
        (docs/scl.md §3.8), at its dot as a bit .%X3."""
        token = str(children[0])
        return A.Bit(self._loc(meta), int(token[2:]), SLICE_WIDTHS[token[1].upper()])

    def type_label(self, children):
        """CASE TypeOf(#v) OF Int: ... (a data type as a label, of a VARIANT): read and refused
        by name (§6)."""
        token = children[0]
        message = (
            f"the data type {token} as a CASE label (CASE TypeOf(...) OF, of a VARIANT) is not "
            "supported (docs/scl.md §6): the subset has no VARIANT"
        )
        self._error(token, message, Code.UNSUPPORTED)
        return (0, 0)  # in place of the label refused

    def named_constant(self, children):
        token = children[0]
        return _Constant(_name(str(token)), self._loc(token))

    @v_args(meta=True)
    def struct_default(self, meta, _):
        return A.StructInit(self._loc(meta), [])

    @v_args(meta=True)
    def struct_positional(self, meta, children):
        """(#C, (), ()) as TIA writes a STRUCT's or UDT's start value: the members in their
        order, without names; () leaves one at its default (value None)."""
        return A.StructInit(self._loc(meta), list(children))

    @v_args(meta=True)
    def position_init(self, meta, children):
        value = children[0]
        if isinstance(value, A.StructInit) and not value.members:
            value = None  # (): the member's default, of an elementary member too
        return (None, self._loc(meta), value)
