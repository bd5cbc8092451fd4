"""The demo scenarios of LGF_FloatingAverage (docs/behaviour.md §15), as
tools/blocks.py describes them."""

from tools.scenario import Scenario, scattered_sine


def measured(k: int) -> float:
    """A scattered measurement at sample k: a slow sine with a jitter of up to ±3."""
    return scattered_sine(k, 10.0, 40.0, 6)


def _rows() -> list[tuple[float, dict]]:
    rows = [(0.0, {"cyclicExecution": True, "trigger": False, "windowSize": 10, "reset": False})]
    for k in range(80):
        t = round(k * 0.1, 1)
        changes = {"value": measured(k)}
        if 3.0 <= t < 5.0:  # triggered: a rising edge every 0.2 s
            changes["trigger"] = k % 2 == 0
        rows.append((t, changes))
    return rows + [
        (3.0, {"cyclicExecution": False}),
        (5.0, {"windowSize": 0, "trigger": False}),  # a restart, then 16#8200
        (5.5, {"windowSize": 5, "cyclicExecution": True}),
        (6.5, {"reset": True}),
        (6.7, {"reset": False}),
    ]


def _merged(rows):
    merged: dict[float, dict] = {}
    for t, changes in rows:
        merged.setdefault(t, {}).update(changes)
    return sorted(merged.items())


SCENARIOS = [
    Scenario(
        name="floating_average",
        title="LGF_FloatingAverage: a window of 10 read cyclically, then on trigger edges, an "
        "invalid window size (16#8200), a window of 5 and a reset",
        stop_time=8.0,
        inputs=_merged(_rows()),
        expected_warning="the scenario sets windowSize = 0 at t = 5 s to show status 16#8200",
    ),
]
