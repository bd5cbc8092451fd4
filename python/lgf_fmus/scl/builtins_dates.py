"""The date and time functions of an S7-1500 (docs/scl.md §3.6): T_ADD, T_SUB, T_DIFF of DTLs
and the conversions between DTL, DATE and TIME_OF_DAY; their checks and their C (the C in
runtime/scl/dates.h)."""

from __future__ import annotations

from . import ast as A
from . import types as T
from .builtins import entry
from .diagnostics import Code, refuse

TOD = T.ELEMENTARY["TIME_OF_DAY"]
DATE = T.ELEMENTARY["DATE"]


def _argument(ck, c, name: str, t, what: str):
    value = ck.arguments(c, [name])[name] if len(c.args) == 1 else None
    if value is None:
        refuse(Code.PARAMETER, c, f"{c.callee} takes one {t}: {c.callee}({name} := ...)")
    ck.expr(value)
    ck.coerce(value, t, what)
    c.args = [A.Argument(c.loc, name, value)]
    return value


@entry(
    "T_ADD",
    "T_SUB",
    signatures=("T_ADD(IN1 : DTL, IN2 : TIME) : DTL", "T_SUB(IN1 : DTL, IN2 : TIME) : DTL"),
)
class TAdd:
    """IN1 plus (minus) IN2 ms, as DTL + TIME (docs/scl.md §3.6). T_ADD and T_SUB of TIMEs are
    TIME + TIME and TIME - TIME. The checked call's `resolved` is (IN1, IN2)."""

    def check(ck, c):
        given = ck.arguments(c, ["IN1", "IN2"])
        a = ck.expr(given["IN1"])
        ck.expr(given["IN2"])
        ck.coerce(given["IN2"], T.TIME, f"{c.callee}'s IN2")
        if a is not T.DTL and a != T.TIME:
            refuse(Code.OPERAND, given["IN1"], f"{c.callee}'s IN1 is a DTL or a TIME, not {a}")
        c.resolved = (given["IN1"], given["IN2"])
        return a

    def emit(g, c):
        a, b = c.resolved
        minus = c.callee.upper() == "T_SUB"
        if a.type is T.DTL:
            return f"scl_dtl_add({g.expr(a)}, {'-' if minus else ''}(int64_t){g.expr(b, T.TIME)})"
        body = f"(int64_t){g.expr(a, T.TIME)} {'-' if minus else '+'} (int64_t){g.expr(b, T.TIME)}"
        return g.wrap(body, T.TIME)


@entry("T_DIFF", signatures=("T_DIFF(IN1 : DTL, IN2 : DTL) : TIME",))
class TDiff:
    """IN1 - IN2 of two DTLs as a TIME (docs/scl.md §3.6). The checked call's `resolved` is
    (IN1, IN2)."""

    def check(ck, c):
        given = ck.arguments(c, ["IN1", "IN2"])
        for name in ("IN1", "IN2"):
            t = ck.expr(given[name])
            if t is not T.DTL:
                refuse(Code.OPERAND, given[name], f"T_DIFF's {name} is a DTL, not {t}")
        c.resolved = (given["IN1"], given["IN2"])
        return T.TIME

    def emit(g, c):
        a, b = c.resolved
        return f"scl_t_diff({g.expr(a)}, {g.expr(b)})"


CONVERSIONS = {
    "DTL_TO_DATE": (T.DTL, DATE, "scl_dtl_to_date"),
    "DTL_TO_TOD": (T.DTL, TOD, "scl_dtl_to_tod"),
    "DTL_TO_TIME_OF_DAY": (T.DTL, TOD, "scl_dtl_to_tod"),
    "DATE_TO_DTL": (DATE, T.DTL, "scl_date_to_dtl"),
}


@entry(*CONVERSIONS, signatures=("DTL_TO_DATE(IN : DTL) : DATE", "DATE_TO_DTL(IN : DATE) : DTL"))
class DtlConversion:
    """A DTL's date (days since 1990-01-01) or time of day (ms since midnight), and the DTL of a
    DATE at 00:00 (docs/scl.md §3.6). The checked call's `resolved` is IN."""

    def check(ck, c):
        source, target, _ = CONVERSIONS[c.callee.upper()]
        c.resolved = _argument(ck, c, "IN", source, f"{c.callee}'s argument")
        return target

    def emit(g, c):
        source, _, function = CONVERSIONS[c.callee.upper()]
        return f"{function}({g.expr(c.resolved, source)})"
