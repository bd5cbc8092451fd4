"""LGF_RectangleCI for the generic suites: its Hypothesis spec, the inputs under which it visibly
works (ACTIVE) and the names of the original the documentation must mention (ORIGINAL_NAMES),
the last two shared by the five signal generators (tests/signal_generators.py)."""

from tests.signal_generators import (
    ACTIVE,
    ORIGINAL_NAMES,
    finite_reals,
    spec,
    with_infinities,
)

from .model import RectangleCI

# amplitude sometimes ±Inf, offset finite (offset ± amplitude is never NaN then)
SPEC = spec(RectangleCI, with_infinities(finite_reals()), finite_reals())

__all__ = ["SPEC", "ACTIVE", "ORIGINAL_NAMES"]
