"""LGF_SawToothCI (docs/behaviour.md §6) on the FMU: what only this block does (the runs worked
out by hand in traces.py, the refusals and the cycle: tests/test_signal_generator_blocks.py)."""

import math

from tests.harness import Slave
from tests.signal_generators import fmu_values

from . import traces

BLOCK = "LGF_SawToothCI"


def test_worked_example_values_are_float32_values():
    s = Slave(BLOCK)
    assert s.outputs()["value"] == -0.800000011920929 != -0.8
    s.free()


def test_reset_value_is_the_float32_sum_0_plus_offset():
    # 0.0 + (-0.0) = +0.0 in IEEE arithmetic
    s = Slave(BLOCK, inputs={"offset": -0.0, "reset": True})
    assert s.outputs()["value"] == 0.0 and math.copysign(1.0, s.outputs()["value"]) == 1.0
    s.free()


def test_counter_plus_phase_shift_wraps_modulo_2_32():
    # the run itself is checked with the others; here: not what a 64-bit sum would give
    assert fmu_values(BLOCK, traces.UDINT_WRAP)[2] != traces.WITHOUT_WRAP_AT_CALL_2
