"""The demo scenarios of LGF_ScaleLinear (docs/behaviour.md §19), as
tools/blocks.py describes them."""

from tools.scenario import Scenario

# x ramps from -2000 to 30000 over 8 s in steps of 400 every 0.1 s: below 0 the line gives y < 0,
# limited to yMin (16#6001); above 27648 it gives y > 100, limited to yMax (16#6002).
_RAMP = [(round(0.1 * k, 1), {"x": -2000.0 + 400.0 * k}) for k in range(1, 81)]

# Why the default experiment (start values, no input connected) moves no output
# (tests/test_default_experiment.py).
STEADY_DEFAULT = (
    "an FC: y is a function of the inputs alone (docs/behaviour.md §19), so constant inputs give "
    "a constant y"
)

SCENARIOS = [
    Scenario(
        name="scale_linear",
        title="LGF_ScaleLinear: 0 ... 27648 to 0 ... 100 %, limited (16#6001, 16#6002), "
        "yMin > yMax (16#8200), x1 = x2",
        stop_time=12.0,
        inputs=[
            (
                0.0,
                {
                    "x": -2000.0,
                    "x1": 0.0,
                    "y1": 0.0,
                    "x2": 27648.0,
                    "y2": 100.0,
                    "yMin": 0.0,
                    "yMax": 100.0,
                },
            ),
            *_RAMP,
            (8.5, {"x": 20736.0, "yMin": 120.0}),  # yMin > yMax: y = 0.0, error
            (9.5, {"yMin": 0.0, "x2": 0.0, "y1": 25.0}),  # x1 = x2: y = y1
            (10.5, {"y1": -5.0}),  # y1 below yMin: limited
        ],
        expected_warning="the scenario sets yMin = 120 > yMax = 100 at t = 8.5 s to show "
        "status 16#8200",
    ),
    Scenario(
        name="scale_linear_falling",
        title="LGF_ScaleLinear: a falling line, P1 = (4, 100) and P2 = (20, 0), limited to "
        "10 ... 90",
        stop_time=6.0,
        inputs=[
            (
                0.0,
                {
                    "x": 0.0,
                    "x1": 4.0,
                    "y1": 100.0,
                    "x2": 20.0,
                    "y2": 0.0,
                    "yMin": 10.0,
                    "yMax": 90.0,
                },
            ),
            *[(round(0.2 * k, 1), {"x": 1.0 * k}) for k in range(1, 25)],
        ],
    ),
]
