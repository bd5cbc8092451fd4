"""LGF_RectangleCI (docs/behaviour.md §6) on the FMU: what only this block does (the runs worked
out by hand in traces.py, the refusals and the cycle: tests/test_signal_generator_blocks.py)."""

import pytest

from tests.harness import Slave

from . import traces

BLOCK = "LGF_RectangleCI"


@pytest.mark.parametrize("phase_shift, high", traces.DUTY.items())
def test_duty_cycle_falls_below_50_percent_for_a_shift_beyond_half_the_periode(phase_shift, high):
    s = Slave(BLOCK, {"cycleTime": 0.001}, {"periode": 100, "phaseShift": phase_shift})
    values = [s.step(0.001)["value"] for _ in range(300)]
    s.free()
    assert set(values) <= {1.0, -1.0}
    assert values.count(1.0) == 3 * high
