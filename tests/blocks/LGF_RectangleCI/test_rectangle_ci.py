"""LGF_RectangleCI (docs/behaviour.md §6) on the FMU, against runs worked out by hand
(traces.py)."""

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

BLOCK = "LGF_RectangleCI"


@pytest.mark.parametrize("run", [r for r in traces.RUNS if r != "TRUNCATED_CYCLE"])
def test_hand_traced_run(run):
    check_run(fmu_values(BLOCK, getattr(traces, run)), getattr(traces, run))


@pytest.mark.parametrize("phase_shift, high", traces.DUTY.items())
def test_duty_cycle_falls_below_50_percent_for_a_shift_beyond_half_the_periode(phase_shift, high):
    s = Slave(BLOCK, {"cycleTime": 0.001}, {"periode": 100, "phaseShift": phase_shift})
    values = [s.step(0.001)["value"] for _ in range(300)]
    s.free()
    assert set(values) <= {1.0, -1.0}
    assert values.count(1.0) == 3 * high


def test_cycle_of_1_5_ms_runs_on_ts_1_ms():
    check_run(fmu_values(BLOCK, traces.TRUNCATED_CYCLE), traces.TRUNCATED_CYCLE)
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
