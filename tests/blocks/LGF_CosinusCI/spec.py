"""LGF_CosinusCI for the generic suites: its Hypothesis spec, the inputs under which it visibly
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

from .model import CosinusCI

# amplitude sometimes ±Inf (COS of a float32 is never 0), offset finite
# the FMU's COS may differ within one float32 ulp (docs/behaviour.md §6)
SPEC = spec(CosinusCI, with_infinities(finite_reals()), finite_reals(), same_within_trig_ulp)

__all__ = ["SPEC", "ACTIVE", "ORIGINAL_NAMES"]
