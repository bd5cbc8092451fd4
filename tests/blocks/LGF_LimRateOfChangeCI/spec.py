"""LGF_LimRateOfChangeCI's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, cycles, rarely_true, reals

from .model import LimRateOfChangeCI

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: LimRateOfChangeCI(cycle_us),
    cycles_us=cycles,
    inputs={
        "value": reals,
        "setChangeRate": st.one_of(
            st.sampled_from([0.0, 10.0, 0.5, -1.0, 1e6]),
            st.floats(-10, 1e4, allow_nan=False, allow_infinity=False),
        ),
        "defaultOutValue": reals,
        "enDefaultOutValue": rarely_true,
    },
)

ACTIVE = {"value": 100.0, "setChangeRate": 10.0}

# Names of the original V3.0.1 block / older LGF versions (docs/behaviour.md §1.5).
ORIGINAL_NAMES = ["subfunctionStatus", "callOB"]
