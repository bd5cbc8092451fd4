"""LGF_ScaleLinear's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them (docs/behaviour.md §19)."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, cycles, reals

from .model import ScaleLinear

# Coordinates that sometimes coincide or lie within the PRECISION of 1.0E-06 of each other, and
# limits that are sometimes infinite or in the wrong order (status 16#8200). x and the points
# stay finite: ±Inf there can make y NaN (docs/behaviour.md §19.3), which the generic suites
# cannot compare (NaN != NaN); the hand-traced tests cover it. Finite inputs never give NaN.
coordinates = st.one_of(
    reals,
    st.sampled_from([0.0, 1e-6, 5e-7, 1.0000000000000002e-06, 27648.0, -27648.0, 4.0, 20.0]),
)
limits = st.one_of(
    st.sampled_from([0.0, 100.0, -100.0, 50.0, float("inf"), -float("inf")]),
    reals,
)

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: ScaleLinear(cycle_us),
    cycles_us=cycles,
    inputs={
        "x": coordinates,
        "x1": coordinates,
        "y1": coordinates,
        "x2": coordinates,
        "y2": coordinates,
        "yMin": limits,
        "yMax": limits,
    },
)

# The FMU's start values of the inputs (docs/behaviour.md §19.1): an S7 analog input, raw
# 0 ... 27648 to 0 ... 100 %, at half scale.
START = {"x": 13824.0, "x1": 0.0, "y1": 0.0, "x2": 27648.0, "y2": 100.0, "yMin": 0.0, "yMax": 100.0}

ACTIVE = {"x": 20736.0}  # y = 75.0 on the start line 0 ... 27648 -> 0 ... 100

# Names of the original (docs/behaviour.md §1.5, §19.1): the FC's return value.
ORIGINAL_NAMES = ["Ret_Val"]
