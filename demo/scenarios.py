"""The demo scenarios, one or more per block. `make demo` plots them; the test suite compares a
fresh run of each with its committed reference result (tests/references) and with the
independent Python model of the block."""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass
class Scenario:
    name: str
    block: str
    title: str
    stop_time: float
    parameters: dict = field(default_factory=dict)  # start values of parameters (and inputs)
    # Piecewise-constant inputs: (time, changes) rows; each change holds until the next one.
    # Times lie on the output grid, so FMPy's communication points are exactly that grid.
    inputs: list[tuple[float, dict]] = field(default_factory=list)
    output_interval: float = 0.1

    def input_signals(self, defaults: dict):
        """The inputs as the structured array FMPy's simulate_fmu takes (discrete inputs hold
        the value of the latest row at or before t); `defaults` holds every input's start
        value, so that FMPy finds a signal for each input."""
        names = sorted(defaults)
        current, rows = dict(defaults), []
        for time, changes in sorted(self.inputs, key=lambda row: row[0]):
            current.update(changes)
            rows.append((time, current.copy()))
        rows.append((self.stop_time, current.copy()))  # FMPy needs two rows; no change here
        dtype = [("time", np.float64)] + [(n, _dtype(rows[-1][1][n])) for n in names]
        return np.array([(t, *[values[n] for n in names]) for t, values in rows], dtype=dtype)


def input_defaults(model_description) -> dict:
    """Every input of an FMU with its start value, typed."""
    convert = {"Real": float, "Integer": int, "Boolean": lambda text: text in ("true", "1")}
    return {v.name: convert[v.type](v.start) for v in model_description.modelVariables
            if v.causality == "input"}


def _dtype(value):
    return np.bool_ if isinstance(value, bool) else np.int32 if isinstance(value, int) else np.float64


SCENARIOS = [
    Scenario(
        name="lim_rate_of_change",
        block="LGF_LimRateOfChangeCI",
        title="LGF_LimRateOfChangeCI: ramps, a negative rate (16#8200) and a pre-assigned output",
        stop_time=12.0,
        inputs=[
            (0.0, {"value": 0.0, "setChangeRate": 20.0, "defaultOutValue": 30.0,
                   "enDefaultOutValue": False}),
            (0.5, {"value": 50.0}),
            (4.0, {"value": -20.0}),
            (5.0, {"setChangeRate": -5.0}),
            (6.0, {"setChangeRate": 10.0}),
            (8.0, {"enDefaultOutValue": True}),
            (9.0, {"enDefaultOutValue": False, "value": 0.0}),
        ],
    ),
    Scenario(
        name="saw_tooth_documented",
        block="LGF_SawTooth",
        title="LGF_SawTooth, documented timing: a tooth lasts timeRange·(numberSteps+1) = 3 s",
        stop_time=12.0,
        inputs=[
            (0.0, {"startValue": 0, "timeRange": 0.5, "incrementRange": 10, "numberSteps": 5,
                   "reset": False}),
            (6.0, {"incrementRange": -15, "numberSteps": 3, "timeRange": 0.3}),  # no effect yet
            (8.0, {"reset": True}),
            (8.2, {"reset": False}),
        ],
    ),
    Scenario(
        name="saw_tooth_plc_timing",
        block="LGF_SawTooth",
        title="LGF_SawTooth, PLC-exact timing: each step lasts ceil(timeRange/cycle)+2 cycles",
        stop_time=12.0,
        parameters={"plcTiming": True},
        inputs=[
            (0.0, {"startValue": 0, "timeRange": 0.3, "incrementRange": 10, "numberSteps": 3,
                   "reset": False}),
            (8.0, {"reset": True, "timeRange": 0.5}),
            (8.2, {"reset": False}),
        ],
    ),
    Scenario(
        name="saw_tooth_endless",
        block="LGF_SawTooth",
        title="LGF_SawTooth, endless: INT wraps from 32767 to -32768 and goes on",
        stop_time=6.0,
        inputs=[(0.0, {"startValue": 30000, "timeRange": 0.1, "incrementRange": 700,
                       "numberSteps": 0, "endlessSteps": True})],
    ),
    Scenario(
        name="ramp_hold_cyclic",
        block="LGF_RampCI",
        title="LGF_RampCI: a setpoint profile with a hold, repeated cyclically",
        stop_time=28.0,
        parameters={
            "numberOfSetpoints": 5,
            "setpoints[0].outputValue": 0.0, "setpoints[0].time": 2.0,
            "setpoints[1].outputValue": 100.0, "setpoints[1].time": 3.0,
            "setpoints[2].outputValue": 100.0, "setpoints[2].time": 2.0,
            "setpoints[3].outputValue": 40.0, "setpoints[3].time": 1.0,
            "setpoints[4].outputValue": 0.0, "setpoints[4].time": 0.0,
        },
        inputs=[
            (0.0, {"start": False, "cyclicOP": True, "hold": False}),
            (0.5, {"start": True}),
            (1.5, {"hold": True}),
            (3.5, {"hold": False}),
            (20.0, {"cyclicOP": False}),
        ],
    ),
    Scenario(
        name="ramp_modes",
        block="LGF_RampCI",
        title="LGF_RampCI: pre-assigned output, continue at another step, reset and restart",
        stop_time=20.0,
        inputs=[
            (0.0, {"start": True, "defaultOutValue": 50.0, "enDefaultOutValue": False,
                   "contStepNbr": 2, "contStepTime": 1.0}),
            (1.0, {"enDefaultOutValue": True}),
            (2.0, {"enDefaultOutValue": False}),
            (7.0, {"hold": True}),
            (7.5, {"continue": True}),
            (8.0, {"hold": False, "continue": False}),
            (12.0, {"reset": True}),
            (12.5, {"reset": False}),
            (14.0, {"start": False}),
            (15.0, {"start": True}),
        ],
    ),
]
