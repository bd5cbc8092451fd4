"""The S7 data types of the supported subset (docs/scl.md §3.1) and their rules: how each is held
in C, which FMI variable and FMU-state field it becomes, and S7's implicit conversions
(docs/scl.md §3.2)."""

from __future__ import annotations

import dataclasses
import enum
from dataclasses import dataclass


class Kind(str, enum.Enum):
    """What a type is, for the rules that ask for a number, a BOOL or a bit string."""

    BOOL = "bool"
    INT = "int"
    BITS = "bits"
    REAL = "real"
    TIME = "time"
    CHAR = "char"
    STRING = "string"
    DATE = "date"  # DATE and TIME_OF_DAY: a point in time, no number (docs/scl.md §3.1)
    ARRAY = "array"
    STRUCT = "struct"
    ERROR = "error"

    def __str__(self) -> str:
        return self.value

    __format__ = str.__format__


K = Kind


@dataclass(frozen=True)
class Elementary:
    name: str
    kind: Kind
    bits: int
    signed: bool
    c: str  # the C type of the block's struct
    var: str | None  # the core's var_type (src/core/model.h), None: no FMI variable kind
    field: str  # the core's field_type, for the FMU state

    @property
    def low(self) -> int:
        return -(1 << (self.bits - 1)) if self.signed else 0

    @property
    def high(self) -> int:
        return (1 << (self.bits - 1)) - 1 if self.signed else (1 << self.bits) - 1

    def __str__(self) -> str:
        return self.name


def _e(name, kind, bits, signed, c, var, field):
    return Elementary(name, Kind(kind), bits, signed, c, var, field)


ELEMENTARY = {
    t.name: t
    for t in (
        _e("BOOL", "bool", 1, False, "bool", "VAR_BOOL", "FIELD_BOOL"),
        _e("SINT", "int", 8, True, "int8_t", "VAR_SINT", "FIELD_INT8"),
        _e("INT", "int", 16, True, "int16_t", "VAR_INT", "FIELD_INT16"),
        _e("DINT", "int", 32, True, "int32_t", "VAR_DINT", "FIELD_INT32"),
        _e("USINT", "int", 8, False, "uint8_t", "VAR_USINT", "FIELD_UINT8"),
        _e("UINT", "int", 16, False, "uint16_t", "VAR_UINT", "FIELD_UINT16"),
        _e("UDINT", "int", 32, False, "uint32_t", "VAR_UDINT", "FIELD_UINT32"),
        _e("BYTE", "bits", 8, False, "uint8_t", "VAR_BYTE", "FIELD_UINT8"),
        _e("WORD", "bits", 16, False, "uint16_t", "VAR_WORD", "FIELD_UINT16"),
        _e("DWORD", "bits", 32, False, "uint32_t", "VAR_DWORD", "FIELD_UINT32"),
        _e("REAL", "real", 32, True, "float", "VAR_REAL", "FIELD_FLOAT32"),
        # an LREAL static may hold the NaN that ±Inf inputs make (docs/behaviour.md §1.4)
        _e("LREAL", "real", 64, True, "double", "VAR_LREAL", "FIELD_RESULT"),
        _e("TIME", "time", 32, True, "iec_time", "VAR_TIME", "FIELD_INT32"),
        # DATE: days since 1990-01-01; TIME_OF_DAY: ms since midnight (docs/scl.md §3.1)
        _e("DATE", "date", 16, False, "uint16_t", "VAR_UINT", "FIELD_UINT16"),
        _e("TIME_OF_DAY", "date", 32, False, "uint32_t", "VAR_UDINT", "FIELD_UINT32"),
        # 64 bits (docs/scl.md §3.1): the core and FMI 2.0 have no 64-bit integer variable, so
        # these are statics and temporaries only; in the FMU state as 8 bytes
        _e("LINT", "int", 64, True, "int64_t", None, "FIELD_INT64"),
        _e("ULINT", "int", 64, False, "uint64_t", None, "FIELD_INT64"),
        _e("LWORD", "bits", 64, False, "uint64_t", None, "FIELD_INT64"),
        _e("LTIME", "time", 64, True, "int64_t", None, "FIELD_INT64"),  # ns
        # a character by its code (docs/scl.md §3.1 [DEC-CHAR-FMI]): an FMI Integer of it
        _e("CHAR", "char", 8, False, "uint8_t", "VAR_USINT", "FIELD_UINT8"),
        _e("WCHAR", "char", 16, False, "uint16_t", "VAR_UINT", "FIELD_UINT16"),
    )
}
BOOL, INT, DINT, UDINT = (ELEMENTARY[n] for n in ("BOOL", "INT", "DINT", "UDINT"))
REAL, LREAL, TIME = ELEMENTARY["REAL"], ELEMENTARY["LREAL"], ELEMENTARY["TIME"]
LINT, LTIME = ELEMENTARY["LINT"], ELEMENTARY["LTIME"]
CHAR, WCHAR = ELEMENTARY["CHAR"], ELEMENTARY["WCHAR"]
# the type of a slice .%B<n>, .%W<n>, .%D<n> by its width (docs/scl.md §3.8)
SLICE_TYPES = {8: ELEMENTARY["BYTE"], 16: ELEMENTARY["WORD"], 32: ELEMENTARY["DWORD"]}


# The rows of an ARRAY[*] in the FMU (docs/scl.md §4): its table holds this many elements, the
# structural parameter numberOf<Name> says how many of them the block sees (as LGF_RampCI)
TABLE_CAPACITY = 64


def table_count(name: str) -> str:
    """The FMU's name of the size of the ARRAY[*] name: setpoints -> numberOfSetpoints."""
    return "numberOf" + name[0].upper() + name[1:]


@dataclass(frozen=True)
class ArrayType:
    """ARRAY[lo..hi, ...] OF element (docs/scl.md §3.8); dims None: ARRAY[*] (of `rank`
    dimensions), whose bounds are the argument's (docs/scl.md §3.7), or in the FMU's FB
    0 .. count-1 at run time, count the FMU's structural parameter."""

    element: object
    dims: tuple[tuple[int, int], ...] | None
    rank: int = 1  # the dimensions of an ARRAY[*]: ARRAY[*, *] has 2

    # no elementary kind: every rule that asks for a number, a BOOL or a bit string refuses it
    kind = K.ARRAY

    @property
    def dimensions(self) -> int:
        return self.rank if self.dims is None else len(self.dims)

    @property
    def sizes(self) -> tuple[int, ...]:
        return tuple(hi - lo + 1 for lo, hi in self.dims)

    def __str__(self) -> str:
        if self.dims is None:
            dims = ", ".join("*" * self.rank)
        else:
            dims = ", ".join(f"{lo}..{hi}" for lo, hi in self.dims)
        return f"ARRAY[{dims}] OF {self.element}"


@dataclass(eq=False)
class StructType:
    """A UDT (name) or an anonymous STRUCT (name None): its members in order, each with its
    type and its initial value (docs/scl.md §3.8). Equal only to itself, as in S7: two
    STRUCTs of the same members are different types."""

    name: str | None
    c: str  # the C typedef the generated block.h declares
    members: dict  # name -> (type, initial value or None)
    comments: dict = dataclasses.field(
        default_factory=dict
    )  # name -> the member's // comment (its FMI
    # variables' description, docs/scl.md §4)
    # the members marked Setpoint: tunable parameters in a global DB (docs/scl.md §3.9)
    setpoints: frozenset = frozenset()
    kind = K.STRUCT  # as ArrayType's

    def member(self, name: str):
        for key in self.members:
            if key.lower() == name.lower():
                return key
        return None

    def __str__(self) -> str:
        return f'"{self.name}"' if self.name else "STRUCT"


# S7's longest STRING (and the longest WSTRING of the subset): 254 characters
STRING_MAX = 254


@dataclass(frozen=True)
class StringType:
    """STRING[n] (wide: WSTRING[n]), n 1 ... 254 characters, 254 by default (docs/scl.md §3.1
    [S7-STRING]): in C an scl_string (runtime/scl/scl_string.h) as S7 lays it out, its maximum
    length, its current length and the characters, one uint16_t each for both widths."""

    wide: bool
    length: int = STRING_MAX

    kind = K.STRING
    c = "scl_string"
    field = "FIELD_UINT16"  # in the FMU state: max, len and every character as a UINT16

    @property
    def var(self) -> str:
        """The core's FMI String variable of it (src/core/model.h)."""
        return "VAR_WSTRING" if self.wide else "VAR_STRING"

    @property
    def name(self) -> str:
        return "WSTRING" if self.wide else "STRING"

    @property
    def char(self) -> Elementary:
        """The type of one character: CHAR of a STRING, WCHAR of a WSTRING."""
        return WCHAR if self.wide else CHAR

    def __str__(self) -> str:
        return self.name if self.length == STRING_MAX else f"{self.name}[{self.length}]"


STRING, WSTRING = StringType(False), StringType(True)


@dataclass(frozen=True)
class TextLiteral:
    """A character string literal '...' without a type prefix: a STRING, or a CHAR where it
    holds one character, as its context needs (docs/scl.md §3.1 [S7-STRING-LIT])."""

    length: int
    kind = K.STRING

    def __str__(self) -> str:
        return "a character string literal"


@dataclass(frozen=True)
class Untyped:
    """An integer or real literal without a type prefix: it takes the type its context needs
    (docs/scl.md §3.2)."""

    kind: Kind  # INT or REAL

    def __str__(self) -> str:
        return "an integer literal" if self.kind == K.INT else "a real literal"


ANY_INT, ANY_REAL = Untyped(K.INT), Untyped(K.REAL)


def concrete(t):
    """The type a value is computed in: an untyped integer in DINT, an untyped real in LREAL
    (docs/scl.md §3.2)."""
    if isinstance(t, Untyped):
        return DINT if t.kind == K.INT else LREAL
    return t


class _Error:
    """The type of a declaration the checks refused (reported once, docs/scl.md §5): a use of
    it ends its statement without a second error."""

    kind = K.ERROR
    name = "an error"

    def __str__(self) -> str:
        return self.name


ERROR = _Error()


@dataclass(frozen=True)
class FbType:
    """An FB instance type (docs/scl.md §3.6): a system FB of the subset or a user
    FUNCTION_BLOCK (block set), and its instance's members."""

    name: str
    c: str  # the C type of the instance
    inputs: dict  # name -> Elementary
    outputs: dict
    call: str = ""  # the C function that runs the instance
    timed: bool = False  # the call takes the plc_call (the time of the call)
    memory: tuple = ()  # the instance's hidden fields in the FMU state: (C member, field type)
    valid: str | None = None  # the C check of a restored instance
    block: object = None  # a user FB: its checks.Checker
    # outputs read through a C function of (instance, call) instead of the member: the S7
    # timers' Q and ET, updated whenever the program reads them (docs/behaviour.md §1.12)
    reads: tuple = ()  # (output name, C function)


_TIMER = dict(
    inputs={"IN": BOOL, "PT": TIME},
    outputs={"Q": BOOL, "ET": TIME},
    timed=True,
    memory=(
        ("timer.in", "FIELD_BOOL"),
        ("timer.running", "FIELD_BOOL"),
        ("timer.pt", "FIELD_INT32"),
        ("timer.start_us", "FIELD_INT64"),
    ),
    valid="scl_timer_is_valid",
)


def _reads(kind: str) -> tuple:
    return (("Q", f"scl_{kind}_q"), ("ET", "scl_timer_et"))


_TRIG = dict(
    inputs={"CLK": BOOL},
    outputs={"Q": BOOL},
    memory=(("memory", "FIELD_BOOL"),),
    valid="scl_trig_is_valid",
)
FB_TYPES = {
    "TON": FbType("TON", "scl_timer", call="scl_ton", reads=_reads("ton"), **_TIMER),
    "TOF": FbType("TOF", "scl_timer", call="scl_tof", reads=_reads("tof"), **_TIMER),
    "TP": FbType("TP", "scl_timer", call="scl_tp", reads=_reads("tp"), **_TIMER),
    "R_TRIG": FbType("R_TRIG", "scl_trig", call="scl_r_trig", **_TRIG),
    "F_TRIG": FbType("F_TRIG", "scl_trig", call="scl_f_trig", **_TRIG),
}
# TIA Portal's instruction names for the IEC timers of an S7-1200/1500
FB_ALIASES = {"TON_TIME": "TON", "TOF_TIME": "TOF", "TP_TIME": "TP"}


def _counters():
    """CTU, CTD, CTUD of the S7 (docs/scl.md §3.6), as CTU_<type> for every integer type of
    the subset; CTU, CTD, CTUD alone are the INT counters."""
    for t in ("SINT", "INT", "DINT", "USINT", "UINT", "UDINT"):
        cv = ELEMENTARY[t]
        c = f"scl_counter_{t.lower()}"
        valid = c + "_is_valid"
        up = (("cu_memory", "FIELD_BOOL"),)
        down = (("cd_memory", "FIELD_BOOL"),)
        kinds = {
            "CTU": ({"CU": BOOL, "R": BOOL, "PV": cv}, {"Q": BOOL, "CV": cv}, up),
            "CTD": ({"CD": BOOL, "LD": BOOL, "PV": cv}, {"Q": BOOL, "CV": cv}, down),
            "CTUD": (
                {"CU": BOOL, "CD": BOOL, "R": BOOL, "LD": BOOL, "PV": cv},
                {"QU": BOOL, "QD": BOOL, "CV": cv},
                up + down,
            ),
        }
        for kind, (inputs, outputs, memory) in kinds.items():
            name = f"{kind}_{t}"
            FB_TYPES[name] = FbType(
                name, c, inputs, outputs, f"scl_{kind.lower()}_{t.lower()}", False, memory, valid
            )
            if t == "INT":
                FB_ALIASES[kind] = name


_counters()

# DTL, the date and time of RD_SYS_T and RD_LOC_T (docs/scl.md §3.1, §3.6): S7's system STRUCT of
# 12 bytes, held as scl_dtl (runtime/scl/scl.h); a STRUCT in everything but its name, its C type,
# its literal DTL#... and what S7 computes with it (T_ADD, T_SUB, T_DIFF, the comparisons)
DTL_MEMBERS = {
    "YEAR": ELEMENTARY["UINT"],
    "MONTH": ELEMENTARY["USINT"],
    "DAY": ELEMENTARY["USINT"],
    "WEEKDAY": ELEMENTARY["USINT"],
    "HOUR": ELEMENTARY["USINT"],
    "MINUTE": ELEMENTARY["USINT"],
    "SECOND": ELEMENTARY["USINT"],
    "NANOSECOND": ELEMENTARY["UDINT"],
}


class DtlType(StructType):
    """DTL: its members as a STRUCT's, its initial value DTL#1970-01-01-00:00:00 (a Thursday,
    WEEKDAY 5)."""

    def __str__(self) -> str:
        return "DTL"


def _dtl_defaults(values: dict) -> dict:
    from . import ast as A  # the literals of the members' initial values

    members = {}
    for name, t in DTL_MEMBERS.items():
        literal = A.Literal(A.Loc("DTL", 0, 0), "int", str(values[name]), values[name])
        literal.type = t
        members[name] = (t, literal)
    return members


DTL_EPOCH = dict(YEAR=1970, MONTH=1, DAY=1, WEEKDAY=5, HOUR=0, MINUTE=0, SECOND=0, NANOSECOND=0)
DTL = DtlType("DTL", "scl_dtl", _dtl_defaults(DTL_EPOCH))


def dtl_start(value: tuple) -> dict:
    """The members of the DTL (year, month, day, hour, minute, second, nanosecond) as an
    initial value: WEEKDAY its day of the week (1 = Sunday), as S7 fills it in."""
    import datetime

    y, mo, d, h, mi, s, ns = value
    weekday = datetime.date(y, mo, d).isoweekday() % 7 + 1  # Sunday 7 % 7 + 1 = 1
    given = dict(YEAR=y, MONTH=mo, DAY=d, WEEKDAY=weekday, HOUR=h, MINUTE=mi, SECOND=s)
    given["NANOSECOND"] = ns
    return {name: literal for name, (_, literal) in _dtl_defaults(given).items()}


# S7's hardware data types of OB numbers (docs/scl.md §4): an INT that names an OB; an LGF CI
# block's input callOB is an OB_CYCLIC, which it passes to QRY_CINT
OB_NUMBERS = ("OB_ANY", "OB_CYCLIC")


def lookup(name: str):
    upper = name.upper()
    upper = FB_ALIASES.get(upper, upper)
    if upper == "DTL":
        return DTL
    if upper == "TOD":
        upper = "TIME_OF_DAY"
    if upper in OB_NUMBERS:
        return ELEMENTARY["INT"]
    if upper in ("STRING", "WSTRING"):
        return WSTRING if upper == "WSTRING" else STRING
    return ELEMENTARY.get(upper) or FB_TYPES.get(upper)


# S7's implicit conversions with the IEC check (docs/scl.md §3.2): only towards a type that
# holds every value of the source; anything else needs an explicit *_TO_* conversion.
_WIDENS = {
    "SINT": {"INT", "DINT", "LINT", "REAL", "LREAL"},
    "INT": {"DINT", "LINT", "REAL", "LREAL"},
    "DINT": {"LINT", "LREAL"},
    "USINT": {"UINT", "UDINT", "ULINT", "INT", "DINT", "LINT", "REAL", "LREAL"},
    "UINT": {"UDINT", "ULINT", "DINT", "LINT", "REAL", "LREAL"},
    "UDINT": {"ULINT", "LINT", "LREAL"},
    "BYTE": {"WORD", "DWORD", "LWORD"},
    "WORD": {"DWORD", "LWORD"},
    "DWORD": {"LWORD"},
    "REAL": {"LREAL"},
}


REAL_MAX = {"REAL": 3.4028234663852886e38, "LREAL": 1.7976931348623157e308}


def same_shape(a, b) -> bool:
    """Whether a STRUCT, UDT or ARRAY of type a is assigned to one of type b (docs/scl.md §3.8):
    the same type; two anonymous STRUCTs of the same members (names, order and types: S7 copies
    a structure to one of the same structure); ARRAYs of the same bounds whose elements are."""
    if a == b:
        return True
    if isinstance(a, ArrayType) and isinstance(b, ArrayType):
        return a.dims == b.dims and a.dims is not None and same_shape(a.element, b.element)
    if isinstance(a, StructType) and isinstance(b, StructType) and a.name is None is b.name:
        return len(a.members) == len(b.members) and all(
            x.lower() == y.lower() and same_shape(s, t)
            for (x, (s, _)), (y, (t, _)) in zip(a.members.items(), b.members.items())
        )
    return False


def implicit(source, target, iec_check: bool = True) -> bool:
    """Whether S7 converts source to target implicitly: with the IEC check only towards a type
    that holds every value; without it (TIA Portal's default) also between every two integers
    and bit strings, and between a bit string and BOOL (docs/scl.md §3.2)."""
    if isinstance(target, StringType):  # a string of any length (truncated), a character
        if isinstance(source, StringType):
            return source.wide == target.wide
        return source == target.char
    if not isinstance(source, Elementary) or not isinstance(target, Elementary):
        return same_shape(source, target)  # a STRUCT, UDT or ARRAY only to the same type
    if source == target or target.name in _WIDENS.get(source.name, ()):
        return True
    return not iec_check and _relaxed(source, target)


def _relaxed(source: Elementary, target: Elementary) -> bool:
    """The conversions TIA Portal adds with the IEC check off, of the subset: integer and bit
    string to integer and bit string of any width, and a bit string to and from BOOL."""
    kinds = {source.kind, target.kind}
    return kinds <= {Kind.INT, Kind.BITS} or kinds == {Kind.BITS, Kind.BOOL}


# the bit string of a width: the type a logic operation of a bit string and an integer (or
# BOOL) runs in without the IEC check (docs/scl.md §3.2)
BITS_OF_WIDTH = {8: "BYTE", 16: "WORD", 32: "DWORD", 64: "LWORD"}


def common(a: Elementary, b: Elementary, logic: bool | None = None) -> Elementary | None:
    """The type a binary operation on a and b runs in: the one the other converts to
    implicitly, or None (docs/scl.md §3.2). logic (True for AND, OR, XOR, False for the
    others) gives, without the IEC check, the type of an integer or bit string with one of the
    other kind: a logic operation runs in the bit string of the wider width, the others in the
    integer of the wider width (of the integer's sign); None: with the IEC check."""
    if not isinstance(a, Elementary) or not isinstance(b, Elementary):
        return None
    strict = _common(a, b)
    if strict is not None or logic is None or not _relaxed(a, b) or a.kind == b.kind:
        return strict
    width = max(a.bits, b.bits)
    if logic:  # a bit string and an integer or BOOL
        return ELEMENTARY[BITS_OF_WIDTH[width]]
    integer = a if a.kind == Kind.INT else b if b.kind == Kind.INT else None
    if integer is None:  # a bit string and BOOL: only a logic operation takes them
        return None
    return next(
        t
        for t in ELEMENTARY.values()
        if t.kind == Kind.INT and t.bits == width and t.signed == integer.signed
    )


def _common(a: Elementary, b: Elementary) -> Elementary | None:
    if implicit(a, b):
        return b
    if implicit(b, a):
        return a
    # else the smallest type both widen to: SINT and USINT meet in INT, INT and UINT in DINT
    for wider in ("INT", "DINT", "LINT", "REAL", "LREAL"):
        t = ELEMENTARY[wider]
        if implicit(a, t) and implicit(b, t):
            return t
    return None


def fits(value: int, t: Elementary) -> bool:
    return t.low <= value <= t.high
