"""LGF_RampCI (docs/behaviour.md §4): its model, spec, cross script, tests and references; its
scenarios are the build's, src/blocks/LGF_RampCI/scenarios.py (its setpoint table helper too:
table.py)."""
