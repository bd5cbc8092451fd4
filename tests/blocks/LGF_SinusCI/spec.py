"""LGF_SinusCI for the generic suites: its Hypothesis spec, the inputs under which it visibly
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
    same_within_trig_ulp,
    with_infinities,
)

from .model import SinusCI

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: SinusCI(cycle_us, parameters),
    cycles_us=CYCLES_US,
    parameters=lambda: st.just({}),
    # amplitude finite (SIN(0) · Inf is NaN), offset sometimes ±Inf
    inputs=inputs(amplitude=finite_reals(), offset=with_infinities(finite_reals())),
    # the FMU's SIN may differ within one float32 ulp (docs/behaviour.md §6)
    same=same_within_trig_ulp,
)

__all__ = ["SPEC", "ACTIVE", "ORIGINAL_NAMES"]
