"""LGF_SawTooth (docs/behaviour.md §2): its model, spec, cross script, tests and references; its
scenarios are the build's, src/blocks/LGF_SawTooth/scenarios.py."""
