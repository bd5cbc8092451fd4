"""LGF_CosinusCI for the generic suites: its Hypothesis spec, the inputs under which it visibly
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

from .model import CosinusCI

SPEC = BlockSpec(
    make_model=lambda cycle_us, parameters: CosinusCI(cycle_us, parameters),
    cycles_us=CYCLES_US,
    parameters=lambda: st.just({}),
    # amplitude sometimes ±Inf (COS of a float32 is never 0), offset finite
    inputs=inputs(amplitude=with_infinities(finite_reals()), offset=finite_reals()),
    # the FMU's COS may differ within one float32 ulp (docs/behaviour.md §6)
    same=same_within_trig_ulp,
)

__all__ = ["SPEC", "ACTIVE", "ORIGINAL_NAMES"]
