"""LGF_IecTimerOnOff's SPEC, ACTIVE and ORIGINAL_NAMES, as tests/lgf_blocks.py describes them."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, time_ms

from .model import IecTimerOnOff

SPEC = BlockSpec(
    # no parameter but cycleTime (docs/behaviour.md §8.1)
    make_model=lambda cycle_us, parameters: IecTimerOnOff(cycle_us, **parameters),
    cycles_us=st.sampled_from([1000, 10000, 100000, 250000, 3300, 1500]),
    inputs={
        "in": st.booleans(),
        # negative delays act as 0 (§8.2); delays around the cycles drawn, on and off the ms grid
        "timeOnDelay": st.one_of(time_ms(-50, 1200), st.sampled_from([0.0, -1.0, 0.1, 0.25])),
        "timeOffDelay": st.one_of(time_ms(-50, 1200), st.sampled_from([0.0, -1.0, 0.1, 0.25])),
    },
)

ACTIVE = {"in": True, "timeOnDelay": 0.2, "timeOffDelay": 0.3}

ORIGINAL_NAMES: list[str] = []  # the interface keeps the original's names (docs/behaviour.md §1.5)
