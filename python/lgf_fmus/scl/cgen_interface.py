"""The interface of a compiled block (docs/scl.md §4), a part of the C generation: block.h's
typedef of every STRUCT and UDT and the block's struct (its inputs, outputs, in/outs and
statics) with its prototypes, and interface.c: the model_variable table (cycleTime, the
interface, the clock's parameters, the statics as FMI locals), the model_static rows of the FMU
state with the checks of restored instances, and lgf_model."""

from __future__ import annotations

import uuid

from . import ast as A
from . import types as T
from .cnames import (
    by_reference,
    c_decl,
    described,
    element_indices,
    field,
    fmi_part,
    identifier,
    is_table,
    reference_decls,
    scalars,
    scl_indices,
)
from .escape import c_comment, c_format, c_string, xml_name, xml_text

FMI_RANGE = {
    "BOOL": ("0", "1"),
    "REAL": ("-INFINITY", "INFINITY"),
    "LREAL": ("-INFINITY", "INFINITY"),
    "TIME": ("-2147483.647", "2147483.647"),
}


# startDateAndTime (docs/scl.md §3.6): 2024-01-01 00:00 UTC by default, up to 2262-01-01 (the
# DTL's range ends in 2262)
START_DATE_AND_TIME = 1704067200.0
START_DATE_AND_TIME_MAX = 9214646400.0
# maxCycleTime (docs/scl.md §4): the CPU property "Maximum cycle time", 150 ms by default, 1 ms
# to 6000 ms
MAX_CYCLE_TIME_MS = 150


def instances(name: str, c: str, t):
    """(SCL name, C path, type) of a static, or of every element of an ARRAY of FB instances
    (docs/scl.md §3.7): axes[1], axes[2], ..."""
    if isinstance(t, T.ArrayType) and isinstance(t.element, T.FbType):
        return [
            (name + ix, c + sub, t.element)
            for sub, ix in zip(element_indices(t.sizes), scl_indices(t))
        ]
    return [(name, c, t)]


def typedefs(structs) -> list[str]:
    """The C of every UDT and STRUCT of the program, inner ones first (docs/scl.md §3.8)."""
    lines = []
    for t in structs:
        lines.append(f"/* {c_comment(str(t))} */" if t.name else "/* an anonymous STRUCT */")
        lines.append("typedef struct {")
        lines += [f"    {c_decl(field(k), m)};" for k, (m, _) in t.members.items()]
        lines += [f"}} {t.c};", ""]
    return lines


class Interface:
    """block.h's struct and prototypes, interface.c (a mixin of cgen.Generator)."""

    def struct_fields(self) -> list[str]:
        lines = []
        S = A.Section
        groups = [("inputs", lambda s: s == S.INPUT), ("outputs", lambda s: s == S.OUTPUT)]
        groups += [("in/outs", lambda s: s == S.IN_OUT)]
        if not self.checker.fc:
            groups += [("statics", lambda s: s.static)]
        for title, belongs in groups:
            decls = [d for d in self.block.decls if belongs(d.section)]
            if decls:
                lines.append(f"    /* {title} */")
            for d in decls:
                comment = f"/* {c_comment(d.comment)} */" if d.comment else ""
                if by_reference(d, self.checker):  # the caller's variable (docs/scl.md §3.7)
                    lines += [f"    {x};" for x in reference_decls(field(d.name), d.type)]
                    continue
                if is_table(d):  # the size the block sees, the FMU's structural parameter
                    lines.append(f"    int16_t {field(T.table_count(d.name))};")
                line = f"    {c_decl(field(d.name), d.type)};"
                if comment and len(line) + len(comment) < 100:
                    line += " " + comment
                elif comment:  # on the line before, where it would not fit after
                    lines.append(f"    {comment}")
                lines.append(line)
        if self.checker.return_type is not None:
            lines.append(f"    {self.checker.return_type.c} scl_return; /* the return value */")
        if self.checker is self.main and self.program.uses_date:
            lines += [
                "    /* the parameters of RD_SYS_T, RD_LOC_T (docs/scl.md §3.6) */",
                "    double scl_start_s;",
                "    iec_time scl_local_ms;",
            ]
        if self.checker is self.main:
            lines += [
                "    /* the cycle watchdog (docs/scl.md §3.4): maxCycleTime, and the loop that",
                "     * stopped the last call (NULL: none) */",
                "    iec_time scl_max_cycle_ms;",
                "    const char *scl_stopped;",
            ]
        return lines or ["    bool unused; /* a block without variables */"]

    def declarations(self) -> list[str]:
        """The block's type and prototypes, for block.h."""
        lines = ["typedef struct {", *self.struct_fields(), f"}} {self.struct};", ""]
        if self.checker.fc:
            params = self.fc_parameters()[3]
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

    def fc_parameters(self):
        """(inputs, outputs, parameters passed by reference, the C parameters) of an FC's
        function: the inputs by value, the outputs by address, then the in/outs and ARRAY[*]s
        as reference_decls (docs/scl.md §3.7)."""
        refs = [d for d in self.block.decls if by_reference(d, self.checker)]
        by_value = [d for d in self.block.decls if not by_reference(d, self.checker)]
        ins = [d for d in by_value if d.section == A.Section.INPUT]
        outs = [d for d in by_value if d.section == A.Section.OUTPUT]
        params = ["const scl_context *ctx"]
        params += [f"{d.type.c} {field(d.name)}" for d in ins]
        params += [f"{d.type.c} *{field(d.name)}" for d in outs]
        for d in refs:
            params += reference_decls(field(d.name), d.type)
        return ins, outs, refs, params

    def variables(self) -> list[str]:
        # the rows in the macros of src/core/model.h, as the bundled blocks write theirs
        rows = ["    OB_CYCLE_TIME_ROW,"]
        schedule = self.checker.program.schedule
        if schedule is not None:  # a program's tick: fixed by its OBs (docs/scl.md §3.10)
            tick = schedule.tick_us / 1e6
            rows = [
                '    {.vr = 0, .name = "cycleTime", .type = VAR_CYCLE,',
                "     .role = ROLE_FIXED_PARAMETER, .count = 1,",
                f"     .min = {tick!r}, .max = {tick!r},",
                '     .original = "none: the tick of the program\'s schedule",',
                '     .description = "The tick of the program: the greatest common divisor of '
                "its OBs' cycles and phases (docs/scl.md §3.10); fixed\"},",
            ]
        vr = 1
        for d in self.block.decls:
            if not d.section.interface:
                continue
            kind = {A.Section.INPUT: "input", A.Section.OUTPUT: "output"}.get(d.section, "in/out")
            if is_table(d):
                count = T.table_count(d.name)
                rows += self.row(
                    vr,
                    fmi_part(count),
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
            elif d.section == A.Section.IN_OUT:  # an input and, as <name>_out(.member), an output
                roles = [("ROLE_INPUT", ""), ("ROLE_OUTPUT", "_out")]
            else:
                roles = [(f"ROLE_{kind.upper()}", "")]
            for role, suffix in roles:
                leaves = described(field(d.name), fmi_part(d.name + suffix), d.type, d.comment)
                for path, name, t, comment in leaves:
                    description = comment or f"{t.name} {kind} of the SCL block {self.block.name}"
                    if comment and not description.upper().startswith(t.name):
                        description = f"{t.name}: {description}"
                    rows += self.row(vr, name, path, t, role, description)
                    vr += 1
        if self.program.uses_date:
            rows.append(
                f'    NAMED_ROW({vr}, "startDateAndTime", scl_start_s, VAR_LREAL, '
                f"ROLE_FIXED_PARAMETER, 0, {START_DATE_AND_TIME_MAX!r}, "
                '"The date and time of the first call for RD_SYS_T, in s since 1970-01-01 00:00 '
                "(UTC); the CPU's clock runs with the simulated time from there (docs/scl.md "
                '§3.6)", .original = "none: the CPU\'s clock"),'
            )
            vr += 1
        if self.program.uses_local:
            rows.append(
                f'    NAMED_ROW({vr}, "localTimeOffset", scl_local_ms, VAR_TIME, '
                "ROLE_FIXED_PARAMETER, -86400, 86400, "
                '"Local time minus system time for RD_LOC_T: the time zone and daylight saving '
                'time of the CPU (docs/scl.md §3.6)", '
                '.original = "none: the CPU\'s time zone and daylight saving time"),'
            )
            vr += 1
        rows.append(
            f'    NAMED_ROW({vr}, "maxCycleTime", scl_max_cycle_ms, VAR_TIME, '
            'ROLE_FIXED_PARAMETER, 0.001, 6, "The cycle watchdog: a PLC call whose loops run '
            "more than 10000 iterations per ms of it ends the step with an error, as the CPU's "
            'time error (docs/scl.md §3.4); 1 ms to 6000 ms", '
            '.original = "none: the CPU\'s property Maximum cycle time"),'
        )
        vr += 1
        setpoints = self.setpoints()
        for name, c_path, t, description in self.locals_of(self.checker, "", ""):
            role = "ROLE_LOCAL"
            if any(name == p or name.startswith((p + ".", p + "[")) for p in setpoints):
                role = "ROLE_TUNABLE_PARAMETER"
            rows += self.row(vr, name, c_path, t, role, description)
            vr += 1
        return rows

    def setpoints(self) -> list[str]:
        """The FMI names of the members of global DBs marked Setpoint that no block writes
        (docs/scl.md §3.9 [S7-DB-SETPOINT]): each, with every scalar it holds, a tunable
        parameter."""
        found = []
        writes = self.program.db_writes

        def written(keys):
            return any(w[: len(keys)] == keys or keys[: len(w)] == w for w in writes)

        def walk(name: str, t, keys: tuple):
            if isinstance(t, T.ArrayType) and t.dims is not None:
                for ix in scl_indices(t):
                    walk(name + ix, t.element, keys + ("[]",))
            elif isinstance(t, T.StructType):
                for key, (m, _) in t.members.items():
                    sub = keys + (key.lower(),)
                    if key in t.setpoints and not written(sub):
                        found.append(f"{name}.{key}")
                    else:
                        walk(f"{name}.{key}", m, sub)

        for d in self.checker.block.decls:
            if d.db and isinstance(d.type, T.StructType):
                walk(d.name, d.type, (d.name.lower(),))
        return found

    def row(self, vr, name, path, t, role, description, limits=None) -> list[str]:
        if isinstance(t, T.StringType):  # its maximum length (src/core/model.h: VAR_STRING)
            limits = ("0", str(t.length))
        low, high = limits or FMI_RANGE.get(t.name, (str(t.low), str(t.high)))
        fmi_name = c_string(xml_name(name))
        # ROW where the FMI name is the C path's (src/core/model.h)
        head = (
            f"ROW({vr}, {path}"
            if fmi_name == f'"{path}"'
            else f"NAMED_ROW({vr}, {fmi_name}, {path}"
        )
        return [f"    {head}, {t.var}, {role}, {low}, {high}, {c_string(xml_text(description))}),"]

    def locals_of(self, checker, name: str, c_path: str):
        """The FMI local variables (docs/scl.md §4): every elementary static, and the members of
        every instance, by their SCL path (m.speed, m.edge.Q, now.YEAR), read-only."""
        for d in checker.block.decls:
            if not d.section.static:
                continue
            for n, c, t in instances(name + fmi_part(d.name), c_path + field(d.name), d.type):
                yield from self.locals_of_static(checker, d, n, c, t)

    def locals_of_static(self, checker, d, n: str, c: str, t):
        """The FMI locals of the static d (or of an element n of its ARRAY of instances)."""
        if isinstance(t, T.FbType) and t.block is not None:
            for sub in t.block.block.decls:
                if sub.section in (A.Section.INPUT, A.Section.OUTPUT):
                    what = "input" if sub.section == A.Section.INPUT else "output"
                    yield (
                        f"{n}.{fmi_part(sub.name)}",
                        f"{c}.{field(sub.name)}",
                        sub.type,
                        f"{sub.type} {what} {sub.name} of the {t.name} instance {n}",
                    )
            yield from self.locals_of(t.block, n + ".", c + ".")
        elif isinstance(t, T.FbType):
            members = {**t.inputs, **t.outputs}
            for m, e in members.items():
                yield f"{n}.{m}", f"{c}.{m}", e, f"{e} {m} of the {t.name} {n}"
        else:  # every scalar of an ARRAY or STRUCT, by its SCL name (a[1].b, docs/scl.md §4)
            for path, leaf_name, leaf, comment in described(c, n, t, d.comment):
                if leaf.var in self.checker.core_vars:  # a 64-bit one has no FMI variable
                    what = comment or f"{leaf.name} static of {checker.block.name}"
                    yield leaf_name, path, leaf, what

    def statics(self) -> tuple[list[str], list[str]]:
        """The rows of the FMU state: every static, every member of every instance (a user FB's
        instance with its own statics and instances, recursively), and the checks of a restored
        instance."""
        rows, checks = [], []

        def walk(checker, path: str):
            for d in checker.block.decls:
                if d.section.static:
                    for _, name, t in instances(d.name, path + field(d.name), d.type):
                        static(checker, d, name, t)

        def static(checker, d, name: str, t):
            if isinstance(t, T.FbType) and t.block is not None:
                for sub in t.block.block.decls:
                    if sub.section in (A.Section.INPUT, A.Section.OUTPUT):
                        rows.append(
                            f"    STATIC(block, {name}.{field(sub.name)}, {sub.type.field}),"
                        )
                walk(t.block, name + ".")
            elif isinstance(t, T.FbType):
                parts = [(m, e.field) for m, e in {**t.inputs, **t.outputs}.items()]
                parts += list(t.memory)
                rows.extend(f"    STATIC(block, {name}.{p}, {f})," for p, f in parts)
                checks.append(f"{t.valid}(&b->{name})")
            else:  # every scalar of an ARRAY or STRUCT (docs/scl.md §4)
                for leaf, _, t in scalars(name, d.name, d.type):
                    if isinstance(t, T.StringType):  # its lengths and every character
                        checks.append(f"scl_string_is_valid(&b->{leaf}, {t.length})")
                        parts = [".max", ".len"] + [f".data[{i}]" for i in range(t.length)]
                        rows.extend(f"    STATIC(block, {leaf}{p}, {t.field})," for p in parts)
                    else:
                        rows.append(f"    STATIC(block, {leaf}, {t.field}),")

        walk(self.checker, "")
        return rows, checks

    def call_and_fault(self) -> list[str]:
        """interface.c's call of the block, with the cycle watchdog where the program has a
        loop, and then model.fault, which reports a call the watchdog stopped (docs/scl.md
        §3.4)."""
        clock = "b->scl_start_s, b->scl_local_ms" if self.program.uses_date else "0, 0"
        if not self.program.has_loop:  # no loop: no call can run out of its budget
            return [
                "static void call(void *data, const plc_call *plc)",
                "{",
                "    block *b = data;",
                f"    const scl_context ctx = {{plc, {clock}, b, NULL}};",
                f"    {self.prefix}_call(b, &ctx);",
                "}",
                "",
            ]
        return [
            "static void call(void *data, const plc_call *plc)",
            "{",
            "    block *b = data;",
            "    scl_watchdog watchdog = scl_watchdog_of(b->scl_max_cycle_ms);",
            f"    const scl_context ctx = {{plc, {clock}, b, &watchdog}};",
            f"    {self.prefix}_call(b, &ctx);",
            "    b->scl_stopped = watchdog.where;",
            "}",
            "",
            "static const char *fault(const void *data, char *msg, size_t size)",
            "{",
            "    const block *b = data;",
            "    return scl_time_error_text(b->scl_stopped, b->scl_max_cycle_ms, msg, size);",
            "}",
            "",
        ]

    def program_tick(self) -> list[str]:
        """A program's FMU starts at its tick (src/core/instance.c: CORE_DEFAULT_CYCLE_US)."""
        schedule = self.checker.program.schedule
        if schedule is None:
            return []
        return [f"#define CORE_DEFAULT_CYCLE_US {schedule.tick_us}", ""]

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
                + c_format(
                    f"a static (an instance, a string) of {self.block.name} lies outside any run"
                )
                + ");",
                "    return msg;",
                "}",
                "",
            ]
        else:
            check = []
        # lgf_model's fields beyond BLOCK_MODEL's (src/core/model.h); a block without statics
        # (an FC) has no table of them
        fields = ["BLOCK_STATICS"] if rows else []
        fields += ["NO_CYCLE_CODES"] + ([".check = check"] if checks else [])
        fields += [".fault = fault"] if self.program.has_loop else []
        statics = ["static const model_static statics[] = {", *rows, "};", ""] if rows else []
        return "\n".join(
            [
                f"/* {c_comment(self.block.name)}: its interface table, generated by lgf_fmus.scl"
                " from its",
                " * SCL (docs/scl.md §4): VAR_INPUT -> inputs, VAR_OUTPUT -> outputs, the statics",
                " * in the FMU state. */",
                "#include <math.h>",
                "#include <stdio.h>",
                "",
                *self.program_tick(),
                f'#include "blocks/{identifier(self.block.name)}/block.c"',
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
                *self.call_and_fault(),
                *check,
                *statics,
                f"BLOCK_MODEL({c_string(identifier(self.block.name))}, " + f'"{{{guid}}}", 10,',
                f"            {c_string(xml_text(description))},",
                f"            {', '.join(fields)});",
                "",
            ]
        )
