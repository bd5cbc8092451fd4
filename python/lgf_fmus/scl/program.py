"""A whole PLC program as one FMU (docs/scl.md §3.10): its ORGANIZATION_BLOCKs, the
program file that gives each OB its number, cycle, phase and priority (TIA keeps them in the OB's
properties, not in its source), and the S7 schedule that runs them, as the SCL of one FB that the
compiler turns into the FMU as any other: called once per tick (its cycleTime, the greatest
common divisor of every cycle and phase), it runs the startup OBs in its first call and then, in
every tick, each OB due, by priority (higher first), then by number, each to its end."""

from __future__ import annotations

import dataclasses
import math
import re
import tomllib
from dataclasses import dataclass, field
from html import escape
from pathlib import Path

from .diagnostics import Code, SclError

STARTUP, CYCLE, CYCLIC = "startup", "program cycle", "cyclic interrupt"
# the class of an OB by its number (S7-1500 System Manual, "Events and OBs", table of the
# triggers: startup 100, cyclic program 1, cyclic interrupt 30 to 38, each also >= 123)
CLASS_OF = {1: CYCLE, 100: STARTUP, **{n: CYCLIC for n in range(30, 39)}}
# OB30 ... OB38: the default interval (µs) and priority class (System Software for S7-300/400,
# System and Standard Functions, "Organization Blocks", the table of OBs and their default
# priority classes: 5 s ... 10 ms, 7 ... 15). An S7-1500 gives a cyclic interrupt a priority of
# 8 to 17 by its frequency (S7-1500 System Manual, "Events and OBs"): the same order.
CYCLIC_DEFAULTS = {
    30: (5_000_000, 7),
    31: (2_000_000, 8),
    32: (1_000_000, 9),
    33: (500_000, 10),
    34: (200_000, 11),
    35: (100_000, 12),
    36: (50_000, 13),
    37: (20_000, 14),
    38: (10_000, 15),
}
# OB1's cycle when program.toml gives none (docs/scl.md §3.10: the CPU's minimum cycle time)
MIN_CYCLE_US = 10_000
MAX_CYCLE_US = 60_000_000  # the core's longest cycleTime (docs/behaviour.md §1.1)
# the start information an optimized OB of each class may declare (its VAR_INPUT, as TIA writes
# it) and the value the schedule passes: Initial_Call is TRUE in an OB's first run
START_INFO = {
    CYCLE: {"INITIAL_CALL": ("Bool", None), "REMANENCE": ("Bool", "FALSE")},
    CYCLIC: {"INITIAL_CALL": ("Bool", None), "EVENT_COUNT": ("Int", "0")},
    STARTUP: {"LOSTRETENTIVE": ("Bool", "FALSE"), "LOSTRTC": ("Bool", "FALSE")},
}


@dataclass
class Ob:
    name: str
    number: int
    kind: str  # STARTUP, CYCLE or CYCLIC
    cycle_us: int = 0
    phase_us: int = 0
    priority: int = 1
    ident: str = ""  # its name in the C: TIA's "Cyclic interrupt" is Cyclic_interrupt
    image: list = field(default_factory=list)  # the tags of its process image partition


@dataclass
class Schedule:
    name: str  # the FMU's (the FB of the schedule)
    obs: list[Ob]
    min_cycle_us: int
    file: str = "program.toml"  # where it was read, for the errors
    tags: list = field(default_factory=list)  # the tag table's (tags.Tag), docs/scl.md §3.12
    tags_file: str = "PLCTags.xlsx"

    def period(self, ob: Ob) -> int:
        return self.min_cycle_us if ob.kind == CYCLE else ob.cycle_us

    @property
    def tick_us(self) -> int:
        """The FMU's cycleTime: every OB's cycle and phase is a whole number of ticks."""
        times = [self.period(ob) for ob in self.obs if ob.kind != STARTUP]
        times += [ob.phase_us for ob in self.obs]
        return math.gcd(*times) or self.min_cycle_us

    @property
    def startups(self) -> list[Ob]:
        return sorted((ob for ob in self.obs if ob.kind == STARTUP), key=lambda ob: ob.number)

    @property
    def cyclic(self) -> list[Ob]:
        """The OBs that run again and again, in the order of one tick: by priority, higher
        first, then by number (S7-1500 System Manual, "Events and OBs": OB priority and runtime
        behavior)."""
        runs = [ob for ob in self.obs if ob.kind != STARTUP]
        return sorted(runs, key=lambda ob: (-ob.priority, ob.number))

    def qry_cint(self) -> list[Ob]:
        return sorted((ob for ob in self.obs if ob.kind == CYCLIC), key=lambda ob: ob.number)


def _fail(file, message: str, loc=None, code=Code.PROGRAM):
    """Refuses the program file (file: its path) or, at loc, a declaration of an OB."""
    raise SclError(loc, f"{file}: {message}" if loc is None else message, code)


def _integer(file, where: str, table: dict, key: str, low: int, high: int, default=None):
    value = table.get(key, default)
    if value is None:
        _fail(file, f"{where}: {key} is missing (docs/scl.md §3.10)")
    if isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high:
        _fail(file, f"{where}: {key} = {value!r} is not a whole number from {low} to {high}")
    return value


def load(path, name: str | None = None) -> Schedule:
    """The program file (docs/scl.md §3.10): its OBs by their names in the SCL."""
    file = str(path)
    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except OSError as e:
        data = f"cannot read it ({e.strerror})"
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as e:
        data = f"not a TOML file ({e})"
    if isinstance(data, str):
        _fail(file, data)
    return from_dict(data, file, name)


def from_dict(data: dict, file="program.toml", name: str | None = None) -> Schedule:
    unknown = set(data) - {"name", "min_cycle_us", "ob"}
    if unknown:
        _fail(file, f"unknown key {sorted(unknown)[0]!r} (name, min_cycle_us, [ob.<Name>])")
    name = data.get("name", name) or "Program"
    if not isinstance(name, str) or not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]{0,127}", name):
        _fail(file, f"name = {name!r}: the FMU's name is letters, digits and _ (a C name)")
    min_cycle = _integer(file, "the program", data, "min_cycle_us", 1, MAX_CYCLE_US, MIN_CYCLE_US)
    tables = data.get("ob", {})
    if not isinstance(tables, dict) or not tables:
        _fail(file, "no OB: give each OB a table [ob.<its name>] with its number")
    obs, numbers = [], {}
    for ob_name, table in tables.items():
        where = f"[ob.{ob_name}]"
        if not isinstance(table, dict):
            _fail(file, f"{where} is no table")
        unknown = set(table) - {"number", "class", "cycle_us", "phase_us", "priority"}
        unknown -= {"process_image"}
        if unknown:
            _fail(file, f"{where}: unknown key {sorted(unknown)[0]!r}")
        number = _integer(file, where, table, "number", 1, 32767)
        if number in numbers:
            _fail(file, f"{where}: OB{number} is also [ob.{numbers[number]}]")
        numbers[number] = ob_name
        kind = CLASS_OF.get(number)
        given = table.get("class")
        if given is not None and given not in (STARTUP, CYCLE, CYCLIC):
            _fail(file, f"{where}: class = {given!r} is none of {STARTUP!r}, {CYCLE!r}, {CYCLIC!r}")
        if kind is None and number >= 123:
            kind = given
            if kind is None:
                _fail(file, f"{where}: OB{number} needs its class ({CYCLE!r}, {CYCLIC!r}, ...)")
        elif kind is None:
            _fail(
                file,
                f"{where}: OB{number} is no startup, program cycle or cyclic-interrupt OB "
                "(1, 100, 30 to 38 or from 123): its events are not supported (docs/scl.md §3.10)",
            )
        elif given is not None and given != kind:
            _fail(file, f"{where}: OB{number} is a {kind} OB, not a {given} OB")
        ob = Ob(ob_name, number, kind)
        if kind == CYCLIC:
            cycle, priority = CYCLIC_DEFAULTS.get(number, (None, None))
            ob.cycle_us = _integer(file, where, table, "cycle_us", 1, MAX_CYCLE_US, cycle)
            ob.phase_us = _integer(file, where, table, "phase_us", 0, ob.cycle_us - 1, 0)
            ob.priority = _integer(file, where, table, "priority", 2, 24, priority)
            ob.image = table.get("process_image", [])
            if not isinstance(ob.image, list) or not all(isinstance(t, str) for t in ob.image):
                _fail(file, f"{where}: process_image is a list of tag names")
        else:
            if "process_image" in table:
                _fail(
                    file,
                    f"{where}: a {kind} OB has no process_image (OB1 updates the whole image "
                    "but the partitions of cyclic OBs: docs/scl.md §3.12)",
                )
            for key in ("cycle_us", "phase_us"):
                if key in table:
                    what = "min_cycle_us of the program" if kind == CYCLE else "none"
                    _fail(file, f"{where}: a {kind} OB has no {key} (its cycle: {what})")
            _integer(file, where, table, "priority", 1, 1, 1)
        obs.append(ob)
    return Schedule(name, obs, min_cycle, file)


def check_obs(schedule: Schedule, found: dict, file: str) -> None:
    """Every OB of the sources has its table in the program file and every table its OB; the
    start information each declares is its class's (docs/scl.md §3.10)."""
    obs = {k: b for k, (b, _) in found.items() if b.kind == "ORGANIZATION_BLOCK"}
    named = {ob.name.lower(): ob for ob in schedule.obs}
    for key, block in obs.items():
        if key not in named:
            _fail(
                file,
                f'the ORGANIZATION_BLOCK "{block.name}" has no table [ob.{block.name}] in '
                f"{file} (its number, cycle, phase, priority: docs/scl.md §3.10)",
                block.loc,
            )
        ob = named[key]
        ob.name = block.name
        allowed = START_INFO[ob.kind]
        for d in block.decls:
            if str(d.section) != "VAR_INPUT":
                continue
            expected = allowed.get(d.name.upper())
            if expected is None or d.type_name.upper() != expected[0].upper():
                info = ", ".join(f"{k.title()} : {t}" for k, (t, _) in allowed.items())
                _fail(
                    file,
                    f"'{d.name}': the VAR_INPUT of a {ob.kind} OB is its start information "
                    f"({info}), as TIA declares it (docs/scl.md §3.10)",
                    d.loc,
                    Code.DECLARATION,
                )
    for ob in schedule.obs:
        if ob.name.lower() not in obs:
            names = ", ".join(b.name for b in obs.values()) or "none"
            _fail(
                file,
                f"[ob.{ob.name}]: no ORGANIZATION_BLOCK of that name in the sources "
                f"(they define: {names})",
            )
    if schedule.name.lower() in found:
        _fail(
            file,
            f"the program's name {schedule.name!r} is a block's of the sources: name the "
            "program otherwise (name = ...)",
        )


def check_tags(schedule: Schedule, names: set, tags_file: str) -> None:
    """The tags against the program (docs/scl.md §3.12): no tag has a block's or DB's name (names:
    theirs, in lower case), each tag of a partition (process_image) is an %I or %Q tag of the
    table and in no other partition."""
    for tag in schedule.tags:
        if tag.name.lower() in names or tag.name.lower() == schedule.name.lower():
            _fail(tags_file, f"row {tag.row}: the tag {tag.name!r} has the name of a block or DB")
    known = {t.name.lower(): t for t in schedule.tags}
    taken = {}
    for ob in schedule.obs:
        for name in ob.image:
            tag = known.get(name.lower())
            where = f"[ob.{ob.name}] process_image"
            if tag is None or tag.area == "M":
                what = "an %M tag, which has no process image" if tag else "no tag of the table"
                _fail(schedule.file, f"{where}: {name!r} is {what}")
            if tag.name in taken:
                _fail(schedule.file, f"{where}: {name!r} is also in [ob.{taken[tag.name]}]'s")
            taken[tag.name] = ob.name


def partition(schedule: Schedule, ob: Ob | None) -> list:
    """The tags whose image the OB updates: ob None, those of OB1's Automatic update, which are
    all tags that no cyclic OB's partition holds (docs/scl.md §3.12 [DEC-TAG-IMAGE])."""
    if ob is not None:
        names = {n.lower() for n in ob.image}
        return [t for t in schedule.tags if t.name.lower() in names]
    held = {n.lower() for o in schedule.obs for n in o.image}
    return [t for t in schedule.tags if t.area != "M" and t.name.lower() not in held]


def _copies(tags: list, area: str) -> list[str]:
    """The SCL that copies the FMU's inputs into the process image input (area I) or the process
    image output into the FMU's outputs (area Q)."""
    if area == "I":
        return [f"    #PII.{t.name} := #{t.name};" for t in tags if t.area == "I"]
    return [f"    #{t.name} := #PIQ.{t.name};" for t in tags if t.area == "Q"]


def _tag_declarations(schedule: Schedule) -> list[str]:
    """The FMU's inputs (%I), outputs (%Q), the process image (PII, PIQ) and the bit memory (%M)
    as declarations of the schedule's FB, each with its comment and address."""

    def decl(t, pad="   "):
        comment = " ".join(f"{t.address} {t.comment}".split())
        return f"{pad}{t.name} : {t.type_name};  // {comment}"

    lines = []
    for area, section in (("I", "VAR_INPUT"), ("Q", "VAR_OUTPUT")):
        tags = [t for t in schedule.tags if t.area == area]
        if tags:
            lines += [section, *(decl(t) for t in tags), "END_VAR"]
    lines.append("VAR")
    for area, image in (("I", "PII"), ("Q", "PIQ")):
        tags = [t for t in schedule.tags if t.area == area]
        if tags:
            what = "input" if area == "I" else "output"
            lines.append(f"   {image} : STRUCT  // the process image {what}")
            lines += [decl(t, "      ") for t in tags]
            lines.append("   END_STRUCT;")
    lines += [decl(t) for t in schedule.tags if t.area == "M"]
    return lines


def c_names(schedule: Schedule, found: dict, file: str) -> None:
    """Gives each OB of the sources a name the C can hold: TIA names a new OB "Cyclic
    interrupt", and nothing calls an OB by its name, so its characters other than letters,
    digits and _ become _ (docs/scl.md §3.10)."""
    for ob in schedule.obs:
        block, text = found.pop(ob.name.lower())
        ob.ident = re.sub(r"[^A-Za-z0-9_]", "_", ob.name)
        if not re.match(r"[A-Za-z_]", ob.ident):
            ob.ident = "_" + ob.ident
        if ob.ident.lower() in found or ob.ident.lower() == schedule.name.lower():
            _fail(
                file,
                f'the OB "{ob.name}" is {ob.ident} in the C, as is another block or the '
                "program: rename one",
                block.loc,
            )
        block.name = ob.ident
        found[ob.ident.lower()] = (block, text)


def ob_constants(schedule: Schedule, found: dict) -> None:
    """An OB's name where a value stands ("Cyclic interrupt" as an LGF CI block's callOB) is the
    system constant TIA makes of it, the OB's number (docs/scl.md §3.10 [S7-OB-CONSTANT]): in
    every block of the program, a quoted name with no selector that names an OB becomes the
    integer literal of its number."""
    from . import ast as A

    numbers = {ob.name.lower(): ob.number for ob in schedule.obs}

    def constant(x):
        if isinstance(x, (list, tuple)):  # a node's children, and IF's (condition, body) pairs
            return type(x)(constant(v) for v in x)
        if isinstance(x, A.VarRef) and x.quoted and not x.members and x.name.lower() in numbers:
            return A.Literal(x.loc, "int", f'"{x.name}"', numbers[x.name.lower()])
        return x

    for block, _ in found.values():
        for node in list(A.nodes(block.body)):
            for f in dataclasses.fields(node):
                if f.init and f.name != "loc":
                    setattr(node, f.name, constant(getattr(node, f.name)))


def _arguments(block, ob: Ob, first: str) -> str:
    given = []
    for d in block.decls:
        if str(d.section) == "VAR_INPUT":
            value = START_INFO[ob.kind][d.name.upper()][1] or first
            given.append(f"{d.name} := {value}")
    return ", ".join(given)


def source(schedule: Schedule, found: dict) -> str:
    """The SCL of the schedule's FB: the FMU calls it once per tick (docs/scl.md §3.10)."""
    tick = schedule.tick_us
    block = {k: b for k, (b, _) in found.items()}
    lines = [
        f'FUNCTION_BLOCK "{schedule.name}"',
        f"TITLE = the PLC program {schedule.name}, one call per tick of {tick} µs",
        *_tag_declarations(schedule),
        "   schedule_started : Bool;  // the startup OBs have run",
    ]
    for ob in schedule.cyclic:
        phase = ob.phase_us // tick
        lines.append(f"   schedule_OB{ob.number}_due : DInt := {phase};  // ticks to its next run")
        lines.append(f"   schedule_OB{ob.number}_first : Bool := TRUE;  // before its first run")
    lines += ["END_VAR", "BEGIN", "IF NOT #schedule_started THEN"]
    for ob in schedule.startups:
        lines.append(f'    "{ob.ident}"({_arguments(block[ob.ident.lower()], ob, "TRUE")});')
    lines += ["    #schedule_started := TRUE;", "END_IF;"]
    cycles = [ob for ob in schedule.cyclic if ob.kind == CYCLE]
    automatic = partition(schedule, None)
    for ob in schedule.cyclic:
        due = f"#schedule_OB{ob.number}_due"
        first = f"#schedule_OB{ob.number}_first"
        # the process image: OB1's around the program cycle OBs, a cyclic OB's around it
        image = automatic if ob.kind == CYCLE else partition(schedule, ob)
        before = _copies(image, "I") if ob.kind != CYCLE or ob is cycles[0] else []
        after = _copies(image, "Q") if ob.kind != CYCLE or ob is cycles[-1] else []
        lines += [
            f"IF {due} = 0 THEN",
            *before,
            f'    "{ob.ident}"({_arguments(block[ob.ident.lower()], ob, first)});',
            *after,
            f"    {first} := FALSE;",
            f"    {due} := {schedule.period(ob) // tick};",
            "END_IF;",
            f"{due} := {due} - 1;",
        ]
    lines += ["END_FUNCTION_BLOCK", ""]
    return "\n".join(lines)


def qry_cint_c(schedule: Schedule) -> list[str]:
    """QRY_CINT of a program (docs/scl.md §3.10): the cycle and phase of the cyclic-interrupt OB
    OB_NR names, as the CPU answers; for a number that is no cyclic-interrupt OB of the
    program, 16#8090 "OB does not exist or is of wrong type" and zeros."""
    lines = [
        "static int16_t scl_program_qry_cint(int64_t ob, uint32_t *cycle, uint32_t *phase,",
        "                                    uint32_t *status)",
        "{",
        "    uint32_t c = 0, p = 0, s = 0;",
        "    int16_t ret = (int16_t)0x8090;",
        "    switch (ob) {",
    ]
    for ob in schedule.qry_cint():
        lines.append(
            f"    case {ob.number}: c = {ob.cycle_us}u; p = {ob.phase_us}u; s = 0x0014u; ret = 0;"
            " break;"
        )
    lines += [
        "    default: break;",
        "    }",
        "    if (cycle) *cycle = c;",
        "    if (phase) *phase = p;",
        "    if (status) *status = s;",
        "    return ret;",
        "}",
        "",
    ]
    return lines


def qry_cint_word_c() -> list[str]:
    """QRY_CINT of a program with its STATUS into a WORD (docs/scl.md §3.6)."""
    return [
        "static int16_t scl_program_qry_cint_word(int64_t ob, uint32_t *cycle, uint32_t *phase,",
        "                                         uint16_t *status)",
        "{",
        "    uint32_t word;",
        "    int16_t ret = scl_program_qry_cint(ob, cycle, phase, &word);",
        "    if (status) *status = (uint16_t)word;",
        "    return ret;",
        "}",
        "",
    ]


def html(schedule: Schedule) -> str:
    """The documentation's table of the OBs, each with its cycle."""
    rows = []
    for ob in schedule.startups + schedule.cyclic:
        if ob.kind == STARTUP:
            when = "once, in the first call (initialization)"
        else:
            period = schedule.period(ob)
            when = f"every {period} µs from {ob.phase_us} µs"
        rows.append(
            f"<tr><td>OB{ob.number}</td><td><code>{escape(ob.name)}</code></td>"
            f"<td>{ob.kind}</td><td>{when}</td><td>{ob.priority}</td></tr>"
        )
    tags = []
    if schedule.tags:
        causality = {"I": "input", "Q": "output", "M": "local"}
        tags = [
            "<h2>PLC tags</h2>",
            "<p>%I tags are read through the process image input <code>PII</code>, %Q tags "
            "written through the process image output <code>PIQ</code> (docs/scl.md §3.12).</p>",
            "<table><tr><th>tag</th><th>address</th><th>type</th><th>FMI</th><th>comment</th></tr>",
            *(
                f"<tr><td><code>{escape(t.name)}</code></td><td>{t.address}</td>"
                f"<td>{escape(t.type_name)}</td><td>{causality[t.area]}</td>"
                f"<td>{escape(t.comment)}</td></tr>"
                for t in schedule.tags
            ),
            "</table>",
        ]
    return "\n".join(
        [
            "<h2>Organization blocks</h2>",
            f"<p>One tick (<code>cycleTime</code>) is {schedule.tick_us} µs; in each tick the OBs "
            "due run by priority, higher first, then by number, each to its end, taking no "
            "simulated time (docs/scl.md §3.10).</p>",
            "<table><tr><th>OB</th><th>name</th><th>class</th><th>runs</th><th>priority</th></tr>",
            *rows,
            "</table>",
            *tags,
        ]
    )
