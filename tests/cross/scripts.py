"""The machinery of the runner scripts of tests/cross/scenario_runner.c: one fixed scenario per
block, each block's in its tests/blocks/<Block>/cross.py (`script(md) -> str`, built with Script),
and every demo scenario as FMPy's simulate_fmu runs it (scenario_script).

The same script is run against the binaries of two platforms of an FMU; the two printouts
must be identical. Each fixed scenario makes a few hundred doStep calls of varying size, changes
the inputs so that every rule of the block is exercised (docs/behaviour.md §2-4), tries a few
values the FMU must refuse, and saves, restores and reserializes the FMU state. Names are
resolved through the FMU's modelDescription.xml, FMI 2.0 or 3.0, so the scripts follow the
interface and its types (an integer outside an FMI 3.0 type's range reaches the FMU converted
to the type, as C converts it: an FMI 3.0 importer has no other way to pass it)."""

from __future__ import annotations

import struct
from math import inf, isclose

# The runner's command for setting (and printing) a variable of each type.
COMMANDS = {
    "Real": "real",
    "Integer": "int",
    "Boolean": "bool",
    "Float64": "float64",
    "Float32": "float32",
    "Int16": "int16",
    "UInt16": "uint16",
    "UInt32": "uint32",
    "Int32": "int32",
    "Int8": "int8",
    "UInt8": "uint8",
}


def bits(value: float) -> str:
    return struct.pack(">d", float(value)).hex()


def bits32(value: float) -> str:
    """The float32 nearest to value, as C's conversion rounds it (beyond the largest float32:
    infinity)."""
    try:
        return struct.pack(">f", float(value)).hex()
    except OverflowError:
        return struct.pack(">f", inf if value > 0 else -inf).hex()


def text(variable_type: str, value) -> str:
    """A value as the runner reads it for a variable of that type."""
    if variable_type in ("Real", "Float64"):
        return bits(value)
    if variable_type == "Float32":
        return bits32(value)
    if variable_type == "Boolean":
        return "1" if value else "0"
    return str(int(value))


def decode(variable_type: str, hex_digits: str):
    """An output as the runner prints it (its bit pattern) -> its value."""
    raw = bytes.fromhex(hex_digits)
    if variable_type in ("Real", "Float64"):
        return struct.unpack(">d", raw)[0]
    if variable_type == "Float32":
        return struct.unpack(">f", raw)[0]
    if variable_type in ("Integer", "Int16", "Int32", "Int8"):
        return struct.unpack(">i", raw)[0]
    if variable_type == "Boolean":
        return bool(struct.unpack(">I", raw)[0])
    return struct.unpack(">I", raw)[0]


class Script:
    def __init__(self, model_description):
        self.md = model_description
        self.variables = {v.name: v for v in model_description.modelVariables}
        self.lines = [f"guid {model_description.guid}"]  # FMPy: instantiationToken in FMI 3.0
        self.time = 0.0
        self.saved_time = None

    def set(self, values: dict):
        for name, value in values.items():
            v = self.variables[name]
            self.lines.append(f"{COMMANDS[v.type]} {v.valueReference} {text(v.type, value)}")

    def start(self, name: str, start_time: float, values: dict, stop_time: float | None = None):
        self.lines.append(f"instantiate {name}")
        for v in self.md.modelVariables:
            if v.causality == "output":
                self.lines.append(f"output {COMMANDS[v.type]} {v.valueReference} {v.name}")
        stop = "" if stop_time is None else f" {bits(stop_time)}"
        self.lines.append(f"setup {bits(start_time)}{stop}")
        self.lines.append("enter")
        self.set(values)
        self.lines.append("exit")
        self.time = start_time

    def run(self, steps: int, sizes: list[float], events: dict[int, dict | str] | None = None):
        """`steps` doSteps with the step sizes of `sizes` in turn; before step k the inputs of
        events[k] are set (or the FMU-state command events[k] is given)."""
        events = events or {}
        for k in range(steps):
            event = events.get(k)
            for command in event if isinstance(event, list) else [event]:
                if isinstance(command, dict):
                    self.set(command)
                elif command == "save":
                    self.lines.append("save")
                    self.saved_time = self.time
                elif command in ("restore", "reserialize"):
                    if command == "reserialize":
                        self.lines.append("reserialize")
                    self.lines.append("restore")
                    self.time = self.saved_time
            h = sizes[k % len(sizes)]
            self.lines.append(f"step {bits(self.time)} {bits(h)}")
            self.time = self.time + h  # as the FMU computes its next communication point

    def step_to(self, point: float):
        """One doStep from the current time to `point`, as an importer computes it."""
        self.lines.append(f"step {bits(self.time)} {bits(point - self.time)}")
        self.time = point

    def finish(self):
        self.lines += ["terminate", "free"]

    def text(self) -> str:
        return "\n".join(self.lines) + "\n"


# The step sizes of the fixed scenarios at a cycle of 10 ms: whole cycles, three cycles in one
# doStep, half cycles (a call every other doStep) and two cycles, in turn.
SIZES_10MS = [0.01, 0.01, 0.03, 0.005, 0.005, 0.02]


def one_run(
    md, name: str, start_time: float, values: dict, steps: int, sizes: list[float], events: dict
) -> str:
    """The script of a fixed scenario of one instance: `values` set in initialization mode at
    start_time, then `steps` doSteps of `sizes` with `events` (Script.run), then terminate and
    free."""
    s = Script(md)
    s.start(name, start_time, values)
    s.run(steps, sizes, events)
    s.finish()
    return s.text()


def scenario_script(scenario, model_description) -> str:
    """A demo scenario (tools.scenario.Scenario) as FMPy's simulate_fmu runs it in
    co-simulation (demo/run_demo.py): start and stop time in setup, the parameters and every
    input at the start time in initialization mode, then doSteps to the points of its
    output_interval, start + n·interval (an input change off that grid ends a step there, as
    FMPy's input events do), and before each step every input that changed since the last one
    set to its value at the step's start (the latest row at or before it, within FMPy's
    isclose). So the printout after exit and after every step is the scenario's committed
    reference result, row by row (tests/test_aarch64.py checks it)."""
    from tools.scenario import input_defaults

    signals = scenario.input_signals(input_defaults(model_description))
    times = [float(t) for t in signals["time"]]
    names = [n for n in signals.dtype.names if n != "time"]

    def inputs_at(time: float, after_event: bool) -> dict:
        # fmpy.simulation.Input.interpolate of a discrete input
        before = sum(1 for t in times if t < time)
        i = 0 if before == 0 else before - 1
        if after_event and 0 < before < len(times):
            while i + 1 < len(times) and (times[i + 1] < time or isclose(time, times[i + 1])):
                i += 1
        return {n: signals[n][i].item() for n in names}

    # fmpy.simulation.Input.findEvents: where an input changes, and repeated times
    changes = sorted(
        {
            times[i + 1]
            for i in range(len(times) - 1)
            if times[i] == times[i + 1] or any(signals[n][i] != signals[n][i + 1] for n in names)
        }
    )
    start, stop, interval = 0.0, float(scenario.stop_time), float(scenario.output_interval)
    s = Script(model_description)
    s.lines.append(f"scenario {scenario.name}")
    applied = inputs_at(start, after_event=False)
    s.start(scenario.name, start, {**scenario.parameters, **applied}, stop_time=stop)
    n = 0
    while not (s.time > stop or isclose(s.time, stop)):
        regular = start + (n + 1) * interval
        point = regular
        event = next((t for t in changes if t > s.time and not isclose(t, s.time)), inf)
        if point > event and not isclose(point, event):
            point = event
        if point > stop and not isclose(point, stop):
            point = stop
        now = inputs_at(s.time, after_event=True)
        s.set({name: value for name, value in now.items() if value != applied[name]})
        applied = now
        s.step_to(point)
        if isclose(s.time, regular):
            n += 1
    s.finish()
    return s.text()
