"""C generation (docs/scl.md §4): from a checked FUNCTION_BLOCK, exactly what a hand-written block
of src/blocks/ is: block.h (the struct of inputs, outputs and statics, the init and the call),
block.c, and interface.c (the model_variable table, the statics of the FMU state, lgf_model) onto
src/core/model.h, src/iec/ and the SCL runtime runtime/scl/scl.h. Every name of the SCL keeps its
spelling as a C field; every S7 operation becomes the C of its rule in docs/scl.md §3."""

from __future__ import annotations

import html
import json
import re
import uuid

from . import ast as A
from . import types as T

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


def c_string(text: str) -> str:
    return json.dumps(text, ensure_ascii=False)


def concrete(t):
    if isinstance(t, T.Untyped):
        return T.DINT if t.kind == "int" else T.LREAL
    return t


def real_literal(value: float, t: T.Elementary) -> str:
    text = repr(float(value))
    if text in ("inf", "-inf", "nan"):
        raise ValueError(text)
    if "." not in text and "e" not in text:
        text += ".0"
    return text + ("f" if t.name == "REAL" else "")


def prefix_of(checker) -> str:
    """The C prefix of a block's functions and types: scl_<fb> for an FB, scl_FC_<fc> for an FC
    (upper case, so that no FB's lower-case prefix meets it)."""
    name = checker.block.name.lower()
    return f"scl_FC_{name}" if checker.fc else f"scl_{name}"


def struct_of(checker) -> str:
    return prefix_of(checker) + ("_frame" if checker.fc else "_block")


STATIC_SECTIONS = ("VAR", "VAR RETAIN", "VAR NON_RETAIN")
# startDateAndTime (docs/scl.md §3.6): 2024-01-01 00:00 UTC by default, up to 2262-01-01 (the
# DTL's range ends in 2262)
START_DATE_AND_TIME = 1704067200.0
START_DATE_AND_TIME_MAX = 9214646400.0
LOCAL_SECTIONS = ("VAR_TEMP", "VAR CONSTANT")
# the C of the REAL and LREAL functions (docs/scl.md §3.5): a REAL's in double, then rounded to
# float; SIN and COS of a REAL are the signal generators' (iec/sin_cos.h)
C_MATH = {"TAN": "tan", "ASIN": "asin", "ACOS": "acos", "ATAN": "atan", "EXP": "exp"}
C_MATH.update({"LN": "log", "LOG": "log10", "SIN": "sin", "COS": "cos"})


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

    # Expressions: C text of the value of e in the C type of e.type

    def convert(self, code: str, source, target) -> str:
        source, target = concrete(source), concrete(target)
        if source == target:
            return code
        if target.kind == "bool":
            return f"({code} != 0)"
        if target.kind == "real":
            return f"(({target.c}){code})"
        if source.kind == "real":  # *_TO_<integer>: rounded (docs/scl.md §3.3)
            return f"(({target.c})scl_limit_round({code}, {target.low}, {target.high}, false))"
        return self.wrap(f"(int64_t){code}", target)

    def wrap(self, code: str, t: T.Elementary) -> str:
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
        t = concrete(e.type)
        if t.kind == "bool":
            return "true" if e.value else "false"
        if t.kind == "real":
            return real_literal(e.value, t)
        value = int(e.value)
        if value == -(1 << 31):
            return "INT32_MIN"
        return f"(({t.c}){value}{'u' if not t.signed and value > 0x7FFFFFFF else ''})"

    def ref(self, e: A.VarRef) -> str:
        d = e.decl
        if d.section == "RETURN":
            return f"{self.me}->scl_return"
        base = field(d.name) if d.section in LOCAL_SECTIONS else f"{self.me}->{field(d.name)}"
        members = e.members
        if isinstance(d.type, T.FbType) and d.type.block is not None:
            names = d.type.block.names
            members = [field(names[m.lower()].name) for m in members]
        return base + "".join("." + m for m in members)

    def unary(self, e: A.Unary) -> str:
        t = concrete(e.type)
        x = self.expr(e.operand, t)
        if e.op == "NOT":
            return f"(!{x})" if t.kind == "bool" else f"(({t.c})~{x})"
        if t.kind == "real":
            return f"(-{x})"
        return self.wrap(f"-(int64_t){x}", t)

    def binary(self, e: A.Binary) -> str:
        t = concrete(e.operand_type)
        op = e.op
        if op == "**":  # EXPT: pow of double, a REAL result rounded to float (docs/scl.md §3.5)
            base = self.expr(e.left, T.LREAL)
            exponent = self.expr(e.right, T.LREAL)
            return f"(({t.c})pow({base}, {exponent}))"
        if t == T.TIME and op in ("*", "/"):
            a, b = self.expr(e.left, T.TIME), self.expr(e.right, T.DINT)
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
        if op == "/":
            body = f"scl_div((int64_t){a}, (int64_t){b})"
        elif op == "MOD":
            body = f"scl_mod((int64_t){a}, (int64_t){b})"
        else:
            body = f"({wide}){a} {op} ({wide}){b}"
        return self.wrap(body, t)

    def call(self, c: A.Call) -> str:
        name = c.callee.upper()
        if hasattr(c, "fc"):
            return self.fc_call(c)
        if hasattr(c, "power"):
            return self.binary(c.power)
        if hasattr(c, "dtl"):
            local = "true" if name == "RD_LOC_T" else "false"
            return f"scl_rd_sys_t(ctx, {local}, &{self.ref(c.dtl)})"
        if hasattr(c, "mem"):
            return f"scl_runtime(&{self.ref(c.mem)}, call)"
        if hasattr(c, "mux"):
            return self.mux(c)
        if name in ("SHL", "SHR", "ROL", "ROR"):
            return self.shift(c, name)
        if hasattr(c, "conversion"):
            source, target = c.conversion
            return self.convert(self.expr(c.args[0].value, source), source, target)
        if name == "QRY_CINT":
            outs = [
                f"&{self.ref(c.outputs[k])}" if k in c.outputs else "NULL"
                for k in ("CYCLE", "PHASE", "STATUS")
            ]
            return f"scl_qry_cint(call, {', '.join(outs)})"
        t = concrete(c.operand)
        values = [a.value for a in c.args]
        if name == "SEL":
            g = self.expr(values[0], T.BOOL)
            return f"({g} ? {self.expr(values[2], t)} : {self.expr(values[1], t)})"
        args = [self.expr(v, t) for v in values]
        suffix = {"REAL": "f", "LREAL": "d"}.get(t.name, "i")
        if name in ("MIN", "MAX"):
            code = args[0]
            for other in args[1:]:
                code = f"scl_{name.lower()}_{suffix}({code}, {other})"
            return f"(({t.c}){code})"
        if name == "LIMIT":
            mn, x, mx = args
            return f"(({t.c})scl_min_{suffix}(scl_max_{suffix}({x}, {mn}), {mx}))"
        if name == "ABS":
            if t.kind == "real":
                return f"{'fabsf' if t.name == 'REAL' else 'fabs'}({args[0]})"
            return self.wrap(f"({args[0]} < 0 ? -(int64_t){args[0]} : (int64_t){args[0]})", t)
        if name in ("SIN", "COS") and t == T.REAL:  # docs/behaviour.md §6.2: iec/sin_cos.h
            return f"iec_sin_cos({args[0]}, {'true' if name == 'COS' else 'false'})"
        if name in C_MATH:
            if t == T.REAL:
                return f"((float){C_MATH[name]}((double){args[0]}))"
            return f"{C_MATH[name]}({args[0]})"
        if name == "SQRT":
            return f"{'sqrtf' if t.name == 'REAL' else 'sqrt'}({args[0]})"
        if name == "TRUNC":
            return f"((int32_t)scl_limit_round({args[0]}, INT32_MIN, INT32_MAX, true))"
        raise AssertionError(name)

    def fc_call(self, c: A.Call) -> str:
        """A call of an FC: its C function with the inputs by value, the outputs by address (NULL
        for one not given)."""
        fc = c.fc
        ins = [d for d in fc.block.decls if d.section == "VAR_INPUT"]
        args = ["ctx"] + [self.expr(v, d.type) for v, d in zip(c.fc_ins, ins)]
        args += [f"&{self.ref(t)}" if t is not None else "NULL" for t in c.fc_outs]
        return f"{prefix_of(fc)}({', '.join(args)})"

    def mux(self, c: A.Call) -> str:
        """MUX: a function of its own per type and count, so that K is evaluated once."""
        k, ins, otherwise = c.mux
        t = concrete(c.operand)
        n = len(ins)
        name = f"scl_mux_{t.name.lower()}_{n}{'_else' if otherwise is not None else ''}"
        if name not in self.helpers:
            params = ", ".join([f"{t.c} in{i}" for i in range(n)])
            params += f", {t.c} inelse" if otherwise is not None else ""
            cases = [f"    case {i}: return in{i};" for i in range(n)]
            fallback = "inelse" if otherwise is not None else "0"
            self.helpers[name] = [
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
        values = [self.expr(v, t) for v in ins]
        if otherwise is not None:
            values.append(self.expr(otherwise, t))
        return f"{name}((int64_t){self.expr(k)}, {', '.join(values)})"

    def shift(self, c: A.Call, name: str) -> str:
        t = concrete(c.operand)
        x = self.expr(c.args[0].value, t)
        n = f"(uint64_t){self.expr(c.args[1].value, T.UDINT)}"
        if name == "SHR" and t.signed:
            return f"(({t.c})scl_shr_signed((int64_t){x}, {n}))"
        code = f"scl_{name.lower()}((uint64_t)(int64_t){x}, {n}, {t.bits})"
        if t.signed:
            return self.wrap(f"(int64_t){code}", t)
        return f"(({t.c}){code})"

    # Statements

    def statements(self, body, indent) -> list[str]:
        lines = []
        for s in body:
            lines += self.statement(s, indent)
        return lines

    def statement(self, s: A.Stmt, indent: int) -> list[str]:
        pad = "    " * indent
        if isinstance(s, A.Assign):
            target = s.target.type
            return [f"{pad}{self.ref(s.target)} = {self.expr(s.value, target)};"]
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
            lines = [f"{pad}{{", f"{pad}    const int64_t {selector} = {self.expr(s.selector)};"]
            for i, (labels, body) in enumerate(s.branches):
                tests = " || ".join(
                    f"{selector} == {low}"
                    if low == high
                    else f"({selector} >= {low} && {selector} <= {high})"
                    for low, high in labels
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
            return [f"{pad}/* REGION {s.title} */"] + self.statements(s.body, indent)
        raise AssertionError(s)

    def call_statement(self, c: A.Call, pad: str) -> list[str]:
        if c.instance is None:
            return [f"{pad}(void){self.expr(c)};"]
        inst = self.ref(c.instance)
        fb = c.fb
        names = fb.block.names if fb.block is not None else None
        member = (lambda n: field(names[n.lower()].name)) if names else (lambda n: n)  # noqa: E731
        lines = [
            f"{pad}{inst}.{member(name)} = {self.expr(v, fb.inputs[name])};" for name, v in c.ins
        ]
        if fb.block is not None:  # a user FB: its instance in the caller's data (multi-instance)
            lines.append(f"{pad}{prefix_of(fb.block)}_call(&{inst}, ctx);")
        elif fb.timed:
            lines.append(f"{pad}{fb.call}(&{inst}, call);")
        else:
            lines.append(f"{pad}{fb.call}(&{inst});")
        for name, target in c.outs:
            lines.append(
                f"{pad}{self.ref(target)} = "
                f"{self.convert(f'{inst}.{member(name)}', fb.outputs[name], target.type)};"
            )
        return lines

    # Files

    def struct_fields(self) -> list[str]:
        lines = []
        groups = [("inputs", ("VAR_INPUT",)), ("outputs", ("VAR_OUTPUT",))]
        if not self.checker.fc:
            groups.append(("statics", STATIC_SECTIONS))
        for title, sections in groups:
            decls = [d for d in self.block.decls if d.section in sections]
            if decls:
                lines.append(f"    /* {title} */")
            for d in decls:
                text = d.comment.replace("*/", "* /").replace("/*", "/ *")
                comment = f" /* {text} */" if text else ""
                c_type = struct_of(d.type.block) if getattr(d.type, "block", None) else d.type.c
                lines.append(f"    {c_type} {field(d.name)};{comment}")
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
                if d.type is T.DTL:
                    body.append(f"    scl_dtl {field(d.name)} = scl_dtl_of(0);")
                    continue
                const = "const " if d.section == "VAR CONSTANT" else ""
                value = self.init_value(d) or ("false" if d.type.kind == "bool" else "0")
                # a VAR_TEMP starts at its declared value or 0 in every call (docs/scl.md §4)
                body.append(f"    {const}{d.type.c} {field(d.name)} = {value};")
        locals_ = [d.name for d in self.block.decls if d.section in LOCAL_SECTIONS]
        body += [f"    (void){field(n)};" for n in locals_]  # a temp may be set and never read
        return body

    def definitions(self) -> list[str]:
        """The block's functions, for block.c (its MUX helpers in self.helpers)."""
        head = ["    const plc_call *call = ctx->plc;", "    (void)call;", "    (void)ctx;"]
        if self.checker.fc:
            body = head + self.locals_() + self.statements(self.block.body, 1)
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
            if d.section in ("VAR_INPUT", "VAR_OUTPUT") + STATIC_SECTIONS:
                if getattr(d.type, "block", None) is not None:
                    init.append(f"    {prefix_of(d.type.block)}_init(&b->{field(d.name)});")
                elif d.type is T.DTL:
                    init.append(f"    b->{field(d.name)} = scl_dtl_of(0);")
                else:
                    value = self.init_value(d)
                    if value is not None:
                        init.append(f"    b->{field(d.name)} = {value};")
        if self.checker is self.main and self.program.uses_date:
            init.append(f"    b->scl_start_s = {START_DATE_AND_TIME!r};")
        body = head + self.locals_() + self.statements(self.block.body, 1)
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
            if d.section not in ("VAR_INPUT", "VAR_OUTPUT"):
                continue
            t = d.type
            low, high = FMI_RANGE.get(t.name, (str(t.low), str(t.high)))
            kind = "input" if d.section == "VAR_INPUT" else "output"
            description = d.comment or f"{t.name} {kind} of the SCL block {self.block.name}"
            if not d.comment:
                pass
            elif not description.upper().startswith(t.name):
                description = f"{t.name}: {description}"
            role = "ROLE_INPUT" if kind == "input" else "ROLE_OUTPUT"
            rows += [
                f"    {{.vr = {vr},",
                f"     .name = {c_string(d.name)},",
                f"     .type = {t.var},",
                f"     .role = {role},",
                f"     AT(block, {field(d.name)}),",
                f"     .min = {low},",
                f"     .max = {high},",
                f"     .description = {c_string(description)}}},",
            ]
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
            low, high = FMI_RANGE.get(t.name, (str(t.low), str(t.high)))
            rows += [
                f"    {{.vr = {vr},",
                f"     .name = {c_string(name)},",
                f"     .type = {t.var},",
                "     .role = ROLE_LOCAL,",
                f"     AT(block, {c_path}),",
                f"     .min = {low},",
                f"     .max = {high},",
                f"     .description = {c_string(description)}}},",
            ]
            vr += 1
        return rows

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
            elif t.var in self.checker.core_vars:
                yield n, c, t, d.comment or f"{t.name} static of {checker.block.name}"

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
                else:
                    rows.append(f"    STATIC(block, {name}, {t.field}),")

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
                f'    snprintf(msg, size, "an FB instance of {self.block.name} lies outside '
                'any run");',
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
                f"/* {self.block.name}: its interface table, generated by lgf_fmus.scl from its",
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
                + "};",
                f"    {self.prefix}_call(b, &ctx);",
                "}",
                "",
                *check,
                "static const model_static statics[] = {",
                *rows,
                "};",
                "",
                "static const model lgf_model = {",
                f"    .identifier = {c_string(self.block.name)},",
                f'    .guid = "{{{guid}}}",',
                f"    .description = {c_string(description)},",
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
    e = html.escape
    rows = [
        "<tr><td><code>cycleTime</code></td><td>parameter</td><td>REAL, s</td><td>0.1</td>"
        "<td>period of the calling OB: one call of the FB per cycleTime</td></tr>"
    ]
    for d in block.decls:
        if d.section not in ("VAR_INPUT", "VAR_OUTPUT"):
            continue
        causality = "input" if d.section == "VAR_INPUT" else "output"
        start = e(d.init.text) if d.init is not None else ""
        rows.append(
            f"<tr><td><code>{e(d.name)}</code></td><td>{causality}</td><td>{d.type}</td>"
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
            f'<html lang="en"><head><meta charset="utf-8"><title>{e(block.name)}</title></head>',
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
        f"/* {name}: generated by lgf_fmus.scl from its SCL (docs/scl.md §4). */",
        f"#ifndef {guard}",
        f"#define {guard}",
        "",
        '#include "scl/scl.h"',
        "",
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
