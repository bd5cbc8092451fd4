"""LGF_Impulse (docs/behaviour.md §9): its model, spec, cross script, tests and references; its
scenarios are the build's, src/blocks/LGF_Impulse/scenarios.py."""
