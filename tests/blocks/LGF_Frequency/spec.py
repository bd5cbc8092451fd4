"""LGF_Frequency's SPEC, ACTIVE and ORIGINAL_NAMES, as tests/lgf_blocks.py describes them."""

import math

from hypothesis import strategies as st

from tests.block_spec import BlockSpec

from .model import Frequency

# docs/behaviour.md §10.4: every REAL but NaN; a pulsePauseRatio of +Inf and pairs whose times
# exceed a TIME are refused. The frequencies here are at least 1e-3 Hz, where no ratio drawn
# (at most 1e6, at least 1e-6 when positive) reaches 2^31 ms: 1000 / 1e-3 = 1e6 ms.
FREQUENCIES = st.one_of(
    st.sampled_from([0.0, -0.0, -1.0, -math.inf, math.inf, 1.0, 2.0, 3.0, 0.3, 0.8, 7.0, 20.0]),
    st.sampled_from([999.0, 1000.0, 2000.0, 1e30, 1e-3]),
    st.floats(0.0625, 50.0, allow_nan=False, allow_infinity=False, width=32),
    st.floats(0.05, 50.0, allow_nan=False, allow_infinity=False),
    st.floats(-1e38, 0.0, allow_nan=False, allow_infinity=False),
)
RATIOS = st.one_of(
    st.sampled_from([1.0, 1.0, 2.0, 3.0, 0.5, 0.25, 0.0, -1.0, -math.inf, 1e6, 1e-6, 0.1]),
    st.floats(1e-6, 1e6, allow_nan=False, allow_infinity=False),
    st.floats(0.0625, 16.0, allow_nan=False, allow_infinity=False, width=32),
    st.floats(-1e38, 0.0, allow_nan=False, allow_infinity=False),
)

SPEC = BlockSpec(
    # no parameter but cycleTime (docs/behaviour.md §10.1)
    make_model=lambda cycle_us, parameters: Frequency(cycle_us, **parameters),
    cycles_us=st.sampled_from([1000, 10000, 100000, 250000, 3300, 1500]),
    inputs={"frequency": FREQUENCIES, "pulsePauseRatio": RATIOS},
)

ACTIVE = {"frequency": 4.0, "pulsePauseRatio": 1.0}

ORIGINAL_NAMES: list[str] = []  # the interface keeps the original's names (docs/behaviour.md §1.5)
