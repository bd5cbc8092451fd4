"""lgf_fmus.scl: the SCL compiler (docs/scl.md). A TIA Portal SCL export in, an FMU out that runs
the FUNCTION_BLOCK once per PLC cycle with S7-1500 semantics:

    parser.py  SCL text -> syntax tree (Lark, scl.lark), every node at its file:line:col
    checks.py  names, S7 types, implicit conversions, in passes (check_*.py): every error of
               the program as one SclError (diagnostics.py) before any C is generated
    lower.py   the checked tree in the simpler forms the C generation takes
    cgen.py    the block's C, as a hand-written block of src/blocks/ (block.h/.c, interface.c)
    build.py   the FMU's translation unit, modelDescription.xml, the library, the zip

    compile(sources, block=..., fmi=2, output=...) -> Path of the .fmu"""

from __future__ import annotations

from pathlib import Path

from .ast import SclError

__all__ = ["SclError", "compile", "generate_c"]


def _read(sources) -> list[tuple[str, str]]:
    if isinstance(sources, (str, Path)):
        sources = [sources]
    texts = []
    for source in sources:
        path = Path(source)
        try:
            texts.append((str(source), path.read_text(encoding="utf-8-sig")))
        except OSError as e:
            raise SclError(None, f"{source}: cannot read it ({e.strerror})") from None
        except UnicodeDecodeError:
            raise SclError(None, f"{source}: not UTF-8 text") from None
    if not texts:
        raise SclError(None, "no SCL source given")
    return texts


def generate_c(
    sources, block: str | None, schedule=None, iec_check: bool = False, auto_eno: bool = False
) -> dict[str, str]:
    """The C of the FB `block` of the SCL sources (paths), by its path under sources/, and its
    documentation/index.html; with a schedule (program.Schedule) instead of a block, of the
    whole program: its OBs run by the FB of the schedule (docs/scl.md §3.10). Raises an SclError
    of every error of the program (docs/scl.md §5): the syntax errors of every source, else
    every error the checks find. iec_check: TIA Portal's "IEC check", off as by TIA's default
    (docs/scl.md §3.2); auto_eno: its "Set ENO automatically", off as by TIA's default (§3.4)."""
    from . import build, cgen, checks, lower, parser, tia
    from . import program as P
    from .diagnostics import Code, Diagnostics

    read = _read(sources)
    diagnostics = Diagnostics(dict(read))
    found, udts, dbs, texts = {}, {}, {}, []
    for file, text in read:
        texts.append(text)
        try:
            units = parser.parse(text, file)
        except SclError as e:
            diagnostics.report(e)
            continue
        for b in units:
            # a UDT (docs/scl.md §2) or a DB (§3.9), for the blocks of every source
            shared = {"TYPE": udts, "DATA_BLOCK": dbs}.get(b.kind)
            table = shared if shared is not None else found
            first = table.get(b.name.lower())
            if first is not None:
                first = first[0] if isinstance(first, tuple) else first
                what = {"TYPE": "the type ", "DATA_BLOCK": "the DB "}.get(b.kind, "")
                diagnostics.report(
                    SclError(
                        b.loc,
                        f"{what}{b.name} is defined twice",
                        Code.DUPLICATE,
                        [(first.loc, "first defined here")],
                    )
                )
            elif shared is not None:
                shared[b.name.lower()] = b
            else:
                found[b.name.lower()] = (b, text)
    diagnostics.check()  # syntax errors: the checks would only repeat them
    # S7's system data types that are STRUCTs (TADDR_Param), where the sources define no type
    # of their name (docs/scl.md §3.8)
    for b in parser.parse(tia.SYSTEM_TYPES, tia.SYSTEM_TYPES_FILE):
        udts.setdefault(b.name.lower(), b)
    if schedule is not None:  # the FB of the schedule, in SCL, compiled as any other
        if schedule.tags:
            P.check_tags(schedule, {*found, *dbs}, schedule.tags_file)
        P.check_obs(schedule, found, schedule.file)
        P.c_names(schedule, found, schedule.file)
        P.ob_constants(schedule, found)
        text = P.source(schedule, found)
        file = f"{schedule.name}.schedule.scl"
        diagnostics.sources[file] = text
        (unit,) = parser.parse(text, file)
        found[unit.name.lower()] = (unit, text)
        texts.append(text)
        block = unit.name
    if block.lower() not in found:
        names = ", ".join(b.name for b, _ in found.values()) or "none"
        raise SclError(None, f"no block {block!r} in the sources (they define: {names})")
    b, text = found[block.lower()]
    core_vars, core_fields = build.core_kinds(build.c_sources())
    blocks = {k: v for k, (v, _) in found.items()}
    try:
        program = checks.Program(
            blocks, core_vars, core_fields, udts, dbs, diagnostics, iec_check, auto_eno
        )
        checker = checks.check(b, program, schedule)
    except SclError as e:  # with the source lines of its places
        e.sources = e.sources or diagnostics.sources
        raise
    lower.lower(checker.program)  # the checked tree in the forms the C generation takes
    # the FMU's GUID from every source its program may take a block or a UDT from
    texts = list(dict.fromkeys(texts))
    generated = cgen.generate(checker, text if len(texts) == 1 else "\n".join(texts))
    page = cgen.documentation(checker)
    if schedule is not None:  # each OB with its cycle
        page = page.replace("</body></html>", P.html(schedule) + "\n</body></html>")
    generated["documentation/index.html"] = page
    return generated


def compile(
    sources,
    block: str | None = None,
    fmi: int = 2,
    output=None,
    *,
    werror: bool = False,
    win64=None,
    aarch64=None,
    iec_check: bool = False,
    program=None,
    tags=None,
    auto_eno: bool = False,
) -> Path:
    """Compiles the FUNCTION_BLOCK `block` of the SCL sources (a path or paths) into an FMU of
    FMI 2.0 (Co-Simulation and Model Exchange) or 3.0, written to output (default <block>.fmu)
    and returned; with program (the path of a program.toml) instead of block, the whole
    program: its OBs on their cycles (docs/scl.md §3.10), the FMU named by the file's `name`, else
    by output; tags, the path of its PLC tag table (TIA's .xlsx export or a CSV of its columns):
    its %I tags the FMU's inputs, its %Q tags its outputs through the process image (docs/scl.md
    §3.12). Raises SclError for a source it refuses: every error, each
    "file:line:col: error E0nn: message" (docs/scl.md §5).
    win64: None adds a win64 binary where mingw-w64 is installed, True requires it, False
    leaves it out; aarch64 likewise for the aarch64-linux binary of an FMI 3.0 FMU (Debian's
    gcc-aarch64-linux-gnu). iec_check: TIA Portal's "IEC check" on, S7's implicit conversions only
    towards a type that holds every value; off (TIA's default) also those between integers
    and bit strings of every width (docs/scl.md §3.2). auto_eno: TIA's "Set ENO automatically"
    on: a REAL operation whose result is no finite REAL sets ENO FALSE (docs/scl.md §3.4)."""
    from . import build
    from . import program as P

    if fmi not in (2, 3):
        raise SclError(None, f"fmi must be 2 or 3, not {fmi!r}")
    schedule = None
    if program is not None:
        if block is not None:
            raise SclError(None, "give a block or a program, not both")
        schedule = P.load(program, Path(output).stem if output is not None else None)
        if tags is not None:
            from . import tags as tag_table

            schedule.tags, schedule.tags_file = tag_table.load(tags), str(tags)
    elif tags is not None:
        raise SclError(None, "a tag table belongs to a program: give program= (--program) too")
    elif block is None:
        raise SclError(None, "compile needs the block to compile, or a program")
    generated = generate_c(sources, block, schedule, iec_check=iec_check, auto_eno=auto_eno)
    name = next(iter(generated)).split("/")[1]
    output = Path(output) if output is not None else Path(f"{name}.fmu")
    return build.build(name, generated, fmi, output, werror=werror, win64=win64, aarch64=aarch64)
