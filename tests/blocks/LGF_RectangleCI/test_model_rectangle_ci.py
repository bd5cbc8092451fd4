"""The LGF_RectangleCI model (model.py) alone: what only this block does (the runs of traces.py
and the refusals: tests/test_signal_generator_blocks.py)."""

import pytest

from tests.signal_generators import START

from . import traces
from .model import RectangleCI


@pytest.mark.parametrize("phase_shift, high", traces.DUTY.items())
def test_model_duty_cycle(phase_shift, high):
    m = RectangleCI(1000)
    inputs = {**START, "periode": 100, "phaseShift": phase_shift}
    values = [m.call(k * 1000, inputs)["value"] for k in range(300)]
    assert values.count(1.0) == 3 * high and values.count(-1.0) == 300 - 3 * high


def test_model_reset_counter_is_the_phase_shift_modulo_periode():
    m = RectangleCI(100000)
    m.call(0, {**START, "phaseShift": 2500.5, "periode": 1000, "reset": True})
    assert m.counter == 500  # REAL_TO_UDINT(2500.5) = 2500 (half to even), MOD 1000


def test_model_high_window_wraps_as_a_udint_sum():
    # periode 4294967295 (FMI 3.0 only), ps 4294967040: periode DIV 2 + ps wraps to 2147483391,
    # below ps, so the window is empty
    m = RectangleCI(1000)
    inputs = {**START, "periode": 4294967295, "phaseShift": 4294967040.0}
    assert m.call(0, inputs)["value"] == -1.0
    m.counter = 4294967100 - 1
    assert m.call(1000, inputs)["value"] == -1.0
