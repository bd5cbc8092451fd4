"""The conversions `*_TO_*` (docs/scl.md §3.3), the shifts and rotations and MUX (§3.5): their
checks and their C."""

from __future__ import annotations

import re

from . import ast as A
from . import types as T
from .builtins import CONVERSION, entry
from .diagnostics import Code, refuse
from .types import K

# DATE (days since 1990-01-01) to and from integers and WORD, the day count (into a DATE its low
# 16 bits); TIME_OF_DAY (ms since midnight) to DINT, UDINT and TIME, its ms (docs/scl.md §3.6)
_COUNTS = ("INT", "UINT", "DINT", "UDINT", "WORD", "DWORD")
DATE_CONVERSIONS = {("DATE", n) for n in _COUNTS} | {(n, "DATE") for n in _COUNTS}
DATE_CONVERSIONS |= {("TIME_OF_DAY", n) for n in ("DINT", "UDINT", "TIME")}


@entry("*_TO_*", signatures=("<S>_TO_<T>(IN : S) : T",))
class Conversion:
    """REAL -> integer to the nearest, halves to even; integer <-> integer the low bits; no
    conversion between REAL and BOOL, TIME or bit strings, nor between BOOL and TIME."""

    def check(ck, c):
        source, target = CONVERSION.match(c.callee.upper()).groups()
        s, t = T.lookup(source), T.lookup(target)
        if isinstance(s, T.StringType) or isinstance(t, T.StringType):
            refuse(
                Code.UNSUPPORTED,
                c,
                f"{c.callee.upper()} is not supported yet (docs/scl.md §6): the conversions "
                "between character strings and numbers",
            )
        if not isinstance(s, T.Elementary) or not isinstance(t, T.Elementary) or s == t:
            refuse(Code.UNDECLARED, c, f"unknown conversion {c.callee}")
        kinds = {s.kind, t.kind}
        if K.REAL in kinds and kinds & {K.BOOL, K.TIME, K.BITS}:
            refuse(Code.CONVERSION, c, f"{c.callee}: S7 has no conversion between {s} and {t}")
        if K.CHAR in kinds and kinds & {K.REAL, K.BOOL, K.TIME}:  # [S7-CHAR-CONV]
            refuse(Code.CONVERSION, c, f"{c.callee}: S7 has no conversion between {s} and {t}")
        if K.BOOL in kinds and K.TIME in kinds:
            refuse(Code.CONVERSION, c, f"{c.callee}: S7 has no conversion between {s} and {t}")
        if K.DATE in kinds and (s.name, t.name) not in DATE_CONVERSIONS:
            refuse(
                Code.CONVERSION,
                c,
                f"{c.callee}: {s} to {t} is not in the subset (docs/scl.md §3.6: "
                "DATE to and from integers, TIME_OF_DAY to DINT, UDINT and TIME)",
            )
        value = ck.arguments(c, ["IN"])["IN"]
        ck.expr(value)
        ck.coerce(value, s, f"{c.callee}'s argument")
        c.args = [A.Argument(c.loc, "IN", value)]
        c.resolved = (s, t)
        return t

    def emit(g, c):
        source, target = c.resolved
        return g.convert(g.expr(c.args[0].value, source), source, target)


@entry(
    "SHL",
    "SHR",
    "ROL",
    "ROR",
    signatures=("SHL(IN : ANY_BIT | ANY_INT, N : UDINT) : the type of IN",),
)
class Shift:
    """A shift by the width or more gives 0, SHR of a signed integer fills with its sign, a
    rotation by N is one by N modulo the width."""

    def check(ck, c):
        name = c.callee.upper()
        given = ck.arguments(c, ["IN", "N"])
        x, n = given["IN"], given["N"]
        t = ck.expr(x)
        if isinstance(t, T.Untyped):
            refuse(Code.OPERAND, c, f"{name} of an untyped literal: give it its type (WORD#16#..)")
        if t.kind not in (K.BITS, K.INT):
            refuse(Code.OPERAND, c, f"{name} needs a bit string or an integer, not {t}")
        ck.expr(n)
        ck.coerce(n, T.UDINT, f"{name}'s N")
        c.args = [A.Argument(c.loc, "IN", x), A.Argument(c.loc, "N", n)]
        c.operand = t
        return t

    def emit(g, c):
        name, t = c.callee.upper(), T.concrete(c.operand)
        x = g.expr(c.args[0].value, t)
        n = f"(uint64_t){g.expr(c.args[1].value, T.UDINT)}"
        if name == "SHR" and t.signed:
            return f"(({t.c})scl_shr_signed((int64_t){x}, {n}))"
        code = f"scl_{name.lower()}((uint64_t)(int64_t){x}, {n}, {t.bits})"
        if t.signed:
            return g.wrap(f"(int64_t){code}", t)
        return f"(({t.c}){code})"


@entry("SWAP", signatures=("SWAP(IN : WORD | DWORD | LWORD) : the type of IN",))
class Swap:
    """The bytes of IN in the reverse order (S7-1200/1500 system manual, SWAP: 16#1234 gives
    16#3412, 16#12345678 gives 16#78563412)."""

    def check(ck, c):
        x = ck.arguments(c, ["IN"])["IN"]
        t = ck.expr(x)
        if not isinstance(t, T.Elementary) or t.name not in ("WORD", "DWORD", "LWORD"):
            refuse(Code.OPERAND, c, f"SWAP needs a WORD, DWORD or LWORD, not {t}")
        c.args = [A.Argument(c.loc, "IN", x)]
        c.operand = t
        return t

    def emit(g, c):
        t = c.operand
        return f"(({t.c})scl_swap((uint64_t){g.expr(c.args[0].value, t)}, {t.bits}))"


@entry("MUX", signatures=("MUX(K : ANY_INT, IN0 : ANY, IN1, ... [, INELSE]) : their type",))
class Mux:
    """IN<K>, K evaluated once; a K outside the inputs gives INELSE, or 0 without one. The
    checked call's `resolved` is (K, [IN0, IN1, ...], INELSE or None)."""

    def check(ck, c):
        if any(a.target is not None for a in c.args):
            refuse(Code.PARAMETER, c, "MUX has no outputs: its value is the input selected")
        if all(a.name is None for a in c.args):
            k, *ins = [a.value for a in c.args]
            otherwise = None
        elif any(a.name is None for a in c.args):
            refuse(Code.PARAMETER, c, "MUX: name every parameter (K := ..., IN0 := ...) or none")
        else:
            given = {}
            for a in c.args:
                key = a.name.upper()
                if key in given:
                    refuse(Code.PARAMETER, a, f"MUX: '{key}' is given twice")
                if key not in ("K", "INELSE") and not re.fullmatch(r"IN[0-9]+", key):
                    refuse(
                        Code.PARAMETER, a, f"MUX has no input '{a.name}' (K, IN0, IN1, ..., INELSE)"
                    )
                given[key] = a.value
            count = len([n for n in given if n not in ("K", "INELSE")])
            ins = [given.get(f"IN{i}") for i in range(count)]
            if "K" not in given or None in ins:
                refuse(Code.PARAMETER, c, "MUX needs K and IN0, IN1, ... without a gap")
            k, otherwise = given["K"], given.get("INELSE")
        if len(ins) < 2:
            refuse(Code.PARAMETER, c, "MUX needs two inputs or more (IN0, IN1, ...)")
        kt = ck.expr(k)
        if isinstance(kt, T.Untyped):
            ck.coerce(k, T.DINT, "MUX's K")
        elif kt.kind != K.INT:
            refuse(Code.OPERAND, k, f"MUX's K must be an integer, not {kt}")
        values = ins + ([otherwise] if otherwise is not None else [])
        for v in values:
            ck.expr(v)
        t = ck.unify(c, values)  # untyped inputs only: the type the context gives (settle)
        c.resolved = (k, ins, otherwise)
        c.operand = t
        return t

    def settle(ck, c, t, what):
        _, ins, otherwise = c.resolved
        for v in ins + ([otherwise] if otherwise is not None else []):
            ck.settle(v, t, what)
        c.type = c.operand = t

    def emit(g, c):
        """A function of its own per type and count (in the block's helpers), so that K is
        evaluated once."""
        k, ins, otherwise = c.resolved
        t = T.concrete(c.operand)
        n = len(ins)
        name = f"scl_mux_{t.name.lower()}_{n}{'_else' if otherwise is not None else ''}"
        if name not in g.helpers:
            params = ", ".join([f"{t.c} in{i}" for i in range(n)])
            params += f", {t.c} inelse" if otherwise is not None else ""
            cases = [f"    case {i}: return in{i};" for i in range(n)]
            fallback = "inelse" if otherwise is not None else "0"
            g.helpers[name] = [
                f"static {t.c} {name}(int64_t k, {params})",
                "{",
                "    switch (k) {",
                *cases,
                # docs/scl.md §3.5 (Decision): a K outside the inputs gives INELSE, or 0
                f"    default: return {fallback};",
                "    }",
                "}",
                "",
            ]
        values = [g.expr(v, t) for v in ins]
        if otherwise is not None:
            values.append(g.expr(otherwise, t))
        return f"{name}((int64_t){g.expr(k)}, {', '.join(values)})"
