"""The demo scenarios of LGF_NonLinearInterpolation, as tools/blocks.py describes them."""

from tools.scenario import Scenario

from .table import table


def _sweep(start: float, stop: float, step: float, t0: float, dt: float) -> list:
    """value from start to stop (both included) by step, one value every dt from t0 on."""
    count = round((stop - start) / step)
    return [(round(t0 + i * dt, 6), {"value": start + i * step}) for i in range(count + 1)]


# Why the default experiment (start values, no input connected) moves no output
# (tests/test_default_experiment.py).
STEADY_DEFAULT = (
    "it maps value through its table (docs/behaviour.md §20): a constant value gives a constant "
    "point of the curve, 60.0 for the start value 65.0"
)

SCENARIOS = [
    Scenario(
        name="characteristic_sweep",
        title="LGF_NonLinearInterpolation: value swept across the default curve and back",
        stop_time=25.0,
        inputs=[
            (0.0, {"value": -10.0, "enDefaultOutValue": False, "track": False, "reset": False}),
            *_sweep(-10.0, 110.0, 1.0, 0.1, 0.1)[1:],
            *_sweep(110.0, -10.0, -1.0, 12.2, 0.1)[1:],
        ],
    ),
    Scenario(
        name="interpolation_modes",
        title="LGF_NonLinearInterpolation: pre-assignment, tracking, reset (in this priority) and "
        "extrapolation",
        stop_time=8.0,
        parameters=table((-50.0, -100.0), (0.0, 0.0), (10.0, 50.0), (60.0, 75.0)),
        inputs=[
            (
                0.0,
                {
                    "value": 5.0,
                    "defaultOutValue": -20.0,
                    "enDefaultOutValue": False,
                    "track": False,
                    "reset": False,
                },
            ),
            (1.0, {"value": 35.0}),
            (2.0, {"value": 90.0}),  # beyond the last point: the last segment continued
            (3.0, {"value": -80.0}),  # below the first point: the first segment continued
            (4.0, {"track": True}),
            (4.5, {"value": 20.0}),
            (5.0, {"track": False, "enDefaultOutValue": True}),
            (5.5, {"reset": True}),  # the pre-assignment comes first
            (6.0, {"enDefaultOutValue": False, "track": True}),  # then tracking, before reset
            (6.3, {"track": False}),  # reset alone: 0.0
            (6.6, {"reset": False}),
            (7.0, {"value": 10.0}),  # on a point
        ],
    ),
]
