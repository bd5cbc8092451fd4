"""LGF_CosinusCI's SPEC, ACTIVE and ORIGINAL_NAMES (tests/signal_generators.py)."""

from tests import signal_generators as g

from .model import CosinusCI

ACTIVE, ORIGINAL_NAMES = g.ACTIVE, g.ORIGINAL_NAMES

# amplitude sometimes ±Inf (COS of a float32 is never 0), offset finite; the FMU's COS may differ
# within one float32 ulp (docs/behaviour.md §6)
SPEC = g.spec(
    CosinusCI, g.with_infinities(g.finite_reals()), g.finite_reals(), g.same_within_trig_ulp
)
