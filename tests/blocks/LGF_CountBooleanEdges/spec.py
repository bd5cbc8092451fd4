"""LGF_CountBooleanEdges's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them (docs/behaviour.md §12)."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, time_ms

from .model import CountBooleanEdges

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: CountBooleanEdges(cycle_us),
    cycles_us=st.sampled_from([1000, 10000, 100000, 250000, 3300, 7]),
    inputs={
        "trigger": st.booleans(),
        "monitorTime": st.one_of(time_ms(-50, 1500), st.sampled_from([0.0, 0.3, 1.0])),
    },
)

# With trigger held TRUE the first call is an edge and long rises once the 1 s has passed, at
# the tenth call of 0.1 s (docs/behaviour.md §12.1).
ACTIVE = {"trigger": True, "monitorTime": 1.0}

ORIGINAL_NAMES: list[str] = []  # the interface keeps the original's names (docs/behaviour.md §1.5)
