"""LGF_SinusCI for the generic suites: its Hypothesis spec, the inputs under which it visibly
works (ACTIVE) and the names of the original the documentation must mention (ORIGINAL_NAMES),
the last two shared by the five signal generators (tests/signal_generators.py)."""

from tests.signal_generators import (
    ACTIVE,
    ORIGINAL_NAMES,
    finite_reals,
    same_within_trig_ulp,
    spec,
    with_infinities,
)

from .model import SinusCI

# amplitude finite (SIN(0) · Inf is NaN), offset sometimes ±Inf
# the FMU's SIN may differ within one float32 ulp (docs/behaviour.md §6)
SPEC = spec(SinusCI, finite_reals(), with_infinities(finite_reals()), same_within_trig_ulp)

__all__ = ["SPEC", "ACTIVE", "ORIGINAL_NAMES"]
