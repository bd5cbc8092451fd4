"""C generation (docs/scl.md §4): from a checked and lowered FUNCTION_BLOCK, exactly what a
hand-written block of src/blocks/ is, onto src/core/model.h, src/iec/ and the SCL runtime
runtime/scl/scl.h. Every name of the SCL keeps its spelling as a C field (cnames.py); every S7
operation becomes the C of its rule in docs/scl.md §3. In three parts:

    cgen.py            the block's C: block.c's statements, init and call functions
    cgen_expr.py       the C of expressions (of the block's C)
    cgen_interface.py  block.h's types and struct, interface.c
    cgen_docs.py       documentation/index.html"""

from __future__ import annotations

import re
from pathlib import Path

from . import ast as A
from . import types as T
from .cformat import formatted
from .cgen_docs import documentation  # noqa: F401  (the FMU's documentation, with the C)
from .cgen_expr import Expressions
from .cgen_interface import MAX_CYCLE_TIME_MS, START_DATE_AND_TIME, Interface, typedefs
from .cnames import (
    bound_fields,
    by_reference,
    c_decl,
    element_indices,
    field,
    identifier,
    is_open,
    is_table,
    overlay,
    prefix_of,
    struct_of,
)
from .escape import c_comment, c_string
from .types import K


def label(name: str) -> str:
    """The C label of a jump label (docs/scl.md §3.4 [S7-GOTO]); labels are case-insensitive."""
    return "scl_label_" + identifier(name.lower())


def bare(code: str) -> str:
    """code without the parentheses around the whole of it: `(a < b)` is `a < b` where it
    stands alone (a condition, the value of an assignment); not a comma expression's nor an
    assignment's, which keep theirs."""
    while code.startswith("(") and code.endswith(")"):
        inner, depth = code[1:-1], 0
        for i, c in enumerate(inner):
            depth += {"(": 1, ")": -1}.get(c, 0)
            if depth < 0:
                return code  # the first parenthesis closes before the end: (a) + (b)
            if depth == 0 and (
                c == ","
                or c == "="
                and inner[i - 1 : i] not in "=<>!"
                and inner[i + 1 : i + 2] != "="
            ):
                return code
        code = inner
    return code


def uses(name: str, c: str) -> tuple[int, int]:
    """(how often the C c names the local name, how often it assigns it): a local that c
    never names is not declared, one it only assigns is declared SCL_UNUSED (runtime scl.h),
    so the C compiler warns of neither."""
    c = re.sub(r"/\*.*?\*/", "", c, flags=re.S)  # a REGION title may name it too
    mention = rf"(?<![\w.>]){re.escape(name)}\b"
    named = len(re.findall(mention, c))
    assigned = len(re.findall(mention + r"\s*=(?!=)", c))
    return named, assigned


class Generator(Expressions, Interface):
    """The C of one block of the program (its statements here, its expressions and interface in
    the mixins)."""

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
        self.spares: list[str] = []  # the stand-ins of elements passed by reference (§3.7)
        self.known: dict = {}  # id of a VarRef -> its place, while a compound assignment reads it

    def statements(self, body, indent) -> list[str]:
        """The C of statements, each after a comment of its place in the SCL (file.scl:LINE)."""
        lines = []
        for s in body:
            if not isinstance(s, A.Region) and not (isinstance(s, A.Label) and not s.used):
                where = f"{Path(s.loc.file).name}:{s.loc.line}"
                lines.append(f"{'    ' * indent}/* {c_comment(where)} */")
            lines += self.statement(s, indent)
        return lines

    def watchdog(self, s: A.Stmt, indent: int) -> list[str]:
        """The first line of each iteration of the loop s: past the call's budget of iterations,
        the block returns (the cycle watchdog, docs/scl.md §3.4 [DEC-WATCHDOG])."""
        where = c_string(f"{Path(s.loc.file).name}:{s.loc.line}")
        self.program.has_loop = True
        return [f"{'    ' * indent}if (scl_time_error(ctx, {where})) return;"]

    def statement(self, s: A.Stmt, indent: int) -> list[str]:
        pad = "    " * indent
        if isinstance(s, A.Assign):
            if isinstance(s.target.type, T.StringType):
                return self.store_string(s.target, self.expr(s.value, s.target.type), pad)
            if not isinstance(s.target.type, T.Elementary):  # a whole STRUCT or ARRAY
                return self.copy(s.target, s.value, pad)
            if s.operation is not None:  # a[i] += ...: the index once, for the read and write
                return self.compound(s, pad)
            return self.store(s.target, self.expr(s.value, s.target.type), pad)
        if isinstance(s, A.CallStmt):
            return self.call_statement(s.call, pad)
        if isinstance(s, A.If):
            lines = []
            for i, (condition, body) in enumerate(s.branches):
                head = "if" if i == 0 else "} else if"
                lines.append(f"{pad}{head} ({bare(self.expr(condition, T.BOOL))}) {{")
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
            lines += self.watchdog(s, indent + 2) + self.statements(s.body, indent + 2)
            lines += [f"{pad}    }}", f"{pad}}}"]
            return lines
        if isinstance(s, A.While):
            lines = [f"{pad}while ({bare(self.expr(s.condition, T.BOOL))}) {{"]
            lines += self.watchdog(s, indent + 1)
            return lines + self.statements(s.body, indent + 1) + [f"{pad}}}"]
        if isinstance(s, A.Repeat):
            lines = [f"{pad}do {{"]
            lines += self.watchdog(s, indent + 1) + self.statements(s.body, indent + 1)
            return lines + [f"{pad}}} while (!{self.expr(s.condition, T.BOOL)});"]
        if isinstance(s, A.Jump):
            return [
                f"{pad}{ {'EXIT': 'break', 'CONTINUE': 'continue', 'RETURN': 'return'}[s.kind] };"
            ]
        if isinstance(s, A.Goto):  # a jump back is a loop's iteration: the watchdog counts it
            head = self.watchdog(s, indent) if s.backward else []
            return head + [f"{pad}goto {label(s.label)};"]
        if isinstance(s, A.Label):  # the C declares no label that no GOTO jumps to
            return [f"{pad}{label(s.name)}:;"] if s.used else []
        if isinstance(s, A.Region):
            title = f"/* REGION {c_comment(s.title)} */"
            return [pad + title] + self.statements(s.body, indent)
        raise AssertionError(s)

    def store(self, target: A.VarRef, value: str, pad: str, place=None) -> list[str]:
        """target := value; at a run-time index outside the bounds the write is ignored
        (docs/scl.md §3.8: Decision); a .%X bit is set or cleared, a slice written, in its
        variable."""
        code, conditions, bit = place or self.place(target)
        lines = []
        if conditions:  # the indices, then the value, each once, even where the write is ignored
            self.temps += 1
            ok, v = f"scl_ok_{self.temps}", f"scl_value_{self.temps}"
            lines = [
                f"{pad}{{",
                f"{pad}    const bool {ok} = {bare(' && '.join(conditions))};",
                f"{pad}    const {target.type.c} {v} = {bare(value)};",
            ]
            value = v
        if bit is not None:  # the other bits of the variable stay as they are
            shift, t, width = bit
            if width == 1:
                mask, part = f"(UINT64_C(1) << {shift})", f"({value} ? 1u : 0u)"
            else:
                whole = re.fullmatch(r"[\w.>-]+", value) or bare(value) != value
                part = value if whole else f"({value})"
                mask = f"(UINT64_C({(1 << width) - 1:#x}) << {shift})"
            value = f"(({t.c})(((uint64_t){code} & ~{mask}) | ((uint64_t){part} << {shift})))"
        line = f"{code} = {bare(value)};"
        if not conditions:
            return [pad + line]
        return lines + [f"{pad}    if ({ok}) {line}", f"{pad}}}"]

    def store_string(self, target: A.VarRef, value: str, pad: str) -> list[str]:
        """A string assigned: cut at the target's maximum length, as S7 assigns (docs/scl.md
        §3.1 [S7-STRING-ASSIGN]); at an index outside its ARRAY the write is ignored."""
        code, conditions, _ = self.place(target)
        line = f"scl_string_store(&{code}, {bare(value)}, {target.type.length});"
        if not conditions:
            return [pad + line]
        self.temps += 1
        ok, v = f"scl_ok_{self.temps}", f"scl_value_{self.temps}"
        return [
            f"{pad}{{",
            f"{pad}    const bool {ok} = {bare(' && '.join(conditions))};",
            f"{pad}    const scl_string {v} = {bare(value)};",
            f"{pad}    if ({ok}) scl_string_store(&{code}, {v}, {target.type.length});",
            f"{pad}}}",
        ]

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

    def copy(self, target: A.VarRef, source: A.Expr, pad: str) -> list[str]:
        """A STRUCT or ARRAY assigned whole (the same type, docs/scl.md §3.8): copied; a source
        element outside its ARRAY's bounds copies as 0."""
        to, to_conditions, _ = self.place(target)
        if isinstance(source, A.VarRef):
            what, conditions, _ = self.place(source)
            inner = [f"memcpy(&{to}, &{what}, sizeof {to});"]
        else:  # the value of a DTL operation or function (docs/scl.md §3.6)
            conditions, inner = [], [f"{to} = {self.expr(source)};"]
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
        inst, conditions, _ = self.place(c.instance)
        if conditions:  # #axes[#i](...) outside the ARRAY: no call (docs/scl.md §3.7)
            inner = self.instance_call(c, pad + "    ", inst)
            return [f"{pad}if ({bare(' && '.join(conditions))}) {{", *inner, f"{pad}}}"]
        return self.instance_call(c, pad, inst)

    def instance_call(self, c: A.Call, pad: str, inst: str) -> list[str]:
        """The call of the instance inst: its inputs set, the FB run, its outputs copied."""
        fb = c.fb
        names = fb.block.names if fb.block is not None else None
        member = (lambda n: field(names[n.lower()].name)) if names else (lambda n: n)  # noqa: E731
        lines = []
        for name, v in c.inputs:
            t, value = fb.inputs[name], self.expr(v, fb.inputs[name])
            if isinstance(t, T.StringType):  # cut at the input's length (docs/scl.md §3.1)
                lines.append(f"{pad}scl_string_store(&{inst}.{member(name)}, {value}, {t.length});")
            else:
                lines.append(f"{pad}{inst}.{member(name)} = {value};")
        for formal, actual in c.references:  # its in/outs: the caller's variables (§3.7)
            fields = [field(formal.name)]
            if is_open(formal.type):
                fields += [b for pair in bound_fields(fields[0], formal.type.rank) for b in pair]
            for n, value in zip(fields, self.reference(formal, actual)):
                lines.append(f"{pad}{inst}.{n} = {value};")
        if fb.block is not None:  # a user FB: its instance in the caller's data (multi-instance)
            lines.append(f"{pad}{prefix_of(fb.block)}_call(&{inst}, ctx);")
        elif fb.timed:
            lines.append(f"{pad}{fb.call}(&{inst}, call);")
        else:
            lines.append(f"{pad}{fb.call}(&{inst});")
        for name, target in c.outputs:
            value = self.convert(f"{inst}.{member(name)}", fb.outputs[name], target.type)
            if isinstance(target.type, T.StringType):
                lines += self.store_string(target, value, pad)
            else:
                lines += self.store(target, value, pad)
        return lines

    def init_value(self, d: A.VarDecl) -> str:
        return self.expr(d.start, d.type) if d.start is not None else None

    def init_lines(self, path: str, t, init, pad="    ") -> list[str]:
        """The assignments that give path of type t its initial value: the declaration's (init),
        else a UDT's or STRUCT's member defaults; everything else stays 0 (memset)."""
        if isinstance(t, T.Elementary):
            if init is None:
                return []
            return [f"{pad}{path} = {self.expr(init, t)};"]
        if isinstance(t, T.StringType):  # its maximum length, its start value or empty
            if init is None:
                return [f"{pad}{path}.max = {t.length};"]
            return [f"{pad}scl_string_store(&{path}, {self.expr(init, t)}, {t.length});"]
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
                quotient = k if stride == 1 else f"{k} / {stride}"
                index += f"[{quotient}]" if stride * n == total else f"[({quotient}) % {n}]"
            lines.append(f"{pad}for (size_t {k} = {first}; {k} < {total}; {k}++) {{")
            lines += self.init_lines(path + index, t.element, None, pad + "    ")
            lines.append(f"{pad}}}")
        return lines

    def locals_(self, statements: str) -> list[str]:
        """The VAR_TEMP and VAR CONSTANT of a call, which start again in every call: those the
        statements name (the others have no effect), marked SCL_UNUSED where only assigned."""
        body = []
        for d in self.block.decls:
            if d.section.local:
                name = field(d.name)
                named, assigned = uses(name, statements)
                if not named:
                    continue
                if not isinstance(d.type, T.Elementary):
                    # a VAR_TEMP starts at its declared value or 0 in every call (docs/scl.md §4)
                    body.append(f"    {c_decl(name, d.type)};")
                    body.append(f"    memset(&{name}, 0, sizeof {name});")
                    body += self.init_lines(name, d.type, d.start)
                    continue
                const = "const " if d.section == A.Section.CONSTANT else ""
                unused = "SCL_UNUSED " if named == assigned else ""
                value = self.init_value(d) or ("false" if d.type.kind == K.BOOL else "0")
                # a VAR_TEMP starts at its declared value or 0 in every call (docs/scl.md §4)
                body.append(f"    {unused}{const}{d.type.c} {name} = {bare(value)};")
        return body

    def body(self) -> list[str]:
        """The C of a call: the PLC call (where it runs timers, QRY_CINT, RUNTIME), the
        temporaries of the run-time indices, the locals, the statements."""
        self.index_temps, self.spares = [], []
        statements = self.statements(self.block.body, 1)
        text = "\n".join(statements)
        temps = [f"    int64_t {t};" for t in self.index_temps]
        temps += [f"    {spare};" for spare in self.spares]
        head = ["    const plc_call *call = ctx->plc;"] if uses("call", text)[0] else []
        return head + temps + self.locals_(text) + statements

    @staticmethod
    def parameter(declaration: str, name: str, body: list[str]) -> str:
        """A parameter of a function, marked SCL_UNUSED where its body does not name it."""
        return declaration if uses(name, "\n".join(body))[0] else f"SCL_UNUSED {declaration}"

    def with_context(self, name: str, data: str, body: list[str]) -> list[str]:
        """The function <prefix>_<name> of the block's data (an FC's frame, an FB's instance) and
        the call's context, running body."""
        data = self.parameter(f"{self.struct} *{data}", data, body)
        context = self.parameter("const scl_context *ctx", "ctx", body)
        return c_function(f"static void {self.prefix}_{name}({data}, {context})", body)

    def definitions(self) -> list[str]:
        """The block's functions, for block.c (its MUX helpers in self.helpers)."""
        if self.checker.fc:
            body = self.body()
            ins, outs, refs, params = self.fc_parameters()
            ret = self.checker.return_type
            # an FC has no instance data: its frame starts at 0 (and the outputs' declared
            # values) in every call, its outputs are copied out when it returns
            wrapper = [f"    {self.struct} f;", "    memset(&f, 0, sizeof f);"]
            for d in ins:
                if isinstance(d.type, T.StringType):  # cut at the input's length
                    wrapper.append(
                        f"    scl_string_store(&f.{field(d.name)}, {field(d.name)}, "
                        f"{d.type.length});"
                    )
                else:
                    wrapper.append(f"    f.{field(d.name)} = {field(d.name)};")
            for d in refs:  # the caller's variables, and the bounds of an ARRAY[*]
                names = [field(d.name)]
                if is_open(d.type):
                    names += [b for pair in bound_fields(names[0], d.type.rank) for b in pair]
                wrapper += [f"    f.{n} = {n};" for n in names]
            for d in outs:
                if isinstance(d.type, T.StringType) or d.start is not None:
                    wrapper += self.init_lines(f"f.{field(d.name)}", d.type, d.start)
            wrapper.append(f"    {self.prefix}_body(&f, ctx);")
            for d in outs:
                name = field(d.name)
                wrapper.append(f"    if ({name}) *{name} = f.{name};")
            if ret is not None:
                wrapper.append("    return f.scl_return;")
            return self.with_context("body", "f", body) + c_function(
                f"static {ret.c if ret else 'void'} {self.prefix}({', '.join(params)})", wrapper
            )
        init = ["    memset(b, 0, sizeof *b);"]
        for d in self.block.decls:
            if d.section.in_struct and not by_reference(d, self.checker):
                element = getattr(d.type, "element", None)
                if isinstance(element, T.FbType):  # an ARRAY of instances: each element's init
                    if element.block is not None:
                        init += [
                            f"    {prefix_of(element.block)}_init(&b->{field(d.name)}{sub});"
                            for sub in element_indices(d.type.sizes)
                        ]
                elif isinstance(d.type, T.FbType) and d.type.block is not None:
                    init.append(f"    {prefix_of(d.type.block)}_init(&b->{field(d.name)});")
                    for m, start in d.db_starts:  # an instance DB's own (docs/scl.md §3.9)
                        path = f"b->{field(d.name)}.{field(m.name)}"
                        init += self.init_lines(path, m.type, start)
                elif not isinstance(d.type, T.FbType):  # a system FB's instance starts at 0
                    if is_table(d):  # numberOf<Name>: the elements given, else all
                        count = len(d.start) if d.start is not None else T.TABLE_CAPACITY
                        init.append(f"    b->{field(T.table_count(d.name))} = {count};")
                    init += self.init_lines(f"b->{field(d.name)}", d.type, d.start)
        if self.checker is self.main and self.program.uses_date:
            init.append(f"    b->scl_start_s = {START_DATE_AND_TIME!r};")
        if self.checker is self.main:
            init.append(f"    b->scl_max_cycle_ms = {MAX_CYCLE_TIME_MS};")
        return c_function(f"static void {self.prefix}_init({self.struct} *b)", init) + (
            self.with_context("call", "b", self.body())
        )


def c_function(signature: str, body: list[str]) -> list[str]:
    """A C function's lines: its signature, its body in braces, a blank line."""
    return [signature, "{", *body, "}", ""]


def generate(checker, source_text: str) -> dict[str, str]:
    """The generated files, by their path under the FMU's sources/: the FB, with every FB and FC
    it uses before it (callees first) in the same block.h and block.c."""
    main = checker
    name = identifier(main.block.name)  # the FMU's modelIdentifier (docs/scl.md §4)
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
    return formatted(
        {
            f"blocks/{name}/block.h": "\n".join(header),
            f"blocks/{name}/block.c": "\n".join(block_c + helper_lines + bodies),
            f"blocks/{name}/interface.c": g.interface_c(),
        }
    )
