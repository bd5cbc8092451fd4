"""The aarch64-linux binary of a compiled FMI 3.0 FMU (docs/scl.md §4): where Debian's aarch64
cross compiler is installed, compile puts binaries/aarch64-linux/<Block>.so beside the native
binary, as `make build` does for the bundled FMI 3.0 FMUs (tests/test_aarch64.py): an aarch64
ELF shared object that exports the fmi3 entry points alone and computes under qemu-user exactly
what the native binary computes, on the fixed cross scenario of the block it twins
(tests/blocks/<Block>/cross.py). FMI 2.0 names no platform for aarch64 Linux, so its FMU has
none. Skipped where the cross compiler (or qemu) is not installed."""

from __future__ import annotations

import shutil
import struct
from pathlib import Path

import pytest

from lgf_fmus import scl
from lgf_fmus.scl import build
from tests.cross import replay
from tests.lgf_blocks import find
from tests.scl.driver import TWINS, unpacked
from tests.test_aarch64 import AARCH64_CC, EM_AARCH64, INSTALL, QEMU, _sysroot
from tests.timeouts import hang_guard

# the twin with a UDT, an ARRAY[*] table and QRY_CINT: the most of the compiler's C
BLOCK = "LGF_RampCI"


@pytest.fixture(scope="module")
def binaries(tmp_path_factory):
    """(model description, native library, aarch64 library) of the twin compiled for FMI 3.0."""
    if build.aarch64_compiler(3, None) is None:
        pytest.skip(f"{AARCH64_CC} (with its C library) is not installed: {INSTALL}")
    out = tmp_path_factory.mktemp("aarch64") / f"{BLOCK}.fmu"
    fmu = scl.compile(
        [TWINS / f"{BLOCK}.scl"], block=BLOCK, fmi=3, output=out, werror=True, win64=False
    )
    directory, md = unpacked(fmu)
    folder = Path(directory) / "binaries"
    return md, folder / "x86_64-linux" / f"{BLOCK}.so", folder / "aarch64-linux" / f"{BLOCK}.so"


def test_an_aarch64_shared_object_exporting_the_fmi3_entry_points_alone(binaries):
    _, native, arm = binaries
    header = arm.read_bytes()[:20]
    assert header[:4] == b"\x7fELF" and header[4:6] == b"\x02\x01", header[:6]
    assert struct.unpack("<HH", header[16:20]) == (3, EM_AARCH64)  # ET_DYN
    exports = replay.exported_functions(arm)
    assert exports and all(name.startswith("fmi3") for name in exports), sorted(exports)
    assert exports == replay.exported_functions(native)


def test_under_qemu_it_computes_what_the_native_binary_does(binaries, tmp_path):
    if not shutil.which(QEMU):
        pytest.skip(f"{QEMU} is not installed: {INSTALL}")
    md, native, arm = binaries
    script = find(BLOCK).script(md)
    runner = replay.build_runner("cc", tmp_path / "runner", "-ldl")
    cross_runner = replay.build_runner(AARCH64_CC, tmp_path / "runner-aarch64", "-ldl")
    qemu = [QEMU, "-L", str(_sysroot()), str(cross_runner), str(arm)]
    runs = [
        replay.Run([str(runner), str(native)], script, tmp_path, "x86_64"),
        replay.Run(qemu, script, tmp_path, "aarch64"),
    ]
    try:
        expected = runs[0].printout(timeout=hang_guard(120))
        replay.assert_exercised(expected)
        replay.assert_same(
            expected, runs[1].printout(timeout=hang_guard(600)), ("x86_64", "aarch64")
        )
    finally:
        for run in runs:
            run.stop()


@pytest.mark.parametrize("fmi, aarch64", [(2, None), (3, False)], ids=["fmi2", "no-aarch64"])
def test_the_native_binary_alone(fmi, aarch64, tmp_path):
    """FMI 2.0's FMU, and an FMI 3.0 FMU compiled with aarch64=False (--no-aarch64)."""
    out = scl.compile(
        [TWINS / "LGF_SinusCI.scl"],
        block="LGF_SinusCI",
        fmi=fmi,
        output=tmp_path / "s.fmu",
        win64=False,
        aarch64=aarch64,
    )
    directory, _ = unpacked(out)
    assert sorted(p.name for p in (Path(directory) / "binaries").iterdir()) == [build.platform(fmi)]
