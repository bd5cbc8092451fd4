"""LGF_RampCI against the rules of docs/behaviour.md §4, with expectations computed by hand.

A row is (outputValue, actTimeTable, stepNumber, remainTime, totalTime, remainTotalTime, status)
after a call, times in ms. Interpolated values are written as the exact expression of 4.2 c),
`ip(prev, target, remainTime_ms)`, chained from the previous expected value, so they are compared
bit for bit; the round value worked out on paper is checked next to it."""

import math

import pytest
from fmpy.fmi2 import fmi2OK, fmi2Real, fmi2ValueReference, fmi2Warning

from src.blocks.LGF_RampCI.table import table
from tests import harness
from tests.harness import Slave, refused
from tests.setpoint_tables import (  # noqa: F401 (run here, on this block)
    test_number_of_setpoints_at_the_limits_is_accepted,
    test_number_of_setpoints_outside_2_to_64_is_refused,
)

BLOCK = "LGF_RampCI"
RUN, START, CYCLIC, END = 0x7000, 0x7001, 0x7002, 0x0000
T, F = True, False
TS = 100  # ms, cycleTime 0.1 s


def ip(prev, target, remain_ms, ts_ms=TS):
    """docs/behaviour.md §4.3 c), in its order."""
    return prev + (target - prev) / remain_ms * ts_ms


def ms(seconds):
    value = round(seconds * 1000)
    assert abs(seconds * 1000 - value) < 1e-6, f"{seconds} s is not a whole number of ms"
    return value


def row(s):
    o = s.outputs()
    assert o["error"] == 0 and o["subFunctionStatus"] == 0
    return (
        o["outputValue"],
        bool(o["actTimeTable"]),
        o["stepNumber"],
        ms(o["remainTime"]),
        ms(o["totalTime"]),
        ms(o["remainTotalTime"]),
        o["status"],
    )


def slave(points, cycle=0.1, **inputs):
    return Slave(BLOCK, {"cycleTime": cycle, **table(*points)}, inputs)


def run(s, changes, cycle=0.1):
    """Rows after the first call and after one step per entry of changes (inputs set before it)."""
    rows = [row(s)]
    for change in changes:
        s.set(change)
        s.step(cycle)
        rows.append(row(s))
    return rows


WORKED_EXAMPLE = [(0.0, 0.3), (30.0, 0.2), (30.0, 0.25), (0.0, 0.0)]


def test_worked_example_of_blocks_4_3():
    s = slave(WORKED_EXAMPLE, start=False)
    v2 = ip(0.0, 30.0, 300)
    v3 = ip(v2, 30.0, 200)
    v7 = ip(30.0, 0.0, 250)
    v8 = ip(v7, 0.0, 150)
    assert (v2, v3, v7, v8) == pytest.approx((10.0, 20.0, 18.0, 6.0), abs=1e-12)
    assert run(s, [{"start": True}] + [{}] * 10) == [
        (0.0, F, 0, 0, 0, 0, RUN),
        (0.0, T, 1, 300, 750, 750, START),
        (v2, T, 1, 200, 750, 650, RUN),
        (v3, T, 1, 100, 750, 550, RUN),
        (30.0, T, 2, 200, 750, 450, RUN),
        (30.0, T, 2, 100, 750, 350, RUN),
        (30.0, T, 3, 250, 750, 250, RUN),
        (v7, T, 3, 150, 750, 150, RUN),
        (v8, T, 3, 50, 750, 50, RUN),
        (0.0, F, 3, 0, 750, 0, END),
        (0.0, F, 3, 0, 750, 0, END),
        (0.0, F, 3, 0, 750, 0, END),
    ]


@pytest.mark.parametrize("h_calls", [3, 0.5])
def test_worked_example_is_the_same_with_other_step_sizes(h_calls):
    expected = run(slave(WORKED_EXAMPLE, start=True), [{}] * 12)
    s = slave(WORKED_EXAMPLE, start=True)
    rows, calls = {0: row(s)}, 0.0
    while calls < 12:
        s.step(0.1 * h_calls)
        calls += h_calls
        if calls == int(calls):
            rows[int(calls)] = row(s)
    assert rows == {k: expected[k] for k in rows} and len(rows) >= 5


def test_reset_blocks_until_the_next_rising_edge_of_start():
    s = slave([(0.0, 0.4), (40.0, 0.0)], start=True)
    v1 = ip(0.0, 40.0, 400)
    assert v1 == pytest.approx(10.0)
    changes = [{}, {"reset": True}, {}, {"reset": False}, {"start": False}, {"start": True}, {}]
    assert run(s, changes) == [
        (0.0, T, 1, 400, 400, 400, START),
        (v1, T, 1, 300, 400, 300, RUN),
        (0.0, F, 0, 0, 400, 400, END),  # reset edge
        (0.0, F, 0, 0, 400, 400, RUN),  # reset held: no edge, blocked
        (0.0, F, 0, 0, 400, 400, RUN),  # start still TRUE: a held start does not restart
        (0.0, F, 0, 0, 400, 400, RUN),  # start FALSE
        (0.0, T, 1, 400, 400, 400, START),  # new rising edge of start
        (v1, T, 1, 300, 400, 300, RUN),
    ]


def test_reset_and_start_rising_together_leave_the_block_blocked():
    # step 1 unblocks, step 2 blocks again in the same call
    s = slave([(5.0, 0.4), (40.0, 0.0)], start=True, reset=True)
    assert run(s, [{"reset": False}, {}]) == [
        (0.0, F, 0, 0, 400, 400, END),
        (0.0, F, 0, 0, 400, 400, RUN),
        (0.0, F, 0, 0, 400, 400, RUN),
    ]


HOLD_TABLE = [(0.0, 0.4), (40.0, 0.2), (0.0, 0.0)]


def test_hold_freezes_output_and_times_and_extends_the_run():
    s = slave(HOLD_TABLE, start=True)
    v1 = ip(0.0, 40.0, 400)
    v4 = ip(v1, 40.0, 300)
    v5 = ip(v4, 40.0, 200)
    v7 = ip(40.0, 0.0, 200)
    assert (v1, v4, v5, v7) == pytest.approx((10.0, 20.0, 30.0, 20.0))
    expected = [
        (0.0, T, 1, 400, 600, 600, START),
        (v1, T, 1, 300, 600, 500, RUN),
        (v1, F, 1, 300, 600, 500, RUN),  # hold
        (v1, F, 1, 300, 600, 500, RUN),  # hold
        (v4, F, 1, 200, 600, 400, RUN),  # released; actTimeTable only returns in 4.2 a) or d)
        (v5, F, 1, 100, 600, 300, RUN),
        (40.0, T, 2, 200, 600, 200, RUN),
        (v7, T, 2, 100, 600, 100, RUN),
        (0.0, F, 2, 0, 600, 0, END),  # two calls later than without hold
    ]
    assert run(s, [{}, {"hold": True}, {}, {"hold": False}, {}, {}, {}, {}]) == expected


def test_continue_without_hold_has_no_effect():
    plain = slave(HOLD_TABLE, start=True)
    with_continue = slave(HOLD_TABLE, start=True, contStepNbr=2, contStepTime=1.0)
    changes = [{}, {"continue": True}, {}, {}, {}, {}, {}, {}]
    assert run(with_continue, changes) == run(plain, [{}] * len(changes))


CONTINUE_TABLE = [(0.0, 0.4), (40.0, 0.2), (40.0, 0.4), (0.0, 0.0)]


def test_hold_and_continue_aim_at_point_contStepNbr_in_contStepTime():
    s = slave(CONTINUE_TABLE, start=True)
    v1 = ip(0.0, 40.0, 400)
    v4 = ip(v1, 40.0, 200)
    v6 = ip(40.0, 0.0, 400)
    v7 = ip(v6, 0.0, 300)
    v8 = ip(v7, 0.0, 200)
    assert (v1, v4, v6, v7, v8) == pytest.approx((10.0, 25.0, 30.0, 20.0, 10.0))
    hold = {"hold": True, "continue": True, "contStepNbr": 2, "contStepTime": 0.2}
    assert run(s, [{}, hold, {}, {"hold": False}, {}, {}, {}, {}, {}]) == [
        (0.0, T, 1, 400, 1000, 1000, START),
        (v1, T, 1, 300, 1000, 900, RUN),
        (v1, F, 2, 200, 1000, 600, RUN),  # 200 + 400 + 0, recomputed while held
        (v1, F, 2, 200, 1000, 600, RUN),
        (v4, F, 2, 100, 1000, 500, RUN),
        (40.0, T, 3, 400, 1000, 400, RUN),
        (v6, T, 3, 300, 1000, 300, RUN),
        (v7, T, 3, 200, 1000, 200, RUN),
        (v8, T, 3, 100, 1000, 100, RUN),
        (0.0, F, 3, 0, 1000, 0, END),
    ]


def test_continue_to_the_last_point_ends_the_run():
    s = slave(CONTINUE_TABLE, start=True)
    v1 = ip(0.0, 40.0, 400)
    v4 = ip(v1, 0.0, 200)
    assert v4 == pytest.approx(5.0)
    hold = {"hold": True, "continue": True, "contStepNbr": 3, "contStepTime": 0.2}
    assert run(s, [{}, hold, {"hold": False}, {}, {}]) == [
        (0.0, T, 1, 400, 1000, 1000, START),
        (v1, T, 1, 300, 1000, 900, RUN),
        (v1, F, 3, 200, 1000, 200, RUN),
        (v4, F, 3, 100, 1000, 100, RUN),
        (0.0, F, 3, 0, 1000, 0, END),
        (0.0, F, 3, 0, 1000, 0, END),
    ]


def test_cyclic_operation_wraps_with_status_7002_without_interpolating_back():
    s = slave([(0.0, 0.2), (20.0, 0.0)], start=True, cyclicOP=True)
    v1 = ip(0.0, 20.0, 200)
    assert v1 == pytest.approx(10.0)
    assert run(s, [{}, {}, {}, {}, {}, {"cyclicOP": False}, {}, {}, {}]) == [
        (0.0, T, 1, 200, 200, 200, START),
        (v1, T, 1, 100, 200, 100, RUN),
        (20.0, T, 1, 0, 200, 0, CYCLIC),
        (0.0, T, 1, 200, 200, 200, RUN),  # jumps to point 0
        (v1, T, 1, 100, 200, 100, RUN),
        (20.0, T, 1, 0, 200, 0, CYCLIC),
        (0.0, T, 1, 200, 200, 200, RUN),  # the wrap was already marked
        (v1, T, 1, 100, 200, 100, RUN),
        (20.0, F, 1, 0, 200, 0, END),
        (20.0, F, 1, 0, 200, 0, END),
    ]


def test_default_value_overrides_output_and_the_ramp_continues_from_it():
    s = slave([(0.0, 0.6), (60.0, 0.0)], start=True)
    v1 = ip(0.0, 60.0, 600)
    v3 = ip(100.0, 60.0, 400)  # previous output is the default value
    v4 = ip(v3, 60.0, 300)
    v5 = ip(v4, 60.0, 200)
    assert (v1, v3, v4, v5) == pytest.approx((10.0, 90.0, 80.0, 70.0))
    on = {"enDefaultOutValue": True, "defaultOutValue": 100.0}
    assert run(s, [{}, on, {"enDefaultOutValue": False}, {}, {}, {}]) == [
        (0.0, T, 1, 600, 600, 600, START),
        (v1, T, 1, 500, 600, 500, RUN),
        (100.0, F, 1, 400, 600, 400, RUN),  # time processing goes on underneath
        (v3, F, 1, 300, 600, 300, RUN),
        (v4, F, 1, 200, 600, 200, RUN),
        (v5, F, 1, 100, 600, 100, RUN),
        (60.0, F, 1, 0, 600, 0, END),
    ]


def test_default_value_also_applies_when_not_running():
    s = slave(WORKED_EXAMPLE, start=False, enDefaultOutValue=True, defaultOutValue=-7.5)
    assert run(s, [{}]) == [(-7.5, F, 0, 0, 0, 0, RUN)] * 2


def test_update_time_recomputes_the_times_after_a_table_change():
    s = slave(HOLD_TABLE, start=True)
    v1 = ip(0.0, 40.0, 400)
    v2 = ip(v1, 40.0, 300)
    v3 = ip(v2, 40.0, 200)
    v5 = ip(40.0, 0.0, 500)
    assert (v2, v3, v5) == pytest.approx((20.0, 30.0, 32.0))
    changes = [{}, {"setpoints[1].time": 0.5}, {"updateTime": True}, {}, {}]
    assert run(s, changes) == [
        (0.0, T, 1, 400, 600, 600, START),
        (v1, T, 1, 300, 600, 500, RUN),
        (v2, T, 1, 200, 600, 400, RUN),  # the change alone leaves the times
        (v3, T, 1, 100, 900, 600, RUN),  # edge: 400 + 500 + 0; 100 + 500 + 0
        (40.0, T, 2, 500, 900, 500, RUN),  # the new segment time is used
        (v5, T, 2, 400, 900, 400, RUN),
    ]


def test_default_table_runs_0_to_100_to_0_in_20_s():
    s = Slave(BLOCK, inputs={"start": True})
    rows = run(s, [{}] * 210)
    assert rows[0] == (0.0, T, 1, 5000, 20000, 20000, START)
    assert rows[50][:3] == (100.0, T, 2) and rows[150][:3] == (100.0, T, 3)
    assert rows[25][0] == pytest.approx(50.0) and rows[175][0] == pytest.approx(50.0)
    assert rows[200] == (0.0, F, 3, 0, 20000, 0, END)
    assert rows[210] == rows[200]


def test_whole_ms_truncation_of_a_cycle_of_1_5_ms():
    s = Slave(BLOCK, initialize=False)
    s.fmu.setupExperiment(startTime=0.0)
    s.fmu.enterInitializationMode()
    # FMPy raises on errors only: call the C function to see the fmi2Warning
    vr, value = (fmi2ValueReference * 1)(s.vr("cycleTime")), (fmi2Real * 1)(0.0015)
    assert s.fmu.fmi2SetReal(s.fmu.component, vr, 1, value) == fmi2Warning
    assert any("truncated period of 1 ms" in text for _, _, text in s.log)
    s.set({**table((0.0, 0.003), (3.0, 0.0)), "start": True})
    s.fmu.exitInitializationMode()
    v1 = ip(0.0, 3.0, 3, 1)
    v2 = ip(v1, 3.0, 2, 1)
    assert (v1, v2) == pytest.approx((1.0, 2.0))
    assert run(s, [{}, {}, {}], cycle=0.0015) == [  # Ts = 1 ms per call of 1.5 ms
        (0.0, T, 1, 3, 3, 3, START),
        (v1, T, 1, 2, 3, 2, RUN),
        (v2, T, 1, 1, 3, 1, RUN),
        (3.0, F, 1, 0, 3, 0, END),
    ]


# ---- bad input: fmi2Error, value not applied (docs/behaviour.md §4.6, §4.2) ----


@pytest.fixture
def initializing():
    yield from harness.initializing(BLOCK)


@pytest.mark.parametrize("name", ["setpoints[0].time", "setpoints[63].time", "contStepTime"])
@pytest.mark.parametrize("value", [-0.001, -1.0, math.nan])
def test_negative_or_nan_times_are_refused(initializing, name, value):
    s = initializing
    assert refused(s, s.fmu.setReal, name, value)
    assert name in s.log[-1][2]


def test_nan_setpoint_value_is_refused(initializing):
    assert refused(initializing, initializing.fmu.setReal, "setpoints[5].outputValue", math.nan)


def test_cont_step_nbr_must_index_the_table(initializing):
    s = initializing
    assert refused(s, s.fmu.setInteger, "contStepNbr", 4)
    assert "contStepNbr" in s.log[-1][2]
    assert refused(s, s.fmu.setInteger, "contStepNbr", -1)
    assert s.status_of(s.fmu.setInteger, [s.vr("contStepNbr")], [3]) == fmi2OK
    # a table shorter than contStepNbr is refused as well, and names the rule
    assert refused(s, s.fmu.setInteger, "numberOfSetpoints", 3)
    assert "contStepNbr" in s.log[-1][2]


def test_cont_step_nbr_is_refused_while_running():
    s = slave(WORKED_EXAMPLE, start=True)
    assert refused(s, s.fmu.setInteger, "contStepNbr", 4)
    s.step(0.1)
    assert row(s) == (ip(0.0, 30.0, 300), T, 1, 200, 750, 650, RUN)


def test_cycle_time_below_1_ms_is_refused(initializing):
    s = initializing
    assert refused(s, s.fmu.setReal, "cycleTime", 0.0005)
    assert "cycleTime" in s.log[-1][2]


def test_fixed_parameters_and_outputs_cannot_be_set_after_initialization():
    s = slave(WORKED_EXAMPLE)
    assert refused(s, s.fmu.setInteger, "numberOfSetpoints", 3)
    assert refused(s, s.fmu.setInteger, "stepNumber", 2)
    # the table is tunable
    assert s.status_of(s.fmu.setReal, [s.vr("setpoints[2].time")], [1.0]) == fmi2OK


def test_start_values_run_the_default_table_with_no_inputs_set():
    # docs/behaviour.md §4.1, decisions on the default table and on start: start is TRUE from
    # the first call, which is therefore a rising edge; the table 0 -> 100 in 5 s, 100 for 10 s,
    # -> 0 in 5 s ends at t = 20 s.
    s = Slave(BLOCK)
    assert s.get(["start"]) == {"start": True}
    rows = [row(s)]
    for _ in range(250):
        s.step(0.1)
        rows.append(row(s))
    assert rows[0] == (0.0, T, 1, 5000, 20000, 20000, START)
    assert rows[1] == (ip(0.0, 100.0, 5000), T, 1, 4900, 20000, 19900, RUN)
    assert rows[50] == (100.0, T, 2, 10000, 20000, 15000, RUN)
    assert rows[150] == (100.0, T, 3, 5000, 20000, 5000, RUN)
    assert rows[200] == (0.0, F, 3, 0, 20000, 0, END)
    assert rows[250] == rows[200]
    assert {r[6] for r in rows[1:200]} == {RUN}
