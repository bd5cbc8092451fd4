"""Independent Python reference models (test oracle) of the LGF blocks, written from
docs/behaviour.md only."""
