"""The demo scenarios of LGF_PulseRelay (docs/behaviour.md §11), as
tools/blocks.py describes them."""

from tools.scenario import Scenario


def _clock(start: float, stop: float, half_period: float) -> list[tuple[float, dict]]:
    """trigger TRUE and FALSE in turn every half_period from start, FALSE again at stop."""
    rows, k = [], 0
    while start + k * half_period < stop - 1e-9:
        rows.append((round(start + k * half_period, 6), {"trigger": k % 2 == 0}))
        k += 1
    rows.append((stop, {"trigger": False}))
    return rows


# Why the default experiment (start values, no input connected) moves no output
# (tests/test_default_experiment.py).
STEADY_DEFAULT = (
    "it acts only on rising edges of trigger, set and reset (docs/behaviour.md §11), and with no "
    "input connected they stay FALSE"
)

SCENARIOS = [
    Scenario(
        name="pulse_relay",
        title="LGF_PulseRelay: a frequency divider on trigger, then set, reset, and both at once",
        stop_time=6.0,
        inputs=[
            (0.0, {"trigger": False, "set": False, "reset": False}),
            *_clock(0.2, 2.6, 0.2),  # trigger with a period of 0.4 s: out toggles every 0.4 s
            (3.0, {"set": True}),
            (3.3, {"set": False}),
            (3.5, {"trigger": True}),  # toggle back to FALSE
            (3.7, {"trigger": False}),
            (4.0, {"set": True}),
            (4.2, {"reset": True}),  # reset while set is held: FALSE
            (4.5, {"reset": False, "set": False}),
            (4.8, {"trigger": True}),  # toggle to TRUE
            (5.0, {"trigger": False}),
            (5.2, {"set": True, "reset": True}),  # both rise: reset wins
            (5.5, {"set": False, "reset": False}),
        ],
    ),
]
