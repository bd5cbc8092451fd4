"""The demo scenarios of LGF_RampCI; each has its reference result in references/<name>.csv.
The first one is the typical run of the FMU's documentation."""
from demo.scenarios import Scenario

from .table import table

SCENARIOS = [
    Scenario(
        name="ramp_hold_cyclic",
        block="LGF_RampCI",
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
