"""The LGF_SawToothCI model (model.py) alone: what only this block does (the runs of traces.py
and the refusals: tests/test_signal_generator_blocks.py)."""

import math

import pytest

from tests.signal_generators import START, model_values

from . import traces
from .model import SawToothCI


def test_model_reset_with_offset_minus_zero_gives_plus_zero():
    value = SawToothCI(100000).call(0, {**START, "offset": -0.0, "reset": True})["value"]
    assert value == 0.0 and math.copysign(1.0, value) == 1.0


def test_model_values_are_float32_values_widened():
    values = model_values(SawToothCI, traces.WORKED_EXAMPLE)
    assert values[0] == -0.800000011920929 and values[0] != -0.8
    assert all(isinstance(v, float) for v in values)


@pytest.mark.parametrize("cycle_us", [999, 0, 60_000_001])
def test_model_refuses_cycles_outside_1_ms_to_60_s(cycle_us):
    with pytest.raises(ValueError):
        SawToothCI(cycle_us)
