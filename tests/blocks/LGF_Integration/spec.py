"""LGF_Integration's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them (docs/behaviour.md §18)."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, rarely_true, reals

from .model import Integration

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: Integration(cycle_us),
    # whole-ms cycles and cycles with a sub-ms part (whose whole-ms readings step unevenly)
    cycles_us=st.sampled_from([1000, 10000, 100000, 1000000, 60000000, 1500, 500, 3300, 7]),
    inputs={
        "enable": st.sampled_from([True, True, True, False]),
        # finite values only: ±Inf can make integral NaN (docs/behaviour.md §18.4), which the
        # generic suites cannot compare (NaN != NaN); the hand-traced tests cover it
        "value": st.one_of(reals, st.sampled_from([1.0, -1.0, 0.5])),
        "reset": rarely_true,
    },
)

ACTIVE = {"enable": True, "value": 5.0}

# Names of the original V3.0.1 block (docs/behaviour.md §1.5, §18.1).
ORIGINAL_NAMES = ["subfunctionStatus", "RD_SYS_T"]
