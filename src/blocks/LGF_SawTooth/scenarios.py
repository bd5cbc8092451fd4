"""The demo scenarios of LGF_SawTooth, as tools/blocks.py describes them."""

from tools.scenario import Scenario

SCENARIOS = [
    Scenario(
        name="saw_tooth_documented",
        title="LGF_SawTooth, documented timing: a tooth lasts timeRange·(numberSteps+1) = 3 s",
        stop_time=12.0,
        inputs=[
            (
                0.0,
                {
                    "startValue": 0,
                    "timeRange": 0.5,
                    "incrementRange": 10,
                    "numberSteps": 5,
                    "reset": False,
                },
            ),
            (6.0, {"incrementRange": -15, "numberSteps": 3, "timeRange": 0.3}),  # no effect yet
            (8.0, {"reset": True}),
            (8.2, {"reset": False}),
        ],
    ),
    Scenario(
        name="saw_tooth_plc_timing",
        title="LGF_SawTooth, PLC-exact timing: each step lasts ceil(timeRange/cycle)+2 cycles",
        stop_time=12.0,
        parameters={"plcTiming": True},
        inputs=[
            (
                0.0,
                {
                    "startValue": 0,
                    "timeRange": 0.3,
                    "incrementRange": 10,
                    "numberSteps": 3,
                    "reset": False,
                },
            ),
            (8.0, {"reset": True, "timeRange": 0.5}),
            (8.2, {"reset": False}),
        ],
    ),
    Scenario(
        name="saw_tooth_endless",
        title="LGF_SawTooth, endless: INT wraps from 32767 to -32768 and goes on",
        stop_time=6.0,
        inputs=[
            (
                0.0,
                {
                    "startValue": 30000,
                    "timeRange": 0.1,
                    "incrementRange": 700,
                    "numberSteps": 0,
                    "endlessSteps": True,
                },
            )
        ],
    ),
]
