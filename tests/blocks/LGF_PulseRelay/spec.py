"""LGF_PulseRelay's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them (docs/behaviour.md §11)."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, cycles, rarely_true

from .model import PulseRelay

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: PulseRelay(cycle_us),
    cycles_us=cycles,
    inputs={
        "trigger": st.booleans(),
        "set": st.sampled_from([False, False, True]),
        "reset": rarely_true,
    },
)

# With constant inputs only the first call can see an edge (docs/behaviour.md §11.1): trigger
# TRUE toggles out to TRUE there, and it stays TRUE.
ACTIVE = {"trigger": True}

ORIGINAL_NAMES: list[str] = []  # the interface keeps the original's names (docs/behaviour.md §1.5)
