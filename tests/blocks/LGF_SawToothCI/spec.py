"""LGF_SawToothCI's SPEC, ACTIVE and ORIGINAL_NAMES (tests/signal_generators.py)."""

from tests import signal_generators as g

from .model import SawToothCI

ACTIVE, ORIGINAL_NAMES = g.ACTIVE, g.ORIGINAL_NAMES

# amplitude finite within ±1e38 (no overflow, no Inf - Inf), offset sometimes ±Inf
SPEC = g.spec(SawToothCI, g.finite_reals(1e38), g.with_infinities(g.finite_reals()))
