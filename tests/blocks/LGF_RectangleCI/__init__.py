"""LGF_RectangleCI (BLOCKS.md §6): its model, spec, scenarios, cross script, tests and
references."""
