"""LGF_RampCI's SPEC, ACTIVE and ORIGINAL_NAMES, as tests/lgf_blocks.py describes them."""

from hypothesis import strategies as st

from src.blocks.LGF_RampCI.table import setpoints
from tests.block_spec import BlockSpec, rarely_true, reals, time_ms

from .model import RampCI


def _points(n: int) -> list:
    """n setpoints of random values and times."""
    return [(reals, time_ms(0, 1500))] * n


SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: RampCI(cycle_us, parameters),
    cycles_us=st.sampled_from([1000, 10000, 100000, 250000, 1500, 33300]),
    parameters=lambda: st.integers(2, 6).flatmap(
        lambda n: st.fixed_dictionaries({"numberOfSetpoints": st.just(n), **setpoints(_points(n))})
    ),
    inputs={
        "defaultOutValue": reals,
        "contStepNbr": st.integers(0, 1),  # valid for every table (numberOfSetpoints >= 2)
        "contStepTime": time_ms(0, 1000),
        "enDefaultOutValue": rarely_true,
        "start": st.sampled_from([True, True, True, False]),
        "hold": rarely_true,
        "continue": rarely_true,
        "cyclicOP": st.booleans(),
        "updateTime": rarely_true,
        "reset": st.sampled_from([False] * 7 + [True]),
    },
    tunables=lambda parameters: setpoints(_points(parameters["numberOfSetpoints"])),
)

ACTIVE = {"start": True, "cyclicOP": True}

# Names of the original V3.0.1 block / older LGF versions (docs/behaviour.md §1.5).
ORIGINAL_NAMES = ["subfunctionStatus", "enDefaulftOutValue", "outVal", "callOB"]
