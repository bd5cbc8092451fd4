"""The demo scenarios of LGF_SimpleSmoothingFB (docs/behaviour.md §16), as
tools/blocks.py describes them."""

import math

from tools.scenario import Scenario


def measured(k: int) -> float:
    """A scattered measurement at sample k: a slow sine with a deterministic jitter of up to
    ±2 (the same numbers on every run, rounded to 0.001)."""
    jitter = ((k * 7919) % 9 - 4) * 0.5
    return round(8.0 * math.sin(2.0 * math.pi * k / 25.0) + jitter, 3)


def _rows() -> list[tuple[float, dict]]:
    """A sample every 0.2 s: insert rises in every other call, with a new value; enable falls
    for 1 s at t = 6 s (status 16#7000) and rises again (16#7001, an empty buffer)."""
    rows: dict[float, dict] = {0.0: {"enable": True, "insert": False, "value": 0.0}}
    for k in range(100):
        t = round(k * 0.1, 1)
        change = rows.setdefault(t, {})
        change["insert"] = k % 2 == 1
        if k % 2 == 1:
            change["value"] = measured(k // 2)
    rows[6.0]["enable"] = False
    rows[7.0]["enable"] = True
    return sorted(rows.items())


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
        inputs=_rows(),
    ),
]
