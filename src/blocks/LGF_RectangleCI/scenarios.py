"""The demo scenarios of LGF_RectangleCI (tools/blocks.py lists them); each has its reference
result in tests/blocks/LGF_RectangleCI/references/<name>.csv. The first one is the typical run
of the FMU's documentation."""

from tools.scenario import Scenario

# The scenario of the FMU's compatibility information (tools/compat.py): its inputs only.
COMPATIBILITY = "rectangle_ci"

SCENARIOS = [
    Scenario(
        name="rectangle_ci",
        block="LGF_RectangleCI",
        title="LGF_RectangleCI: a 1 s square wave between -1 and 1, then amplitude 2 around "
        "offset 1, a 2 s period and a reset (value 0.0)",
        stop_time=8.0,
        inputs=[
            (
                0.0,
                {
                    "amplitude": 1.0,
                    "offset": 0.0,
                    "periode": 1000,
                    "phaseShift": 0.0,
                    "reset": False,
                },
            ),
            (2.0, {"amplitude": 2.0, "offset": 1.0}),
            (4.0, {"periode": 2000}),
            (6.5, {"reset": True}),
            (6.8, {"reset": False}),
        ],
    ),
    Scenario(
        name="rectangle_ci_phase_beyond_half",
        block="LGF_RectangleCI",
        title="LGF_RectangleCI: a phase shift beyond half a period shortens the high part "
        "(700 ms of 1000: 30 % duty), as on the PLC; 1700 ms acts as 700",
        stop_time=8.0,
        inputs=[
            (
                0.0,
                {
                    "amplitude": 1.0,
                    "offset": 0.0,
                    "periode": 1000,
                    "phaseShift": 200.0,
                    "reset": False,
                },
            ),
            (2.0, {"phaseShift": 700.0}),
            (4.0, {"phaseShift": 1700.0}),
            (5.5, {"reset": True}),  # counter := 700, value 0.0
            (5.6, {"reset": False}),
            (6.5, {"phaseShift": 950.0}),  # 5 % duty
        ],
    ),
]
