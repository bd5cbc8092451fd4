"""A scenario simulated with FMPy as co-simulation, a communication step of its output interval:
on a built FMU (simulate: the demo, the tests) or on a library just built (simulate_built: the
build's documentation and compatibility information); the FMU's log messages printed as they
come, each with what it is; results written as CSV that reads back bit for bit."""

from __future__ import annotations

import argparse
import shutil
import tempfile
import zipfile
from contextlib import contextmanager
from ctypes import byref
from pathlib import Path

import numpy as np
from fmpy import read_model_description, simulate_fmu
from fmpy.fmi1 import printLogMessage
from fmpy.fmi2 import fmi2CallbackFunctions, fmi2CallbackLoggerTYPE
from fmpy.logging import addLoggerProxy

from tools import ROOT
from tools.scenario import input_defaults

FMU_DIR = ROOT / "fmus"


def fmu_path(block: str, directory: Path = FMU_DIR) -> Path:
    """The FMU of a block; a missing one is an error (a test that needs it fails), never a
    reason to leave the block out."""
    path = Path(directory) / f"{block}.fmu"
    if not path.exists():
        raise FileNotFoundError(f"{path} is missing: run `make build` first")
    return path


STATUS_NAMES = {0: "OK", 1: "warning", 2: "discard", 3: "error", 4: "fatal", 5: "pending"}


class Messages:
    """The FMU's log messages of one run. Printed as they come, each with what it is: a
    warning the scenario provokes on purpose (Scenario.expected_warning) says so."""

    def __init__(self, scenario, echo: bool = True):
        self.scenario = scenario
        self.echo = echo
        self.lines: list[tuple[int, str]] = []

    def __call__(self, status: int, message: bytes):
        # The FMU writes a literal '#' as '##' (FMI 2.0, 2.1.5); FMPy hands it over unchanged.
        text = message.decode(errors="replace").replace("##", "#")
        self.lines.append((status, text))
        if not self.echo:
            return
        kind = STATUS_NAMES.get(status, str(status))
        if self.scenario.expected_warning and status == 1:
            print(
                f"  {self.scenario.name}: deliberate {kind} "
                f"({self.scenario.expected_warning}): {text}"
            )
        else:
            print(f"  {self.scenario.name}: {kind} from {self.scenario.block}: {text}")


# FMPy formats the FMU's variadic log messages in a native proxy that holds one Python logger
# for the whole process: the last one registered. A logger handed to simulate_fmu lives only as
# long as its run, and the proxy would call it after it is gone (for instance from a later
# simulate_fmu without a logger, which goes through FMPy's default callbacks and that same
# proxy). So this module registers one logger that lives as long as the process, before each of
# its runs, and lets it forward to the run's Messages; outside them it prints as FMPy does.
_current: list = []


def _forward(environment, instance, status, category, message):
    if _current:
        _current[-1](status, message)
    else:
        printLogMessage(environment, instance, status, category, message)


_LOGGER = fmi2CallbackLoggerTYPE(_forward)


@contextmanager
def forwarding_messages(receiver):
    """Within it, the log messages of FMUs that FMPy runs without a logger of their own (as
    simulate_fmu does) go to receiver(status, message)."""
    callbacks = fmi2CallbackFunctions()
    callbacks.logger = _LOGGER
    addLoggerProxy(byref(callbacks))
    _current.append(receiver)
    try:
        yield receiver
    finally:
        _current.pop()


def simulate(scenario, fmu_dir: Path, echo: bool = True):
    """The scenario in FMPy (co-simulation, a communication step of its output_interval):
    (result, output names, model description). The FMU's log messages are printed (echo)."""
    fmu = fmu_path(scenario.block, fmu_dir)
    md = read_model_description(str(fmu))
    outputs = [v.name for v in md.modelVariables if v.causality == "output"]
    with forwarding_messages(Messages(scenario, echo)):
        result = simulate_fmu(
            str(fmu),
            stop_time=scenario.stop_time,
            output_interval=scenario.output_interval,
            start_values=scenario.parameters,
            input=scenario.input_signals(input_defaults(md)),
            output=outputs,
            validate=True,
        )
    return result, outputs, md


def simulate_built(scenario, xml: Path, binary: Path, echo: bool = True):
    """The scenario on a library just built (the build's documentation and reference results):
    packed with its modelDescription.xml into a temporary FMU (documentation and sources are
    not needed to simulate). Returns the result."""
    platform = {".so": "linux64", ".dll": "win64", ".dylib": "darwin64"}[binary.suffix]
    folder = Path(tempfile.mkdtemp(prefix="lgf-sim-"))
    try:
        with zipfile.ZipFile(folder / f"{scenario.block}.fmu", "w") as fmu:
            fmu.write(xml, "modelDescription.xml")
            fmu.write(binary, f"binaries/{platform}/{scenario.block}{binary.suffix}")
        result, _, _ = simulate(scenario, folder, echo)
        return result
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def built_library_parser(description: str, out_help: str) -> argparse.ArgumentParser:
    """The command line of the build steps that simulate a library just built
    (tools/documentation.py, tools/compat.py): --block, --xml, --binary and --out."""
    parser = argparse.ArgumentParser(
        description=description, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--block", required=True, help="the modelIdentifier")
    parser.add_argument("--xml", required=True, type=Path, help="the FMU's modelDescription.xml")
    parser.add_argument("--binary", required=True, type=Path, help="the FMU's library just built")
    parser.add_argument("--out", required=True, type=Path, help=out_help)
    return parser


def csv_number(value) -> str:
    """A CSV cell: Booleans as 0/1, integers as integers, floats with repr's shortest digits
    that read back bit for bit."""
    if isinstance(value, (bool, np.bool_)):
        return "1" if value else "0"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    return repr(float(value))


def csv_time(value: float) -> str:
    """A time of the output grid as a reader expects it: FMPy's n·h as a double (e.g.
    0.30000000000000004) rounded to 1 ns (0.3)."""
    return repr(round(float(value), 9))


def write_csv(result, path: Path, exact_times: bool = True):
    """Numeric CSV, header `time,<names>`: Booleans as 0/1, which FMPy's read_csv and any
    spreadsheet understand. Values read back bit for bit; times too when exact_times (the
    reference results, which a replay compares exactly), else rounded to 1 ns (the demo)."""
    names = result.dtype.names
    with open(path, "w") as f:
        f.write(",".join(names) + "\n")
        for row in result:
            cells = [csv_number(row[0]) if exact_times else csv_time(row[0])]
            cells += [csv_number(row[name]) for name in names[1:]]
            f.write(",".join(cells) + "\n")
