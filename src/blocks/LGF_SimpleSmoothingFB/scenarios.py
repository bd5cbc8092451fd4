"""The demo scenarios of LGF_SimpleSmoothingFB (docs/behaviour.md §16), as
tools/blocks.py describes them."""

from tools.scenario import Scenario, sampled, scattered_sine


def measured(k: int) -> float:
    """A scattered measurement at sample k: a slow sine with a jitter of up to ±2."""
    return scattered_sine(k, 8.0, 25.0, 4)


# Why the default experiment (start values, no input connected) moves no output
# (tests/test_default_experiment.py).
STEADY_DEFAULT = (
    "a value is read in only at a rising edge of insert (docs/behaviour.md §16), and with no "
    "input connected insert stays FALSE"
)

SCENARIOS = [
    Scenario(
        name="simple_smoothing",
        title="LGF_SimpleSmoothingFB: a scattered signal sampled every 0.2 s, smoothed over three "
        "values; enable off for 1 s and on again",
        stop_time=10.0,
        # a sample every 0.2 s; enable falls for 1 s at t = 6 s (status 16#7000) and rises
        # again (16#7001, an empty buffer)
        inputs=sampled(
            {"enable": True, "insert": False, "value": 0.0},
            100,
            measured,
            {6.0: {"enable": False}, 7.0: {"enable": True}},
        ),
    ),
]
