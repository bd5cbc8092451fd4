"""LGF_SimpleSmoothingFB's SPEC, ACTIVE and ORIGINAL_NAMES, as
tests/lgf_blocks.py describes them (docs/behaviour.md §16)."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec, cycles, reals

from .model import SimpleSmoothingFB

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: SimpleSmoothingFB(cycle_us),
    cycles_us=cycles,
    inputs={
        # mostly enabled, so that values are read in; now and then a falling and rising edge
        "enable": st.sampled_from([True, True, True, True, True, False]),
        "insert": st.booleans(),
        "value": st.one_of(reals, st.sampled_from([0.1, 0.2])),
    },
)

ACTIVE = {"enable": True, "insert": True, "value": 3.0}

# No name of the original differs from the FMU's, and the block has no callOB.
ORIGINAL_NAMES: list[str] = []
