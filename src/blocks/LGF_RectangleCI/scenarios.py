"""The demo scenarios of LGF_RectangleCI, as tools/blocks.py describes them."""

from tools.scenario import signal_scenario

SCENARIOS = [
    signal_scenario(
        "rectangle_ci",
        "LGF_RectangleCI: a 1 s square wave between -1 and 1, then amplitude 2 around "
        "offset 1, a 2 s period and a reset (value 0.0)",
        8.0,
        1000,
        [
            (2.0, {"amplitude": 2.0, "offset": 1.0}),
            (4.0, {"periode": 2000}),
            (6.5, {"reset": True}),
            (6.8, {"reset": False}),
        ],
    ),
    signal_scenario(
        "rectangle_ci_phase_beyond_half",
        "LGF_RectangleCI: a phase shift beyond half a period shortens the high part "
        "(700 ms of 1000: 30 % duty), as on the PLC; 1700 ms acts as 700",
        8.0,
        1000,
        [
            (2.0, {"phaseShift": 700.0}),
            (4.0, {"phaseShift": 1700.0}),
            (5.5, {"reset": True}),  # counter := 700, value 0.0
            (5.6, {"reset": False}),
            (6.5, {"phaseShift": 950.0}),  # 5 % duty
        ],
        phase_shift=200.0,
    ),
]
