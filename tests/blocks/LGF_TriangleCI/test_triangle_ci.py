"""LGF_TriangleCI (docs/behaviour.md §6) on the FMU, against runs worked out by hand (traces.py)."""

import pytest

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

BLOCK = "LGF_TriangleCI"


def test_worked_example_of_blocks_6():
    check_run(fmu_values(BLOCK, traces.WORKED_EXAMPLE), traces.WORKED_EXAMPLE)


def test_reset_gives_the_offset_and_restarts_at_counter_ts():
    check_run(fmu_values(BLOCK, traces.RESET), traces.RESET)


def test_first_computed_sample_is_at_counter_ts():
    check_run(fmu_values(BLOCK, traces.FIRST_SAMPLE), traces.FIRST_SAMPLE)


def test_counter_plus_phase_shift_wraps_modulo_2_32():
    check_run(fmu_values(BLOCK, traces.UDINT_WRAP), traces.UDINT_WRAP)


@pytest.mark.parametrize("run", ["PHASE_BEYOND_PERIODE", "PHASE_250"])
def test_phase_shift_beyond_the_periode_acts_modulo_periode(run):
    check_run(fmu_values(BLOCK, getattr(traces, run)), getattr(traces, run))


def test_cycle_of_1_5_ms_runs_on_ts_1_ms():
    check_run(fmu_values(BLOCK, traces.TRUNCATED_CYCLE), traces.TRUNCATED_CYCLE)
    check_truncated_cycle_warns(BLOCK, 0.0015)


@pytest.mark.parametrize("run", ["INFINITE_AMPLITUDE", "INFINITE_OFFSET"])
def test_infinities_follow_ieee(run):
    check_run(fmu_values(BLOCK, getattr(traces, run)), getattr(traces, run))


@pytest.mark.parametrize("name, value", REFUSED, ids=[f"{n}={v}" for n, v in REFUSED])
def test_invalid_inputs_are_refused(name, value):
    check_refused(BLOCK, name, value)


@pytest.mark.parametrize("name, value", ACCEPTED, ids=[f"{n}={v}" for n, v in ACCEPTED])
def test_inputs_at_their_limits_are_accepted(name, value):
    check_accepted(BLOCK, name, value)


@pytest.mark.parametrize("cycle", [0.0009, 0.0])
def test_cycle_time_below_1_ms_is_refused(cycle):
    check_cycle_time_refused(BLOCK, cycle)
