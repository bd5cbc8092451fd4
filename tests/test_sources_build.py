"""The sources/ inside each FMU are enough to build it: an importer that compiles FMUs for its
own platform does what FMPy's fmpy.build.build_platform_binary does (CMake with sources/ as
include directory and the XML's SourceFiles as sources). From a copy of each FMU whose binaries
are removed (tests/rebuild.py), that rebuild must compile without a warning (FMPy's -Wall
-Wextra -Wpedantic), FMI 2.0 and FMI 3.0, and simulate every demo scenario of the block with
results identical, bit for bit, to the FMU of the CMake build (the FMI 3.0 FMUs:
tests/test_fmi3.py)."""
from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import fmpy
import numpy as np
import pytest
from fmpy import extract

from demo.run_demo import simulate
from tests.harness import ROOT, fmu_path
from tests.lgf_blocks import names, scenarios
from tests.rebuild import FMPY, FMU_DIRS, HEADERS, by_block

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


@pytest.mark.parametrize("scenario", scenarios(), ids=lambda s: s.name)
def test_rebuilt_fmu_simulates_identically(scenario, rebuilt):
    built = by_block(rebuilt, FMPY, 2)[scenario.block]
    if built.failure:
        pytest.fail(built.failure)
    expected, outputs, _ = simulate(scenario, ROOT / "fmus")
    result, _, _ = simulate(scenario, built.folder)
    assert result.dtype == expected.dtype
    for name in ("time", *outputs):
        assert np.array_equal(result[name], expected[name]), name


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
            f'#include "{HEADERS / "fmi2Functions.h"}"\n' +
            "".join(f"#undef fmi2{n}\n#define fmi2{n} {block}_fmi2{n}\n" for n in _entry_points()))
        obj = tmp_path / f"{block}.o"
        subprocess.run(["cc", "-c", "-O1", "-Wall", "-Wextra", "-Werror", f"-DFMI2_FUNCTION_PREFIX={block}_",
                        f"-I{prefixed}", f"-I{sources}", f"-I{HEADERS}",
                        str(sources / f"{block}.c"), "-o", str(obj)],
                       check=True, capture_output=True, text=True)
        nm = subprocess.run(["nm", "--defined-only", "--extern-only", str(obj)],
                            check=True, capture_output=True, text=True).stdout
        defined = [line.split()[-1] for line in nm.splitlines() if line.strip()]
        assert defined and [s for s in defined if not s.startswith(f"{block}_fmi2")] == [], block
        objects.append(str(obj))
        main.append(f"const char *{block}_fmi2GetVersion(void);")
    main.append("int main(void) {")
    main += [f'    printf("%s\\n", {block}_fmi2GetVersion());' for block in BLOCKS]
    main.append("    return 0;\n}")
    (tmp_path / "main.c").write_text("\n".join(main) + "\n")
    program = tmp_path / "program"
    link = subprocess.run(["cc", str(tmp_path / "main.c"), *objects, "-lm", "-o", str(program)],
                          capture_output=True, text=True)
    assert link.returncode == 0, link.stderr
    run = subprocess.run([str(program)], check=True, capture_output=True, text=True)
    assert run.stdout.split() == ["2.0"] * len(BLOCKS)
