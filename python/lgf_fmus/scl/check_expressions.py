"""The checks of expressions and conversions (docs/scl.md §3.2-§3.8), which the statements'
pass runs on each expression: every variable declared and read or written as it may be, its
members, indices and bits; every operand of a type its operation takes, in the type both meet
in; untyped literals taking their context's type; S7's implicit conversions and no other; the
calls of the built-ins (builtins.py: each entry's check; an FC's: check_inout.py). Annotates
the tree: VarRef.decl and .path, Expr.type, Binary.operand_type, the Call's fields."""

from __future__ import annotations

from . import ast as A
from . import builtins, unsupported
from . import types as T
from .diagnostics import Code, Silent, refuse
from .types import K

ARITHMETIC = {"+", "-", "*", "/", "MOD"}
COMPARISON = {"=", "<>", "<", ">", "<=", ">="}
LOGIC = {"AND", "&", "OR", "XOR"}
# a part of a bit string or integer by its width: .%X3, .%B1, .%W1, .%D1 (docs/scl.md §3.8)
SLICE_LETTERS = {1: "X", 8: "B", 16: "W", 32: "D"}
PART_NAMES = {1: "bits", 8: "bytes", 16: "words", 32: "double words"}


class Expressions:
    """The checks of an expression (a mixin of checks.Checker)."""

    def variable(self, ref: A.VarRef, write=False):
        d = ref.decl = self.decl(ref)
        if d.type is T.ERROR:
            raise Silent()
        if isinstance(d.type, T.FbType):
            fb = d.type
            if not ref.members:
                refuse(
                    Code.INSTANCE,
                    ref,
                    f"the {fb.name} instance '{d.name}' is not a value: use "
                    f"#{d.name}.{next(iter(fb.outputs), '<output>')}",
                )
            if len(ref.members) > 1 or not isinstance(ref.members[0], str):
                refuse(Code.SELECTOR, ref, f"'{d.name}': {fb.name} has members .Q, .IN, ... only")
            member = ref.members[0].upper()
            if fb.block is not None and member not in fb.inputs and member not in fb.outputs:
                refuse(
                    Code.SELECTOR,
                    ref,
                    f"{fb.name} has no input or output '{ref.members[0]}' (the statics of an "
                    "instance are its own)",
                )
            if member in fb.outputs:
                if write:
                    refuse(
                        Code.READ_ONLY,
                        ref,
                        f"'{d.name}.{ref.members[0]}' is an output of {fb.name}: "
                        "only the instance writes it",
                    )
                ref.type = fb.outputs[member]
            elif member in fb.inputs:
                ref.type = fb.inputs[member]
            else:
                refuse(Code.SELECTOR, ref, f"{fb.name} has no member '{ref.members[0]}'")
            ref.members = [member]
            return ref.type
        if write and d.section == A.Section.CONSTANT:
            refuse(Code.READ_ONLY, ref, f"'{d.name}' is a constant")
        if write and (d.section == A.Section.INPUT or d.calling_ob):
            refuse(
                Code.READ_ONLY,
                ref,
                f"'{d.name}' is an input, set by the importer at every call; assign a "
                "static instead (docs/scl.md §4)",
            )
        ref.type = self.selectors(ref, d.type, d.name, write)
        if isinstance(ref.type, T.FbType) and write:
            refuse(Code.INSTANCE, ref, f"'{d.name}[..]' is an FB instance: it is not assigned")
        if write and d.db:  # a setpoint the program writes is no parameter (docs/scl.md §3.9)
            members = []
            for step in ref.path:
                if step[0] != "member":
                    break
                members.append(step[1].lower())
            self.program.db_writes.add((d.name.lower(), *members))
        return ref.type

    def selectors(self, ref: A.VarRef, t, name: str, write=False):
        """The type of name.member[i, j].%X3 ...; annotates the ref's path for cgen.py:
        ("member", name), ("index", [exprs], ArrayType), ("bit", shift, type, width)
        (docs/scl.md §3.8)."""
        ref.path = []
        for sel in ref.members:
            if isinstance(sel, str) and isinstance(t, T.FbType):  # #axes[1].pos (§3.7)
                t, member = self.instance_member(ref, t, sel, name, write), sel.upper()
                if t.block is not None:
                    member = t.block.names[member.lower()].name
                ref.path.append(("instance", member, t))
                t, name = (t.outputs.get(sel.upper()) or t.inputs[sel.upper()]), f"{name}.{sel}"
            elif isinstance(sel, str):
                key = t.member(sel) if isinstance(t, T.StructType) else None
                if key is None:
                    refuse(Code.SELECTOR, ref, f"'{name}' is a {t}: it has no member '{sel}'")
                ref.path.append(("member", key))
                t, name = t.members[key][0], f"{name}.{key}"
            elif isinstance(sel, A.Index) and isinstance(t, T.StringType):
                t, name = self.character(ref, sel, t, name)
            elif isinstance(sel, A.Index):
                if not isinstance(t, T.ArrayType):
                    refuse(
                        Code.SELECTOR, sel, f"'{name}' is a {t}, not an ARRAY: it takes no index"
                    )
                rank = t.dimensions
                if len(sel.exprs) != rank:
                    given = len(sel.exprs)
                    refuse(
                        Code.SELECTOR,
                        sel,
                        f"'{name}' is an {t}: it takes {rank} index(es), not {given}",
                    )
                for i, e in enumerate(sel.exprs):
                    it = self.expr(e)
                    if isinstance(it, T.Untyped):
                        self.coerce(e, T.DINT, f"the index of '{name}'")
                    elif not isinstance(it, T.Elementary) or it.kind != K.INT or it.bits > 32:
                        refuse(
                            Code.OPERAND,
                            e,
                            f"the index of '{name}' must be an integer of up to 32 bits, not {it}",
                        )
                    if isinstance(e, A.Literal) and t.dims is not None:
                        lo, hi = t.dims[i]
                        if not lo <= e.value <= hi:
                            refuse(
                                Code.RANGE, e, f"the index {e.value} is outside {name}'s {lo}..{hi}"
                            )
                ref.path.append(("index", sel.exprs, t))
                t, name = t.element, f"{name}[..]"
            else:
                t, name = self.part(ref, sel, t, name)
        return t

    def character(self, ref: A.VarRef, sel: A.Index, t: T.StringType, name: str):
        """#s[i]: the character i of a STRING (a CHAR) or WSTRING (a WCHAR), i from 1 to its
        maximum length (docs/scl.md §3.1 [S7-STRING-CHAR])."""
        if len(sel.exprs) != 1:
            refuse(Code.SELECTOR, sel, f"'{name}' is a {t}: it takes one index")
        (e,) = sel.exprs
        it = self.expr(e)
        if isinstance(it, T.Untyped):
            self.coerce(e, T.DINT, f"the index of '{name}'")
        elif not isinstance(it, T.Elementary) or it.kind != K.INT or it.bits > 32:
            refuse(Code.OPERAND, e, f"the index of '{name}' must be an integer of up to 32 bits")
        if isinstance(e, A.Literal) and not 1 <= e.value <= t.length:
            refuse(Code.RANGE, e, f"the index {e.value} is outside {name}'s 1..{t.length}")
        ref.path.append(("char", e, t))
        return t.char, f"{name}[..]"

    @staticmethod
    def instance_member(ref: A.VarRef, fb, sel: str, name: str, write: bool):
        """An input or output of the element of an ARRAY of instances, `#axes[#i].pos`: an
        output read only, as an instance's (docs/scl.md §3.6, §3.7)."""
        member = sel.upper()
        if member in fb.outputs and write:
            refuse(
                Code.READ_ONLY,
                ref,
                f"'{name}.{sel}' is an output of {fb.name}: only the instance writes it",
            )
        if member not in fb.outputs and member not in fb.inputs:
            refuse(Code.SELECTOR, ref, f"{fb.name} has no input or output '{sel}'")
        return fb

    def part(self, ref: A.VarRef, sel: A.Bit, t, name: str):
        """A bit .%X3 or a slice .%B1, .%W1, .%D1 of a bit string or integer (docs/scl.md
        §3.8): a slice narrower than the variable, its parts counted from the least significant
        one; a part of a slice is the part of the variable under it (one path step)."""
        letter = SLICE_LETTERS[sel.width]
        if not isinstance(t, T.Elementary) or t.kind not in (K.INT, K.BITS):
            access = "bit access .%X" if sel.width == 1 else f"the slice .%{letter}"
            refuse(Code.SELECTOR, sel, f"'{name}' is a {t}: {access} is on a bit string or integer")
        if sel.width >= t.bits:
            refuse(
                Code.SELECTOR,
                sel,
                f"'{name}' is a {t}: the slice .%{letter} is of a variable wider than a "
                f"{T.SLICE_TYPES[sel.width]}",
            )
        count = t.bits // sel.width
        if sel.number >= count:
            refuse(
                Code.RANGE,
                sel,
                f"'{name}' is a {t}: its {PART_NAMES[sel.width]} are %{letter}0 to "
                f"%{letter}{count - 1}",
            )
        shift, whole = sel.number * sel.width, t
        if ref.path and ref.path[-1][0] == "bit":  # a part of a slice
            _, outer, whole, _ = ref.path.pop()
            shift += outer
        ref.path.append(("bit", shift, whole, sel.width))
        part = T.BOOL if sel.width == 1 else T.SLICE_TYPES[sel.width]
        return part, f"{name}.%{letter}{sel.number}"

    def expr(self, e: A.Expr):
        if isinstance(e, A.Literal):
            e.type = self.literal_type(e)
        elif isinstance(e, A.VarRef):
            self.variable(e)
        elif isinstance(e, A.Unary):
            self.unary(e)
        elif isinstance(e, A.Binary):
            self.binary(e)
        elif isinstance(e, A.Call):
            self.call(e)
        if e.type is T.ERROR:  # a call of an FC whose return type was refused
            raise Silent()
        return e.type

    def literal_type(self, e: A.Literal):
        if e.kind == "string":
            return self.text_type(e)
        if e.kind == "bool":
            return T.BOOL
        if e.kind == "time":
            return T.LTIME if e.type_prefix == "LTIME" else T.TIME
        if e.kind == "date":  # DTL#..., D#..., TOD#... (docs/scl.md §2.1)
            return T.lookup(e.type_prefix)
        if e.type_prefix is None:
            return T.ANY_INT if e.kind == "int" else T.ANY_REAL
        t = T.lookup(e.type_prefix)
        if not isinstance(t, T.Elementary) or t.kind == K.BOOL:
            refuse(Code.LITERAL, e, f"{e.text}: unknown literal type {e.type_prefix}")
        if e.kind == "real" and t.kind != K.REAL:
            refuse(Code.LITERAL, e, f"{e.text}: a {t} literal must be a whole number")
        if e.kind == "int" and t.kind in (K.INT, K.BITS) and not T.fits(e.value, t):
            refuse(Code.RANGE, e, f"{e.text} does not fit {t} ({t.low} to {t.high})")
        if t.kind == K.REAL and abs(float(e.value)) > T.REAL_MAX[t.name]:
            refuse(Code.RANGE, e, f"{e.text} is beyond the largest {t}")
        if t.kind == K.TIME:
            refuse(Code.LITERAL, e, f"{e.text}: write a TIME as T#...")
        return t

    def text_type(self, e: A.Literal):
        """'abc' (untyped: a STRING or a CHAR as its context needs), STRING#'..', WSTRING#'..',
        CHAR#'a', WCHAR#'a' (docs/scl.md §3.1 [S7-STRING-LIT])."""
        if e.type_prefix is None:
            return T.TextLiteral(len(e.value))
        t = T.lookup(e.type_prefix)
        if isinstance(t, T.Elementary) and len(e.value) != 1:
            refuse(Code.LITERAL, e, f"{e.text}: a {t} literal is one character")
        return t

    def coerce(self, e: A.Expr, t, what: str):
        """Gives an untyped literal (or an expression of them) the type t, or checks that e's
        type converts to t implicitly (docs/scl.md §3.2)."""
        if t is T.ERROR or e.type is T.ERROR:
            raise Silent()
        if isinstance(e.type, T.TextLiteral):  # 'abc' as a STRING, 'a' as a CHAR too
            if isinstance(t, T.StringType) or (
                isinstance(t, T.Elementary) and t.kind == K.CHAR and e.type.length <= 1
            ):  # '' as a CHAR: code 0 (docs/scl.md §3.1 [DEC-CHAR-EMPTY])
                e.type = t
                return
            refuse(Code.CONVERSION, e, f"{what}: {e.type} is no {t}")
        if isinstance(e.type, T.Untyped) and not isinstance(t, T.Elementary):
            refuse(Code.CONVERSION, e, f"{what}: {e.type} is no {t}")
        if isinstance(e.type, T.Untyped):
            if t.kind in (K.BOOL, K.TIME, K.CHAR) or (e.type.kind == K.REAL and t.kind != K.REAL):
                refuse(Code.CONVERSION, e, f"{what}: {e.type} is no {t}")
            self.settle(e, t, what)
            return
        if not T.implicit(e.type, t, self.program.iec_check):
            both = isinstance(e.type, T.Elementary) and isinstance(t, T.Elementary)
            hint = f"; write {e.type}_TO_{t}(...)" if both else ""
            refuse(Code.CONVERSION, e, f"{what}: S7 converts no {e.type} to {t} implicitly{hint}")

    def settle(self, e, t, what):
        if isinstance(e, A.Literal):
            if e.kind == "int" and t.kind in (K.INT, K.BITS) and not T.fits(e.value, t):
                if t.kind == K.BITS and e.value >= 0 and not self.program.iec_check:
                    # a bit pattern too wide for a bit string: its low bits, as TIA takes it
                    # without the IEC check (LGF_SplitDWordToWords's Byte := 16#FFFF, §3.2)
                    e.value &= t.high
                else:
                    refuse(
                        Code.RANGE, e, f"{what}: {e.text} does not fit {t} ({t.low} to {t.high})"
                    )
            if t.kind == K.REAL and abs(float(e.value)) > T.REAL_MAX[t.name]:
                refuse(Code.RANGE, e, f"{what}: {e.text} is beyond the largest {t}")
            e.type = t
        elif isinstance(e, A.Unary):
            self.settle(e.operand, t, what)
            e.type = t
        elif isinstance(e, A.Binary):
            self.settle(e.left, t, what)
            self.settle(e.right, t, what)
            e.operand_type = t
            e.type = T.BOOL if e.op in COMPARISON else t
        elif isinstance(e, A.Call) and e.builtin is not None and e.builtin.settle is not None:
            e.builtin.settle(self, e, t, what)
        else:
            e.type = t

    def unary(self, e: A.Unary):
        t = self.expr(e.operand)
        if e.op == "NOT":
            if isinstance(t, T.Untyped) or t.kind not in (K.BOOL, K.BITS):
                refuse(Code.OPERAND, e, f"NOT needs a BOOL or a bit string, not {t}")
        elif not isinstance(t, T.Untyped) and (
            not isinstance(t, T.Elementary) or t.kind not in (K.INT, K.REAL, K.TIME) or not t.signed
        ):
            refuse(Code.OPERAND, e, f"unary minus needs a signed number or TIME, not {t}")
        e.type = t

    def binary(self, e: A.Binary):
        a, b = self.expr(e.left), self.expr(e.right)
        op = "AND" if e.op == "&" else e.op  # lower.py writes it so after the checks
        if op == "**":
            return self.power(e, a, b)
        texts = (T.StringType, T.TextLiteral)
        if isinstance(a, texts) or isinstance(b, texts):
            if isinstance(a, T.TextLiteral) and isinstance(b, T.Elementary):
                self.coerce(e.left, b, f"the {op} operand")  # 'A' = #c: a CHAR
                a = b
            elif isinstance(b, T.TextLiteral) and isinstance(a, T.Elementary):
                self.coerce(e.right, a, f"the {op} operand")
                b = a
            else:
                return self.text_comparison(e, op, a, b)
        if isinstance(a, T.Untyped) and isinstance(b, T.Untyped):
            if op in LOGIC or op == "MOD" and K.REAL in (a.kind, b.kind):
                refuse(Code.OPERAND, e, f"{op} of two untyped literals: give one a type (INT#..)")
            kind = K.REAL if K.REAL in (a.kind, b.kind) else K.INT
            e.type = T.BOOL if op in COMPARISON else T.Untyped(kind)
            e.operand_type = T.Untyped(kind)
            return
        if T.DTL in (a, b):
            return self.dtl_binary(e, op, a, b)
        # TIME arithmetic: TIME ± TIME, TIME * integer, TIME / integer (docs/scl.md §3.4)
        timed = [x for x in (a, b) if isinstance(x, T.Elementary) and x.kind == K.TIME]
        if timed and op in ARITHMETIC:
            tt = timed[0]
            count = T.LINT if tt == T.LTIME else T.DINT  # what a TIME (LTIME) counts in
            if op in ("+", "-") and a == b == tt:
                e.operand_type = e.type = tt
                return
            if op in ("*", "/") and a == tt:
                if isinstance(b, T.Untyped):
                    self.coerce(e.right, count, f"the {op} operand")
                    b = count
                if b.kind == K.INT and T.implicit(b, count):
                    e.operand_type = e.type = tt
                    return
            refuse(
                Code.OPERAND, e, f"{a} {op} {b}: {tt} takes + and - of {tt}, * and / by an integer"
            )
        if isinstance(a, T.Untyped):
            self.coerce(e.left, b, f"the {op} operand")
            a = b
        elif isinstance(b, T.Untyped):
            self.coerce(e.right, a, f"the {op} operand")
            b = a
        t = T.common(a, b, None if self.program.iec_check else op in LOGIC)
        if t is None:
            refuse(
                Code.CONVERSION,
                e,
                f"{a} {op} {b}: S7 converts neither operand to the other's type implicitly;"
                " convert one with *_TO_*",
            )
        e.operand_type = t
        if op in ARITHMETIC:
            if t.kind not in (K.INT, K.REAL):
                refuse(Code.OPERAND, e, f"{op} needs numbers, not {t}")
            if op == "MOD" and t.kind != K.INT:
                refuse(Code.OPERAND, e, f"MOD needs integers, not {t}")
            e.type = t
        elif op in COMPARISON:
            if t.kind == K.BOOL and op not in ("=", "<>"):
                refuse(Code.OPERAND, e, f"BOOL values compare with = and <> only, not {op}")
            e.type = T.BOOL
        else:
            if t.kind not in (K.BOOL, K.BITS):
                refuse(Code.OPERAND, e, f"{op} needs BOOL or bit strings, not {t}")
            e.type = t

    def text_comparison(self, e: A.Binary, op: str, a, b):
        """Two strings compared (docs/scl.md §3.1 [S7-STRING-CMP]): STRING with STRING,
        WSTRING with WSTRING, of any lengths; a literal takes the other's type."""
        if op not in COMPARISON:
            refuse(Code.OPERAND, e, f"{op} needs numbers or bit strings, not {a} and {b}")
        known = [x for x in (a, b) if isinstance(x, T.StringType)]
        t = T.StringType(known[0].wide) if known else T.STRING
        for side, x in ((e.left, a), (e.right, b)):
            if isinstance(x, T.StringType) and x.wide == t.wide:
                continue
            if isinstance(x, T.TextLiteral):
                self.coerce(side, t, f"the {op} operand")
                continue
            refuse(
                Code.CONVERSION,
                e,
                f"{a} {op} {b}: S7 compares a {t.name} with a {t.name} only; convert the other",
            )
        e.operand_type, e.type = t, T.BOOL
        return e.type

    def dtl_binary(self, e: A.Binary, op: str, a, b):
        """DTL = DTL, <> ... (a comparison), DTL + TIME, DTL - TIME (T_ADD, T_SUB) and
        DTL - DTL (T_DIFF, a TIME), as S7-1500's SCL writes them (docs/scl.md §3.4)."""
        if a is b is T.DTL and op in COMPARISON:
            e.operand_type, e.type = T.DTL, T.BOOL
        elif a is T.DTL and b == T.TIME and op in ("+", "-"):
            e.operand_type, e.type = T.DTL, T.DTL
        elif a is b is T.DTL and op == "-":
            e.operand_type, e.type = T.DTL, T.TIME
        else:
            refuse(
                Code.OPERAND,
                e,
                f"{a} {op} {b}: a DTL compares with a DTL, takes + and - of a TIME, and - of a DTL",
            )

    def power(self, e: A.Binary, a, b):
        """a ** b, S7's EXPT (docs/scl.md §3.5): a REAL or LREAL base, an integer or real
        exponent; the result has the base's type, or LREAL where either is an LREAL."""
        if isinstance(a, T.Untyped):
            a = T.LREAL if not isinstance(b, T.Elementary) or b.kind != K.REAL else b
            self.coerce(e.left, a, "the base of **")
        if not isinstance(a, T.Elementary) or a.kind != K.REAL:
            refuse(
                Code.OPERAND,
                e,
                f"** needs a REAL or LREAL base, not {a}; convert it with *_TO_REAL",
            )
        if isinstance(b, T.Untyped):
            b = a if b.kind == K.REAL else T.DINT
            self.coerce(e.right, b, "the exponent of **")
        if b.kind == K.REAL:
            e.type = e.operand_type = T.common(a, b)
        elif b.kind == K.INT and T.implicit(b, T.LREAL):
            e.type = e.operand_type = a
        else:
            refuse(Code.OPERAND, e, f"the exponent of ** must be a number, not {b}")
        return e.type

    def arguments(self, call: A.Call, names: list[str], positional_ok=True) -> dict:
        given = {}
        for i, arg in enumerate(call.args):
            if arg.target is not None:
                refuse(Code.PARAMETER, arg, f"{call.callee} has no output '{arg.name}'")
            name = arg.name.upper() if arg.name else None
            if name is None:
                if not positional_ok or i >= len(names) or any(a.name for a in call.args):
                    refuse(
                        Code.PARAMETER,
                        arg,
                        f"{call.callee}: name the arguments ({', '.join(names)} := ...)",
                    )
                name = names[i]
            if name not in names:
                refuse(
                    Code.PARAMETER,
                    arg,
                    f"{call.callee} has no input '{arg.name}' (it takes {', '.join(names)})",
                )
            if name in given:
                refuse(Code.PARAMETER, arg, f"{call.callee}: '{name}' is given twice")
            given[name] = arg.value
        missing = [n for n in names if n not in given]
        if missing:
            refuse(Code.PARAMETER, call, f"{call.callee} needs {', '.join(missing)}")
        return given

    def call(self, c: A.Call, statement: bool = False):
        """A call as a value (or, statement, one whose value is dropped): of a user FC, else of
        a built-in (builtins/, its entry's check)."""
        d = None if c.quoted else self.names.get(c.callee.lower())
        if c.local or (d is not None and isinstance(d.type, T.FbType)):
            refuse(
                Code.STATEMENT, c, f"the instance call #{c.callee}(...) is a statement, not a value"
            )
        unit = self.user_unit(c)
        if unit is not None:
            return self.fc_call(c, unit, statement=False)
        c.builtin = builtins.lookup(c.callee)
        if c.builtin is None:
            message = unsupported.function_message(c.callee)
            if message:
                refuse(Code.UNSUPPORTED, c, message)
            refuse(
                Code.UNDECLARED,
                c,
                f"unknown or unsupported function '{c.callee}' (docs/scl.md §3.5)",
            )
        if c.builtin.statement and not statement:
            refuse(Code.STATEMENT, c, f"{c.callee.upper()} has no value: call it as a statement")
        c.type = c.builtin.check(self, c)
        return c.type

    def unify(self, c, values):
        if any(isinstance(v.type, (T.StringType, T.TextLiteral)) for v in values):
            refuse(
                Code.UNSUPPORTED,
                c,
                f"{c.callee.upper()} of character strings is not supported yet (docs/scl.md §6)",
            )
        typed = [v.type for v in values if isinstance(v.type, T.Elementary)]
        if not typed:
            kinds = {v.type.kind for v in values}
            return T.Untyped(K.REAL if K.REAL in kinds else K.INT)
        t = typed[0]
        for other in typed[1:]:
            u = T.common(t, other)
            if u is None:
                refuse(
                    Code.CONVERSION,
                    c,
                    f"{c.callee}: {t} and {other} have no common type; convert with *_TO_*",
                )
            t = u
        for v in values:
            self.coerce(v, t, f"{c.callee}'s argument")
        return t
