"""LGF_SinusCI's SPEC, ACTIVE and ORIGINAL_NAMES (tests/signal_generators.py)."""

from tests import signal_generators as g

from .model import SinusCI

ACTIVE, ORIGINAL_NAMES = g.ACTIVE, g.ORIGINAL_NAMES

# amplitude finite (SIN(0) · Inf is NaN), offset sometimes ±Inf; the FMU's SIN may differ within
# one float32 ulp (docs/behaviour.md §6)
SPEC = g.spec(
    SinusCI, g.finite_reals(), g.with_infinities(g.finite_reals()), g.same_within_trig_ulp
)
