"""The demo scenarios of LGF_DifferenceQuotientFB (docs/behaviour.md §17), as
tools/blocks.py describes them."""

import math

from tools.scenario import Scenario, sampled

SAMPLE = 0.2  # s: a rising edge of insert in every other call of 0.1 s


def position(k: int) -> float:
    """A measured position at sample k (t = k * 0.2 s): 5 sin(t), with a small deterministic
    scatter of up to ±0.02, rounded to 0.001; its derivative is about 5 cos(t)."""
    scatter = ((k * 7919) % 5 - 2) * 0.01
    return round(5.0 * math.sin(k * SAMPLE) + scatter, 3)


# Why the default experiment (start values, no input connected) moves no output
# (tests/test_default_experiment.py).
STEADY_DEFAULT = (
    "a value is read in only at a rising edge of insert (docs/behaviour.md §17), and with no "
    "input connected insert stays FALSE"
)

SCENARIOS = [
    Scenario(
        name="difference_quotient",
        title="LGF_DifferenceQuotientFB: the velocity of a measured position 5 sin(t) sampled "
        "every 0.2 s; deltaT 0 for 1 s (16#8200), enable off for 1 s",
        stop_time=13.0,
        # samples every 0.2 s with deltaT 0.2 s; deltaT 0 from 6 s to 7 s (16#8200); enable off
        # for 1 s at 9 s (16#7000) and on again (16#7001, five new values needed)
        inputs=sampled(
            {"enable": True, "insert": False, "value": 0.0, "deltaT": SAMPLE},
            130,
            position,
            {
                6.0: {"deltaT": 0.0},
                7.0: {"deltaT": SAMPLE},
                9.0: {"enable": False},
                10.0: {"enable": True},
            },
        ),
        expected_warning="the scenario sets deltaT = 0 at t = 6 s to show status 16#8200",
    ),
]
