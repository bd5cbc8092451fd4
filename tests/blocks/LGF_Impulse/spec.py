"""LGF_Impulse's SPEC, ACTIVE and ORIGINAL_NAMES, as tests/lgf_blocks.py describes them."""

import math

from hypothesis import strategies as st

from tests.block_spec import BlockSpec

from .model import Impulse

# docs/behaviour.md §9.4: every REAL but NaN. Below 0.001 Hz TRUNC(f * 1000) is 0 and the
# period a division by 0 (0 ms, §9.5); above 1000 Hz it is 0 ms too.
FREQUENCIES = st.one_of(
    st.sampled_from(
        [0.0, -0.0, -1.0, -math.inf, math.inf, 1.0, 2.0, 3.0, 0.3, 0.8, 7.0, 20.0, 999.0, 1000.0]
    ),
    st.sampled_from([1001.0, 2000.0, 1e30, 4.656613157294487e-07, 1e-3, 0.0123, 1.4e-45]),
    st.sampled_from([0.0009999999310821295, 1e-4, 0.0015, 0.002, 2147483.0, 3e9]),
    st.floats(0.05, 50.0, allow_nan=False, allow_infinity=False),
    st.floats(0.0625, 50.0, allow_nan=False, allow_infinity=False, width=32),
    st.floats(-1e38, 0.0, allow_nan=False, allow_infinity=False),
)

SPEC = BlockSpec(
    # no parameter but cycleTime (docs/behaviour.md §9.1)
    make_model=lambda cycle_us, parameters: Impulse(cycle_us, **parameters),
    cycles_us=st.sampled_from([1000, 10000, 100000, 250000, 3300, 1500]),
    inputs={"frequency": FREQUENCIES},
)

ACTIVE = {"frequency": 4.0}

ORIGINAL_NAMES: list[str] = []  # the interface keeps the original's names (docs/behaviour.md §1.5)
