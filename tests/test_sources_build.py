"""The sources/ inside each FMU are enough to build it: an importer that compiles FMUs for its
own platform does what FMPy's fmpy.build.build_platform_binary does (CMake with sources/ as
include directory and the XML's SourceFiles as sources). From a copy of each FMU whose binaries
are removed, that rebuild must compile without a warning (FMPy's -Wall -Wextra -Wpedantic) and
simulate every demo scenario of the block with results identical, bit for bit, to the FMU of
the CMake build."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import fmpy
import numpy as np
import pytest
from fmpy import extract, platform
from fmpy.build import build_platform_binary

from tests.harness import ROOT, fmu_path
from tests.lgf_blocks import names, scenarios
from tools.simulate import simulate

BLOCKS = names()
HEADERS = Path(fmpy.__file__).parent / "c-code"


def output_to(log: Path, function, *args, **kwargs):
    """Runs function with the process's stdout and stderr (and so its subprocesses') in log."""
    sys.stdout.flush()
    sys.stderr.flush()
    saved = os.dup(1), os.dup(2)
    with open(log, "w") as f:
        os.dup2(f.fileno(), 1)
        os.dup2(f.fileno(), 2)
        try:
            return function(*args, **kwargs)
        finally:
            os.dup2(saved[0], 1)
            os.dup2(saved[1], 2)
            os.close(saved[0])
            os.close(saved[1])


def zip_directory(directory: Path, fmu: Path):
    with zipfile.ZipFile(fmu, "w", zipfile.ZIP_DEFLATED) as z:
        for path in sorted(directory.rglob("*")):
            z.write(path, path.relative_to(directory).as_posix())


@pytest.fixture(scope="module")
def rebuilt(tmp_path_factory):
    """{block: (folder holding <block>.fmu rebuilt from its sources/ alone, its unzipped
    folder, the build's output)}."""
    if not shutil.which("cmake"):
        pytest.skip("cmake is not on PATH (FMPy's build runs it)")
    root = tmp_path_factory.mktemp("rebuilt")
    folders = {}
    for block in BLOCKS:
        unzipped = Path(extract(str(fmu_path(block)), str(root / f"{block}-unzipped")))
        shutil.rmtree(unzipped / "binaries")
        build = root / f"{block}-build"
        build.mkdir()
        log = root / f"{block}-build.log"
        try:
            output_to(log, build_platform_binary, unzipped, build_dir=build, all_warnings=True)
        except Exception as e:
            pytest.fail(f"building {block} from its sources failed ({e}):\n{log.read_text()}")
        folder = root / block
        folder.mkdir()
        zip_directory(unzipped, folder / f"{block}.fmu")
        folders[block] = (folder, unzipped, log)
    return folders


@pytest.mark.parametrize("block", BLOCKS)
def test_builds_from_sources_alone(block, rebuilt):
    _, unzipped, log = rebuilt[block]
    binaries = [p.relative_to(unzipped).as_posix() for p in (unzipped / "binaries").rglob("*") if p.is_file()]
    suffix = {"linux64": ".so", "darwin64": ".dylib", "win64": ".dll"}.get(platform, "")
    assert f"binaries/{platform}/{block}{suffix}" in binaries
    output = log.read_text(errors="replace")
    assert "Building C object" in output, output
    assert [line for line in output.splitlines() if "warning" in line.lower()] == []


@pytest.mark.parametrize("scenario", scenarios(), ids=lambda s: s.name)
def test_rebuilt_fmu_simulates_identically(scenario, rebuilt):
    folder, _, _ = rebuilt[scenario.block]
    expected, outputs, _ = simulate(scenario, ROOT / "fmus")
    result, _, _ = simulate(scenario, folder)
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
