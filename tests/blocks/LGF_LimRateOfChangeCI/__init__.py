"""LGF_LimRateOfChangeCI (docs/behaviour.md §3): its model, spec, scenarios, cross script, tests
and references."""
