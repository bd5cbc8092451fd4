"""LGF_FloatingAverage's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them (docs/behaviour.md §15)."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, cycles, rarely_true

from .model import FloatingAverage

# LREAL values (§15.1): small integers (exact sums), fractions (double rounding), large values
# (a running sum that loses the small ones), 1e308 (a sum that overflows to Inf); no ±Inf input,
# whose NaN (Inf - Inf) the generic suites cannot compare: the hand-traced tests have it.
values = st.one_of(
    st.integers(-100, 100).map(float),
    st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False, width=32),
    st.floats(-1e6, 1e6, allow_nan=False, allow_infinity=False),
    st.sampled_from([0.0, -0.0, 1e16, -1e16, 1e308, 5e-324, 0.1]),
    st.sampled_from([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]),
)

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: FloatingAverage(cycle_us),
    cycles_us=cycles,
    inputs={
        "cyclicExecution": st.sampled_from([True, True, False]),
        "trigger": st.booleans(),
        "value": values,
        # mostly a few valid sizes, so that windows fill and slide; sometimes 100 and the
        # invalid ones (16#8200)
        "windowSize": st.one_of(
            st.sampled_from([1, 2, 3, 4, 5, 5, 5, 3, 3, 100]),
            st.sampled_from([0, 101, -1, 32767, -32768]),
        ),
        "reset": rarely_true,
    },
)

ACTIVE = {"cyclicExecution": True, "value": 5.0, "windowSize": 4}

# No name of the original differs from the FMU's, and the block has no callOB.
ORIGINAL_NAMES: list[str] = []
