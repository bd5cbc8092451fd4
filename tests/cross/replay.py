"""What the tests of the cross-built binaries share (tests/test_win64.py: win64 under wine,
tests/test_aarch64.py: aarch64-linux under qemu): the scenario runner built for a platform, the
binary of a platform inside an unpacked FMU (missing: a failure where its cross compiler is
installed, else a skip saying how to install it), the functions a shared library exports, the
runner's processes, their printouts compared line by line, and a printout read back as rows."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import fmpy
import pytest

from tests.cross.scripts import decode
from tests.harness import ROOT

RUNNER = ROOT / "tests" / "cross" / "scenario_runner.c"
FMI_HEADERS = Path(fmpy.__file__).parent / "c-code"
FLAGS = ["-std=c11", "-O2", "-Wall", "-Wextra", "-Wpedantic", "-Werror", f"-I{FMI_HEADERS}"]


def build_runner(compiler: str, output: Path, *options: str) -> Path:
    """tests/cross/scenario_runner.c compiled with `compiler` into `output`."""
    subprocess.run([compiler, *FLAGS, "-o", str(output), str(RUNNER), *options], check=True)
    return output


def binary(directory, platform: str, file: str, compiler: str, install: str) -> Path:
    """binaries/<platform>/<file> of an unpacked FMU, which the build puts there whenever
    `compiler` is installed."""
    path = Path(directory) / "binaries" / platform / file
    if not path.exists():
        if shutil.which(compiler):
            pytest.fail(
                f"the FMU has no binaries/{platform}/{file} although {compiler} is "
                "installed: run make build"
            )
        pytest.skip(
            f"{compiler} is not installed, so the FMUs carry no binaries/{platform}: {install}"
        )
    return path


def exported_functions(path: Path) -> set[str]:
    """The functions an ELF shared library exports (nm reads the ELF of any architecture)."""
    if not shutil.which("nm"):
        pytest.skip("nm (binutils) is not installed")
    nm = subprocess.run(
        ["nm", "-D", "--defined-only", str(path)], check=True, capture_output=True, text=True
    ).stdout
    return {line.split()[-1] for line in nm.splitlines() if line.split()[1:2] in (["T"], ["W"])}


class Run:
    """The runner started on a script, its printout and messages in files, not pipes (the
    services wine starts with a new prefix inherit the standard streams and outlive the
    program; and many runs can go on at once)."""

    def __init__(
        self, command: list[str], script: str, directory: Path, name: str, env: dict | None = None
    ):
        self.files = {kind: Path(directory) / f"{name}.{kind}" for kind in ("script", "out", "err")}
        self.files["script"].write_text(script)
        with (
            open(self.files["script"]) as stdin,
            open(self.files["out"], "w") as stdout,
            open(self.files["err"], "w") as stderr,
        ):
            self.process = subprocess.Popen(
                command, stdin=stdin, stdout=stdout, stderr=stderr, env=env
            )

    def printout(self, timeout: float) -> str:
        """The printout once the runner has ended; it must end well."""
        try:
            code = self.process.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
            raise
        assert code == 0, self.files["err"].read_text()
        return self.files["out"].read_text()

    def stop(self):
        if self.process.poll() is None:
            self.process.kill()
            self.process.wait()


def assert_same(expected: str, actual: str, names: tuple[str, str]):
    """Two printouts of one script, identical line for line; a difference is reported with
    the scenario it is in."""
    a, b = expected.splitlines(), actual.splitlines()
    scenario = "the fixed scenario"
    for number, (x, y) in enumerate(zip(a, b), 1):
        if x.startswith("scenario "):
            scenario = x
        assert x == y, f"line {number} ({scenario}) differs: {names[0]} {x!r}, {names[1]} {y!r}"
    assert len(a) == len(b), f"{names[0]} prints {len(a)} lines, {names[1]} {len(b)}"


def assert_exercised(printout: str):
    """The fixed scenario of a block (the printout up to its first demo scenario) makes at
    least 300 steps, all accepted, and moves the outputs: they change from one step to the next
    more than 8 times (counted as changes, not as distinct rows, since a block with one Boolean
    output, LGF_IecTimerOnOff, has only two rows to show)."""
    lines = printout.split("\nscenario ", 1)[0].splitlines()
    steps = [line for line in lines if line.startswith("step ")]
    assert len(steps) >= 300 and all(" -> 0 " in line for line in steps)
    outputs = [line.split(" -> ")[1] for line in steps]
    changes = sum(a != b for a, b in zip(outputs, outputs[1:]))
    assert changes > 8, f"the scenario barely moves the outputs ({changes} changes)"


def rows(printout: str, types: dict[str, str]) -> dict[str, list[tuple[int, dict]]]:
    """The outputs after exit and after every step of each demo scenario of a printout:
    scenario name -> (status of the call, outputs) per row, the outputs decoded by their types
    (name -> FMI type)."""
    result: dict[str, list[tuple[int, dict]]] = {}
    current = None
    for line in printout.splitlines():
        if line.startswith("scenario "):
            current = result.setdefault(line.split()[1], [])
        elif current is not None and line.startswith(("exit ", "step ")):
            status, *cells = line.split(" -> ", 1)[1].split(" ")
            outputs = {}
            for cell in cells:
                name, _, digits = cell.partition("=")
                if not digits or "(" in digits:
                    raise ValueError(f"an output could not be read: {line!r}")
                outputs[name] = decode(types[name], digits)
            current.append((int(status), outputs))
    return result
