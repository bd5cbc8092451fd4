"""One fixed scenario per block for tests/cross/scenario_runner.c, written as a runner script.

The same script is run against the linux64 and the win64 binary of an FMU; the two printouts
must be identical. Each scenario makes a few hundred doStep calls of varying size, changes the
inputs so that every rule of the block is exercised (docs/behaviour.md §2-4), tries a few values the FMU
must refuse, and saves, restores and reserializes the FMU state. Names are resolved through the
FMU's modelDescription.xml, so the scripts follow the interface."""
from __future__ import annotations

import math
import struct


def bits(value: float) -> str:
    return struct.pack(">d", float(value)).hex()


class Script:
    def __init__(self, model_description):
        self.md = model_description
        self.variables = {v.name: v for v in model_description.modelVariables}
        self.lines = [f"guid {model_description.guid}"]
        self.time = 0.0
        self.saved_time = None

    def set(self, values: dict):
        for name, value in values.items():
            v = self.variables[name]
            if v.type == "Real":
                self.lines.append(f"real {v.valueReference} {bits(value)}")
            elif v.type == "Integer":
                self.lines.append(f"int {v.valueReference} {int(value)}")
            else:
                self.lines.append(f"bool {v.valueReference} {1 if value else 0}")

    def start(self, name: str, start_time: float, values: dict):
        self.lines.append(f"instantiate {name}")
        for v in self.md.modelVariables:
            if v.causality == "output":
                self.lines.append(f"output {v.type[0].lower()} {v.valueReference} {v.name}")
        self.lines.append(f"setup {bits(start_time)}")
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
            for command in (event if isinstance(event, list) else [event]):
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

    def finish(self):
        self.lines += ["terminate", "free"]

    def text(self) -> str:
        return "\n".join(self.lines) + "\n"


def lim_rate_of_change(md) -> str:
    s = Script(md)
    s.start("limrate", 0.5, {"cycleTime": 0.01, "value": 0.0, "setChangeRate": 20.0,
                             "defaultOutValue": 30.0, "enDefaultOutValue": False})
    s.run(320, [0.01, 0.01, 0.03, 0.005, 0.005, 0.02], {
        10: {"value": 50.0},
        60: {"value": -20.125, "setChangeRate": 7.3},
        100: {"setChangeRate": -5.0},                         # error, status 16#8200, frozen
        120: {"setChangeRate": 0.0, "value": 1e6},            # rate 0 freezes
        140: {"setChangeRate": 1e5},
        160: {"enDefaultOutValue": True, "defaultOutValue": 0.1},
        180: {"enDefaultOutValue": False, "value": 1.0 / 3.0, "setChangeRate": 0.37},
        200: [{"value": math.nan}, {"setChangeRate": math.inf}],  # NaN refused; +Inf allowed
        210: [{"setChangeRate": 2.5, "value": -1e-3}, "save"],
        260: {"value": 77.7},
        280: "restore",                                       # replay from step 210 ...
        290: "reserialize",                                   # ... and once more via bytes
    })
    s.finish()
    return s.text()


def saw_tooth(md) -> str:
    s = Script(md)
    # documented timing, a timeRange that is not a multiple of the cycle, INT wrap-around
    s.start("sawtooth", 0.0, {"cycleTime": 0.02, "plcTiming": False, "startValue": 30000,
                              "timeRange": 0.25, "incrementRange": 700, "numberSteps": 4,
                              "endlessSteps": False, "reset": False})
    s.run(300, [0.02, 0.02, 0.06, 0.01, 0.01], {
        60: {"incrementRange": -9, "numberSteps": 7, "timeRange": 0.0125},  # no effect yet
        90: {"reset": True},
        94: {"reset": False},
        150: {"startValue": 40000},                            # refused: outside INT
        160: [{"endlessSteps": True, "incrementRange": 3000, "timeRange": 0.04, "reset": True}, "save"],
        161: {"reset": False},
        230: {"timeRange": 0.0, "reset": True},                # a step on every call
        232: {"reset": False},
        260: "restore",
        280: "reserialize",
    })
    s.finish()
    # PLC-exact timing (the TON of the original)
    s.start("sawtooth_plc", 0.0, {"cycleTime": 0.1, "plcTiming": True, "startValue": 0,
                                  "timeRange": 0.3, "incrementRange": 10, "numberSteps": 3,
                                  "endlessSteps": False, "reset": False})
    s.run(120, [0.1, 0.1, 0.2, 0.05, 0.05], {
        50: {"reset": True, "timeRange": 0.45, "incrementRange": -7},
        52: {"reset": False},
    })
    s.finish()
    return s.text()


def ramp(md) -> str:
    s = Script(md)
    table = [(0.0, 0.3), (33.3, 0.25), (-17.25, 0.0), (-17.25, 1.234), (1e-3, 0.5), (100.0 / 3.0, 0.0)]
    parameters = {"cycleTime": 0.05, "numberOfSetpoints": len(table)}
    for i, (value, time) in enumerate(table):
        parameters[f"setpoints[{i}].outputValue"] = value
        parameters[f"setpoints[{i}].time"] = time
    s.start("ramp", 0.0, {**parameters, "start": False, "cyclicOP": True, "hold": False,
                          "continue": False, "contStepNbr": 3, "contStepTime": 0.77,
                          "defaultOutValue": 12.5, "enDefaultOutValue": False,
                          "updateTime": False, "reset": False})
    s.run(340, [0.05, 0.05, 0.1, 0.025, 0.025], {
        5: {"start": True},
        40: {"hold": True},
        50: {"continue": True},
        55: {"hold": False, "continue": False},
        90: {"enDefaultOutValue": True},
        100: {"enDefaultOutValue": False},
        130: {"setpoints[1].outputValue": 45.6, "setpoints[3].time": 0.6},  # tunable at run time
        131: {"updateTime": True},
        140: [{"updateTime": False}, "save"],
        180: {"cyclicOP": False},
        220: {"reset": True},
        225: {"reset": False},
        230: {"start": False},
        240: {"start": True},
        250: [{"contStepNbr": 9}, {"setpoints[2].time": -1.0}],  # refused: outside the table
        270: "restore",
        300: "reserialize",
    })
    s.finish()
    return s.text()


SCRIPTS = {"LGF_LimRateOfChangeCI": lim_rate_of_change, "LGF_SawTooth": saw_tooth,
           "LGF_RampCI": ramp}
