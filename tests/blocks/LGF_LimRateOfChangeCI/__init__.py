"""LGF_LimRateOfChangeCI (docs/behaviour.md §3): its model, spec, cross script, tests and
references; its scenarios are the build's, src/blocks/LGF_LimRateOfChangeCI/scenarios.py."""
