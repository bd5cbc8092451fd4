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
    "b plc model variables statics lgf_model init check status status_text".split()
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


class Generator:
    def __init__(self, checker, source_text: str):
        self.block = checker.block
        self.checker = checker
        self.source_text = source_text
        self.prefix = "scl_" + self.block.name.lower()
        self.struct = self.prefix + "_block"
        self.temps = 0

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
        base = field(d.name) if d.section in ("VAR_TEMP", "VAR CONSTANT") else f"b->{field(d.name)}"
        return base + "".join("." + m for m in e.members)

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
        if name in ("SIN", "COS"):  # docs/behaviour.md §6.2: iec/sin_cos.h
            return f"iec_sin_cos({args[0]}, {'true' if name == 'COS' else 'false'})"
        if name == "SQRT":
            return f"{'sqrtf' if t.name == 'REAL' else 'sqrt'}({args[0]})"
        if name == "TRUNC":
            return f"((int32_t)scl_limit_round({args[0]}, INT32_MIN, INT32_MAX, true))"
        raise AssertionError(name)

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
        lines = [f"{pad}{inst}.{name} = {self.expr(v, c.fb.inputs[name])};" for name, v in c.ins]
        if c.fb.c == "scl_timer":
            lines.append(f"{pad}scl_{c.fb.name.lower()}(&{inst}, call);")
        else:
            lines.append(f"{pad}scl_{c.fb.name.lower()}(&{inst});")
        for name, target in c.outs:
            lines.append(
                f"{pad}{self.ref(target)} = "
                f"{self.convert(f'{inst}.{name}', c.fb.outputs[name], target.type)};"
            )
        return lines

    # Files

    def struct_fields(self) -> list[str]:
        lines = []
        for title, sections in (
            ("inputs", ("VAR_INPUT",)),
            ("outputs", ("VAR_OUTPUT",)),
            ("statics", ("VAR", "VAR RETAIN", "VAR NON_RETAIN")),
        ):
            decls = [d for d in self.block.decls if d.section in sections]
            if decls:
                lines.append(f"    /* {title} */")
            for d in decls:
                text = d.comment.replace("*/", "* /").replace("/*", "/ *")
                comment = f" /* {text} */" if text else ""
                lines.append(f"    {d.type.c} {field(d.name)};{comment}")
        return lines or ["    bool unused; /* an FB without variables */"]

    def init_value(self, d: A.VarDecl) -> str:
        return self.expr(d.init, d.type) if d.init is not None else None

    def block_h(self) -> str:
        guard = f"SCL_{self.block.name.upper()}_H"
        return "\n".join(
            [
                f"/* {self.block.name}: generated by lgf_fmus.scl from its SCL "
                "(docs/scl.md §4). */",
                f"#ifndef {guard}",
                f"#define {guard}",
                "",
                '#include "scl/scl.h"',
                "",
                "typedef struct {",
                *self.struct_fields(),
                f"}} {self.struct};",
                "",
                f"static void {self.prefix}_init({self.struct} *b);",
                f"static void {self.prefix}_call({self.struct} *b, const plc_call *call);",
                "",
                "#endif",
                "",
            ]
        )

    def block_c(self) -> str:
        init = ["    memset(b, 0, sizeof *b);"]
        for d in self.block.decls:
            if d.section in ("VAR_INPUT", "VAR_OUTPUT", "VAR", "VAR RETAIN", "VAR NON_RETAIN"):
                value = self.init_value(d)
                if value is not None:
                    init.append(f"    b->{field(d.name)} = {value};")
        body = []
        for d in self.block.decls:
            if d.section in ("VAR_TEMP", "VAR CONSTANT"):
                const = "const " if d.section == "VAR CONSTANT" else ""
                value = self.init_value(d) or ("false" if d.type.kind == "bool" else "0")
                # a VAR_TEMP starts at its declared value or 0 in every call (docs/scl.md §4)
                body.append(f"    {const}{d.type.c} {field(d.name)} = {value};")
        locals_ = [d.name for d in self.block.decls if d.section in ("VAR_TEMP", "VAR CONSTANT")]
        body += [f"    (void){field(n)};" for n in locals_]  # a temp may be set and never read
        body += self.statements(self.block.body, 1)
        return "\n".join(
            [
                f'#include "blocks/{self.block.name}/block.h"',
                "",
                "#include <string.h>",
                "",
                f"static void {self.prefix}_init({self.struct} *b)",
                "{",
                *init,
                "}",
                "",
                f"static void {self.prefix}_call({self.struct} *b, const plc_call *call)",
                "{",
                "    (void)call;",
                *body,
                "}",
                "",
            ]
        )

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
        return rows

    def statics(self) -> tuple[list[str], list[str]]:
        rows, checks = [], []
        for d in self.block.decls:
            if d.section not in ("VAR", "VAR RETAIN", "VAR NON_RETAIN"):
                continue
            name = field(d.name)
            if isinstance(d.type, T.FbType):
                if d.type.c == "scl_timer":
                    parts = [
                        ("IN", "FIELD_BOOL"),
                        ("PT", "FIELD_INT32"),
                        ("Q", "FIELD_BOOL"),
                        ("ET", "FIELD_INT32"),
                        ("timer.in", "FIELD_BOOL"),
                        ("timer.running", "FIELD_BOOL"),
                        ("timer.pt", "FIELD_INT32"),
                        ("timer.start_us", "FIELD_INT64"),
                    ]
                    checks.append(f"scl_timer_is_valid(&b->{name})")
                else:
                    parts = [("CLK", "FIELD_BOOL"), ("Q", "FIELD_BOOL"), ("memory", "FIELD_BOOL")]
                    checks.append(f"scl_trig_is_valid(&b->{name})")
                rows += [f"    STATIC(block, {name}.{p}, {f})," for p, f in parts]
            else:
                rows.append(f"    STATIC(block, {name}, {d.type.field}),")
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
                "static void call(void *data, const plc_call *plc) "
                f"{{ {self.prefix}_call(data, plc); }}",
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
            f"<p>Statics (in the FMU state, not FMI variables): {e(', '.join(statics))}.</p>"
            if statics
            else "",
            "</body></html>",
            "",
        ]
    )


def generate(checker, source_text: str) -> dict[str, str]:
    """The generated files, by their path under the FMU's sources/."""
    g = Generator(checker, source_text)
    name = checker.block.name
    return {
        f"blocks/{name}/block.h": g.block_h(),
        f"blocks/{name}/block.c": g.block_c(),
        f"blocks/{name}/interface.c": g.interface_c(),
    }
