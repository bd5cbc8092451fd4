"""C generation (docs/scl.md §4): from a checked FUNCTION_BLOCK, exactly what a hand-written block
of src/blocks/ is: block.h (the struct of inputs, outputs and statics, the init and the call),
block.c, and interface.c (the model_variable table, the statics of the FMU state, lgf_model) onto
src/core/model.h, src/iec/ and the SCL runtime runtime/scl/scl.h. Every name of the SCL keeps its
spelling as a C field; every S7 operation becomes the C of its rule in docs/scl.md §3."""

from __future__ import annotations

import re
import uuid

from . import ast as A
from . import types as T
from .escape import c_comment, c_format, c_string, html_text, xml_name, xml_text

C_KEYWORDS = set(
    "auto break case char const continue default do double else enum extern float for goto if "
    "inline int long register restrict return short signed sizeof static struct switch typedef "
    "union unsigned void volatile while block call data".split()
)
FMI_RANGE = {
    "BOOL": ("0", "1"),
    "REAL": ("-INFINITY", "INFINITY"),
    "LREAL": ("-INFINITY", "INFINITY"),
    "TIME": ("-2147483.647", "2147483.647"),
}


# what the generated C's headers define (stdbool, stdint, stddef, math, stdio, string) or the
# generated code names itself: an SCL name that is one of them gets a "_" in the C
C_NAMES = set(
    "bool true false NULL INFINITY NAN HUGE_VAL EOF errno assert offsetof stdin stdout stderr "
    "b f ctx plc model variables statics lgf_model init check status status_text".split()
)
C_MACRO = re.compile(r"U?INT(8|16|32|64|MAX|PTR)_(MIN|MAX|C)|SIZE_MAX|(FLT|DBL|LDBL)_\w+|E[A-Z]+")
C_PREFIXES = ("scl_", "iec_", "lgf_", "core_", "fmi", "var_", "role_", "field_")


def field(name: str) -> str:
    """The C name of an SCL name: its own, unless C or the generated code has it already."""
    clash = (
        name in C_KEYWORDS
        or name in C_NAMES
        or C_MACRO.fullmatch(name)
        or name.lower().startswith(C_PREFIXES)
    )
    return name + "_" if clash else name


STATIC_SECTIONS = ("VAR", "VAR RETAIN", "VAR NON_RETAIN")
SECTIONS_IN_STRUCT = ("VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT", *STATIC_SECTIONS)


def is_table(d) -> bool:
    """An ARRAY[*] VAR_IN_OUT: a table of tunable parameters with its size (docs/scl.md §4)."""
    return isinstance(d.type, T.ArrayType) and d.type.dims is None


def real_literal(value: float, t: T.Elementary) -> str:
    text = repr(float(value))
    if text in ("inf", "-inf", "nan"):
        raise ValueError(text)
    if "." not in text and "e" not in text:
        text += ".0"
    return text + ("f" if t.name == "REAL" else "")


def c_decl(name: str, t) -> str:
    """The C declaration of a field or local name of type t: ARRAY[1..3, 0..1] OF INT is
    int16_t name[3][2], an ARRAY[*] its table of T.TABLE_CAPACITY elements."""
    if isinstance(t, T.ArrayType):
        sizes = (T.TABLE_CAPACITY,) if t.dims is None else t.sizes
        return c_decl(name, t.element) + "".join(f"[{n}]" for n in sizes)
    if isinstance(t, T.FbType) and t.block is not None:  # a user FB's instance
        return f"{struct_of(t.block)} {name}"
    return f"{t.c} {name}"


def zero(t) -> str:
    return "false" if t.kind == "bool" else f"(({t.c})0)"


def element_indices(sizes):
    """The C subscripts of every element of an array of these sizes, in S7's order (the last
    index runs fastest)."""
    if not sizes:
        return [""]
    return [f"[{i}]{rest}" for i in range(sizes[0]) for rest in element_indices(sizes[1:])]


def scl_indices(t: T.ArrayType):
    """The SCL indices of every element, as the FMI names write them: [1], [1,0], ..."""
    dims = ((0, T.TABLE_CAPACITY - 1),) if t.dims is None else t.dims

    def walk(k):
        if k == len(dims):
            return [()]
        lo, hi = dims[k]
        return [(i, *rest) for i in range(lo, hi + 1) for rest in walk(k + 1)]

    return ["[" + ",".join(map(str, ix)) + "]" for ix in walk(0)]


def leaves(path: str, name: str, t):
    """(C path, FMI name, elementary type) of every scalar an ARRAY or STRUCT holds."""
    if isinstance(t, T.ArrayType):
        sizes = (T.TABLE_CAPACITY,) if t.dims is None else t.sizes
        return [
            leaf
            for sub, ix in zip(element_indices(sizes), scl_indices(t))
            for leaf in leaves(path + sub, name + ix, t.element)
        ]
    if isinstance(t, T.StructType):
        return [
            leaf
            for key, (m, _) in t.members.items()
            for leaf in leaves(f"{path}.{field(key)}", f"{name}.{key}", m)
        ]
    return [(path, name, t)]


def overlay(default, given):
    """An initial value given over a member's default: a STRUCT's members and an ARRAY's
    elements that the given value leaves out keep the default's (docs/scl.md §3.8)."""
    if given is None:
        return default
    if isinstance(default, dict) and isinstance(given, dict):
        return {**default, **{k: overlay(default.get(k), v) for k, v in given.items()}}
    if isinstance(default, list) and isinstance(given, list):
        merged = [overlay(d, g) for d, g in zip(default, given)]
        return merged + given[len(default) :] + default[len(given) :]
    return given


def prefix_of(checker) -> str:
    """The C prefix of a block's functions and types: scl_<fb> for an FB, scl_FC_<fc> for an FC
    (upper case, so that no FB's lower-case prefix meets it)."""
    name = checker.block.name.lower()
    return f"scl_FC_{name}" if checker.fc else f"scl_{name}"


def struct_of(checker) -> str:
    return prefix_of(checker) + ("_frame" if checker.fc else "_block")


# startDateAndTime (docs/scl.md §3.6): 2024-01-01 00:00 UTC by default, up to 2262-01-01 (the
# DTL's range ends in 2262)
START_DATE_AND_TIME = 1704067200.0
START_DATE_AND_TIME_MAX = 9214646400.0
LOCAL_SECTIONS = ("VAR_TEMP", "VAR CONSTANT")


class Generator:
    def __init__(self, checker, source_text: str, main=None):
        self.block = checker.block
        self.checker = checker
        self.source_text = source_text
        self.prefix = prefix_of(checker)
        self.struct = struct_of(checker)
        self.me = "f" if checker.fc else "b"  # the pointer to the block's data in its C
        self.temps = 0
        self.helpers: dict[str, list[str]] = {}  # MUX functions by name, written before the block
        self.program = checker.program
        self.main = main or checker
        self.index_temps: list[str] = []  # the int64_t of the run-time indices of a function
        self.known: dict = {}  # id of a VarRef -> its place, while a compound assignment reads it

    # Expressions: C text of the value of e in the C type of e.type

    def convert(self, code: str, source, target) -> str:
        source, target = T.concrete(source), T.concrete(target)
        if source == target:
            return code
        if target.kind == "bool":
            return f"({code} != 0)"
        if target.kind == "real":
            return f"(({target.c}){code})"
        if source.kind == "real":  # *_TO_<integer>: rounded (docs/scl.md §3.3)
            if target.bits == 64 and not target.signed:
                return f"scl_limit_round_u64({code}, false)"
            low, high = self.limits(target)
            return f"(({target.c})scl_limit_round({code}, {low}, {high}, false))"
        if source.kind == target.kind == "time":  # TIME (ms) <-> LTIME (ns)
            if target.bits == 64:
                return f"((int64_t){code} * 1000000)"
            return self.wrap(f"scl_div64((int64_t){code}, 1000000)", target)
        return self.wrap(f"(int64_t){code}", target)

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

    def literal(self, e: A.Literal) -> str:
        t = T.concrete(e.type)
        if t.kind == "bool":
            return "true" if e.value else "false"
        if t.kind == "real":
            return real_literal(e.value, t)
        value = int(e.value)
        if value == -(1 << 31):
            return "INT32_MIN"
        if value == -(1 << 63):
            return "INT64_MIN"
        return f"(({t.c}){value}{'u' if not t.signed and value > 0x7FFFFFFF else ''})"

    def ref(self, e: A.VarRef) -> str:
        """The value of a variable; an element at a run-time index outside the ARRAY's bounds
        reads 0 (docs/scl.md §3.8: Decision)."""
        code, conditions, bit = self.place(e)
        if bit is not None:
            n, _ = bit
            code = f"((((uint64_t){code}) >> {n}) & 1u) != 0"
            if not conditions:
                return f"({code})"
        if conditions:
            return f"({' && '.join(conditions)} ? {code} : {zero(e.type)})"
        return code

    def place(self, e: A.VarRef):
        """(C lvalue, the run-time index conditions under which it exists, (bit, type) of a
        .%X access or None)."""
        d = e.decl
        known = self.known.get(id(e))
        if known is not None:  # the target of a compound assignment, read in its value
            return known
        if d.section == "RETURN":
            return f"{self.me}->scl_return", [], None
        base = field(d.name) if d.section in LOCAL_SECTIONS else f"{self.me}->{field(d.name)}"
        if d.db and self.block is not self.program.top:  # docs/scl.md §3.9: the top FB's static
            top = struct_of(self.program.top_checker)
            base = f"(({top} *)ctx->top)->{field(d.name)}"
        path = e.path
        if path is None:  # an FB instance's or a DTL's member
            members = e.members
            if isinstance(d.type, T.FbType) and d.type.block is not None:
                names = d.type.block.names
                members = [field(names[m.lower()].name) for m in members]
            return base + "".join("." + m for m in members), [], None
        conditions, assigns, bit = [], [], None
        for step in path:
            if step[0] == "member":
                base += "." + field(step[1])
            elif step[0] == "index":
                _, exprs, t = step
                for i, x in enumerate(exprs):
                    if t.dims is None:
                        lo = 0
                        count = f"{self.me}->{field(T.table_count(d.name))}"
                        hi = f"scl_count({count}, {T.TABLE_CAPACITY}) - 1"
                    else:
                        lo, hi = t.dims[i]
                    if isinstance(x, A.Literal) and t.dims is not None:
                        base += f"[{int(x.value) - lo}]"  # checked against the bounds
                        continue
                    # the index once, in a temporary of the function: the bounds check and the
                    # subscript both read it (an FC with outputs in it runs once)
                    self.temps += 1
                    index = f"scl_index_{self.temps}"
                    self.index_temps.append(index)
                    assigns.append(f"{index} = (int64_t){self.expr(x)}")
                    conditions.append(f"scl_in({index}, {lo}, {hi})")
                    base += f"[scl_at({index}, {lo}, {hi})]"
            else:
                bit = (step[1], step[2])
        if assigns:  # every index is evaluated, in order, before any bound is checked
            conditions = [f"({', '.join(assigns)}, {' && '.join(conditions)})"]
        return base, conditions, bit

    def unary(self, e: A.Unary) -> str:
        t = T.concrete(e.type)
        x = self.expr(e.operand, t)
        if e.op == "NOT":
            return f"(!{x})" if t.kind == "bool" else f"(({t.c})~{x})"
        if t.kind == "real":
            return f"(-{x})"
        if t.bits == 64:
            return f"(({t.c})(UINT64_C(0) - (uint64_t){x}))"
        return self.wrap(f"-(int64_t){x}", t)

    def binary(self, e: A.Binary) -> str:
        t = T.concrete(e.operand_type)
        op = e.op
        if op == "**":  # EXPT: pow of double, a REAL result rounded to float (docs/scl.md §3.5)
            base = self.expr(e.left, T.LREAL)
            exponent = self.expr(e.right, T.LREAL)
            return f"(({t.c})pow({base}, {exponent}))"
        if t.kind == "time" and op in ("*", "/"):
            a, b = self.expr(e.left, t), self.expr(e.right, T.LINT if t.bits == 64 else T.DINT)
        else:
            a, b = self.expr(e.left, t), self.expr(e.right, t)
        if op in ("=", "<>", "<", ">", "<=", ">="):
            c_op = {"=": "==", "<>": "!="}.get(op, op)
            return f"({a} {c_op} {b})"
        if op in ("AND", "OR", "XOR"):
            if t.kind == "bool":
                return f"({a} {({'AND': '&&', 'OR': '||', 'XOR': '!='})[op]} {b})"
            return f"(({t.c})({a} {({'AND': '&', 'OR': '|', 'XOR': '^'})[op]} {b}))"
        if t.kind == "real":
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
            return f"(({t.c})((uint64_t){a} {op} (uint64_t){b}))"
        if op == "/":
            body = f"scl_div((int64_t){a}, (int64_t){b})"
        elif op == "MOD":
            body = f"scl_mod((int64_t){a}, (int64_t){b})"
        else:
            body = f"({wide}){a} {op} ({wide}){b}"
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
        ins = [d for d in fc.block.decls if d.section == "VAR_INPUT"]
        args = ["ctx"] + [self.expr(v, d.type) for v, d in zip(c.inputs, ins)]
        args += [self.address(t) if t is not None else "NULL" for t in c.outputs]
        return f"{prefix_of(fc)}({', '.join(args)})"

    def address(self, target: A.VarRef) -> str:
        """Where an FC's output goes (checks.py refuses a bit): NULL, the output not given, for
        an element at an index outside its ARRAY, as a write there is ignored."""
        code, conditions, _ = self.place(target)
        if conditions:
            return f"({' && '.join(conditions)} ? &{code} : NULL)"
        return f"&{code}"

    # Statements

    def statements(self, body, indent) -> list[str]:
        lines = []
        for s in body:
            lines += self.statement(s, indent)
        return lines

    def statement(self, s: A.Stmt, indent: int) -> list[str]:
        pad = "    " * indent
        if isinstance(s, A.Assign):
            if not isinstance(s.target.type, T.Elementary):  # a whole STRUCT or ARRAY
                return self.copy(s.target, s.value, pad)
            if isinstance(s.value, A.Binary) and s.value.left is s.target:  # a[i] += ...
                return self.compound(s, pad)
            return self.store(s.target, self.expr(s.value, s.target.type), pad)
        if isinstance(s, A.CallStmt):
            return self.call_statement(s.call, pad)
        if isinstance(s, A.If):
            lines = []
            for i, (condition, body) in enumerate(s.branches):
                head = "if" if i == 0 else "} else if"
                lines.append(f"{pad}{head} ({self.expr(condition, T.BOOL)}) {{")
                lines += self.statements(body, indent + 1)
            if s.otherwise:
                lines.append(f"{pad}}} else {{")
                lines += self.statements(s.otherwise, indent + 1)
            lines.append(f"{pad}}}")
            return lines
        if isinstance(s, A.Case):
            # an if chain, not a C switch: EXIT in a branch leaves the loop around the CASE
            self.temps += 1
            selector = f"scl_selector_{self.temps}"
            wide = "uint64_t" if s.selector.type.name in ("ULINT", "LWORD") else "int64_t"
            lines = [f"{pad}{{", f"{pad}    const {wide} {selector} = {self.expr(s.selector)};"]
            for i, (labels, body) in enumerate(s.branches):
                tests = " || ".join(
                    self.label_test(selector, s.selector.type, low, high) for low, high in labels
                )
                lines.append(f"{pad}    {'if' if i == 0 else '} else if'} ({tests}) {{")
                lines += self.statements(body, indent + 2)
            if s.otherwise:
                lines.append(f"{pad}    }} else {{")
                lines += self.statements(s.otherwise, indent + 2)
            if s.branches:
                lines.append(f"{pad}    }}")
            lines.append(f"{pad}}}")
            return lines
        if isinstance(s, A.For):
            self.temps += 1
            n = self.temps
            t = s.variable.type
            v = self.ref(s.variable)
            step = self.expr(s.step, t) if s.step is not None else "1"
            end, by, more = f"scl_end_{n}", f"scl_by_{n}", f"scl_more_{n}"
            lines = [
                f"{pad}{{",
                f"{pad}    const int64_t {end} = {self.expr(s.end, t)};",
                f"{pad}    const int64_t {by} = {step};",
                f"{pad}    bool {more} = true;",
                # docs/scl.md §3.4: the end and the step are evaluated once; the variable
                # is never stepped past the end, so a loop up to the type's limit ends
                f"{pad}    for ({v} = {self.expr(s.start, t)};",
                f"{pad}         {more} && ({by} >= 0 ? {v} <= {end} : {v} >= {end});",
                f"{pad}         {more} = {by} >= 0 ? (int64_t){v} + {by} <= {end}"
                f" : (int64_t){v} + {by} >= {end},",
                f"{pad}         {v} = {more} ? ({t.c})((int64_t){v} + {by}) : {v}) {{",
            ]
            lines += self.statements(s.body, indent + 2)
            lines += [f"{pad}    }}", f"{pad}}}"]
            return lines
        if isinstance(s, A.While):
            lines = [f"{pad}while ({self.expr(s.condition, T.BOOL)}) {{"]
            return lines + self.statements(s.body, indent + 1) + [f"{pad}}}"]
        if isinstance(s, A.Repeat):
            lines = [f"{pad}do {{"]
            lines += self.statements(s.body, indent + 1)
            return lines + [f"{pad}}} while (!{self.expr(s.condition, T.BOOL)});"]
        if isinstance(s, A.Jump):
            return [
                f"{pad}{ {'EXIT': 'break', 'CONTINUE': 'continue', 'RETURN': 'return'}[s.kind] };"
            ]
        if isinstance(s, A.Region):
            title = f"/* REGION {c_comment(s.title)} */"
            return [pad + title] + self.statements(s.body, indent)
        raise AssertionError(s)

    def store(self, target: A.VarRef, value: str, pad: str, place=None) -> list[str]:
        """target := value; at a run-time index outside the bounds the write is ignored
        (docs/scl.md §3.8: Decision); a .%X bit is set or cleared in its bit string."""
        code, conditions, bit = place or self.place(target)
        lines = []
        if conditions:  # the indices, then the value, each once, even where the write is ignored
            self.temps += 1
            ok, v = f"scl_ok_{self.temps}", f"scl_value_{self.temps}"
            lines = [
                f"{pad}{{",
                f"{pad}    const bool {ok} = {' && '.join(conditions)};",
                f"{pad}    const {target.type.c} {v} = {value};",
            ]
            value = v
        if bit is not None:
            n, t = bit
            mask = f"(UINT64_C(1) << {n})"
            value = (
                f"(({t.c})(((uint64_t){code} & ~{mask}) | ((uint64_t)({value} ? 1u : 0u) << {n})))"
            )
        line = f"{code} = {value};"
        if not conditions:
            return [pad + line]
        return lines + [f"{pad}    if ({ok}) {line}", f"{pad}}}"]

    def compound(self, s: A.Assign, pad: str) -> list[str]:
        """target op= value: the target's indices are evaluated once, for the write and for the
        read of its value, which happens where the write's bounds hold (docs/scl.md §3.8)."""
        code, conditions, bit = self.place(s.target)
        self.known[id(s.target)] = (code, [], bit)
        try:
            value = self.expr(s.value, s.target.type)
        finally:
            del self.known[id(s.target)]
        return self.store(s.target, value, pad, (code, conditions, bit))

    def copy(self, target: A.VarRef, source: A.VarRef, pad: str) -> list[str]:
        """A STRUCT or ARRAY assigned whole (the same type, docs/scl.md §3.8): copied; a source
        element outside its ARRAY's bounds copies as 0."""
        to, to_conditions, _ = self.place(target)
        what, conditions, _ = self.place(source)
        inner = [f"memcpy(&{to}, &{what}, sizeof {to});"]
        if conditions:
            inner = [
                f"if ({' && '.join(conditions)}) {{",
                "    " + inner[0],
                "} else {",
                f"    memset(&{to}, 0, sizeof {to});",
                "}",
            ]
        if not to_conditions:
            return [pad + line for line in inner]
        return (
            [f"{pad}if ({' && '.join(to_conditions)}) {{"]
            + [f"{pad}    {line}" for line in inner]
            + [f"{pad}}}"]
        )

    @staticmethod
    def label_test(selector: str, t: T.Elementary, low: int, high: int) -> str:
        """A CASE label low..high as C: a bound at the type's own limit is left out (C warns of
        a comparison that is always true); a label beyond INT64_MAX is unsigned."""

        def c(value):
            return f"{value}u" if value > (1 << 63) - 1 else str(value)

        if low == high:
            return f"{selector} == {c(low)}"
        tests = [f"{selector} >= {c(low)}"] if low > t.low else []
        tests += [f"{selector} <= {c(high)}"] if high < t.high else []
        return f"({' && '.join(tests)})" if tests else "true"

    def call_statement(self, c: A.Call, pad: str) -> list[str]:
        if c.instance is None:
            return [f"{pad}(void){self.expr(c)};"]
        inst = self.ref(c.instance)
        fb = c.fb
        names = fb.block.names if fb.block is not None else None
        member = (lambda n: field(names[n.lower()].name)) if names else (lambda n: n)  # noqa: E731
        lines = [
            f"{pad}{inst}.{member(name)} = {self.expr(v, fb.inputs[name])};" for name, v in c.inputs
        ]
        if fb.block is not None:  # a user FB: its instance in the caller's data (multi-instance)
            lines.append(f"{pad}{prefix_of(fb.block)}_call(&{inst}, ctx);")
        elif fb.timed:
            lines.append(f"{pad}{fb.call}(&{inst}, call);")
        else:
            lines.append(f"{pad}{fb.call}(&{inst});")
        for name, target in c.outputs:
            lines += self.store(
                target,
                self.convert(f"{inst}.{member(name)}", fb.outputs[name], target.type),
                pad,
            )
        return lines

    # Files

    def struct_fields(self) -> list[str]:
        lines = []
        groups = [("inputs", ("VAR_INPUT",)), ("outputs", ("VAR_OUTPUT",))]
        if not self.checker.fc:
            groups += [("in/outs", ("VAR_IN_OUT",)), ("statics", STATIC_SECTIONS)]
        for title, sections in groups:
            decls = [d for d in self.block.decls if d.section in sections]
            if decls:
                lines.append(f"    /* {title} */")
            for d in decls:
                comment = f" /* {c_comment(d.comment)} */" if d.comment else ""
                if is_table(d):  # the size the block sees, the FMU's structural parameter
                    lines.append(f"    int16_t {field(T.table_count(d.name))};")
                lines.append(f"    {c_decl(field(d.name), d.type)};{comment}")
        if self.checker.return_type is not None:
            lines.append(f"    {self.checker.return_type.c} scl_return; /* the return value */")
        if self.checker is self.main and self.program.uses_date:
            lines += [
                "    /* the parameters of RD_SYS_T, RD_LOC_T (docs/scl.md §3.6) */",
                "    double scl_start_s;",
                "    iec_time scl_local_ms;",
            ]
        return lines or ["    bool unused; /* a block without variables */"]

    def init_value(self, d: A.VarDecl) -> str:
        return self.expr(d.init, d.type) if d.init is not None else None

    def init_lines(self, path: str, t, init, pad="    ") -> list[str]:
        """The assignments that give path of type t its initial value: the declaration's (init),
        else a UDT's or STRUCT's member defaults; everything else stays 0 (memset)."""
        if isinstance(t, T.Elementary):
            if init is None:
                return []
            return [f"{pad}{path} = {self.expr(init, t)};"]
        if isinstance(t, T.StructType):
            lines = []
            for key, (m, default) in t.members.items():
                given = (init or {}).get(key)
                lines += self.init_lines(f"{path}.{field(key)}", m, overlay(default, given), pad)
            return lines
        sizes = (T.TABLE_CAPACITY,) if t.dims is None else t.sizes
        values = init or []
        lines = []
        subscripts = element_indices(sizes)
        for sub, value in zip(subscripts, values):
            lines += self.init_lines(path + sub, t.element, value, pad)
        rest = subscripts[len(values) :]
        defaults = self.init_lines("e", t.element, None, "")
        if rest and defaults:  # the UDT's defaults in every element not given
            self.temps += 1
            k = f"scl_k_{self.temps}"
            first = len(values)
            total = len(subscripts)
            index, stride = "", total
            for n in sizes:
                stride //= n
                index += f"[({k} / {stride}) % {n}]"
            lines.append(f"{pad}for (size_t {k} = {first}; {k} < {total}; {k}++) {{")
            lines += self.init_lines(path + index, t.element, None, pad + "    ")
            lines.append(f"{pad}}}")
        return lines

    def declarations(self) -> list[str]:
        """The block's type and prototypes, for block.h."""
        lines = ["typedef struct {", *self.struct_fields(), f"}} {self.struct};", ""]
        if self.checker.fc:
            ins = [d for d in self.block.decls if d.section == "VAR_INPUT"]
            outs = [d for d in self.block.decls if d.section == "VAR_OUTPUT"]
            params = ["const scl_context *ctx"]
            params += [f"{d.type.c} {field(d.name)}" for d in ins]
            params += [f"{d.type.c} *{field(d.name)}" for d in outs]
            ret = self.checker.return_type.c if self.checker.return_type else "void"
            lines.append(f"static {ret} {self.prefix}({', '.join(params)});")
            lines.append(
                f"static void {self.prefix}_body({self.struct} *f, const scl_context *ctx);"
            )
        else:
            lines.append(f"static void {self.prefix}_init({self.struct} *b);")
            lines.append(
                f"static void {self.prefix}_call({self.struct} *b, const scl_context *ctx);"
            )
        return lines + [""]

    def locals_(self) -> list[str]:
        """The VAR_TEMP and VAR CONSTANT of a call: they start again in every call."""
        body = []
        for d in self.block.decls:
            if d.section in LOCAL_SECTIONS:
                name = field(d.name)
                if d.type is T.DTL:
                    body.append(f"    scl_dtl {name} = scl_dtl_of(0);")
                    continue
                if not isinstance(d.type, T.Elementary):
                    # a VAR_TEMP starts at its declared value or 0 in every call (docs/scl.md §4)
                    body.append(f"    {c_decl(name, d.type)};")
                    body.append(f"    memset(&{name}, 0, sizeof {name});")
                    body += self.init_lines(name, d.type, d.init)
                    continue
                const = "const " if d.section == "VAR CONSTANT" else ""
                value = self.init_value(d) or ("false" if d.type.kind == "bool" else "0")
                # a VAR_TEMP starts at its declared value or 0 in every call (docs/scl.md §4)
                body.append(f"    {const}{d.type.c} {field(d.name)} = {value};")
        locals_ = [d.name for d in self.block.decls if d.section in LOCAL_SECTIONS]
        body += [f"    (void){field(n)};" for n in locals_]  # a temp may be set and never read
        return body

    def body(self) -> list[str]:
        """The C of a call: the temporaries of the run-time indices, the locals, the
        statements."""
        self.index_temps = []
        statements = self.statements(self.block.body, 1)
        temps = [f"    int64_t {t};" for t in self.index_temps]
        return temps + self.locals_() + statements

    def definitions(self) -> list[str]:
        """The block's functions, for block.c (its MUX helpers in self.helpers)."""
        head = ["    const plc_call *call = ctx->plc;", "    (void)call;", "    (void)ctx;"]
        if self.checker.fc:
            body = head + self.body()
            ins = [d for d in self.block.decls if d.section == "VAR_INPUT"]
            outs = [d for d in self.block.decls if d.section == "VAR_OUTPUT"]
            params = ["const scl_context *ctx"]
            params += [f"{d.type.c} {field(d.name)}" for d in ins]
            params += [f"{d.type.c} *{field(d.name)}" for d in outs]
            ret = self.checker.return_type
            # an FC has no instance data: its frame starts at 0 (and the outputs' declared
            # values) in every call, its outputs are copied out when it returns
            wrapper = [f"    {self.struct} f;", "    memset(&f, 0, sizeof f);"]
            for d in ins:
                wrapper.append(f"    f.{field(d.name)} = {field(d.name)};")
            for d in outs:
                if d.init is not None:
                    wrapper.append(f"    f.{field(d.name)} = {self.init_value(d)};")
            wrapper.append(f"    {self.prefix}_body(&f, ctx);")
            for d in outs:
                name = field(d.name)
                wrapper.append(f"    if ({name}) *{name} = f.{name};")
            if ret is not None:
                wrapper.append("    return f.scl_return;")
            return [
                f"static void {self.prefix}_body({self.struct} *f, const scl_context *ctx)",
                "{",
                *body,
                "}",
                "",
                f"static {ret.c if ret else 'void'} {self.prefix}({', '.join(params)})",
                "{",
                *wrapper,
                "}",
                "",
            ]
        init = ["    memset(b, 0, sizeof *b);"]
        for d in self.block.decls:
            if d.section in SECTIONS_IN_STRUCT:
                if isinstance(d.type, T.FbType) and d.type.block is not None:
                    init.append(f"    {prefix_of(d.type.block)}_init(&b->{field(d.name)});")
                elif d.type is T.DTL:
                    init.append(f"    b->{field(d.name)} = scl_dtl_of(0);")
                elif not isinstance(d.type, T.FbType):  # a system FB's instance starts at 0
                    if is_table(d):  # numberOf<Name>: the elements given, else all
                        count = len(d.init) if d.init is not None else T.TABLE_CAPACITY
                        init.append(f"    b->{field(T.table_count(d.name))} = {count};")
                    init += self.init_lines(f"b->{field(d.name)}", d.type, d.init)
        if self.checker is self.main and self.program.uses_date:
            init.append(f"    b->scl_start_s = {START_DATE_AND_TIME!r};")
        body = head + self.body()
        return [
            f"static void {self.prefix}_init({self.struct} *b)",
            "{",
            *init,
            "}",
            "",
            f"static void {self.prefix}_call({self.struct} *b, const scl_context *ctx)",
            "{",
            *body,
            "}",
            "",
        ]

    def variables(self) -> list[str]:
        rows = [
            '    CYCLE_TIME_ROW(1e-6, "none: the period of the calling OB",',
            '                   "Period of the calling OB: the block is called once per '
            'cycleTime; held in whole µs, 1 µs to 60 s"),',
        ]
        vr = 1
        for d in self.block.decls:
            if d.section not in ("VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT"):
                continue
            kind = {"VAR_INPUT": "input", "VAR_OUTPUT": "output"}.get(d.section, "in/out")
            if is_table(d):
                count = T.table_count(d.name)
                rows += self.row(
                    vr,
                    count,
                    field(count),
                    T.INT,
                    "ROLE_FIXED_PARAMETER",
                    f"The elements 0 to {count} - 1 of {d.name} that the block sees "
                    f"(1 to {T.TABLE_CAPACITY}); the others are ignored",
                    ("1", str(T.TABLE_CAPACITY)),
                )
                vr += 1
            if is_table(d):
                roles = [("ROLE_TUNABLE_PARAMETER", "")]
            elif d.section == "VAR_IN_OUT":  # an input and, as <name>_out(.member), an output
                roles = [("ROLE_INPUT", ""), ("ROLE_OUTPUT", "_out")]
            else:
                roles = [(f"ROLE_{kind.upper()}", "")]
            for role, suffix in roles:
                for path, name, t in leaves(field(d.name), d.name + suffix, d.type):
                    description = d.comment or f"{t.name} {kind} of the SCL block {self.block.name}"
                    if d.comment and not description.upper().startswith(t.name):
                        description = f"{t.name}: {description}"
                    rows += self.row(vr, name, path, t, role, description)
                    vr += 1
        if self.program.uses_date:
            rows += [
                f"    {{.vr = {vr},",
                '     .name = "startDateAndTime",',
                "     .type = VAR_LREAL,",
                "     .role = ROLE_FIXED_PARAMETER,",
                "     AT(block, scl_start_s),",
                "     .min = 0,",
                f"     .max = {START_DATE_AND_TIME_MAX!r},",
                '     .original = "none: the CPU\'s clock",',
                '     .description = "The date and time of the first call for RD_SYS_T, in s '
                "since 1970-01-01 00:00 (UTC); the CPU's clock runs with the simulated time "
                'from there (docs/scl.md §3.6)"},',
            ]
            vr += 1
        if self.program.uses_local:
            rows += [
                f"    {{.vr = {vr},",
                '     .name = "localTimeOffset",',
                "     .type = VAR_TIME,",
                "     .role = ROLE_FIXED_PARAMETER,",
                "     AT(block, scl_local_ms),",
                "     .min = -86400,",
                "     .max = 86400,",
                '     .original = "none: the CPU\'s time zone and daylight saving time",',
                '     .description = "Local time minus system time for RD_LOC_T: the time zone '
                'and daylight saving time of the CPU (docs/scl.md §3.6)"},',
            ]
            vr += 1
        for name, c_path, t, description in self.locals_of(self.checker, "", ""):
            rows += self.row(vr, name, c_path, t, "ROLE_LOCAL", description)
            vr += 1
        return rows

    def row(self, vr, name, path, t, role, description, limits=None) -> list[str]:
        low, high = limits or FMI_RANGE.get(t.name, (str(t.low), str(t.high)))
        return [
            f"    {{.vr = {vr},",
            f"     .name = {c_string(xml_name(name))},",
            f"     .type = {t.var},",
            f"     .role = {role},",
            f"     AT(block, {path}),",
            f"     .min = {low},",
            f"     .max = {high},",
            f"     .description = {c_string(xml_text(description))}}},",
        ]

    def locals_of(self, checker, name: str, c_path: str):
        """The FMI local variables (docs/scl.md §4): every elementary static, and the members of
        every instance, by their SCL path (m.speed, m.edge.Q, now.YEAR), read-only."""
        for d in checker.block.decls:
            if d.section not in STATIC_SECTIONS:
                continue
            n, c = name + d.name, c_path + field(d.name)
            t = d.type
            if isinstance(t, T.FbType) and t.block is not None:
                for sub in t.block.block.decls:
                    if sub.section in ("VAR_INPUT", "VAR_OUTPUT"):
                        what = "input" if sub.section == "VAR_INPUT" else "output"
                        yield (
                            f"{n}.{sub.name}",
                            f"{c}.{field(sub.name)}",
                            sub.type,
                            f"{sub.type} {what} {sub.name} of the {t.name} instance {n}",
                        )
                yield from self.locals_of(t.block, n + ".", c + ".")
            elif isinstance(t, T.FbType) or t is T.DTL:
                members = {**t.inputs, **t.outputs} if t is not T.DTL else T.DTL_MEMBERS
                for m, e in members.items():
                    yield f"{n}.{m}", f"{c}.{m}", e, f"{e} {m} of the {t.name} {n}"
            else:  # every scalar of an ARRAY or STRUCT, by its SCL name (a[1].b, docs/scl.md §4)
                for path, leaf_name, leaf in leaves(c, n, t):
                    if leaf.var in self.checker.core_vars:  # a 64-bit one has no FMI variable
                        what = d.comment or f"{leaf.name} static of {checker.block.name}"
                        yield leaf_name, path, leaf, what

    def statics(self) -> tuple[list[str], list[str]]:
        """The rows of the FMU state: every static, every member of every instance (a user FB's
        instance with its own statics and instances, recursively), and the checks of a restored
        instance."""
        rows, checks = [], []

        def walk(checker, path: str):
            for d in checker.block.decls:
                if d.section not in STATIC_SECTIONS:
                    continue
                name = path + field(d.name)
                t = d.type
                if isinstance(t, T.FbType) and t.block is not None:
                    for sub in t.block.block.decls:
                        if sub.section in ("VAR_INPUT", "VAR_OUTPUT"):
                            rows.append(
                                f"    STATIC(block, {name}.{field(sub.name)}, {sub.type.field}),"
                            )
                    walk(t.block, name + ".")
                elif isinstance(t, T.FbType):
                    parts = [(m, e.field) for m, e in {**t.inputs, **t.outputs}.items()]
                    parts += list(t.memory)
                    rows.extend(f"    STATIC(block, {name}.{p}, {f})," for p, f in parts)
                    checks.append(f"{t.valid}(&b->{name})")
                elif t is T.DTL:
                    rows.extend(
                        f"    STATIC(block, {name}.{m}, {e.field}),"
                        for m, e in T.DTL_MEMBERS.items()
                    )
                else:  # every scalar of an ARRAY or STRUCT (docs/scl.md §4)
                    for leaf, _, t in leaves(name, d.name, d.type):
                        rows.append(f"    STATIC(block, {leaf}, {t.field}),")

        walk(self.checker, "")
        return rows, checks

    def interface_c(self) -> str:
        rows, checks = self.statics()
        guid = uuid.uuid5(uuid.NAMESPACE_URL, "lgf-fmus-scl:" + self.source_text)
        title = self.block.headers.get("TITLE", "")
        description = (
            f"{self.block.name}, compiled from SCL by lgf-fmus"
            + (f": {title}" if title else "")
            + ". One PLC call every cycleTime."
        )
        if checks:
            check = [
                "static const char *check(const void *data, char *msg, size_t size)",
                "{",
                "    const block *b = data;",
                f"    if ({' && '.join(checks)}) return NULL;",
                "    snprintf(msg, size, "
                + c_format(f"an FB instance of {self.block.name} lies outside any run")
                + ");",
                "    return msg;",
                "}",
                "",
            ]
        else:
            check = []
        if not rows:
            rows = ["    {NULL, FIELD_BOOL, 0}, /* no static */"]
        static_count = (
            "sizeof statics / sizeof statics[0]"
            if checks or any("STATIC" in r for r in rows)
            else "0"
        )
        return "\n".join(
            [
                f"/* {c_comment(self.block.name)}: its interface table, generated by lgf_fmus.scl"
                " from its",
                " * SCL (docs/scl.md §4): VAR_INPUT -> inputs, VAR_OUTPUT -> outputs, the statics",
                " * in the FMU state. */",
                "#include <math.h>",
                "#include <stdio.h>",
                "",
                f'#include "blocks/{self.block.name}/block.c"',
                '#include "core/model.h"',
                "",
                f"typedef {self.struct} block;",
                "",
                "static const model_variable variables[] = {",
                *self.variables(),
                "};",
                "",
                f"static void init(void *data) {{ {self.prefix}_init(data); }}",
                "",
                "static void call(void *data, const plc_call *plc)",
                "{",
                "    block *b = data;",
                "    const scl_context ctx = {plc, "
                + ("b->scl_start_s, b->scl_local_ms" if self.program.uses_date else "0, 0")
                + ", b};",
                f"    {self.prefix}_call(b, &ctx);",
                "}",
                "",
                *check,
                "static const model_static statics[] = {",
                *rows,
                "};",
                "",
                "static const model lgf_model = {",
                f"    .identifier = {c_string(xml_name(self.block.name))},",
                f'    .guid = "{{{guid}}}",',
                f"    .description = {c_string(xml_text(description))},",
                "    .stop_time = 10,",
                "    .variables = variables,",
                "    .variable_count = sizeof variables / sizeof variables[0],",
                "    .statics = statics,",
                f"    .static_count = {static_count},",
                "    .data_size = sizeof(block),",
                "    .cycle_granularity_us = 1,",
                "    .cycle_codes = NULL,",
                "    .init = init,",
                "    .call = call,",
                f"    .check = {'check' if checks else 'NULL'},",
                "    .status = NULL,",
                "    .status_text = NULL,",
                "};",
                "",
            ]
        )


def documentation(checker) -> str:
    """documentation/index.html of the FMU: the FB's title and headers, and its interface from
    the declarations and their comments (docs/scl.md §4)."""
    block = checker.block
    e = html_text
    rows = [
        "<tr><td><code>cycleTime</code></td><td>parameter</td><td>REAL, s</td><td>0.1</td>"
        "<td>period of the calling OB: one call of the FB per cycleTime</td></tr>"
    ]
    for d in block.decls:
        if d.section not in ("VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT"):
            continue
        causality = {"VAR_INPUT": "input", "VAR_OUTPUT": "output"}.get(d.section)
        if d.section == "VAR_IN_OUT":  # docs/scl.md §4
            causality = (
                f"tunable parameters {d.name}[i], their number {T.table_count(d.name)}"
                if is_table(d)
                else f"input, and output {d.name}_out"
            )
        causality = e(causality)
        start = e(d.init.text) if isinstance(d.init, A.Literal) else ""
        rows.append(
            f"<tr><td><code>{e(d.name)}</code></td><td>{causality}</td><td>{e(str(d.type))}</td>"
            f"<td>{start}</td><td>{e(d.comment)}</td></tr>"
        )
    statics = [d.name for d in block.decls if d.section in ("VAR", "VAR RETAIN", "VAR NON_RETAIN")]
    headers = "".join(
        f"<li>{e(k.title())}: {e(v)}</li>" for k, v in block.headers.items() if k != "TITLE"
    )
    title = block.headers.get("TITLE", "")
    return "\n".join(
        [
            "<!DOCTYPE html>",
            f'<html lang="en"><head><meta charset="utf-8"/><title>{e(block.name)}</title></head>',
            "<body>",
            f"<h1>{e(block.name)}</h1>",
            f"<p>{e(title)}</p>" if title else "",
            f"<ul>{headers}</ul>" if headers else "",
            "<p>Compiled from its SCL by lgf-fmus (docs/scl.md): the FUNCTION_BLOCK runs once per "
            "<code>cycleTime</code> with S7-1500 semantics, the first call at the start time.</p>",
            "<h2>Interface</h2>",
            "<table><tr><th>name</th><th>causality</th><th>type</th><th>start</th>"
            "<th>description</th></tr>",
            *rows,
            "</table>",
            f"<p>Statics (in the FMU state, and FMI local variables to read): "
            f"{e(', '.join(statics))}.</p>"
            if statics
            else "",
            "</body></html>",
            "",
        ]
    )


def typedefs(structs) -> list[str]:
    """The C of every UDT and STRUCT of the program, inner ones first (docs/scl.md §3.8)."""
    lines = []
    for t in structs:
        lines.append(f"/* {c_comment(str(t))} */" if t.name else "/* an anonymous STRUCT */")
        lines.append("typedef struct {")
        lines += [f"    {c_decl(field(k), m)};" for k, (m, _) in t.members.items()]
        lines += [f"}} {t.c};", ""]
    return lines


def generate(checker, source_text: str) -> dict[str, str]:
    """The generated files, by their path under the FMU's sources/: the FB, with every FB and FC
    it uses before it (callees first) in the same block.h and block.c."""
    main = checker
    name = main.block.name
    gens = [Generator(c, source_text, main) for c in main.program.order]
    g = gens[-1]
    assert g.checker is main
    guard = f"SCL_{name.upper()}_H"
    header = [
        f"/* {c_comment(name)}: generated by lgf_fmus.scl from its SCL (docs/scl.md §4). */",
        f"#ifndef {guard}",
        f"#define {guard}",
        "",
        '#include "scl/scl.h"',
        "",
        *typedefs(main.program.structs),
    ]
    for each in gens:
        header += each.declarations()
    header += ["#endif", ""]
    bodies = []
    for each in gens:
        bodies += each.definitions()
    helpers: dict[str, list[str]] = {}
    for each in gens:
        helpers.update(each.helpers)  # one function per MUX shape for the whole program
    helper_lines = [line for lines in helpers.values() for line in lines]
    block_c = [f'#include "blocks/{name}/block.h"', "", "#include <string.h>", ""]
    return {
        f"blocks/{name}/block.h": "\n".join(header),
        f"blocks/{name}/block.c": "\n".join(block_c + helper_lines + bodies),
        f"blocks/{name}/interface.c": g.interface_c(),
    }
