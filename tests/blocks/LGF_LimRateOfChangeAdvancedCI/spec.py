"""LGF_LimRateOfChangeAdvancedCI's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, cycles, rarely_true, reals

from .model import LimRateOfChangeAdvancedCI

rates = st.one_of(
    st.sampled_from([0.0, 10.0, 0.5, 40.0, -1.0, 1e6]),
    st.floats(-10, 1e4, allow_nan=False, allow_infinity=False),
)
limits = st.one_of(
    st.sampled_from([100.0, -100.0, 0.0, 50.0, -50.0, 1e300, -1e300]),
    st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False),
)

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: LimRateOfChangeAdvancedCI(cycle_us, **parameters),
    cycles_us=cycles,
    inputs={
        "autoValue": reals,
        "manualValue": reals,
        "setPosUpRateLim": rates,
        "setPosDownRateLim": rates,
        "setNegUpRateLim": rates,
        "setNegDownRateLim": rates,
        "setHighLim": limits,
        "setLowLim": limits,
        "defaultOutValue": reals,
        "enDefaultOutValue": rarely_true,
        "track": rarely_true,
        "manOp": rarely_true,
        "reset": rarely_true,
    },
)

ACTIVE = {"autoValue": 50.0, "setPosUpRateLim": 10.0, "setHighLim": 100.0, "setLowLim": -100.0}

# Names of the original V3.0.1 block and of the LGF documentation (docs/behaviour.md §1.5, §21.1).
ORIGINAL_NAMES = ["subfunctionStatus", "callOB"]
