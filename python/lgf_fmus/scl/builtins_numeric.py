"""The numeric built-ins (docs/scl.md §3.5): their checks and their C. The arguments meet in a
common type (§3.2); an untyped literal argument takes DINT or LREAL (a REAL for SIN and COS)."""

from __future__ import annotations

from . import ast as A
from . import types as T
from .builtins import entry
from .diagnostics import Code, refuse
from .types import K

# the C of the REAL and LREAL functions (docs/scl.md §3.5): a REAL's in double, then rounded to
# float; SIN and COS of a REAL are the signal generators' (iec/sin_cos.h)
C_MATH = {"TAN": "tan", "ASIN": "asin", "ACOS": "acos", "ATAN": "atan", "EXP": "exp"}
C_MATH.update({"LN": "log", "LOG": "log10", "SIN": "sin", "COS": "cos"})


def arguments(ck, c: A.Call, names: list[str]) -> list[A.Expr]:
    """The values of the inputs names (given by name or in this order), checked, in order."""
    given = ck.arguments(c, names)
    c.args = [A.Argument(c.loc, n, given[n]) for n in names]
    values = [a.value for a in c.args]
    for v in values:
        ck.expr(v)
    return values


def real_argument(ck, c: A.Call, untyped=T.LREAL) -> T.Elementary:
    """IN of a REAL or LREAL function; an untyped literal is an `untyped`."""
    name = c.callee.upper()
    values = arguments(ck, c, ["IN"])
    t = ck.unify(c, values)
    if isinstance(t, T.Untyped):
        t = untyped
        ck.coerce(values[0], t, f"{name}'s IN")
    if t.kind != K.REAL:
        refuse(Code.OPERAND, c, f"{name} needs a REAL or LREAL, not {t}")
    c.operand = t
    return t


def numbers(ck, c: A.Call, names: list[str]) -> T.Elementary:
    """Numeric arguments meeting in a common type; untyped literals alone in DINT or LREAL."""
    name = c.callee.upper()
    values = arguments(ck, c, names)
    t = ck.unify(c, values)
    if isinstance(t, T.Untyped) or t.kind not in (K.INT, K.REAL):
        if not isinstance(t, T.Untyped):
            refuse(Code.OPERAND, c, f"{name} needs numbers, not {t}")
        t = T.DINT if t.kind == K.INT else T.LREAL
        for v in values:
            ck.coerce(v, t, f"{name}'s argument")
    c.operand = t
    return t


def suffix(t: T.Elementary) -> str:
    """The runtime's MIN/MAX flavour: ULINT and LWORD compare as unsigned 64 bits."""
    return {"REAL": "f", "LREAL": "d", "ULINT": "u", "LWORD": "u"}.get(t.name, "i")


@entry("ABS", signatures=("ABS(IN : ANY_NUM) : the type of IN",))
class Abs:
    def check(ck, c):
        t = numbers(ck, c, ["IN"])
        if t.kind == K.INT and not t.signed:
            refuse(Code.OPERAND, c, f"ABS of an unsigned {t}")
        return t

    def emit(g, c):
        t = T.concrete(c.operand)
        x = g.expr(c.args[0].value, t)
        if t.kind == K.REAL:
            return f"{'fabsf' if t.name == 'REAL' else 'fabs'}({x})"
        if t.bits == 64:
            return f"(({t.c})({x} < 0 ? UINT64_C(0) - (uint64_t){x} : (uint64_t){x}))"
        return g.wrap(f"({x} < 0 ? -(int64_t){x} : (int64_t){x})", t)


def of_real(name: str) -> tuple[str, ...]:
    """The signatures of a function of a REAL or an LREAL of the same type."""
    return (f"{name}(IN : REAL) : REAL", f"{name}(IN : LREAL) : LREAL")


@entry("SQRT", signatures=of_real("SQRT"))
class Sqrt:
    check = real_argument

    def emit(g, c):
        t = c.operand
        return f"{'sqrtf' if t.name == 'REAL' else 'sqrt'}({g.expr(c.args[0].value, t)})"


@entry("SQR", signatures=of_real("SQR"))
class Sqr:
    """IN * IN, rounded once to IN's type (docs/scl.md §3.5); IN evaluated once."""

    check = real_argument

    def emit(g, c):
        t = c.operand
        name = f"scl_sqr_{t.name.lower()}"
        g.helpers.setdefault(name, [f"static {t.c} {name}({t.c} x) {{ return x * x; }}", ""])
        return f"{name}({g.expr(c.args[0].value, t)})"


@entry("TRUNC", signatures=("TRUNC(IN : REAL | LREAL) : DINT",))
class Trunc:
    def check(ck, c):
        real_argument(ck, c)
        return T.DINT

    def emit(g, c):
        x = g.expr(c.args[0].value, c.operand)
        return f"((int32_t)scl_limit_round({x}, INT32_MIN, INT32_MAX, true))"


# FRAC and its forms with the type of IN and OUT in the name (docs/scl.md §3.5)
FRAC_TYPES = {"FRAC": None, "FRAC_REAL": T.REAL, "FRAC_LREAL": T.LREAL}


@entry(*FRAC_TYPES, signatures=("FRAC(IN : REAL | LREAL) : the type of IN",))
class Frac:
    """The places after the decimal point of a REAL or LREAL, IN - TRUNC(IN), of IN's sign
    (docs/scl.md §3.5 [DEC-FRAC]): exact in IN's type; IN evaluated once. FRAC_REAL and
    FRAC_LREAL take IN as that type (an assignment's conversion, §3.2)."""

    def check(ck, c):
        typed = FRAC_TYPES[c.callee.upper()]
        if typed is None:
            return real_argument(ck, c)
        (value,) = arguments(ck, c, ["IN"])
        ck.coerce(value, typed, f"{c.callee.upper()}'s IN")
        c.operand = typed
        return typed

    def emit(g, c):
        t = c.operand
        name = f"scl_frac_{t.name.lower()}"
        trunc = "truncf" if t.name == "REAL" else "trunc"
        g.helpers.setdefault(
            name, [f"static {t.c} {name}({t.c} x) {{ return x - {trunc}(x); }}", ""]
        )
        return f"{name}({g.expr(c.args[0].value, t)})"


# ROUND, CEIL and FLOOR: the C function of the whole number, of a double and of a float
WHOLE = {"ROUND": ("nearbyint", "nearbyintf"), "CEIL": ("ceil", "ceilf")}
WHOLE["FLOOR"] = ("floor", "floorf")


@entry(*WHOLE, signatures=("ROUND(IN : REAL | LREAL) : DINT",))
class Whole:
    """ROUND (to the nearest, halves to even: ROUND(10.5) = 10, ROUND(11.5) = 12), CEIL (the
    smallest whole number not below IN), FLOOR (the largest not above IN) of a REAL or LREAL, as
    a DINT, SCL's type of their value; NaN gives 0 and a value beyond the DINT range its limit
    (docs/scl.md §3.5)."""

    def check(ck, c):
        real_argument(ck, c)
        return T.DINT

    def emit(g, c):
        t = c.operand
        whole = f"{WHOLE[c.callee.upper()][t.name == 'REAL']}({g.expr(c.args[0].value, t)})"
        return f"((int32_t)scl_limit_whole({whole}, INT32_MIN, INT32_MAX))"


@entry("NORM_X", signatures=("NORM_X(MIN : ANY_NUM, VALUE, MAX) : REAL | LREAL",))
class NormX:
    """(VALUE - MIN) / (MAX - MIN), MIN, VALUE and MAX meeting in a common type; its value a
    REAL or an LREAL as its context takes it (an untyped real, LREAL alone), computed in LREAL
    and rounded once to it (docs/scl.md §3.5)."""

    def check(ck, c):
        numbers(ck, c, ["MIN", "VALUE", "MAX"])
        return T.ANY_REAL

    def settle(ck, c, t, what):
        c.type = t  # a REAL or LREAL: coerce gives an untyped real no other type

    def emit(g, c):
        low, value, high = (g.expr(a.value, T.LREAL) for a in c.args)
        return in_type(f"scl_norm_x({low}, {value}, {high})", T.concrete(c.type))


@entry("SCALE_X", signatures=("SCALE_X(MIN : REAL | LREAL, VALUE : REAL | LREAL, MAX) : MIN's",))
class ScaleX:
    """VALUE * (MAX - MIN) + MIN, of the type of MIN and MAX, a REAL or an LREAL (of literals
    alone, the type its context takes, as NORM_X's), computed in LREAL and rounded once to it
    (docs/scl.md §3.5)."""

    def check(ck, c):
        low, value, high = arguments(ck, c, ["MIN", "VALUE", "MAX"])
        t = ck.unify(c, [low, high])
        if isinstance(t, T.Untyped):
            t = T.ANY_REAL
        elif t.kind == K.INT:
            refuse(
                Code.UNSUPPORTED,
                c,
                f"SCALE_X to {t} is not supported yet: Siemens' description leaves the rounding "
                "of an integer result open (docs/scl.md §3.5)",
            )
        elif not isinstance(t, T.Elementary) or t.kind != K.REAL:
            refuse(Code.OPERAND, c, f"SCALE_X's MIN and MAX are numbers, not {t}")
        vt = ck.expr(value)
        if isinstance(vt, T.Untyped):
            vt = T.LREAL
            ck.coerce(value, vt, "SCALE_X's VALUE")
        if not isinstance(vt, T.Elementary) or vt.kind != K.REAL:
            refuse(Code.OPERAND, value, f"SCALE_X's VALUE is a REAL or LREAL, not {vt}")
        c.operand = t
        return t

    def settle(ck, c, t, what):
        for v in (c.args[0].value, c.args[2].value):
            ck.settle(v, t, what)
        c.type = c.operand = t

    def emit(g, c):
        low, value, high = (g.expr(a.value, T.LREAL) for a in c.args)
        return in_type(f"scl_scale_x({low}, {value}, {high})", T.concrete(c.operand))


def in_type(code: str, t: T.Elementary) -> str:
    """The double of NORM_X or SCALE_X as their REAL or LREAL."""
    return code if t == T.LREAL else f"((float){code})"


class RealFunction:
    """SIN, COS (an untyped literal is a REAL: the signal generators' SIN and COS), TAN, ASIN,
    ACOS, ATAN, EXP, LN, LOG: the C library's double function, a REAL's result rounded once."""

    def check(ck, c):
        name = c.callee.upper()
        return real_argument(ck, c, T.REAL if name in ("SIN", "COS") else T.LREAL)

    def emit(g, c):
        name, t = c.callee.upper(), c.operand
        x = g.expr(c.args[0].value, t)
        if name in ("SIN", "COS") and t == T.REAL:  # docs/behaviour.md §6.2: iec/sin_cos.h
            return f"iec_sin_cos({x}, {'true' if name == 'COS' else 'false'})"
        if t == T.REAL:
            return f"((float){C_MATH[name]}((double){x}))"
        return f"{C_MATH[name]}({x})"


entry(*C_MATH, signatures=("SIN(IN : REAL | LREAL) : the type of IN",))(RealFunction)


@entry("MIN", "MAX", signatures=("MIN(IN1 : ANY_NUM, IN2, ... IN32) : their common type",))
class MinMax:
    """A tie gives the first argument; a NaN loses to a number (IEEE minNum/maxNum)."""

    def check(ck, c):
        count = max(2, len(c.args))
        return numbers(ck, c, [f"IN{i}" for i in range(1, count + 1)])

    def emit(g, c):
        t = T.concrete(c.operand)
        name = c.callee.lower()
        args = [g.expr(a.value, t) for a in c.args]
        code = args[0]
        for other in args[1:]:
            code = f"scl_{name}_{suffix(t)}({code}, {other})"
        return f"(({t.c}){code})"


@entry("LIMIT", signatures=("LIMIT(MN : ANY_NUM, IN, MX) : their common type",))
class Limit:
    """MIN(MAX(IN, MN), MX)."""

    def check(ck, c):
        return numbers(ck, c, ["MN", "IN", "MX"])

    def emit(g, c):
        t = T.concrete(c.operand)
        mn, x, mx = (g.expr(a.value, t) for a in c.args)
        s = suffix(t)
        return f"(({t.c})scl_min_{s}(scl_max_{s}({x}, {mn}), {mx}))"


@entry("SEL", signatures=("SEL(G : BOOL, IN0 : ANY, IN1 : ANY) : their common type",))
class Sel:
    def check(ck, c):
        g, *values = arguments(ck, c, ["G", "IN0", "IN1"])
        ck.coerce(g, T.BOOL, "SEL's G")
        t = ck.unify(c, values)
        c.operand = t
        return t

    def emit(g, c):
        t = T.concrete(c.operand)
        select, in0, in1 = (a.value for a in c.args)
        return f"({g.expr(select, T.BOOL)} ? {g.expr(in1, t)} : {g.expr(in0, t)})"


@entry("EXPT", signatures=("EXPT(IN1 : REAL | LREAL, IN2 : ANY_NUM) : the type of IN1",))
class Expt:
    """IN1 ** IN2, with the rules of ** (docs/scl.md §3.5)."""

    def check(ck, c):
        given = ck.arguments(c, ["IN1", "IN2"])
        c.resolved = A.Binary(c.loc, "**", given["IN1"], given["IN2"])
        return ck.expr(c.resolved)

    def emit(g, c):
        return g.binary(c.resolved)
