"""The conversions between character strings and numbers (docs/scl.md §3.5 [S7-VAL-STRG],
[S7-STRG-VAL], [DEC-NUMBER-STRING]): VAL_STRG, STRG_VAL, <integer>_TO_STRING and
STRING_TO_<integer>, one entry each: their checks and their C (runtime/scl/scl_number_string.h,
where the rules of Siemens' S7-1200 system manual are). Of the numbers, the integers of the
manual's parameter tables (SInt, Int, DInt, USInt, UInt, UDInt); of the strings, STRING.
S_CONV, REAL and LREAL stay refused (docs/scl.md §6)."""

from __future__ import annotations

from . import ast as A
from . import types as T
from .builtins import entry
from .diagnostics import Code, refuse
from .types import K

# the integers VAL_STRG writes and STRG_VAL reads (S7-1200 system manual, their data types)
INTEGERS = ("SINT", "INT", "DINT", "USINT", "UINT", "UDINT")
USINT, UINT, WORD = (T.ELEMENTARY[n] for n in ("USINT", "UINT", "WORD"))
NOT_YET = " (REAL and LREAL are not supported yet, docs/scl.md §6)"


def _integer(t) -> bool:
    return isinstance(t, T.Elementary) and t.name in INTEGERS


def _named(ck, c: A.Call, inputs: dict, outputs: dict) -> tuple[dict, dict]:
    """The arguments of a system function called by the names of its parameters (as TIA writes
    them): {input: value} and {output: target}, every one given once, none missing."""
    name = c.callee.upper()
    given, targets = {}, {}
    for arg in c.args:
        key = (arg.name or "").upper()
        if arg.name is None:
            refuse(Code.PARAMETER, arg, f"{name}: name the parameters ({', '.join(inputs)} := ...)")
        table = outputs if arg.target is not None else inputs
        if key not in table:
            kind = "output" if arg.target is not None else "input"
            refuse(Code.PARAMETER, arg, f"{name} has no {kind} '{arg.name}'")
        if key in given or key in targets:
            refuse(Code.PARAMETER, arg, f"{name}: '{key}' is given twice")
        (targets if arg.target is not None else given)[key] = arg.target or arg.value
    missing = [n for n in [*inputs, *outputs] if n not in given and n not in targets]
    if missing:
        refuse(Code.PARAMETER, c, f"{name} needs {', '.join(missing)}")
    for key, t in inputs.items():
        ck.expr(given[key])
        if t is not None:
            ck.coerce(given[key], t, f"{name}'s {key}")
    return given, targets


def _target(ck, c: A.Call, target: A.VarRef, what: str):
    """An output's variable: written, no bit of a variable and no element at a run-time index
    (the C writes it through one pointer)."""
    t = ck.variable(target, write=True)
    for step in target.path or ():
        dynamic = step[0] == "index" and not all(isinstance(x, A.Literal) for x in step[1])
        if step[0] == "bit" or dynamic:
            refuse(
                Code.PARAMETER,
                target,
                f"{c.callee.upper()}'s {what} is a variable, a member or an element at a "
                "literal index",
            )
    return t


def _place(g, target: A.VarRef) -> str:
    code, conditions, bit = g.place(target)
    assert not conditions and bit is None  # refused by _target
    return code


@entry(
    "VAL_STRG",
    signatures=(
        "VAL_STRG(IN : SInt | Int | DInt | USInt | UInt | UDInt, SIZE : USInt, PREC : USInt, "
        "FORMAT : Word, P : UInt, OUT => String)",
    ),
    statement=True,
)
class ValStrg:
    """IN written into OUT at P, right-justified in SIZE characters (docs/scl.md §3.5
    [S7-VAL-STRG]). The checked call's `resolved` is (IN, SIZE, PREC, FORMAT, P, OUT)."""

    def check(ck, c):
        inputs = {"IN": None, "SIZE": USINT, "PREC": USINT, "FORMAT": WORD, "P": UINT}
        given, targets = _named(ck, c, inputs, {"OUT": None})
        value = given["IN"]
        if isinstance(value.type, T.Untyped) and value.type.kind == K.INT:
            ck.coerce(value, T.DINT, "VAL_STRG's IN")
        if not _integer(value.type):
            real = isinstance(value.type, T.Elementary) and value.type.kind == K.REAL
            refuse(
                Code.UNSUPPORTED if real else Code.OPERAND,
                value,
                f"VAL_STRG of {value.type}: the subset writes SInt, Int, DInt, USInt, UInt and "
                f"UDInt{NOT_YET if real else ''}",
            )
        out = targets["OUT"]
        t = _target(ck, c, out, "OUT")
        if not isinstance(t, T.StringType) or t.wide:
            refuse(Code.PARAMETER, out, f"VAL_STRG's OUT is a STRING; '{out.name}' is a {t}")
        c.resolved = (value, given["SIZE"], given["PREC"], given["FORMAT"], given["P"], out)
        return T.BOOL

    def emit(g, c):
        value, size, prec, fmt, p, out = c.resolved
        args = [
            f"&{_place(g, out)}",
            str(out.type.length),
            f"(int64_t){g.expr(value)}",
            g.expr(size, USINT),
            g.expr(prec, USINT),
            g.expr(fmt, WORD),
            g.expr(p, UINT),
        ]
        return f"scl_val_strg_integer({', '.join(args)})"


@entry(
    "STRG_VAL",
    signatures=(
        "STRG_VAL(IN : String, FORMAT : Word, P : UInt (in/out), "
        "OUT => SInt | Int | DInt | USInt | UInt | UDInt)",
    ),
    statement=True,
)
class StrgVal:
    """The number in IN from P into OUT, P then past it (docs/scl.md §3.5 [S7-STRG-VAL]). P is
    an in/out: a variable takes the position after the number; a constant or literal is read
    only, as TIA's LGF code passes it. The checked call's `resolved` is (IN, FORMAT, P, the
    variable P or None, OUT)."""

    def check(ck, c):
        given, targets = _named(ck, c, {"IN": T.STRING, "FORMAT": WORD, "P": UINT}, {"OUT": None})
        p = given["P"]
        back = None
        if isinstance(p, A.VarRef) and p.decl.section != A.Section.CONSTANT:
            if _target(ck, c, p, "P") != UINT:
                refuse(Code.PARAMETER, p, f"STRG_VAL's P is a UInt; '{p.name}' is a {p.type}")
            back = p
        out = targets["OUT"]
        t = _target(ck, c, out, "OUT")
        if not _integer(t):
            real = isinstance(t, T.Elementary) and t.kind == K.REAL
            refuse(
                Code.UNSUPPORTED if real else Code.PARAMETER,
                out,
                f"STRG_VAL into {t}: the subset reads SInt, Int, DInt, USInt, UInt and "
                f"UDInt{NOT_YET if real else ''}",
            )
        c.resolved = (given["IN"], given["FORMAT"], p, back, out)
        return T.BOOL

    def emit(g, c):
        text, fmt, p, back, out = c.resolved
        t = out.type
        low, high = g.limits(t)
        pointer = f"&{_place(g, back)}" if back is not None else "NULL"
        args = [g.expr(text, T.STRING), g.expr(fmt, WORD), g.expr(p, UINT), pointer, low, high]
        return f"({_place(g, out)} = ({t.c})scl_strg_val_integer({', '.join(args)}))"


@entry(
    *(f"{n}_TO_STRING" for n in INTEGERS),
    signatures=("<integer>_TO_STRING(IN : SInt | Int | DInt | USInt | UInt | UDInt) : String",),
)
class IntegerToString:
    """The sign and the digits of IN (docs/scl.md §3.5 [DEC-NUMBER-STRING])."""

    def check(ck, c):
        source = T.ELEMENTARY[c.callee.upper().split("_TO_")[0]]
        value = ck.arguments(c, ["IN"])["IN"]
        ck.expr(value)
        ck.coerce(value, source, f"{c.callee.upper()}'s IN")
        c.args = [A.Argument(c.loc, "IN", value)]
        c.operand = source
        return T.STRING

    def emit(g, c):
        return f"scl_integer_to_string((int64_t){g.expr(c.args[0].value, c.operand)})"


@entry(
    *(f"STRING_TO_{n}" for n in INTEGERS),
    signatures=("STRING_TO_<integer>(IN : String) : SInt | Int | DInt | USInt | UInt | UDInt",),
)
class StringToInteger:
    """The integer at the start of IN, as STRG_VAL in FORMAT 16#0000 from P = 1, 0 where there
    is none or it is beyond the type (docs/scl.md §3.5 [DEC-NUMBER-STRING])."""

    def check(ck, c):
        target = T.ELEMENTARY[c.callee.upper().split("_TO_")[1]]
        value = ck.arguments(c, ["IN"])["IN"]
        ck.expr(value)
        ck.coerce(value, T.STRING, f"{c.callee.upper()}'s IN")
        c.args = [A.Argument(c.loc, "IN", value)]
        c.operand = target
        return target

    def emit(g, c):
        low, high = g.limits(c.operand)
        text = g.expr(c.args[0].value, T.STRING)
        return f"(({c.operand.c})scl_string_to_integer({text}, {low}, {high}))"
