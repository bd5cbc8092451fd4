"""The demo scenarios of LGF_Integration (docs/behaviour.md §18), as
tools/blocks.py describes them."""

from tools.scenario import Scenario

SCENARIOS = [
    Scenario(
        name="integration",
        title="LGF_Integration: steps of value, disabled from 5 s to 6 s (held), reset at 8 s",
        stop_time=12.0,
        inputs=[
            (0.0, {"enable": True, "value": 1.0, "reset": False}),
            (2.0, {"value": 3.0}),
            (4.0, {"value": -1.0}),
            (5.0, {"enable": False}),
            (6.0, {"enable": True, "value": 2.0}),
            (8.0, {"reset": True}),
            (8.3, {"reset": False, "value": 0.5}),
        ],
    ),
    Scenario(
        name="integration_ramp",
        title="LGF_Integration: value ramps by 0.1 per call, integral = t^2 / 2 by trapezoids",
        stop_time=10.0,
        inputs=[
            (0.0, {"enable": True, "value": 0.0, "reset": False}),
            *[(round(0.1 * k, 1), {"value": round(0.1 * k, 1)}) for k in range(1, 100)],
        ],
    ),
]
