"""LGF_RampCI (docs/behaviour.md §4): its model, spec, scenarios, cross script, setpoint table
helper (table.py), tests and references."""
