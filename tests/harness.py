"""Drives the built FMUs through FMPy's low-level FMI 2.0 API, and the independent Python
models of the blocks (tests/blocks/<Block>/model.py) through the call clock of docs/behaviour.md
§1.2-1.3, so that tests can compare the two step by step. The blocks themselves are listed by
tests/lgf_blocks.py."""

from __future__ import annotations

import shutil
import tempfile
from ctypes import byref
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException, calloc, free
from fmpy.fmi2 import (
    FMU2Model,
    FMU2Slave,
    fmi2CallbackAllocateMemoryTYPE,
    fmi2CallbackFreeMemoryTYPE,
    fmi2CallbackFunctions,
    fmi2CallbackLoggerTYPE,
    fmi2Error,
    fmi2OK,
)

# The tests take the repository's root and the built FMUs from here too.
from tools import ROOT  # noqa: F401
from tools.simulate import FMU_DIR, fmu_path  # noqa: F401

_unzipped: dict[str, tuple] = {}


# The cross compiler `make build` builds each cross-built platform's binaries with.
CROSS_COMPILERS = {
    "win64": "x86_64-w64-mingw32-gcc",
    "x86_64-windows": "x86_64-w64-mingw32-gcc",
    "aarch64-linux": "aarch64-linux-gnu-gcc",
}


def built_platforms(folder: str) -> tuple[str, ...]:
    """The platforms every FMU of a release folder ("fmi2": fmus/, "fmi3": fmus/fmi3/) holds a
    binary for (release/dist.py: PLATFORMS): the native one, and each cross-built one where its
    cross compiler is installed, as make build builds it then."""
    from release.dist import PLATFORMS

    return tuple(
        p for p in PLATFORMS[folder] if p not in CROSS_COMPILERS or shutil.which(CROSS_COMPILERS[p])
    )


def binaries(fmu: Path) -> dict[str, list[str]]:
    """platform -> the files of binaries/<platform>/ of an FMU."""
    import zipfile

    found: dict[str, list[str]] = {}
    with zipfile.ZipFile(fmu) as z:
        for name in z.namelist():
            parts = name.removeprefix("./").split("/")
            if len(parts) == 3 and parts[0] == "binaries" and parts[2]:
                found.setdefault(parts[1], []).append(parts[2])
    return found


def unpacked(block: str):
    """(model description, unzip directory) of a block's FMU, extracted once per session."""
    if block not in _unzipped:
        directory = extract(str(fmu_path(block)), tempfile.mkdtemp(prefix=f"{block}-"))
        _unzipped[block] = (read_model_description(directory), directory)
    return _unzipped[block]


def cleanup():
    for _, directory in _unzipped.values():
        shutil.rmtree(directory, ignore_errors=True)
    _unzipped.clear()


# FMPy's native logger proxy (needed to format the variadic message) keeps one Python logger
# for the whole process, so one logger serves every instance and dispatches on the
# componentEnvironment pointer, which each instance sets to its own key.
_slaves: dict[int, "Slave"] = {}
_next_key = [1]


def _dispatch(env, name, status, category, message):
    slave = _slaves.get(env or 0)
    if slave is not None:
        slave._log(status, category, message)


_logger = fmi2CallbackLoggerTYPE(_dispatch)
_allocate = fmi2CallbackAllocateMemoryTYPE(calloc)
_free = fmi2CallbackFreeMemoryTYPE(free)


def callbacks_for(slave) -> fmi2CallbackFunctions:
    """The FMI 2.0 callbacks of an instance whose messages go to its _log(status, category,
    message); forget(instance) when it is freed."""
    from fmpy.logging import addLoggerProxy

    key = _next_key[0]
    _next_key[0] += 1
    _slaves[key] = slave
    slave._key = key
    callbacks = fmi2CallbackFunctions()
    callbacks.logger = _logger
    callbacks.allocateMemory = _allocate
    callbacks.freeMemory = _free
    callbacks.componentEnvironment = key
    addLoggerProxy(byref(callbacks))
    return callbacks


def forget(slave) -> None:
    _slaves.pop(slave._key, None)


MALFORMED_LOG_MESSAGES: list[str] = []


def read_references(message: str) -> str:
    """A log message as an FMI Library based importer prints it: '#' starts a variable
    reference and "##" is a literal '#' (FMI 2.0, 2.1.5). The FMU writes no references, so any
    '#' not doubled would be misread; such messages are collected in MALFORMED_LOG_MESSAGES
    (conftest.py fails the session on them)."""
    if "#" in message.replace("##", ""):
        MALFORMED_LOG_MESSAGES.append(message)
    return message.replace("##", "#")


class Slave:
    """One FMU instance, co-simulation or (model_exchange=True) Model Exchange, which ends
    initialization in event mode. Records every log message in `log` as (status, category,
    text)."""

    def __init__(
        self,
        block: str,
        parameters: dict | None = None,
        inputs: dict | None = None,
        start_time: float = 0.0,
        initialize: bool = True,
        instance_name: str = "test",
        model_exchange: bool = False,
    ):
        self.block = block
        self.md, directory = unpacked(block)
        self.variables = {v.name: v for v in self.md.modelVariables}
        self.log: list[tuple[int, str, str]] = []
        self.raw_log: list[str] = []  # the messages as the FMU sent them, '#' escaped as '##'
        kind = FMU2Model if model_exchange else FMU2Slave
        self.fmu = kind(
            guid=self.md.guid,
            unzipDirectory=directory,
            modelIdentifier=self.md.coSimulation.modelIdentifier,
            instanceName=instance_name,
        )
        self.callbacks = callbacks_for(self)
        self.fmu.instantiate(callbacks=self.callbacks)
        self.time = start_time
        self.start_time = start_time
        if initialize:
            self.fmu.setupExperiment(startTime=start_time)
            self.fmu.enterInitializationMode()
            self.set({**(parameters or {}), **(inputs or {})})
            self.fmu.exitInitializationMode()

    def _log(self, status, category, message):
        raw = message.decode()
        self.raw_log.append(raw)
        self.log.append((status, category.decode(), read_references(raw)))

    def free(self):
        status_of(self.fmu.terminate)  # refused unless in step mode; freeing works in any mode
        self.fmu.freeInstance()
        forget(self)

    def vr(self, name: str) -> int:
        return self.variables[name].valueReference

    def set(self, values: dict) -> None:
        for name, value in values.items():
            v = self.variables[name]
            if v.type == "Real":
                self.fmu.setReal([v.valueReference], [float(value)])
            elif v.type == "Integer":
                self.fmu.setInteger([v.valueReference], [int(value)])
            else:
                self.fmu.setBoolean([v.valueReference], [bool(value)])

    def get(self, names) -> dict:
        result = {}
        for name in names:
            v = self.variables[name]
            getter = {
                "Real": self.fmu.getReal,
                "Integer": self.fmu.getInteger,
                "Boolean": self.fmu.getBoolean,
            }[v.type]
            result[name] = getter([v.valueReference])[0]
        return result

    def outputs(self) -> dict:
        return self.get([u.variable.name for u in self.md.outputs])

    def step(self, h: float) -> dict:
        self.fmu.doStep(currentCommunicationPoint=self.time, communicationStepSize=h)
        self.time += h
        return self.outputs()

    def event(self, time: float, inputs: dict) -> dict:
        """Model Exchange, from continuous-time mode: an event at `time`, `inputs` set in event
        mode, one event iteration (the PLC call due at `time`, docs/behaviour.md §1.11); the
        outputs after it."""
        self.fmu.setTime(time)
        self.fmu.enterEventMode()
        self.set(inputs)
        self.fmu.newDiscreteStates()
        return self.outputs()

    def replayed(self, run: Callable[[], object]) -> tuple:
        """run() from here, then again from the FMU state saved here, the time put back
        (docs/behaviour.md §1.9): the two results, which a restore must make equal."""
        state, time = self.fmu.getFMUstate(), self.time
        first = run()
        self.fmu.setFMUstate(state)
        self.time = time
        again = run()
        self.fmu.freeFMUstate(state)
        return first, again

    def status_of(self, function, *args) -> int:
        """Calls an FMPy FMU2Slave method and returns the FMI status instead of raising."""
        try:
            function(*args)
            return fmi2OK
        except FMICallException as e:
            return e.status


def status_of(function, *args) -> int:
    try:
        function(*args)
        return fmi2OK
    except FMICallException as e:
        return e.status


def run_calls(block: str, cycle: float, calls: list[dict], **start) -> list[dict]:
    """Outputs of calls 0, 1, ...: calls[0] (with start) is set during initialization and reaches
    call 0, calls[k] is set before the step that executes call k (docs/behaviour.md §1.3)."""
    s = Slave(block, {"cycleTime": cycle}, {**start, **calls[0]})
    rows = [s.outputs()]
    for changes in calls[1:]:
        s.set(changes)
        rows.append(s.step(cycle))
    s.free()
    return rows


def column(rows: list[dict], name: str) -> list:
    return [row[name] for row in rows]


def initializing(block: str):
    """A Slave of the block in Initialization Mode (a generator, for a fixture): left and freed
    after the test."""
    s = Slave(block, initialize=False)
    s.fmu.setupExperiment(startTime=0.0)
    s.fmu.enterInitializationMode()
    yield s
    s.fmu.exitInitializationMode()
    s.free()


def refused(s: Slave, setter, name: str, value) -> bool:
    """Setting name to value is fmi2Error, logged as an error, and the value is not applied."""
    before = s.get([name])[name]
    status = s.status_of(setter, [s.vr(name)], [value])
    after = s.get([name])[name]
    return status == fmi2Error and after == before and s.log and s.log[-1][0] == fmi2Error


def step_rows(s: Slave, calls: int, row, changes: dict | None = None, h: float | None = None):
    """row(outputs) of call 0 and of `calls` further calls, one step of h (default: cycleTime)
    each; changes[k] is set before call k."""
    h = h or s.get(["cycleTime"])["cycleTime"]
    changes = changes or {}
    rows = [row(s.outputs())]
    for k in range(1, calls + 1):
        if k in changes:
            s.set(changes[k])
        rows.append(row(s.step(h)))
    return rows


def model_exchange_run(fmu: Path, scenario, md, outputs: list[str], **options):
    """The scenario run by FMPy's Model Exchange on fmu with every input change one cycle later
    (in Model Exchange a change at a call time reaches that call, in co-simulation the next one:
    docs/behaviour.md §1.11), so that it equals the co-simulation run; the last row of each time
    point (FMPy records an event's time point twice, before and after)."""
    from dataclasses import replace

    from fmpy import simulate_fmu

    from tools.scenario import input_defaults

    cycle = scenario.cycle_time(md)
    shifted = replace(scenario, inputs=[(t + cycle if t > 0 else t, c) for t, c in scenario.inputs])
    result = simulate_fmu(
        str(fmu),
        fmi_type="ModelExchange",
        stop_time=scenario.stop_time,
        output_interval=scenario.output_interval,
        start_values=scenario.parameters,
        input=shifted.input_signals(input_defaults(md)),
        output=outputs,
        **options,
    )
    times = result["time"]
    return result[[i for i in range(len(times)) if i + 1 == len(times) or times[i + 1] != times[i]]]


@dataclass
class Trace:
    """A run as a list of (h in µs, input changes applied before that step)."""

    initial: dict
    steps: list[tuple[int, dict]] = field(default_factory=list)


def run_fmu(
    block: str, cycle_us: int, trace: Trace, parameters: dict | None = None, start_time: float = 0.0
) -> list[dict]:
    """Outputs after initialization and after every step. The communication point is computed as
    an importer like FMPy does, start + elapsed, so it carries floating-point round-off."""
    slave = Slave(
        block,
        {"cycleTime": cycle_us / 1e6, **(parameters or {})},
        trace.initial,
        start_time=start_time,
    )
    rows = [slave.outputs()]
    elapsed_us = 0
    for h_us, changes in trace.steps:
        slave.set(changes)
        t = start_time + elapsed_us / 1e6
        end = start_time + (elapsed_us + h_us) / 1e6
        slave.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=end - t)
        elapsed_us += h_us
        rows.append(slave.outputs())
    slave.free()
    return rows


def run_model(model, cycle_us: int, trace: Trace) -> list[dict]:
    """The same trace on a Python model, with the call clock of docs/behaviour.md §1.2-1.3 in exact
    integers:
    call k at k·cycle; a step (t, t + h] executes every call in it with the inputs set before it,
    and a call within ε = 1e-4·cycle after t + h counts as inside it (§1.3, tolerance);
    outputs stay as they were when no call falls into a step."""
    inputs = dict(trace.initial)
    outputs = model.call(0, inputs)
    rows = [dict(outputs)]
    k, now_us = 1, 0
    for h_us, changes in trace.steps:
        for name, value in changes.items():
            if name in inputs:
                inputs[name] = value
            else:
                model.set(name, value)  # a tunable parameter
        now_us += h_us
        while (k * cycle_us - now_us) * 10_000 <= cycle_us:  # k·cycle <= now + 1e-4·cycle
            outputs = model.call(k * cycle_us, dict(inputs))
            k += 1
        rows.append(dict(outputs))
    return rows
