"""What a compiled FMU holds and that it is the bundled FMUs' kind (docs/scl.md §4): its files,
FMPy's validation, its documentation, and a rebuild from its sources/ alone (FMPy's build and
gcc at another optimisation level, as tests/rebuild.py rebuilds ours) that runs bit for bit as
the binary it ships."""

from __future__ import annotations

import shutil
import zipfile

import pytest
from fmpy.validation import validate_fmu

from lgf_fmus import scl
from lgf_fmus.scl import build
from tests.cross.wine import MINGW_CC
from tests.rebuild import FMPY, Compiler, rebuild
from tests.scl.driver import TWINS, run_cs

BLOCK = "LGF_SawTooth"


@pytest.fixture(scope="module", params=[2, 3])
def fmu(request, tmp_path_factory):
    out = tmp_path_factory.mktemp(f"fmi{request.param}") / f"{BLOCK}.fmu"
    return scl.compile([TWINS / f"{BLOCK}.scl"], block=BLOCK, fmi=request.param, output=out)


def test_contents(fmu):
    names = set(zipfile.ZipFile(fmu).namelist())
    platform = "linux64" if "binaries/linux64/LGF_SawTooth.so" in names else "x86_64-linux"
    expected = {
        "modelDescription.xml",
        f"binaries/{platform}/{BLOCK}.so",
        "documentation/index.html",
        f"sources/{BLOCK}.c",
        f"sources/blocks/{BLOCK}/block.h",
        f"sources/blocks/{BLOCK}/block.c",
        f"sources/blocks/{BLOCK}/interface.c",
        "sources/scl/scl.h",
        "sources/core/numerics.h",
        "sources/iec/timer.h",
    }
    if shutil.which(MINGW_CC):  # compile adds the win64 binary where mingw-w64 is there
        windows = "win64" if platform == "linux64" else "x86_64-windows"
        expected.add(f"binaries/{windows}/{BLOCK}.dll")
    if platform == "x86_64-linux" and build.aarch64_compiler(3, None):  # and for aarch64 Linux
        expected.add(f"binaries/aarch64-linux/{BLOCK}.so")
    assert expected <= names
    doc = zipfile.ZipFile(fmu).read("documentation/index.html").decode()
    assert "Latch the inputs and restart at startValue" in doc  # the declaration's comment
    assert "statTimer" in doc
    assert "<code>maxCycleTime</code>" in doc  # docs/scl.md rules: [DEC-WATCHDOG]


def test_fmpy_validates_it(fmu):
    assert validate_fmu(str(fmu)) == []


@pytest.mark.parametrize("builder", [FMPY, Compiler("gcc", ("-O2",))], ids=["fmpy", "gcc-O2"])
def test_rebuilt_from_its_sources_runs_as_shipped(fmu, builder, tmp_path):
    if builder.missing():
        pytest.skip(builder.missing())
    if builder is FMPY and "fmi3" in fmu.parent.name:
        pytest.skip("FMPy's build (CMake, slow) is run on the FMI 2.0 FMU only")
    rebuilt = rebuild(builder, fmu, tmp_path)
    assert rebuilt.failure is None, rebuilt.failure
    inputs = {"timeRange": 0.25, "numberSteps": 3, "incrementRange": 7, "startValue": -2}
    steps = [(100_000, {"reset": k == 12}) for k in range(40)]
    assert run_cs(rebuilt.fmu, 100_000, {}, inputs, steps) == run_cs(
        fmu, 100_000, {}, inputs, steps
    )


def test_the_same_scl_gives_the_same_bytes(fmu, tmp_path):
    """Packed as the bundled FMUs (lgf_fmus.fmuzip): sorted, one time stamp, fixed permissions;
    the win64 DLL (where mingw-w64 is there) without a link time."""
    fmi = 3 if "fmi3" in fmu.parent.name else 2
    again = scl.compile([TWINS / f"{BLOCK}.scl"], block=BLOCK, fmi=fmi, output=tmp_path / "a.fmu")
    assert again.read_bytes() == fmu.read_bytes()
    assert {i.date_time for i in zipfile.ZipFile(fmu).infolist()} == {(1980, 1, 1, 0, 0, 0)}


@pytest.mark.parametrize("fmi", [2, 3])
def test_fmpy_validates_structs_arrays_and_tables(fmi, tmp_path):
    """The names of STRUCT members, ARRAY elements (from a negative lower bound too), in/outs and
    ARRAY[*] tables (docs/scl.md §4): LGF_RampCI's twin and the constructs' data block."""
    from tests.scl.test_constructs import DATA

    source = tmp_path / "Data.scl"
    source.write_text(DATA, encoding="utf-8")
    for sources, block in (([TWINS / "LGF_RampCI.scl"], "LGF_RampCI"), ([source], "Data")):
        out = scl.compile(
            sources, block=block, fmi=fmi, output=tmp_path / f"{block}.fmu", win64=False
        )
        assert validate_fmu(str(out)) == [], block
