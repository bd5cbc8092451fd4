"""LGF_FloatingAverage (docs/behaviour.md §15): its model, spec, cross script, tests and
references; its scenarios are the build's, src/blocks/LGF_FloatingAverage/scenarios.py."""
