"""LGF_TriangleCI for the generic suites: its Hypothesis spec, the inputs under which it visibly
works (ACTIVE) and the names of the original the documentation must mention (ORIGINAL_NAMES),
the last two shared by the five signal generators (tests/signal_generators.py)."""

from tests.signal_generators import (
    ACTIVE,
    ORIGINAL_NAMES,
    finite_reals,
    spec,
    with_infinities,
)

from .model import TriangleCI

# amplitude finite within ±1e38 (no overflow, no Inf - Inf), offset sometimes ±Inf
SPEC = spec(TriangleCI, finite_reals(1e38), with_infinities(finite_reals()))

__all__ = ["SPEC", "ACTIVE", "ORIGINAL_NAMES"]
