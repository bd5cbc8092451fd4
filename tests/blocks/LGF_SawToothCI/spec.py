"""LGF_SawToothCI for the generic suites: its Hypothesis spec, the inputs under which it visibly
works (ACTIVE) and the names of the original the documentation must mention (ORIGINAL_NAMES),
the last two shared by the five signal generators (tests/signal_generators.py)."""

from hypothesis import strategies as st

from tests.block_spec import BlockSpec
from tests.signal_generators import (
    ACTIVE,
    CYCLES_US,
    ORIGINAL_NAMES,
    finite_reals,
    inputs,
    with_infinities,
)

from .model import SawToothCI

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: SawToothCI(cycle_us, parameters),
    cycles_us=CYCLES_US,
    parameters=lambda: st.just({}),
    # amplitude finite within ±1e38 (no overflow, no Inf - Inf), offset sometimes ±Inf
    inputs=inputs(amplitude=finite_reals(1e38), offset=with_infinities(finite_reals())),
)

__all__ = ["SPEC", "ACTIVE", "ORIGINAL_NAMES"]
