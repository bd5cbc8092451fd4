"""The demo scenarios of LGF_StoreMinMax (docs/behaviour.md §14), as
tools/blocks.py describes them."""

from tools.scenario import Scenario


def _jumpy(k: int) -> float:
    """A value that jumps up and down with a growing swing (exact binary fractions: k / 64)."""
    return ((k * 7) % 23 - 11) * (1.0 + k / 64)


# Why the default experiment (start values, no input connected) moves no output
# (tests/test_default_experiment.py).
STEADY_DEFAULT = (
    "the minimum and maximum of a constant value are that value (docs/behaviour.md §14)"
)

# One reset call at 6.0 s: as in the original code, that call outputs the clearing values
# ±1.7976931348623157e308 and does not count its value (docs/behaviour.md §14); the plot draws
# them at the lane's edge.
SCENARIOS = [
    Scenario(
        name="store_min_max",
        title="LGF_StoreMinMax: the extremes of a value that jumps with a growing swing, "
        "a reset at 6 s",
        stop_time=12.0,
        inputs=[
            (0.0, {"value": _jumpy(0), "reset": False}),
            *[
                (
                    round(0.1 * k, 1),
                    {"value": _jumpy(k), **({"reset": k == 60} if k in (60, 61) else {})},
                )
                for k in range(1, 120)
            ],
        ],
    ),
]
