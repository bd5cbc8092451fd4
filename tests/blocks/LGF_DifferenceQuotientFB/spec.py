"""LGF_DifferenceQuotientFB's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them (docs/behaviour.md §17)."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, cycles, reals

from .model import DifferenceQuotientFB

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: DifferenceQuotientFB(cycle_us),
    cycles_us=cycles,
    inputs={
        # mostly enabled, so that five values are read in; now and then a falling edge
        "enable": st.sampled_from([True, True, True, True, True, True, False]),
        "insert": st.booleans(),
        "value": st.one_of(reals, st.sampled_from([float("inf"), float("-inf"), 0.1, 0.2])),
        "deltaT": st.one_of(
            st.sampled_from([1.0, 0.1, 0.5, 0.2, 1.0, 0.0, -0.0, -0.25, 1e-300, float("inf")]),
            st.floats(-10, 10, allow_nan=False),
        ),
    },
)

ACTIVE = {"enable": True, "insert": True, "value": 3.0, "deltaT": 0.5}

# No name of the original differs from the FMU's, and the block has no callOB.
ORIGINAL_NAMES: list[str] = []
