"""LGF_SinusCI (BLOCKS.md §6): its model, spec, scenarios, cross script, tests and
references."""
