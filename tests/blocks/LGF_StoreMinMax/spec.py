"""LGF_StoreMinMax's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them (docs/behaviour.md §14)."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, cycles, rarely_true, reals

from .model import StoreMinMax

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: StoreMinMax(cycle_us),
    cycles_us=cycles,
    inputs={
        "value": st.one_of(
            reals,
            st.sampled_from(
                [float("inf"), -float("inf"), 1.7976931348623157e308, -1.7976931348623157e308]
            ),
        ),
        "reset": rarely_true,
    },
)

ACTIVE = {"value": 42.0}

# The block has no name that differs from the original's (docs/behaviour.md §14.1).
ORIGINAL_NAMES = []
