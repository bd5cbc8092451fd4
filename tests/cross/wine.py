"""What the tests of the win64 binaries share (tests/test_win64.py: the bundled FMUs,
tests/scl/test_win64.py: compiled SCL): mingw-w64's tools, what objdump tells of a DLL, and the
scenario runner built natively and for win64 with a wine environment to run it in. Skips, with
the reason, where mingw-w64 or wine are not installed (Debian packages gcc-mingw-w64-x86-64 and
wine64; .ci/run installs them)."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import tempfile
from pathlib import Path

import pytest

from tests.cross import replay
from tests.timeouts import hang_guard

MINGW_CC = "x86_64-w64-mingw32-gcc"
OBJDUMP = "x86_64-w64-mingw32-objdump"
# What Windows itself provides: the kernel and the C runtime (msvcrt, or the UCRT's forwarders).
SYSTEM_DLLS = re.compile(r"^(kernel32|msvcrt|ucrtbase|api-ms-win-crt-[a-z0-9-]+)\.dll$", re.I)
INSTALL = (
    "install the Debian packages gcc-mingw-w64-x86-64 and wine64 (.ci/run does) and run make build"
)


def objdump(path: Path) -> str:
    if not shutil.which(OBJDUMP):
        pytest.skip(f"{OBJDUMP} is not installed: {INSTALL}")
    return subprocess.run(
        [OBJDUMP, "-p", str(path)], check=True, capture_output=True, text=True
    ).stdout


def imported_dlls(dump: str) -> list[str]:
    return re.findall(r"DLL Name: (\S+)", dump)


def exported_names(dump: str) -> set[str]:
    table = dump.split("[Ordinal/Name Pointer] Table", 1)
    return (
        set(re.findall(r"^\s*\[\s*\d+\]\s+(\S+)\s*$", table[1], re.M)) if len(table) == 2 else set()
    )


def assert_self_contained(dll: Path):
    """A PE32+ x86-64 DLL importing only system DLLs: static libgcc, no mingw runtime DLLs."""
    dump = objdump(dll)
    assert "file format pei-x86-64" in dump
    dlls = imported_dlls(dump)
    assert dlls, "no import table found"
    assert [d for d in dlls if not SYSTEM_DLLS.match(d)] == [], dlls


def assert_exports_as_native(dll: Path, native: Path, prefix: str):
    """The DLL exports the entry points (names starting with prefix) and nothing else, the
    same the native library exports."""
    exports = exported_names(objdump(dll))
    assert exports and all(name.startswith(prefix) for name in exports), sorted(exports)
    if shutil.which("nm"):
        assert exports == replay.exported_functions(native)


def _wine_loader() -> str | None:
    """Debian's wine64 package puts no `wine` on PATH: its loader is /usr/lib/wine/wine64."""
    for candidate in ("wine64", "wine", "/usr/lib/wine/wine64", "/usr/lib/wine/wine"):
        path = shutil.which(candidate)
        if path:
            return path
    return None


@pytest.fixture(scope="module")
def wine_runners(tmp_path_factory):
    """The scenario runner built natively and for win64, and a wine environment to run it in."""
    if not shutil.which(MINGW_CC):
        pytest.skip(f"{MINGW_CC} is not installed: {INSTALL}")
    wine = _wine_loader()
    if not wine:
        pytest.skip(f"wine is not installed: {INSTALL}")
    directory = tmp_path_factory.mktemp("cross")
    native = replay.build_runner("cc", directory / "scenario_runner", "-ldl")
    windows = replay.build_runner(MINGW_CC, directory / "scenario_runner.exe", "-static-libgcc")
    prefix = Path(tempfile.mkdtemp(prefix="lgf-wine-"))
    env = {
        **os.environ,
        "WINEPREFIX": str(prefix),
        "WINEDEBUG": "-all",
        "WINEDLLOVERRIDES": "mscoree,mshtml=",
    }  # no Mono/Gecko installer in a new prefix
    server = _wine_server(wine)

    # One wine server for all runs (a new one per run costs seconds); it detaches, and ends 30 s
    # after the last run at the latest; -k below ends it and the services of the prefix.
    def tell_server(option: str):
        if server:
            null = subprocess.DEVNULL
            run = {"stdin": null, "stdout": null, "stderr": null, "timeout": hang_guard(60)}
            subprocess.run([server, option], env=env, **run)

    tell_server("-p30")
    yield {"native": native, "windows": windows, "wine": wine, "env": env}
    tell_server("-k")
    shutil.rmtree(prefix, ignore_errors=True)


def _wine_server(wine: str) -> str | None:
    for candidate in (
        Path(wine).resolve().with_name("wineserver64"),
        Path(wine).resolve().with_name("wineserver"),
    ):
        if candidate.exists():
            return str(candidate)
    return shutil.which("wineserver")


def windows_path(path: Path) -> str:
    return "Z:" + str(path).replace("/", "\\")  # wine maps the Unix root to drive Z:


def assert_win64_equals_native(runners, native: Path, dll: Path, script: str, name: str):
    """The script's printout against the win64 DLL under wine is the one against the native
    library, bit for bit, and exercises the FMU."""
    directory = runners["windows"].parent
    linux = replay.Run(
        [str(runners["native"]), str(native)], script, directory, f"{name}.native"
    ).printout(timeout=hang_guard(60))
    # The first start of a new prefix takes a while.
    windows = replay.Run(
        [runners["wine"], str(runners["windows"]), windows_path(dll)],
        script,
        directory,
        f"{name}.win64",
        env=runners["env"],
    )
    replay.assert_exercised(linux)
    replay.assert_same(linux, windows.printout(timeout=hang_guard(600)), ("native", "win64"))
