"""The demo scenarios of LGF_TriangleCI, as tools/blocks.py describes them."""

from tools.scenario import slope_scenario

SCENARIOS = [
    slope_scenario(
        "triangle_ci",
        "LGF_TriangleCI: a 1 s triangle between -1 and 1, then amplitude 2 around offset 1, "
        "a quarter-period phase shift, a 2 s period and a reset",
    )
]
