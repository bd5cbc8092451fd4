"""The demo scenarios of LGF_CosinusCI (tools/blocks.py lists them); each has its reference
result in tests/blocks/LGF_CosinusCI/references/<name>.csv. The first one is the typical run of
the FMU's documentation."""

from tools.scenario import Scenario

# The scenario of the FMU's compatibility information (tools/compat.py): its inputs only.
COMPATIBILITY = "cosinus_ci"

SCENARIOS = [
    Scenario(
        name="cosinus_ci",
        block="LGF_CosinusCI",
        title="LGF_CosinusCI: a 2 s cosine of amplitude 1, then amplitude 2 around offset 1, a "
        "quarter-period phase shift, a 1 s period and a reset (value 0.0)",
        stop_time=10.0,
        inputs=[
            (
                0.0,
                {
                    "amplitude": 1.0,
                    "offset": 0.0,
                    "periode": 2000,
                    "phaseShift": 0.0,
                    "reset": False,
                },
            ),
            (4.0, {"amplitude": 2.0, "offset": 1.0}),
            (5.0, {"phaseShift": 500.0}),
            (7.0, {"periode": 1000}),
            (8.5, {"reset": True}),
            (8.8, {"reset": False}),
        ],
    ),
]
