"""LGF_RectangleCI's SPEC, ACTIVE and ORIGINAL_NAMES (tests/signal_generators.py)."""

from tests import signal_generators as g

from .model import RectangleCI

ACTIVE, ORIGINAL_NAMES = g.ACTIVE, g.ORIGINAL_NAMES

# amplitude sometimes ±Inf, offset finite (offset ± amplitude is never NaN then)
SPEC = g.spec(RectangleCI, g.with_infinities(g.finite_reals()), g.finite_reals())
