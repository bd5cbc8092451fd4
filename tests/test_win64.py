"""The win64 binaries inside the FMUs (binaries/win64/<id>.dll, cross-built with mingw-w64 by
`make build`): a PE32+ DLL that needs nothing beyond Windows' own KERNEL32 and C runtime,
exports the fmi2 entry points and nothing else, and computes exactly what the linux64 binary
computes: tests/cross/scenario_runner.c, built for both platforms, runs one fixed scenario per
block (tests/blocks/<Block>/cross.py) through the FMI API against each binary, the win64 one
under wine, and the two printouts (every output after every step, as hex bit patterns) must be
identical. (tests/cross/replay.py holds what this shares with tests/test_aarch64.py.)

Skips, with the reason, where mingw-w64 or wine are not installed (tests/cross/wine.py)."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.cross import replay
from tests.cross.wine import (
    INSTALL,
    MINGW_CC,
    assert_exports_as_native,
    assert_self_contained,
    assert_win64_equals_native,
)
from tests.harness import unpacked
from tests.lgf_blocks import find, names

BLOCKS = names()


def native_binary(block: str) -> Path:
    _, directory = unpacked(block)
    return Path(directory) / "binaries" / "linux64" / f"{block}.so"


def win64_binary(block: str) -> Path:
    _, directory = unpacked(block)
    return replay.binary(directory, "win64", f"{block}.dll", MINGW_CC, INSTALL)


@pytest.mark.parametrize("block", BLOCKS)
def test_dll_is_self_contained(block):
    assert_self_contained(win64_binary(block))


@pytest.mark.parametrize("block", BLOCKS)
def test_dll_exports_only_the_fmi2_entry_points(block):
    assert_exports_as_native(win64_binary(block), native_binary(block), "fmi2")


@pytest.mark.parametrize("block", BLOCKS)
def test_win64_under_wine_equals_linux64(block, wine_runners):
    md, _ = unpacked(block)
    script = find(block).script(md)
    assert_win64_equals_native(
        wine_runners, native_binary(block), win64_binary(block), script, block
    )
