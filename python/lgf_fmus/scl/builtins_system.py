"""The built-ins of arrays and of the CPU (docs/scl.md §3.6, §3.8): LOWER_BOUND, UPPER_BOUND,
QRY_CINT, RD_SYS_T, RD_LOC_T, RUNTIME; their checks and their C."""

from __future__ import annotations

from . import ast as A
from . import types as T
from .builtins import entry
from .cnames import bound_fields, by_reference, field
from .diagnostics import Code, refuse
from .lower import fold
from .types import K


def _integer_constant(ck, e):
    """The value of an integer literal, or of a constant of the block (VAR CONSTANT with an
    integer literal, as TIA's LGF code passes `DIM := #DIMENSION_ONE`); None for anything
    else."""
    if isinstance(e, A.Literal):
        return e.value if e.kind == "int" else None
    if isinstance(e, A.VarRef) and not e.members:
        t = ck.expr(e)
        d = e.decl
        if (
            d is not None
            and d.section == A.Section.CONSTANT
            and isinstance(t, T.Elementary)
            and t.kind in (K.INT, K.BITS)
        ):
            init = d.init
            if init is None:
                return 0
            if isinstance(init, A.Literal) and init.kind in ("int", "typed"):
                return init.value if isinstance(init.value, int) else None
    return None


@entry(
    "LOWER_BOUND",
    "UPPER_BOUND",
    signatures=("LOWER_BOUND(ARR : ARRAY[*], DIM : UDINT) : DINT",),
)
class Bound:
    """A bound of an ARRAY as a DINT; of an ARRAY[*] of the FMU 0 and numberOf<Name> - 1
    (docs/scl.md §3.8), of one passed by reference its argument's (docs/scl.md §3.7). The
    checked call's `resolved` is (the ARRAY, DIM)."""

    def check(ck, c):
        name = c.callee.upper()
        given = ck.arguments(c, ["ARR", "DIM"])
        arr, dim = given["ARR"], fold(given["DIM"])
        if not isinstance(arr, A.VarRef):
            refuse(Code.OPERAND, arr, f"{name}'s ARR must be an ARRAY variable")
        t = ck.expr(arr)
        if not isinstance(t, T.ArrayType):
            refuse(Code.OPERAND, arr, f"{name}'s ARR must be an ARRAY, not {t}")
        rank = t.dimensions
        value = _integer_constant(ck, dim)
        if value is None or not 1 <= value <= rank:
            refuse(
                Code.PARAMETER,
                dim,
                f"{name}'s DIM must be a literal or a constant of the block from 1 to {rank}",
            )
        if isinstance(dim, A.Literal):
            ck.expr(dim)
            ck.coerce(dim, T.UDINT, f"{name}'s DIM")
        c.resolved = (arr, value)
        return T.DINT

    def emit(g, c):
        arr, dim = c.resolved
        lower = c.callee.upper() == "LOWER_BOUND"
        t = arr.type
        if t.dims is not None:  # a DINT constant
            bound = t.dims[dim - 1][0 if lower else 1]
            return "INT32_MIN" if bound == -(1 << 31) else str(bound)
        if by_reference(arr.decl, g.checker):  # the bounds of the argument (docs/scl.md §3.7)
            lo, hi = bound_fields(field(arr.decl.name), t.rank)[dim - 1]
            return f"{g.me}->{lo if lower else hi}"
        if lower:
            return "0"
        count = field(T.table_count(arr.decl.name))
        return f"((int32_t)scl_count({g.me}->{count}, {T.TABLE_CAPACITY}) - 1)"


QRY_OUTPUTS = {"CYCLE": T.UDINT, "PHASE": T.UDINT, "STATUS": T.ELEMENTARY["DWORD"]}


@entry(
    "QRY_CINT",
    signatures=(
        "QRY_CINT(OB_NR : OB_CYCLIC, CYCLE => UDINT, PHASE => UDINT, STATUS => DWORD) : INT",
    ),
)
class QryCint:
    """The period of the calling cyclic-interrupt OB: the FMU's cycleTime (docs/behaviour.md
    §1.1). The checked call's `resolved` is {output name: its target}."""

    def check(ck, c):
        c.resolved = {}
        for arg in c.args:
            name = (arg.name or "").upper()
            if arg.target is not None:
                if name not in QRY_OUTPUTS:
                    refuse(
                        Code.PARAMETER,
                        arg,
                        f"QRY_CINT has no output '{arg.name}' (CYCLE, PHASE, STATUS)",
                    )
                t = ck.variable(arg.target, write=True)
                if any(not isinstance(m, str) for m in arg.target.members):
                    refuse(
                        Code.PARAMETER,
                        arg,
                        f"QRY_CINT's {name} goes to a variable or member, not to an element",
                    )
                # TIA compiles without "IEC check" by default, and then converts a DWORD into a
                # WORD implicitly, keeping its low word: the LGF CI blocks take STATUS so
                if t != QRY_OUTPUTS[name] and not (name == "STATUS" and t == T.ELEMENTARY["WORD"]):
                    refuse(
                        Code.PARAMETER,
                        arg,
                        f"QRY_CINT's {name} is a {QRY_OUTPUTS[name]}; '{arg.target.name}' is a {t}",
                    )
                c.resolved[name] = arg.target
            elif name == "OB_NR":
                c.resolved["OB_NR"] = arg.value
                t = ck.expr(arg.value)
                if isinstance(t, T.Untyped):
                    ck.coerce(arg.value, T.INT, "OB_NR")
                elif t.kind != K.INT:
                    refuse(Code.OPERAND, arg, f"QRY_CINT's OB_NR is a number, not {t}")
            else:
                refuse(
                    Code.PARAMETER, arg, "QRY_CINT takes OB_NR := and CYCLE =>, PHASE =>, STATUS =>"
                )
        return T.INT

    def emit(g, c):
        outs = [
            f"&{g.ref(c.resolved[k])}" if k in c.resolved else "NULL"
            for k in ("CYCLE", "PHASE", "STATUS")
        ]
        status = c.resolved.get("STATUS")
        word = status is not None and status.type == T.ELEMENTARY["WORD"]
        schedule = g.checker.program.schedule
        if schedule is not None:  # a program's: the OB that OB_NR names (docs/scl.md §3.10)
            from .program import qry_cint_c, qry_cint_word_c

            g.helpers["scl_program_qry_cint"] = qry_cint_c(schedule)
            if word:
                g.helpers["scl_program_qry_cint_word"] = qry_cint_word_c()
            ob = g.expr(c.resolved["OB_NR"], T.DINT) if "OB_NR" in c.resolved else "0"
            return f"scl_program_qry_cint{'_word' if word else ''}({ob}, {', '.join(outs)})"
        return f"scl_qry_cint{'_word' if word else ''}(call, {', '.join(outs)})"


@entry("RESET_TIMER", signatures=("RESET_TIMER(TIMER : IEC_TIMER)",), statement=True)
class ResetTimer:
    """An IEC timer set back to its state before its first run: not running, ET 0, Q FALSE,
    IN's memory FALSE (docs/scl.md §3.6). The checked call's `resolved` is the instance."""

    def check(ck, c):
        args = c.args
        if (
            len(args) != 1
            or args[0].target is not None
            or (args[0].name or "TIMER").upper() != ("TIMER")
        ):
            refuse(Code.PARAMETER, c, "RESET_TIMER takes one timer: RESET_TIMER(#inst)")
        v = args[0].value
        d = ck.decl(v) if isinstance(v, A.VarRef) and not v.members else None
        t = d.type if d is not None else None
        if not isinstance(t, T.FbType) or t.name not in ("TON", "TOF", "TP"):
            refuse(Code.PARAMETER, v, "RESET_TIMER's TIMER must be a TON, TOF or TP instance")
        v.decl = d  # the instance itself, no value of it
        c.resolved = v
        return T.BOOL

    def emit(g, c):
        return f"scl_reset_timer(&{g.ref(c.resolved)})"


@entry(
    "RD_SYS_T",
    "RD_LOC_T",
    signatures=("RD_SYS_T(OUT => DTL) : INT", "RD_LOC_T(OUT => DTL) : INT"),
)
class ReadClock:
    """The date and time of the call from the FMU's parameter startDateAndTime (and for
    RD_LOC_T localTimeOffset, docs/scl.md §3.6). The checked call's `resolved` is the DTL."""

    def check(ck, c):
        name = c.callee.upper()
        ck.program.uses_date = True
        if name == "RD_LOC_T":
            ck.program.uses_local = True
        c.resolved = None
        for arg in c.args:
            # OUT => #dtl, or the DTL alone as TIA writes it too (RD_LOC_T(#now))
            alone = len(c.args) == 1 and arg.name is None and isinstance(arg.value, A.VarRef)
            if not alone and (arg.target is None or (arg.name or "").upper() != "OUT"):
                refuse(Code.PARAMETER, arg, f"{name} takes OUT => #dtl (a DTL) only")
            target = arg.value if alone else arg.target
            t = ck.variable(target)
            if t is not T.DTL or any(s[0] == "index" for s in target.path or ()):
                refuse(
                    Code.PARAMETER,
                    arg,
                    f"{name}'s OUT is a DTL variable or member; '{target.name}' is not",
                )
            ck.variable(target, write=True)
            c.resolved = target
        if c.resolved is None:
            refuse(Code.PARAMETER, c, f"{name} needs OUT => #dtl (a DTL)")
        return T.INT

    def emit(g, c):
        local = "true" if c.callee.upper() == "RD_LOC_T" else "false"
        return f"scl_rd_sys_t(ctx, {local}, &{g.ref(c.resolved)})"


@entry("RUNTIME", signatures=("RUNTIME(MEM : LREAL) : LREAL",))
class Runtime:
    """The simulated s since the last RUNTIME of MEM (docs/scl.md §3.6). The checked call's
    `resolved` is MEM."""

    def check(ck, c):
        if (
            len(c.args) != 1
            or c.args[0].target is not None
            or (c.args[0].name or "MEM").upper() != "MEM"
        ):
            refuse(
                Code.PARAMETER,
                c,
                "RUNTIME takes one LREAL variable: RUNTIME(#mem) or RUNTIME(MEM := #mem)",
            )
        v = c.args[0].value
        if not isinstance(v, A.VarRef):
            refuse(
                Code.PARAMETER,
                v,
                "RUNTIME's MEM must be a variable: it keeps the time of the last call",
            )
        t = ck.variable(v, write=True)
        if t != T.LREAL:
            refuse(Code.PARAMETER, v, f"RUNTIME's MEM is an LREAL; '{v.name}' is a {t}")
        if any(
            step[0] == "index"
            and (step[2].dims is None or not all(isinstance(x, A.Literal) for x in step[1]))
            for step in v.path
        ):
            refuse(
                Code.PARAMETER,
                v,
                "RUNTIME's MEM is a variable, a member or an element at a literal index",
            )
        c.resolved = v
        return T.LREAL

    def emit(g, c):
        return f"scl_runtime(&{g.ref(c.resolved)}, call)"
