"""LGF_SawTooth's SPEC, ACTIVE and ORIGINAL_NAMES, as tests/lgf_blocks.py describes them."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, ints, rarely_true, time_ms

from .model import SawTooth

SPEC = BlockSpec(
    # plcTiming starts false (docs/behaviour.md §2) where a scenario does not set it
    make_model=lambda cycle_us, parameters: SawTooth(cycle_us, parameters.get("plcTiming", False)),
    cycles_us=st.sampled_from([1000, 10000, 100000, 250000, 3300]),
    parameters=lambda: st.fixed_dictionaries({"plcTiming": st.booleans()}),
    inputs={
        "startValue": ints,
        "timeRange": time_ms(-50, 1200),
        "incrementRange": ints,
        "numberSteps": st.one_of(st.integers(-2, 8), ints),
        "endlessSteps": st.booleans(),
        "reset": rarely_true,
    },
)


def inp(start=0, tr=0.0, inc=0, n=0, endless=False, reset=False) -> dict:
    """The block's inputs by short names, for the hand-traced model tests."""
    return {
        "startValue": start,
        "timeRange": tr,
        "incrementRange": inc,
        "numberSteps": n,
        "endlessSteps": endless,
        "reset": reset,
    }


# Example 1 of docs/behaviour.md §2.5 (a steady run at cycleTime 0.1 s): steps at 0.4, 0.9 and
# 1.4 s, back to startValue at 1.9 s; the hand traces of both timings start from it.
EXAMPLE_1 = inp(start=0, tr=0.3, inc=10, n=3)

ACTIVE = {"startValue": 5, "timeRange": 0.2, "incrementRange": 3, "numberSteps": 4}

ORIGINAL_NAMES: list[str] = []  # the interface keeps the original's names (docs/behaviour.md §1.5)
