"""The string functions of S7 (docs/scl.md §3.5 [S7-STRING-FN]): LEN, CONCAT, LEFT, RIGHT, MID,
FIND, INSERT, DELETE, REPLACE, one entry each: their checks and their C (runtime/scl/
scl_string.h, where their edge cases are, as Siemens' S7-1200/1500 system manual documents
them). A STRING function takes STRINGs (a CHAR, a literal as one), a WSTRING function WSTRINGs
(a WCHAR); L and P are INTs, as the manual's parameter tables give them."""

from __future__ import annotations

from . import ast as A
from . import types as T
from .builtins import entry
from .diagnostics import Code, refuse
from .types import K


def _width(ck, c, given: dict, texts: tuple[str, ...]) -> T.StringType:
    """The string type the call computes in: WSTRING where an argument is a WSTRING or WCHAR,
    else STRING; every string argument checked and converted to it."""
    types = {name: ck.expr(given[name]) for name in texts}
    wide = None
    for t in types.values():
        if isinstance(t, T.StringType) or isinstance(t, T.Elementary) and t.kind == K.CHAR:
            wide = t.wide if isinstance(t, T.StringType) else t == T.WCHAR
            break
    operand = T.WSTRING if wide else T.STRING
    for name in texts:
        ck.coerce(given[name], operand, f"{c.callee.upper()}'s {name}")
    return operand


def _check(ck, c, texts: tuple[str, ...], integers: tuple[str, ...] = ()):
    """Checks a call of IN/IN1/IN2 strings and L/P INTs, in this order, by name or position;
    records the arguments in that order (Call.args) and the string type (Call.operand)."""
    names = list(texts + integers)
    given = ck.arguments(c, names)
    c.operand = _width(ck, c, given, texts)
    for name in integers:
        ck.expr(given[name])
        ck.coerce(given[name], T.INT, f"{c.callee.upper()}'s {name}")
    c.args = [A.Argument(c.loc, name, given[name]) for name in names]
    return c.operand


class _StringFunction:
    """An entry: its S7 parameters (strings, then integers), its C function and its result
    (None: a string of the arguments' width)."""

    texts: tuple[str, ...] = ()
    integers: tuple[str, ...] = ()
    result = None

    @classmethod
    def check(cls, ck, c):
        operand = _check(ck, c, cls.texts, cls.integers)
        return cls.result or operand

    @classmethod
    def emit(cls, g, c):
        """scl_<name>(strings..., integers...): the strings as scl_string, L and P as INT."""
        types = [c.operand] * len(cls.texts) + [T.INT] * len(cls.integers)
        values = [g.expr(a.value, t) for a, t in zip(c.args, types)]
        return f"scl_{c.callee.lower()}({', '.join(values)})"


def _register(name: str, signature: str, texts, integers=(), result=None):
    cls = type(name, (_StringFunction,), {"texts": texts, "integers": integers, "result": result})
    entry(name, signatures=(signature,))(cls)


_register("LEN", "LEN(IN : STRING | WSTRING) : INT", ("IN",), result=T.INT)


@entry("CONCAT", signatures=("CONCAT(IN1, IN2 [, IN3, ...] : STRING | WSTRING) : their type",))
class Concat(_StringFunction):
    """IN1 then IN2, then IN3 ... where given (docs/scl.md §3.5 [DEC-CONCAT-MORE])."""

    @classmethod
    def check(cls, ck, c):
        count = max(len(c.args), 2)
        return _check(ck, c, tuple(f"IN{i}" for i in range(1, count + 1)))

    @classmethod
    def emit(cls, g, c):
        code, *rest = [g.expr(a.value, c.operand) for a in c.args]
        for value in rest:
            code = f"scl_concat({code}, {value})"
        return code


_register("LEFT", "LEFT(IN : STRING | WSTRING, L : INT) : the type of IN", ("IN",), ("L",))
_register("RIGHT", "RIGHT(IN : STRING | WSTRING, L : INT) : the type of IN", ("IN",), ("L",))
_register(
    "MID", "MID(IN : STRING | WSTRING, L : INT, P : INT) : the type of IN", ("IN",), ("L", "P")
)
_register("FIND", "FIND(IN1, IN2 : STRING | WSTRING) : INT", ("IN1", "IN2"), result=T.INT)
_register(
    "INSERT", "INSERT(IN1, IN2 : STRING | WSTRING, P : INT) : their type", ("IN1", "IN2"), ("P",)
)
_register(
    "DELETE",
    "DELETE(IN : STRING | WSTRING, L : INT, P : INT) : the type of IN",
    ("IN",),
    ("L", "P"),
)
_register(
    "REPLACE",
    "REPLACE(IN1, IN2 : STRING | WSTRING, L : INT, P : INT) : their type",
    ("IN1", "IN2"),
    ("L", "P"),
)


@entry("MAX_LEN", signatures=("MAX_LEN(IN : STRING | WSTRING) : DINT",))
class MaxLen:
    """The declared maximum length of a string variable (STRING[n]: n), as a DINT."""

    def check(ck, c):
        value = ck.arguments(c, ["IN"])["IN"]
        t = ck.expr(value)
        if not isinstance(value, A.VarRef) or not isinstance(t, T.StringType):
            refuse(Code.OPERAND, value, f"MAX_LEN needs a STRING or WSTRING variable, not {t}")
        c.args = [A.Argument(c.loc, "IN", value)]
        c.operand = t
        return T.DINT

    def emit(g, c):
        return str(c.operand.length)
