"""The win64 binary of a compiled FMU (docs/scl.md §4): where mingw-w64 is installed, compile
puts binaries/win64/<Block>.dll (FMI 3.0: binaries/x86_64-windows) beside the native binary, a
DLL as the bundled FMUs' (it imports only Windows' own DLLs and exports the entry points alone)
that computes under wine exactly what the native binary computes, on the fixed cross scenario
of the block it twins (tests/blocks/<Block>/cross.py, tests/cross/wine.py)."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest

from lgf_fmus import scl
from lgf_fmus.scl import build
from tests.cross.wine import (
    INSTALL,
    MINGW_CC,
    assert_exports_as_native,
    assert_self_contained,
    assert_win64_equals_native,
)
from tests.lgf_blocks import find
from tests.scl.driver import TWINS, unpacked

# the twin with a UDT, an ARRAY[*] table and QRY_CINT: the most of the compiler's C
BLOCK = "LGF_RampCI"


@pytest.fixture(scope="module", params=[2, 3], ids=["fmi2", "fmi3"])
def binaries(request, tmp_path_factory):
    """(FMI version, unpacked FMU, native library, win64 DLL) of the twin compiled with win64."""
    if not shutil.which(MINGW_CC):
        pytest.skip(f"{MINGW_CC} is not installed: {INSTALL}")
    fmi = request.param
    out = tmp_path_factory.mktemp(f"win64-fmi{fmi}") / f"{BLOCK}.fmu"
    fmu = scl.compile(
        [TWINS / f"{BLOCK}.scl"], block=BLOCK, fmi=fmi, output=out, werror=True, win64=True
    )
    directory, md = unpacked(fmu)
    native, windows = ("linux64", "win64") if fmi == 2 else ("x86_64-linux", "x86_64-windows")
    folder = Path(directory) / "binaries"
    return fmi, md, folder / native / f"{BLOCK}.so", folder / windows / f"{BLOCK}.dll"


def test_the_dll_is_self_contained_and_exports_the_entry_points_alone(binaries):
    fmi, _, native, dll = binaries
    assert_self_contained(dll)
    assert_exports_as_native(dll, native, f"fmi{fmi}")


def test_the_dll_under_wine_computes_what_the_native_binary_does(binaries, wine_runners):
    fmi, md, native, dll = binaries
    script = find(BLOCK).script(md)
    assert_win64_equals_native(wine_runners, native, dll, script, f"{BLOCK}-fmi{fmi}")


def test_without_win64_the_fmu_has_the_native_binary_alone(tmp_path):
    """Where mingw-w64 is there (else compile adds no DLL anyway, and this shows nothing)."""
    if not shutil.which(MINGW_CC):
        pytest.skip(f"{MINGW_CC} is not installed: {INSTALL}")
    out = scl.compile(
        [TWINS / "LGF_SinusCI.scl"], block="LGF_SinusCI", output=tmp_path / "s.fmu", win64=False
    )
    directory, _ = unpacked(out)
    native = build.platform(2)
    assert sorted(p.name for p in (Path(directory) / "binaries").iterdir()) == [native]
