"""The sources/ inside each FMU are enough to build it, and they carry the FMU's floating-point
contract themselves (src/core/numerics.h, docs/behaviour.md §1.4), so that any compiler flags
give the same bits. From a copy of each FMU whose binaries are removed (tests/rebuild.py):

- an importer that compiles FMUs for its own platform does what FMPy's
  fmpy.build.build_platform_binary does (CMake with sources/ as include directory and the XML's
  SourceFiles as sources). That rebuild must compile without a warning (FMPy's -Wall -Wextra
  -Wpedantic) and simulate every demo scenario of the block with results identical, bit for
  bit, to the FMU of the CMake build (the FMI 3.0 FMUs: tests/test_fmi3.py);
- rebuilt with gcc and clang, one compiler command each, at -O2 -march=native (the FMI 2.0
  FMUs) and at -O3 with -mfma (on x86-64 whose CPU has FMA, so that the compiler may fuse a
  multiply and an add even where -march=native would not) and a flag that the header's pragmas
  must override (FMI 2.0 and 3.0), every FMU must compile without a warning under -Werror and
  replay every committed reference result (tests/blocks/<Block>/references/) bit for bit.
  Without the header, a fused multiply-add rounds once instead of twice and the results
  differ in the last bit;
- -ffast-math and its parts are refused at compile time, with a message that says why;
- several source-code FMUs compiled with a prefix link into one program."""

from __future__ import annotations

import platform
import re
import shutil
import subprocess
from pathlib import Path

import fmpy
import numpy as np
import pytest
from fmpy import extract

from tests.harness import ROOT, fmu_path, unpacked
from tests.lgf_blocks import blocks, names, param_id, scenarios
from tests.rebuild import FMPY, FMU_DIRS, HEADERS, Compiler, by_block
from tests.test_references import as_number, read_reference
from tests.timeouts import hang_guard
from tools.simulate import simulate

BLOCKS = names()


@pytest.mark.parametrize("block", BLOCKS)
@pytest.mark.parametrize("version", FMU_DIRS)
def test_builds_from_sources_alone(version, block, rebuilt):
    """FMPy's build, FMI 2.0 and FMI 3.0: the binary, and not one warning."""
    built = by_block(rebuilt, FMPY, version)[block]
    if built.failure:
        pytest.fail(built.failure)
    folder = fmpy.platform if version == 2 else fmpy.platform_tuple
    binary = built.unzipped / "binaries" / folder / f"{block}{fmpy.sharedLibraryExtension}"
    assert binary.is_file()
    output = built.output
    assert "Building C object" in output, output
    assert [line for line in output.splitlines() if "warning" in line.lower()] == []


@pytest.mark.parametrize("scenario", scenarios())
def test_rebuilt_fmu_simulates_identically(scenario, rebuilt):
    built = by_block(rebuilt, FMPY, 2)[scenario.block]
    if built.failure:
        pytest.fail(built.failure)
    expected, outputs, _ = simulate(scenario, ROOT / "fmus")
    result, _, _ = simulate(scenario, built.folder)
    assert result.dtype == expected.dtype
    for name in ("time", *outputs):
        assert np.array_equal(result[name], expected[name]), name


def _x86_64_with_fma() -> bool:
    """An x86-64 whose CPU has FMA (on one without, -mfma code would stop at the first fused
    instruction; aarch64 always has FMA, and -march=native there enables it)."""
    if platform.machine().lower() not in ("x86_64", "amd64"):
        return False
    try:
        return "fma" in Path("/proc/cpuinfo").read_text().split()
    except OSError:
        return False


FMA = ("-mfma",) if _x86_64_with_fma() else ()
# Two builds a compiler: -O3 with FMA and the flag joined, since a header whose pragmas undo the
# flag at -O3 undoes the compiler's own default contraction there too (the 22 blocks' 264
# rebuilds of three builds a compiler were the suite's largest part).
COMPILERS = [
    Compiler("gcc", ("-O2", "-march=native")),
    Compiler("gcc", ("-O3", *FMA, "-ffp-contract=fast")),  # GCC's pragma overrides it
    Compiler("clang", ("-O2", "-march=native")),
    Compiler("clang", ("-O3", *FMA, "-funsafe-math-optimizations")),  # float_control undoes it
]
# The FMI 3.0 FMUs by the two -O3 builds alone: their blocks' C is the FMI 2.0 FMUs', so what
# -O2 -march=native would fuse there the -O3 builds with FMA fuse too (the test time it saves
# keeps make test within its budget as the catalogue grows).
BUILDS = [(c, 2) for c in COMPILERS] + [(c, 3) for c in COMPILERS if "-O3" in c.flags]
BUILD_IDS = [f"{c.name.replace(' ', '')}-{version}" for c, version in BUILDS]
SCENARIOS = [(block, scenario) for block in blocks() for scenario in block.scenarios]


@pytest.fixture(scope="module")
def compiled(rebuilt):
    """Every FMU rebuilt by the compilers of BUILDS that are installed, each FMI version's
    builds at once, so that they keep every CPU busy: {(compiler, fmu): Rebuilt}."""
    built = {}
    for version, folder in FMU_DIRS.items():
        compilers = [c for c, v in BUILDS if v == version and not c.missing()]
        built.update(rebuilt(compilers, [fmu_path(block, folder) for block in BLOCKS]))
    return built


def compiled_fmu(compiled, compiler: Compiler, block: str, version: int):
    if reason := compiler.missing():
        pytest.skip(reason)
    return compiled[compiler, fmu_path(block, FMU_DIRS[version])]


@pytest.mark.parametrize("compiler, version", BUILDS, ids=BUILD_IDS)
def test_compiles_without_a_warning(compiler, version, compiled):
    """-Wall -Wextra -Wpedantic -Werror: no warning, none of an unknown pragma either."""
    failures = [
        built.failure
        for built in (compiled_fmu(compiled, compiler, block, version) for block in BLOCKS)
        if built.failure
    ]
    assert not failures, "\n".join(failures)


def same_bits(a: float, b: float) -> bool:
    """The same double, the sign of zero included (any NaN equals any NaN)."""
    return repr(a) == repr(b)


@pytest.mark.parametrize("block, scenario", SCENARIOS, ids=[param_id(s) for _, s in SCENARIOS])
@pytest.mark.parametrize("compiler, version", BUILDS, ids=BUILD_IDS)
def test_replays_every_reference_bit_for_bit(compiler, version, block, scenario, compiled):
    built = compiled_fmu(compiled, compiler, block.name, version)
    if built.failure:
        pytest.fail(built.failure)
    reference = read_reference(block, scenario)
    result, _, _ = simulate(scenario, built.folder, echo=False)
    assert len(result) == len(reference)
    differing = [
        (ref, {n: as_number(row[n]) for n in ref})
        for row, ref in zip(result, reference)
        if not all(same_bits(as_number(row[n]), value) for n, value in ref.items())
    ]
    if differing:
        ref, got = differing[0]
        first = {n: (got[n], ref[n]) for n in ref if not same_bits(got[n], ref[n])}
        pytest.fail(
            f"{len(differing)} of {len(reference)} rows differ from "
            f"{block.reference(scenario).relative_to(ROOT)}; the first at "
            f"t = {ref['time']}: (rebuilt, reference) {first}"
        )


# The flags refused at compile time, with (a part of) the message that names them.
REFUSED = [
    ("gcc", "-ffast-math", "-ffast-math (or -Ofast) is not supported"),
    ("gcc", "-Ofast", "-ffast-math (or -Ofast) is not supported"),
    ("gcc", "-ffinite-math-only", "-ffinite-math-only is not supported"),
    ("gcc", "-funsafe-math-optimizations", "-funsafe-math-optimizations (or a part) is not"),
    ("gcc", "-fno-signed-zeros", "-funsafe-math-optimizations (or a part) is not"),
    ("gcc", "-fsingle-precision-constant", "breaks IEEE 754 arithmetic (__GCC_IEC_559 is 0)"),
    ("clang", "-ffast-math", "-ffast-math (or -Ofast) is not supported"),
    ("clang", "-Ofast", "-ffast-math (or -Ofast) is not supported"),
    ("clang", "-ffinite-math-only", "-ffinite-math-only is not supported"),
]


@pytest.mark.parametrize("cc, flag, message", REFUSED, ids=[f"{c}{f}" for c, f, _ in REFUSED])
def test_value_changing_flags_are_refused(cc, flag, message):
    """Every FMU's one translation unit includes the header first (tests/test_fmu_contents.py),
    so one FMU's stands for all."""
    if not shutil.which(cc):
        pytest.skip(Compiler(cc, ()).missing())
    sources = Path(unpacked(BLOCKS[0])[1]) / "sources"
    run = subprocess.run(
        [
            cc,
            flag,
            "-fsyntax-only",
            f"-I{sources}",
            f"-I{HEADERS}",
            str(sources / f"{BLOCKS[0]}.c"),
        ],
        check=False,
        capture_output=True,
        text=True,
        timeout=hang_guard(60),
    )
    assert run.returncode != 0, f"{cc} {flag} was accepted"
    errors = [line for line in run.stderr.splitlines() if "error:" in line]
    assert errors and all("core/numerics.h:" in line for line in errors), run.stderr
    assert message in run.stderr, run.stderr


def _entry_points() -> list[str]:
    """The names of the FMI 2.0 functions, from the typedefs of FMPy's fmi2FunctionTypes.h."""
    text = (HEADERS / "fmi2FunctionTypes.h").read_text()
    return sorted(set(re.findall(r"\bfmi2(\w+)TYPE\s*\(", text)))


def test_sources_link_beside_each_other(tmp_path):
    """Two or more source-code FMUs compiled with FMI2_FUNCTION_PREFIX link into one program:
    nothing but the (prefixed) fmi2 functions has external linkage. FMPy's copy of
    fmi2Functions.h ignores the prefix, so a header of the same name in front of it applies the
    prefix as the standard's header does: every function name defined to <prefix>fmi2<Name>."""
    if not shutil.which("cc") or not shutil.which("nm"):
        pytest.fail("cc and nm are needed to compile the FMUs' sources")
    assert len(BLOCKS) >= 2
    objects, main = [], ["#include <stdio.h>"]
    for block in BLOCKS:
        sources = Path(extract(str(fmu_path(block)), str(tmp_path / block))) / "sources"
        prefixed = tmp_path / f"{block}-include"
        prefixed.mkdir()
        (prefixed / "fmi2Functions.h").write_text(
            f'#include "{HEADERS / "fmi2Functions.h"}"\n'
            + "".join(f"#undef fmi2{n}\n#define fmi2{n} {block}_fmi2{n}\n" for n in _entry_points())
        )
        obj = tmp_path / f"{block}.o"
        subprocess.run(
            [
                "cc",
                "-c",
                "-O1",
                "-Wall",
                "-Wextra",
                "-Werror",
                f"-DFMI2_FUNCTION_PREFIX={block}_",
                f"-I{prefixed}",
                f"-I{sources}",
                f"-I{HEADERS}",
                str(sources / f"{block}.c"),
                "-o",
                str(obj),
            ],
            check=True,
            capture_output=True,
            text=True,
        )
        nm = subprocess.run(
            ["nm", "--defined-only", "--extern-only", str(obj)],
            check=True,
            capture_output=True,
            text=True,
        ).stdout
        defined = [line.split()[-1] for line in nm.splitlines() if line.strip()]
        assert defined and [s for s in defined if not s.startswith(f"{block}_fmi2")] == [], block
        objects.append(str(obj))
        main.append(f"const char *{block}_fmi2GetVersion(void);")
    main.append("int main(void) {")
    main += [f'    printf("%s\\n", {block}_fmi2GetVersion());' for block in BLOCKS]
    main.append("    return 0;\n}")
    (tmp_path / "main.c").write_text("\n".join(main) + "\n")
    program = tmp_path / "program"
    link = subprocess.run(
        ["cc", str(tmp_path / "main.c"), *objects, "-lm", "-o", str(program)],
        capture_output=True,
        text=True,
    )
    assert link.returncode == 0, link.stderr
    run = subprocess.run([str(program)], check=True, capture_output=True, text=True)
    assert run.stdout.split() == ["2.0"] * len(BLOCKS)


def test_a_rebuilt_library_leaves_the_process_s_subnormals_alone(compiled):
    """The FMU rebuilt with clang -funsafe-math-optimizations, loaded and run in this process,
    must not switch the process to flush-to-zero (a fast-math runtime linked into it would:
    every later subnormal result of the test suite would read 0)."""
    unsafe = next((c for c in COMPILERS if "-funsafe-math-optimizations" in c.flags), None)
    if unsafe is None or unsafe.missing():
        pytest.skip("clang is not installed")
    block, scenario = SCENARIOS[0]
    simulate(scenario, compiled_fmu(compiled, unsafe, block.name, 2).folder, echo=False)
    tiny = float(np.float64(1e-320))
    assert tiny * 1.0 == tiny and tiny / 2.0 > 0.0
