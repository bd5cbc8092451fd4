"""LGF_PulseRelay for the generic suites: its Hypothesis spec, the inputs under which it visibly
works, and the names of the original the documentation must mention (docs/behaviour.md §11)."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec

from .model import PulseRelay

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: PulseRelay(cycle_us),
    cycles_us=st.sampled_from([1000, 10000, 100000, 1000000, 3300, 7]),
    parameters=lambda: st.just({}),
    inputs={
        "trigger": st.booleans(),
        "set": st.sampled_from([False, False, True]),
        "reset": st.sampled_from([False, False, False, True]),
    },
)

# With constant inputs only the first call can see an edge (docs/behaviour.md §11.1): trigger
# TRUE toggles out to TRUE there, and it stays TRUE.
ACTIVE = {"trigger": True}

ORIGINAL_NAMES: list[str] = []  # the interface keeps the original's names (docs/behaviour.md §1.5)
