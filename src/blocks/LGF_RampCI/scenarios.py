"""The demo scenarios of LGF_RampCI, as tools/blocks.py describes them."""

from tools.scenario import Scenario

from .table import table

# The scenario of the FMU's compatibility information: not the first, which sets parameters
# (tools/blocks.py).
COMPATIBILITY = "ramp_modes"

SCENARIOS = [
    Scenario(
        name="ramp_hold_cyclic",
        title="LGF_RampCI: a setpoint profile with a hold, repeated cyclically",
        stop_time=28.0,
        parameters=table((0.0, 2.0), (100.0, 3.0), (100.0, 2.0), (40.0, 1.0), (0.0, 0.0)),
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
        title="LGF_RampCI: pre-assigned output, continue at another step, reset and restart",
        stop_time=20.0,
        inputs=[
            (
                0.0,
                {
                    "start": True,
                    "defaultOutValue": 50.0,
                    "enDefaultOutValue": False,
                    "contStepNbr": 2,
                    "contStepTime": 1.0,
                },
            ),
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


def plot_marks(result) -> dict:
    """The table points the profile reaches, for the plots (tools/plots.py): the calls in which
    outputValue snaps exactly onto a point (docs/behaviour.md §4.3 a, d, e): a run starts at
    point 0 (status 16#7001, or the call after a cyclic wrap), stepNumber moves on by one while
    the table is being output, or the last point is reached (16#7002, or 0 outside a reset)."""
    step, status, active = result["stepNumber"], result["status"], result["actTimeTable"]
    times, values = [], []
    for i in range(len(result)):
        before_step = step[i - 1] if i else 0
        before_status = status[i - 1] if i else 0x7000
        started = status[i] == 0x7001 or (before_status == 0x7002 and step[i] == 1)
        moved_on = active[i] and step[i] == before_step + 1
        ended = status[i] == 0x7002 or (status[i] == 0 and before_status != 0 and step[i] != 0)
        if started or moved_on or ended:
            times.append(result["time"][i])
            values.append(result["outputValue"][i])
    return {"outputValue": [(times, values, "table point reached")]}
