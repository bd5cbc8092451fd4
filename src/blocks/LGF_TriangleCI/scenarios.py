"""The demo scenarios of LGF_TriangleCI (tools/blocks.py lists them); each has its reference
result in tests/blocks/LGF_TriangleCI/references/<name>.csv. The first one is the typical run of
the FMU's documentation."""

from tools.scenario import Scenario

# The scenario of the FMU's compatibility information (tools/compat.py): its inputs only.
COMPATIBILITY = "triangle_ci"

SCENARIOS = [
    Scenario(
        name="triangle_ci",
        block="LGF_TriangleCI",
        title="LGF_TriangleCI: a 1 s triangle between -1 and 1, then amplitude 2 around offset 1, "
        "a quarter-period phase shift, a 2 s period and a reset",
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
            (3.0, {"phaseShift": 250.0}),
            (4.0, {"periode": 2000}),
            (6.5, {"reset": True}),  # value = offset while reset is TRUE
            (6.8, {"reset": False}),
        ],
    ),
]
