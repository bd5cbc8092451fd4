"""The demo scenarios of LGF_CosinusCI, as tools/blocks.py describes them."""

from tools.scenario import harmonic_scenario

SCENARIOS = [harmonic_scenario("LGF_CosinusCI", "cosine")]
