"""LGF_NonLinearInterpolation (docs/behaviour.md §20): its model, spec, cross script, tests and
references; its scenarios are the build's, src/blocks/LGF_NonLinearInterpolation/scenarios.py."""
