"""LGF_SawToothCI (docs/behaviour.md §6): its model, spec, scenarios, cross script, tests and
references."""
