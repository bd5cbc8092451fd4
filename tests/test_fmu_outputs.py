"""fmus/ is a pure output: the build writes exactly the FMUs of the blocks that exist. At build
time, before any FMU is packed, CMake removes every .fmu of fmus/ and fmus/fmi3/ that no block
makes (the target lgf_prune_fmus, cmake/prune-fmus.cmake), so that the FMU of a deleted or
renamed block is neither bundled by `make package` nor released by `make dist`. Checked on a
build folder of its own, without documentation, whose FMU folder is a temporary one."""

from __future__ import annotations

import shutil
import subprocess
import sys
import zipfile

import pytest

from tests.harness import ROOT
from tests.lgf_blocks import names
from tests.timeouts import hang_guard


def cmake(*args: str) -> subprocess.CompletedProcess:
    program = shutil.which("cmake")
    assert program, "cmake is not on PATH (make build needs it too)"
    child = subprocess.run(
        [program, *args], capture_output=True, text=True, timeout=hang_guard(300)
    )
    assert child.returncode == 0, f"cmake {' '.join(args)}:\n{child.stdout}\n{child.stderr}"
    return child


@pytest.fixture(scope="module")
def build(tmp_path_factory):
    """(build folder, FMU folder): configured, nothing built yet."""
    root = tmp_path_factory.mktemp("outputs")
    cmake(
        "-S",
        str(ROOT),
        "-B",
        str(root / "build"),
        "--log-level=WARNING",
        f"-DPython3_EXECUTABLE={sys.executable}",
        f"-DFMU_OUTPUT_DIR={root / 'fmus'}",
        "-DLGF_DOCUMENTATION=OFF",
    )
    return root / "build", root / "fmus"


def stray(fmus):
    """FMUs that no block makes, in both FMU folders."""
    paths = [fmus / "LGF_Gone.fmu", fmus / "fmi3" / "LGF_Gone.fmu", fmus / "fmi3" / "Renamed.fmu"]
    for path in paths:
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(b"an FMU of a block that is gone")
    return paths


def test_the_build_lists_every_fmu_the_blocks_make(build):
    folder, fmus = build
    listed = (folder / "fmus.list").read_text().split()
    assert sorted(listed) == sorted(
        [str(fmus / f"{b}.fmu") for b in names()]
        + [str(fmus / "fmi3" / f"{b}.fmu") for b in names()]
    )


def test_pruning_removes_the_fmus_no_block_makes_and_keeps_the_rest(build):
    folder, fmus = build
    gone = stray(fmus)
    kept = {
        fmus / "LGF_RampCI.fmu": b"the FMU of a block that exists",
        fmus / "fmi3" / "LGF_SawTooth.fmu": b"another one",
        fmus / "README.txt": b"not an FMU",
    }
    for path, content in kept.items():
        path.write_bytes(content)
    child = cmake("--build", str(folder), "--target", "lgf_prune_fmus")
    assert [p for p in gone if p.exists()] == []
    assert {p: p.read_bytes() for p in kept} == kept
    assert "LGF_Gone.fmu: no block makes it" in child.stdout
    for path in kept:
        path.unlink()


def test_building_an_fmu_prunes_first(build):
    """The FMU targets depend on the pruning, so any build removes the stray FMUs."""
    folder, fmus = build
    gone = stray(fmus)
    cmake("--build", str(folder), "--target", "LGF_SawTooth_fmi2_fmu")
    assert [p for p in gone if p.exists()] == []
    with zipfile.ZipFile(fmus / "LGF_SawTooth.fmu") as fmu:
        assert "modelDescription.xml" in {n.removeprefix("./") for n in fmu.namelist()}
