"""The C of expressions (docs/scl.md §3.2-§3.8), a part of the block's C (cgen.py): each S7
operation as the C of its rule, in the C type of its S7 type; a variable's place, with the
run-time index checks of an ARRAY; the calls of FCs and of the built-ins (builtins.py: each
entry's emit)."""

from __future__ import annotations

import struct

from . import ast as A
from . import types as T
from .cnames import bound_fields, by_reference, c_decl, field, is_open, prefix_of, struct_of, zero
from .types import K


def real_literal(value: float, t: T.Elementary) -> str:
    text = repr(float(value))
    if text in ("inf", "-inf", "nan"):
        raise ValueError(text)
    if "." not in text and "e" not in text:
        text += ".0"
    return text + ("f" if t.name == "REAL" else "")


def cast(ctype: str, code: str) -> str:
    """(ctype)code, once: code that is a cast to ctype already stays as it is."""
    inner = f"(({ctype})"
    if code.startswith(inner) and code.endswith(")"):
        depth = 0
        for i, c in enumerate(code):
            depth += {"(": 1, ")": -1}.get(c, 0)
            if depth == 0:
                if i == len(code) - 1:
                    return code
                break
    return f"({ctype}){code}"


def text_literal(codes, t) -> str:
    """A character string literal as C: a CHAR's or WCHAR's code, a STRING's or WSTRING's
    scl_string (runtime/scl/scl_string.h), its characters as the bytes of a C string, octal
    where not printable (a WSTRING's codes beyond 16#FF as an array)."""
    if isinstance(t, T.Elementary):  # CHAR, WCHAR
        return str(codes[0] if codes else 0)  # '' as a CHAR: code 0 [DEC-CHAR-EMPTY]
    if any(c > 0xFF for c in codes):
        return f"scl_wstring_of((const uint16_t[]){{{', '.join(map(str, codes))}}}, {len(codes)})"
    text = "".join(
        chr(c) if 0x20 <= c < 0x7F and chr(c) not in '\\"?' else f"\\{c:03o}" for c in codes
    )
    return f'scl_string_of("{text}", {len(codes)})'


class Expressions:
    """C text of the value of an expression in the C type of its S7 type (a mixin of
    cgen.Generator)."""

    def convert(self, code: str, source, target) -> str:
        if isinstance(target, T.StringType):  # every string value is an scl_string
            return f"scl_string_char({code})" if isinstance(source, T.Elementary) else code
        source, target = T.concrete(source), T.concrete(target)
        if source == target:
            return code
        if target.kind == K.BOOL:
            return f"({code} != 0)"
        if target.kind == K.REAL:
            return f"(({target.c}){code})"
        if source.kind == K.REAL:  # *_TO_<integer>: rounded (docs/scl.md §3.3)
            if target.bits == 64 and not target.signed:
                return f"scl_limit_round_u64({code}, false)"
            low, high = self.limits(target)
            return f"(({target.c})scl_limit_round({code}, {low}, {high}, false))"
        if source.kind == target.kind == K.TIME:  # TIME (ms) <-> LTIME (ns)
            if target.bits == 64:
                return f"((int64_t){code} * 1000000)"
            return self.wrap(f"scl_div64((int64_t){code}, 1000000)", target)
        if target.low <= source.low and source.high <= target.high:  # every value fits
            return f"(({target.c}){code})"
        if not target.signed and target.bits < 64:  # the low bits of the value
            return f"(({target.c})scl_wrap_unsigned((uint64_t){code}, {target.bits}))"
        return self.wrap(cast("int64_t", code), target)

    @staticmethod
    def limits(t: T.Elementary) -> tuple[str, str]:
        if t.bits == 64:
            return "INT64_MIN", "INT64_MAX"
        return str(t.low), str(t.high)

    def wrap(self, code: str, t: T.Elementary) -> str:
        if t.bits == 64:  # computed in 64 bits already: C's conversion keeps the low bits
            return f"(({t.c})({code}))"
        if t.signed:
            return f"(({t.c})scl_wrap({code}, {t.bits}))"
        return f"(({t.c})scl_wrap_unsigned((uint64_t)({code}), {t.bits}))"

    def expr(self, e: A.Expr, want=None) -> str:
        """The C of e, converted to the type want (None: e's own)."""
        if isinstance(e, A.Literal) and e.kind == "string":
            return text_literal(e.value, want if want is not None else e.type)
        if isinstance(e, A.Literal) and isinstance(want, T.Elementary):
            code = self.literal(e, want)  # a literal of the type wanted, where it holds it
            if code is not None:
                return code
        code = self._expr(e)
        if want is not None:
            code = self.convert(code, e.type, want)
        return code

    def _expr(self, e: A.Expr) -> str:
        if isinstance(e, A.Literal):
            return self.literal(e)
        if isinstance(e, A.VarRef):
            return self.ref(e)
        if isinstance(e, A.Unary):
            return self.unary(e)
        if isinstance(e, A.Binary):
            return self.binary(e)
        if isinstance(e, A.Call):
            return self.call(e)
        raise AssertionError(e)

    def literal(self, e: A.Literal, want=None) -> str | None:
        """A literal as C: the value of its own type, or of the type want where it holds it
        (None where not: the caller converts). An integer is a plain C constant, an int where
        it fits one (every operation casts its operands), else with its 64-bit macro."""
        t = T.concrete(e.type)
        if t is T.DTL:  # DTL#...: its members in the order of scl_dtl
            members = T.dtl_start(e.value)
            return f"((scl_dtl){{{', '.join(str(m.value) for m in members.values())}}})"
        if want is not None and want != t and t == T.REAL and want == T.LREAL:
            # the REAL's float32 value, exact in double
            return real_literal(struct.unpack("f", struct.pack("f", e.value))[0], want)
        if want is not None and want != t:
            if t.kind not in (K.INT, K.BITS) or want.kind not in (K.INT, K.BITS, K.REAL):
                return None
            if want.kind != K.REAL and not T.fits(int(e.value), want):
                return None
            t, e = want, A.Literal(e.loc, e.kind, e.text, e.value, e.type_prefix)
        if t.kind == K.BOOL:
            return "true" if e.value else "false"
        if t.kind == K.REAL:
            return real_literal(e.value, t)
        value = int(e.value)
        if value == -(1 << 31):
            return "INT32_MIN"
        if value == -(1 << 63):
            return "INT64_MIN"
        if -(1 << 31) < value < (1 << 31):
            return str(value)
        if not t.signed and value < (1 << 32):
            return f"{value}u"
        return f"{'INT64_C' if t.signed else 'UINT64_C'}({value})"

    def ref(self, e: A.VarRef) -> str:
        """The value of a variable; an element at a run-time index outside the ARRAY's bounds
        reads 0 (docs/scl.md §3.8: Decision)."""
        code, conditions, bit = self.place(e)
        reads = dict(getattr(e.decl.type, "reads", ()))
        member = e.members[0] if e.path is None and len(e.members) == 1 else None
        if isinstance(member, str) and member.upper() in reads and code.endswith("." + member):
            # a timer's Q or ET, updated at the time of the read (docs/behaviour.md §1.12)
            return f"{reads[member.upper()]}(&{code[: -len(member) - 1]}, call)"
        last = e.path[-1] if e.path else None
        if last is not None and last[0] == "instance" and last[1] in dict(last[2].reads):
            # the same of an element of an ARRAY of timers, #t[#i].Q
            code = f"{dict(last[2].reads)[last[1]]}(&{code[: -len(last[1]) - 1]}, call)"
        if bit is not None:  # a .%X bit or a slice: the bits under it (docs/scl.md §3.8)
            shift, _, width = bit
            if width == 1:
                code = f"((((uint64_t){code}) >> {shift}) & 1u) != 0"
                if not conditions:
                    return f"({code})"
            else:
                code = f"(({T.SLICE_TYPES[width].c})((uint64_t){code} >> {shift}))"
        if conditions:
            return f"({' && '.join(conditions)} ? {code} : {zero(e.type)})"
        return code

    def place(self, e: A.VarRef):
        """(C lvalue, the run-time index conditions under which it exists, (shift, type,
        width) of a .%X bit or a slice .%B, .%W, .%D of the lvalue, or None)."""
        d = e.decl
        known = self.known.get(id(e))
        if known is not None:  # the target of a compound assignment, read in its value
            return known
        returned = d.section == A.Section.RETURN  # an FC's return value, whole or a member
        if returned:
            base = f"{self.me}->scl_return"
        elif d.db and self.block is not self.program.top:  # docs/scl.md §3.9: the top FB's static
            top = struct_of(self.program.top_checker)
            base = f"(({top} *)ctx->top)->{field(d.name)}"
        else:
            base = field(d.name) if d.section.local else f"{self.me}->{field(d.name)}"
        reference = not returned and by_reference(d, self.checker)
        if reference and not is_open(d.type):  # the caller's variable (docs/scl.md §3.7)
            base = f"(*{base})"
        path = e.path
        if path is None:  # an FB instance's member
            members = e.members
            if isinstance(d.type, T.FbType) and d.type.block is not None:
                names = d.type.block.names
                members = [field(names[m.lower()].name) for m in members]
            return base + "".join("." + m for m in members), [], None
        conditions, assigns, bit = [], [], None
        for step in path:
            if step[0] in ("member", "instance"):
                base += "." + field(step[1])
            elif step[0] == "index" and reference and is_open(step[2]):
                # an ARRAY[*] passed by reference: its elements in S7's order (the last index
                # runs fastest) from the pointer, within the argument's bounds
                offset = None
                for x, (lo, hi) in zip(step[1], bound_fields(field(d.name), step[2].rank)):
                    lo, hi = f"{self.me}->{lo}", f"{self.me}->{hi}"
                    at = self._checked_index(x, lo, hi, assigns, conditions)
                    offset = at if offset is None else f"({offset}) * ({hi} - {lo} + 1) + {at}"
                base += f"[{offset}]"
            elif step[0] == "index":
                _, exprs, t = step
                for i, x in enumerate(exprs):
                    if t.dims is None:
                        lo = 0
                        count = f"{self.me}->{field(T.table_count(d.name))}"
                        hi = f"scl_count({count}, {T.TABLE_CAPACITY}) - 1"
                    else:
                        lo, hi = t.dims[i]
                    if isinstance(x, A.Literal) and t.dims is not None and lo <= x.value <= hi:
                        base += f"[{int(x.value) - lo}]"  # a literal within the bounds
                        continue
                    base += f"[{self._checked_index(x, lo, hi, assigns, conditions)}]"
            elif step[0] == "char":  # a character of a string: data[i - 1], i 1 .. its length
                _, x, t = step
                if isinstance(x, A.Literal):
                    base += f".data[{int(x.value) - 1}]"
                    continue
                base += f".data[{self._checked_index(x, 1, t.length, assigns, conditions)}]"
            else:
                bit = step[1:]
        if assigns:  # every index is evaluated, in order, before any bound is checked
            conditions = [f"({', '.join(assigns)}, {' && '.join(conditions)})"]
        return base, conditions, bit

    def _checked_index(self, x: A.Expr, lo, hi, assigns: list, conditions: list) -> str:
        """The subscript of index x within lo .. hi: x once, in a temporary of the function (its
        assignment into `assigns`, its bounds check into `conditions`), which the bounds check
        and the subscript both read (an FC with outputs in it runs once)."""
        self.temps += 1
        index = f"scl_index_{self.temps}"
        self.index_temps.append(index)
        assigns.append(f"{index} = (int64_t){self.expr(x)}")
        conditions.append(f"scl_in({index}, {lo}, {hi})")
        return f"scl_at({index}, {lo}, {hi})"

    def unary(self, e: A.Unary) -> str:
        t = T.concrete(e.type)
        x = self.expr(e.operand, t)
        if e.op == "NOT":
            return f"(!{x})" if t.kind == K.BOOL else f"(({t.c})~{x})"
        if t.kind == K.REAL:
            return f"(-{x})"
        if t.bits == 64:
            return f"(({t.c})(UINT64_C(0) - (uint64_t){x}))"
        return self.wrap(f"-(int64_t){x}", t)

    def binary(self, e: A.Binary) -> str:
        t = T.concrete(e.operand_type)
        op = e.op
        if isinstance(t, T.StringType):  # S7's comparison of strings (docs/scl.md §3.1)
            a, b = self.expr(e.left, t), self.expr(e.right, t)
            c_op = {"=": "==", "<>": "!="}.get(op, op)
            return f"(scl_string_compare({a}, {b}) {c_op} 0)"
        if op == "**":  # EXPT: pow of double, a REAL result rounded to float (docs/scl.md §3.5)
            base = self.expr(e.left, T.LREAL)
            exponent = self.expr(e.right, T.LREAL)
            return f"(({t.c})pow({base}, {exponent}))"
        if t is T.DTL:  # docs/scl.md §3.4: runtime/scl/dates.h
            a, b = self.expr(e.left, t), self.expr(e.right, e.right.type)
            if op in ("=", "<>", "<", ">", "<=", ">="):
                return f"(scl_dtl_compare({a}, {b}) {({'=': '==', '<>': '!='}).get(op, op)} 0)"
            if e.right.type is T.DTL:
                return f"scl_t_diff({a}, {b})"
            return f"scl_dtl_add({a}, {'-' if op == '-' else ''}(int64_t){b})"
        if t.kind == K.TIME and op in ("*", "/"):
            a, b = self.expr(e.left, t), self.expr(e.right, T.LINT if t.bits == 64 else T.DINT)
        else:
            a, b = self.expr(e.left, t), self.expr(e.right, t)
        if op in ("=", "<>", "<", ">", "<=", ">="):
            c_op = {"=": "==", "<>": "!="}.get(op, op)
            return f"({a} {c_op} {b})"
        if op in ("AND", "OR", "XOR"):
            if t.kind == K.BOOL:
                return f"({a} {({'AND': '&&', 'OR': '||', 'XOR': '!='})[op]} {b})"
            return f"(({t.c})({a} {({'AND': '&', 'OR': '|', 'XOR': '^'})[op]} {b}))"
        if t.kind == K.REAL:
            eno = self.checker.names.get("eno") if self.program.auto_eno else None
            if eno is not None and op in ("+", "-", "*", "/"):
                # TIA's "Set ENO automatically": a result that is no finite REAL sets ENO FALSE
                # (docs/scl.md §3.4 [S7-ENO-AUTO])
                return f"scl_real_eno(&{field(eno.name)}, {a} {op} {b})"
            return f"({a} {op} {b})"
        wide = "int64_t" if t.signed else "uint64_t"
        if t.bits == 64:  # in uint64_t, where C wraps; / and MOD by their own rules
            if op in ("/", "MOD"):
                f = (
                    ("scl_div64" if op == "/" else "scl_mod64")
                    if t.signed
                    else ("scl_udiv64" if op == "/" else "scl_umod64")
                )
                return f"(({t.c}){f}({a}, {b}))"
            return f"(({t.c})({cast('uint64_t', a)} {op} {cast('uint64_t', b)}))"
        if op == "/":
            body = f"scl_div({cast('int64_t', a)}, {cast('int64_t', b)})"
        elif op == "MOD":
            body = f"scl_mod({cast('int64_t', a)}, {cast('int64_t', b)})"
        else:
            body = f"{cast(wide, a)} {op} {cast(wide, b)}"
        return self.wrap(body, t)

    def call(self, c: A.Call) -> str:
        """A call's value: a user FC's function, or its built-in's C (builtins/)."""
        if c.unit is not None:
            return self.fc_call(c)
        return c.builtin.emit(self, c)

    def fc_call(self, c: A.Call) -> str:
        """A call of an FC: its C function with the inputs by value, the outputs by address (NULL
        for one not given)."""
        fc = c.unit
        ins = [
            d for d in fc.block.decls if d.section == A.Section.INPUT and not by_reference(d, fc)
        ]
        args = ["ctx"] + [self.expr(v, d.type) for v, d in zip(c.inputs, ins)]
        args += [self.address(t) if t is not None else "NULL" for t in c.outputs]
        for formal, actual in c.references:
            args += self.reference(formal, actual)
        return f"{prefix_of(fc)}({', '.join(args)})"

    def reference(self, formal: A.VarDecl, actual: A.VarRef) -> list[str]:
        """The C arguments of a parameter passed by reference (docs/scl.md §3.7): the address of
        the variable; for an ARRAY[*], of its first element, then each dimension's bounds."""
        code, conditions, _ = self.place(actual)
        if conditions:  # at a run-time index outside its ARRAY: a stand-in of zeros (§3.7)
            self.temps += 1
            spare = f"scl_spare_{self.temps}"
            self.spares.append(c_decl(spare, actual.type))
            zeroed = f"(memset(&{spare}, 0, sizeof {spare}), &{spare})"
            code = f"(*({' && '.join(conditions)} ? &{code} : {zeroed}))"
        if not is_open(formal.type):
            return [f"&{code}"]
        t = actual.type
        if t.dims is not None:
            bounds = ["INT32_MIN" if b == -(1 << 31) else str(b) for dim in t.dims for b in dim]
            return [f"&{code}" + "[0]" * len(t.dims), *bounds]
        d = actual.decl
        if by_reference(d, self.checker):  # passed on: the same element and bounds
            fields = [b for pair in bound_fields(field(d.name), t.rank) for b in pair]
            return [code] + [f"{self.me}->{b}" for b in fields]
        count = f"{self.me}->{field(T.table_count(d.name))}"  # the table of the FMU's FB
        return [code, "0", f"(int32_t)scl_count({count}, {T.TABLE_CAPACITY}) - 1"]

    def address(self, target: A.VarRef) -> str:
        """Where an FC's output goes (checks.py refuses a bit): NULL, the output not given, for
        an element at an index outside its ARRAY, as a write there is ignored."""
        code, conditions, _ = self.place(target)
        if conditions:
            return f"({' && '.join(conditions)} ? &{code} : NULL)"
        return f"&{code}"
