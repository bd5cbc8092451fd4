"""LGF_SinusCI (docs/behaviour.md §6) on the FMU, against runs worked out by hand (traces.py):
`value` within one float32 ulp of the correctly rounded result, everything else exact."""

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

BLOCK = "LGF_SinusCI"


@pytest.mark.parametrize("run", traces.RUNS)
def test_hand_traced_run(run):
    check_run(fmu_values(BLOCK, getattr(traces, run)), getattr(traces, run), ulps=traces.ULPS)


def test_cycle_of_1_5_ms_warns_that_it_runs_on_ts_1_ms():
    check_truncated_cycle_warns(BLOCK, 0.0015)


@pytest.mark.parametrize("name, value", REFUSED, ids=[f"{n}={v}" for n, v in REFUSED])
def test_invalid_inputs_are_refused(name, value):
    check_refused(BLOCK, name, value)


@pytest.mark.parametrize("name, value", ACCEPTED, ids=[f"{n}={v}" for n, v in ACCEPTED])
def test_inputs_at_their_limits_are_accepted(name, value):
    check_accepted(BLOCK, name, value)


@pytest.mark.parametrize("cycle", [0.0009, 0.0])
def test_cycle_time_below_1_ms_is_refused(cycle):
    check_cycle_time_refused(BLOCK, cycle)
