"""LGF_SawToothCI (docs/behaviour.md §6) on the FMU, against runs worked out by hand (traces.py)."""

import math

import pytest

from tests.harness import Slave
from tests.signal_generators import (
    ACCEPTED,
    REFUSED,
    check_accepted,
    check_cycle_time_refused,
    check_refused,
    check_run,
    check_truncated_cycle_warns,
    fmu_values,
)

from . import traces

BLOCK = "LGF_SawToothCI"


def test_worked_example_of_blocks_6():
    check_run(fmu_values(BLOCK, traces.WORKED_EXAMPLE), traces.WORKED_EXAMPLE)


def test_worked_example_values_are_float32_values():
    s = Slave(BLOCK)
    assert s.outputs()["value"] == -0.800000011920929 != -0.8
    s.free()


def test_reset_gives_the_offset_and_restarts_at_counter_ts():
    check_run(fmu_values(BLOCK, traces.RESET), traces.RESET)


def test_reset_value_is_the_float32_sum_0_plus_offset():
    # 0.0 + (-0.0) = +0.0 in IEEE arithmetic
    s = Slave(BLOCK, inputs={"offset": -0.0, "reset": True})
    assert s.outputs()["value"] == 0.0 and math.copysign(1.0, s.outputs()["value"]) == 1.0
    s.free()


def test_first_computed_sample_is_at_counter_ts():
    check_run(fmu_values(BLOCK, traces.FIRST_SAMPLE), traces.FIRST_SAMPLE)


def test_counter_plus_phase_shift_wraps_modulo_2_32():
    values = fmu_values(BLOCK, traces.UDINT_WRAP)
    check_run(values, traces.UDINT_WRAP)
    assert values[2] != traces.WITHOUT_WRAP_AT_CALL_2


def test_cycle_of_1_5_ms_runs_on_ts_1_ms():
    check_run(fmu_values(BLOCK, traces.TRUNCATED_CYCLE), traces.TRUNCATED_CYCLE)
    check_truncated_cycle_warns(BLOCK, 0.0015)


def test_a_new_periode_applies_at_the_next_call():
    check_run(fmu_values(BLOCK, traces.NEW_PERIODE), traces.NEW_PERIODE)


@pytest.mark.parametrize("run", ["INFINITE_OFFSET", "INFINITE_AMPLITUDE", "OVERFLOW"])
def test_infinities_and_float32_overflow(run):
    check_run(fmu_values(BLOCK, getattr(traces, run)), getattr(traces, run))


@pytest.mark.parametrize("name, value", REFUSED, ids=[f"{n}={v}" for n, v in REFUSED])
def test_invalid_inputs_are_refused(name, value):
    check_refused(BLOCK, name, value)


@pytest.mark.parametrize("name, value", ACCEPTED, ids=[f"{n}={v}" for n, v in ACCEPTED])
def test_inputs_at_their_limits_are_accepted(name, value):
    check_accepted(BLOCK, name, value)


@pytest.mark.parametrize("cycle", [0.0009, 0.0, -0.1])
def test_cycle_time_below_1_ms_is_refused(cycle):
    check_cycle_time_refused(BLOCK, cycle)
