"""The aarch64-linux binaries of the FMI 3.0 FMUs (fmus/fmi3/<Block>.fmu:
binaries/aarch64-linux/<id>.so, cross-built by `make build`): an aarch64 ELF shared object
that exports the fmi3 entry points and nothing else, as the x86_64-linux binary does, and
computes exactly what the x86_64-linux binary computes. tests/cross/scenario_runner.c, built
for both, runs one script per block through the FMI 3.0 API against each binary, the aarch64
one under qemu-user: the block's fixed scenario (tests/blocks/<Block>/cross.py) and then every
demo scenario as FMPy runs it (tests/cross/scripts.py: scenario_script), whose x86_64 printout
must be the committed reference result; the two printouts (every output after every step, as
hex bit patterns) must be identical. The runs of all blocks go on at once.

Skips, with the reason, where the cross compiler or qemu are not installed (Debian packages
gcc-aarch64-linux-gnu, libc6-dev-arm64-cross and qemu-user; .ci/run installs them)."""

from __future__ import annotations

import shutil
import struct
import subprocess
from pathlib import Path

import pytest
from fmpy import extract, read_model_description
from fmpy.util import read_csv

from tests.cross import replay
from tests.cross.scripts import scenario_script
from tests.harness import FMU_DIR, fmu_path
from tests.lgf_blocks import find, names
from tests.timeouts import hang_guard

BLOCKS = names()
AARCH64_CC = "aarch64-linux-gnu-gcc"
QEMU = "qemu-aarch64"
INSTALL = (
    "install the Debian packages gcc-aarch64-linux-gnu, libc6-dev-arm64-cross and "
    "qemu-user (.ci/run does) and run make build"
)
EM_AARCH64 = 183


@pytest.fixture(scope="module")
def fmus(tmp_path_factory):
    """block -> (FMI 3.0 model description, unzip directory)."""
    root = tmp_path_factory.mktemp("fmi3")
    result = {}
    for block in BLOCKS:
        fmu = fmu_path(block, FMU_DIR / "fmi3")
        result[block] = (read_model_description(str(fmu)), extract(str(fmu), str(root / block)))
    return result


def native_binary(fmus, block: str) -> Path:
    return Path(fmus[block][1]) / "binaries" / "x86_64-linux" / f"{block}.so"


def aarch64_binary(fmus, block: str) -> Path:
    return replay.binary(fmus[block][1], "aarch64-linux", f"{block}.so", AARCH64_CC, INSTALL)


def script(fmus, block: str) -> str:
    """The block's fixed scenario, then each of its demo scenarios, for the FMI 3.0 FMU."""
    md = fmus[block][0]
    return find(block).script(md) + "".join(scenario_script(s, md) for s in find(block).scenarios)


@pytest.mark.parametrize("block", BLOCKS)
def test_is_an_aarch64_shared_object(fmus, block):
    """ELF, 64-bit, little-endian, a shared object (ET_DYN) for EM_AARCH64."""
    header = aarch64_binary(fmus, block).read_bytes()[:20]
    assert header[:4] == b"\x7fELF" and header[4:6] == b"\x02\x01", header[:6]
    e_type, e_machine = struct.unpack("<HH", header[16:20])
    assert (e_type, e_machine) == (3, EM_AARCH64)


@pytest.mark.parametrize("block", BLOCKS)
def test_exports_only_the_fmi3_entry_points(fmus, block):
    exports = replay.exported_functions(aarch64_binary(fmus, block))
    assert exports and all(name.startswith("fmi3") for name in exports), sorted(exports)
    assert exports == replay.exported_functions(native_binary(fmus, block))


@pytest.fixture(scope="module")
def native(fmus, tmp_path_factory):
    """block -> the printout of its script against the x86_64-linux binary."""
    directory = tmp_path_factory.mktemp("native")
    runner = replay.build_runner("cc", directory / "scenario_runner", "-ldl")
    runs = {
        block: replay.Run(
            [str(runner), str(native_binary(fmus, block))], script(fmus, block), directory, block
        )
        for block in BLOCKS
    }
    return {block: run.printout(timeout=hang_guard(120)) for block, run in runs.items()}


def _sysroot() -> Path:
    """Where the cross toolchain keeps the aarch64 C library, <sysroot>/lib/libc.so.6: qemu's -L."""
    libc = subprocess.run(
        [AARCH64_CC, "-print-file-name=libc.so.6"], check=True, capture_output=True, text=True
    ).stdout.strip()
    return Path(libc).resolve().parent.parent


@pytest.fixture(scope="module")
def under_qemu(fmus, tmp_path_factory):
    """block -> the run of its script against the aarch64-linux binary under qemu, all
    started at once."""
    if not shutil.which(AARCH64_CC):
        pytest.skip(f"{AARCH64_CC} is not installed: {INSTALL}")
    if not shutil.which(QEMU):
        pytest.skip(f"{QEMU} is not installed: {INSTALL}")
    directory = tmp_path_factory.mktemp("aarch64")
    runner = replay.build_runner(AARCH64_CC, directory / "scenario_runner", "-ldl")
    command = [QEMU, "-L", str(_sysroot()), str(runner)]
    runs = {
        block: replay.Run(
            command + [str(aarch64_binary(fmus, block))], script(fmus, block), directory, block
        )
        for block in BLOCKS
    }
    yield runs
    for run in runs.values():
        run.stop()


@pytest.mark.parametrize("block", BLOCKS)
def test_aarch64_under_qemu_equals_x86_64(block, native, under_qemu):
    printout = under_qemu[block].printout(timeout=hang_guard(600))
    replay.assert_exercised(native[block])
    replay.assert_same(native[block], printout, ("x86_64", "aarch64"))


@pytest.mark.parametrize("block", BLOCKS)
def test_the_x86_64_replay_of_each_demo_scenario_is_its_reference(fmus, block, native):
    """So the aarch64 binary, which prints the same, replays every committed reference bit
    for bit. (The FMI 3.0 FMU gives the FMI 2.0 FMU's results, tests/test_fmi3.py.)"""
    md = fmus[block][0]
    types = {v.name: v.type for v in md.modelVariables}
    replayed = replay.rows(native[block], types)
    assert list(replayed) == [s.name for s in find(block).scenarios]
    for scenario in find(block).scenarios:
        reference = read_csv(str(find(block).reference(scenario)))
        result = replayed[scenario.name]
        assert len(result) == len(reference), scenario.name
        # a warning only where the scenario provokes one (tools.scenario.Scenario)
        assert {status for status, _ in result} <= ({0, 1} if scenario.expected_warning else {0})
        for number, ((_, outputs), expected) in enumerate(zip(result, reference)):
            for name in reference.dtype.names[1:]:
                value, wanted = outputs[name], expected[name].item()
                assert struct.pack(">d", float(value)) == struct.pack(">d", float(wanted)), (
                    f"{scenario.name}, row {number}, {name}: {value!r}, not {wanted!r}"
                )
