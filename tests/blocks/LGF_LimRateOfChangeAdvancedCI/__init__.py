"""LGF_LimRateOfChangeAdvancedCI (docs/behaviour.md §21): its model, spec, cross script, tests and
references; its scenarios are the build's, src/blocks/LGF_LimRateOfChangeAdvancedCI/scenarios.py."""
