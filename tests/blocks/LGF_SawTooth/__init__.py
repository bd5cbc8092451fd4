"""LGF_SawTooth (docs/behaviour.md §2): its model, spec, scenarios, cross script, tests and
references."""
