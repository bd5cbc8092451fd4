"""The demo scenarios of LGF_SawToothCI, as tools/blocks.py describes them."""

from tools.scenario import slope_scenario

SCENARIOS = [
    slope_scenario(
        "saw_tooth_ci",
        "LGF_SawToothCI: a 1 s sawtooth from -1 to 1, then amplitude 2 around offset 1, "
        "a quarter-period phase shift, a 2 s period and a reset",
    )
]
