"""LGF_DifferenceQuotientFB (docs/behaviour.md §17): its model, spec, cross script, tests and
references; its scenarios are the build's, src/blocks/LGF_DifferenceQuotientFB/scenarios.py."""
