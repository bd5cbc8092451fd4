"""LGF_IsValueInToleranceByTime's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them (docs/behaviour.md §13)."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, rarely_true, time_ms

from .model import IsValueInToleranceByTime

FLT_MAX = 3.4028234663852886e38  # the largest float32


def _reals(*typical: float) -> st.SearchStrategy:
    """REAL inputs: typical values (most draws, so that the value moves around the band), any
    float32, and sometimes ±Inf."""
    return st.one_of(
        st.sampled_from(typical),
        st.integers(-100, 120).map(float),
        st.floats(-FLT_MAX, FLT_MAX, allow_nan=False, allow_infinity=False, width=32),
        st.sampled_from([float("inf"), -float("inf"), 0.0, -0.0]),
    )


rarely = st.sampled_from([False, False, False, False, True])

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: IsValueInToleranceByTime(cycle_us),
    cycles_us=st.sampled_from([1000, 10000, 100000, 250000, 3300, 7]),
    inputs={
        "value": _reals(50.0, 52.5, 56.0, 44.0, 60.0, 40.0, 75.0),
        "setpoint": _reals(50.0, 50.0, 50.0, 80.0, -20.0),
        "lowerMinimum": _reals(10.0, 10.0, 5.0, 0.0, 120.0, -5.0, 30.0),
        "upperMaximum": _reals(10.0, 10.0, 5.0, 0.0, -5.0, 90.0),
        "reset": rarely_true,
        "configuration.disableLimits": rarely,
        "configuration.limitsAsAbsoluteValues": rarely,
        "configuration.toleranceAsAbsoluteValues": rarely,
        "configuration.upperLimitMonitoringTime": time_ms(-50, 1500),
        "configuration.lowerLimitMonitoringTime": time_ms(-50, 1500),
        "configuration.setpointChangeMonitoringTime": time_ms(-50, 2500),
    },
)

# The start values with the value outside the band: setpointChange from the start (the value
# never arrives), the change timer elapsed at 0.5 s, overHighLimit from 0.8 s (docs/behaviour.md
# §13.3), i.e. within the first ten calls of 0.1 s.
# The FMU's start values of the inputs (docs/behaviour.md §13.1), from which the tests start.
C = "configuration."
START = {
    "value": 60.0,
    "setpoint": 50.0,
    "lowerMinimum": 10.0,
    "upperMaximum": 10.0,
    "reset": False,
    C + "disableLimits": False,
    C + "limitsAsAbsoluteValues": False,
    C + "toleranceAsAbsoluteValues": False,
    C + "upperLimitMonitoringTime": 1.0,
    C + "lowerLimitMonitoringTime": 1.0,
    C + "setpointChangeMonitoringTime": 2.0,
}

ACTIVE = {
    "value": 60.0,
    "configuration.setpointChangeMonitoringTime": 0.5,
    "configuration.upperLimitMonitoringTime": 0.3,
}

ORIGINAL_NAMES: list[str] = ["LGF_typeIsValueInToleranceByTimeConfiguration"]
