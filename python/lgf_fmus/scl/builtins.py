"""The system functions of the subset (docs/scl.md §3.5, §3.6, §3.8): one entry per built-in,
its S7 signature(s), its check and its C side by side. The checks find a call's entry with
`lookup` and run its `check`, which checks the arguments (their number and names, their types
and the implicit conversions of docs/scl.md §3.2), refuses what S7 refuses, and records on the
call what the C needs (`Call.builtin`, `Call.operand`, `Call.resolved`); C generation runs the
entry's `emit` on the checked call. Adding a built-in is an entry here, its rule in
docs/scl.md and its tests: nothing else.

An entry is a class holding

    check(checker, call) -> the S7 type of the call's value
    emit(generator, call) -> the C expression of its value
    settle(checker, call, t, what)   optional: the call's untyped value takes the type t

    builtins_numeric.py   ABS, SQR, SQRT, TRUNC, ROUND, CEIL, FLOOR, NORM_X, SCALE_X, MIN, MAX,
                          LIMIT, SEL, SIN ... LOG, EXPT
    builtins_bits.py      the *_TO_* conversions, SHL, SHR, ROL, ROR, MUX
    builtins_dates.py     T_ADD, T_SUB, T_DIFF, DTL_TO_DATE, DTL_TO_TOD, DATE_TO_DTL
    builtins_system.py    LOWER_BOUND, UPPER_BOUND, QRY_CINT, RD_SYS_T, RD_LOC_T, RUNTIME
    builtins_string.py    LEN, CONCAT, LEFT, RIGHT, MID, FIND, INSERT, DELETE, REPLACE, MAX_LEN
    builtins_string_numbers.py  VAL_STRG, STRG_VAL, <integer>_TO_STRING, STRING_TO_<integer>
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import Callable


@dataclass(frozen=True)
class Builtin:
    name: str
    signatures: tuple[str, ...]  # as Siemens' documentation writes them
    check: Callable
    emit: Callable
    settle: Callable | None = None
    statement: bool = False  # a VOID system function (RESET_TIMER): a statement, never a value


REGISTRY: dict[str, Builtin] = {}
# X_TO_Y: one entry for every conversion, found by the pattern
CONVERSION = re.compile(r"([A-Z]+)_TO_([A-Z]+)\Z")
_CONVERSION_ENTRY = "*_TO_*"


def entry(*names: str, signatures: tuple[str, ...], statement: bool = False):
    """Registers the class below as the built-in of each of names."""

    def register(cls):
        for name in names:
            REGISTRY[name] = Builtin(
                name,
                signatures,
                cls.check,
                cls.emit,
                getattr(cls, "settle", None),
                statement,
            )
        return cls

    return register


def lookup(name: str) -> Builtin | None:
    """The built-in a call of name runs, None for no system function of the subset."""
    upper = name.upper()
    if upper in REGISTRY:
        return REGISTRY[upper]
    if CONVERSION.match(upper):
        return REGISTRY[_CONVERSION_ENTRY]
    return None


from . import (  # noqa: E402, F401  (the entries)
    builtins_bits,
    builtins_dates,
    builtins_numeric,
    builtins_string,
    builtins_string_numbers,
    builtins_system,
)
