"""LGF_FloatingAverage against the rules of docs/behaviour.md §15, with expectations traced by
hand through the block's original code (the arithmetic in the comments; LREAL values are
doubles, as Python's floats)."""

import math

import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, column, run_calls, status_of

BLOCK = "LGF_FloatingAverage"
WRONG_WINDOW_SIZE = 0x8200
CYCLE = 0.1


def run(calls: list[dict], **start) -> list[dict]:
    return run_calls(BLOCK, CYCLE, calls, **start)


def test_worked_example_fills_then_slides():
    # §15.3: window 3, values 3, 6, 9, 12, 0, 15. Call 0: windowSize 3 differs from
    # statWindowSizeOld 0: a restart, 3 is not read in (0.0). Filling: 6/1 = 6, (6 + 9)/2 = 7.5,
    # (15 + 12)/3 = 9 (statCount 3, windowSizeReached still FALSE). Sliding, from call 4 on:
    # slot 3 MOD 3 = 0 holds 6: 27 + (0 - 6) = 21, /3 = 7, windowSizeReached TRUE, statCount
    # 3 + 1 = 4; call 5: slot 4 MOD 3 = 1 holds 9: 21 + (15 - 9) = 27, /3 = 9.
    rows = run(
        [{"value": v} for v in (3.0, 6.0, 9.0, 12.0, 0.0, 15.0)],
        cyclicExecution=True,
        windowSize=3,
    )
    assert column(rows, "average") == [0.0, 6.0, 7.5, 9.0, 7.0, 9.0]
    assert column(rows, "windowSizeReached") == [False] * 4 + [True] * 2
    assert {(r["error"], r["status"]) for r in rows} == {(False, 0)}


def test_start_values_read_one_per_call_into_a_window_of_ten():
    # §15.1: cyclicExecution true, value 1.0, windowSize 10: call 0 takes the window size (a
    # restart, 0.0); calls 1 ... 10 fill the window (1.0), call 11 slides: windowSizeReached.
    s = Slave(BLOCK)
    rows = [s.outputs()] + [s.step(CYCLE) for _ in range(12)]
    s.free()
    assert column(rows, "average") == [0.0] + [1.0] * 12
    assert column(rows, "windowSizeReached") == [False] * 11 + [True] * 2


def test_a_hundred_values_fill_the_largest_window():
    # §15.2: window 100; call 0 restarts; values 1, 2, ..., 101 in calls 1 ... 101: after k
    # values the mean is (k+1)/2 (the sums k(k+1)/2 are exact); the 100th fills the window
    # (mean 50.5, windowSizeReached still FALSE); the 101st (101) replaces 1, slot 100 MOD 100
    # = 0: 5050 + (101 - 1) = 5150, /100 = 51.5, windowSizeReached TRUE.
    rows = run(
        [{"value": -1.0}] + [{"value": float(k)} for k in range(1, 102)],
        cyclicExecution=True,
        windowSize=100,
    )
    assert column(rows, "average")[:4] == [0.0, 1.0, 1.5, 2.0]
    assert rows[100]["average"] == 50.5 and not rows[100]["windowSizeReached"]
    assert rows[101]["average"] == 51.5 and rows[101]["windowSizeReached"]


def test_trigger_reads_at_rising_edges_only():
    # §15.2 steps 1 and 4: cyclicExecution FALSE, window 2. Call 0: trigger TRUE is an edge (the
    # memory starts FALSE), but call 0 restarts and reads nothing. Call 1 held (no edge), 2
    # FALSE, 3 TRUE (edge): 40 -> 40; 4 held; 5 FALSE; 6 edge: (40 + 60)/2 = 50; 7 FALSE;
    # 8 edge: slot 2 MOD 2 = 0 holds 40: 100 + (70 - 40) = 130, /2 = 65, windowSizeReached.
    trigger = [True, True, False, True, True, False, True, False, True]
    values = [10.0, 20.0, 30.0, 40.0, 50.0, 55.0, 60.0, 65.0, 70.0]
    rows = run(
        [{"trigger": t, "value": v} for t, v in zip(trigger, values)],
        cyclicExecution=False,
        windowSize=2,
    )
    assert column(rows, "average") == [0.0, 0.0, 0.0, 40.0, 40.0, 40.0, 50.0, 50.0, 65.0]
    assert column(rows, "windowSizeReached") == [False] * 8 + [True]


def test_no_read_in_holds_the_outputs():
    # §15.3: with neither cyclicExecution nor an edge, nothing is read: the outputs hold.
    rows = run(
        [{"value": 4.0}, {}, {"cyclicExecution": False, "value": 100.0}, {"value": -7.0}],
        cyclicExecution=True,
        windowSize=5,
    )
    assert column(rows, "average") == [0.0, 4.0, 4.0, 4.0]


def test_cyclic_execution_and_a_trigger_edge_read_one_value():
    # §15.2 step 4: both together read one value, not two. Window 2: call 0 restarts; call 1
    # reads 2; call 2 (edge) reads 4 once: (2 + 4)/2 = 3, statCount 2; call 3: slot 0 holds 2:
    # 6 + (4 - 2) = 8, /2 = 4 (had call 2 read 4 twice, it would show 8/2 = 4.0).
    rows = run(
        [
            {"trigger": True, "value": 2.0},
            {"trigger": False},
            {"trigger": True, "value": 4.0},
            {"trigger": False},
        ],
        cyclicExecution=True,
        windowSize=2,
    )
    assert column(rows, "average") == [0.0, 2.0, 3.0, 4.0]


def test_trigger_held_when_cyclic_execution_falls_is_no_edge():
    # §15.2 step 1: the edge memory follows trigger in every call, also while cyclicExecution
    # is TRUE and in the restart of call 0.
    rows = run(
        [{"trigger": True, "value": 1.0}, {}, {"cyclicExecution": False, "value": 9.0}],
        cyclicExecution=True,
        windowSize=3,
    )
    assert column(rows, "average") == [0.0, 1.0, 1.0]


@pytest.mark.parametrize("size", [0, -1, 101, 32767, -32768])
def test_invalid_window_size_errors_one_call_later(size):
    # §15.2 steps 2 and 3, §15.4: window 1 with 6.0: call 0 restarts, call 1 fills (6.0),
    # call 2 slides: 6 + (6 - 6) = 6, windowSizeReached TRUE. The change to the invalid size in
    # call 3 is a restart (0.0, FALSE, no error, status 0); from call 4 on, the size is the one
    # of the call before and invalid: error TRUE, status 16#8200, nothing read in.
    s = Slave(BLOCK, {"cycleTime": CYCLE}, {"value": 6.0, "windowSize": 1})
    assert s.outputs() == {"average": 0.0, "windowSizeReached": False, "error": False, "status": 0}
    assert s.step(CYCLE)["average"] == 6.0
    assert s.step(CYCLE) == {"average": 6.0, "windowSizeReached": True, "error": False, "status": 0}
    s.set({"windowSize": size})
    restart = {"average": 0.0, "windowSizeReached": False, "error": False, "status": 0}
    assert s.step(CYCLE) == restart
    assert not any("16#8200" in text for _, _, text in s.log)
    want = {"average": 0.0, "windowSizeReached": False, "error": True, "status": WRONG_WINDOW_SIZE}
    assert s.step(CYCLE) == want
    assert s.step(CYCLE) == want
    assert any("16#8200" in text and cat == "logStatusWarning" for _, cat, text in s.log)
    # back to a valid size: a restart (nothing read in), then a fresh window
    s.set({"windowSize": 2, "value": 8.0})
    assert s.step(CYCLE) == restart
    assert s.step(CYCLE) == {
        "average": 8.0,
        "windowSizeReached": False,
        "error": False,
        "status": 0,
    }
    s.free()


def test_invalid_window_size_from_the_first_call():
    # statWindowSizeOld starts at 0: windowSize 0 in call 0 is no change, so call 0 is already
    # the error; 101 is a change (a restart), the error comes in call 1.
    error = {"average": 0.0, "windowSizeReached": False, "error": True, "status": WRONG_WINDOW_SIZE}
    restart = {"average": 0.0, "windowSizeReached": False, "error": False, "status": 0}
    assert run([{"windowSize": 0}, {}], value=5.0) == [error, error]
    assert run([{"windowSize": 101}, {}], value=5.0) == [restart, error]


def test_reset_comes_before_the_window_size_check():
    # §15.2 step 2: reset held TRUE restarts in every call, so an invalid size shows no error
    # until reset falls.
    rows = run([{"reset": True}, {}, {"reset": False}], windowSize=0, value=5.0)
    assert column(rows, "status") == [0, 0, WRONG_WINDOW_SIZE]
    assert column(rows, "error") == [False, False, True]


def test_a_new_window_size_restarts_the_window_and_reads_nothing():
    # §15.2 step 2: the worked example's calls 0 ... 4 (7.0, windowSizeReached TRUE); windowSize
    # 4 in call 5 restarts: 0.0, FALSE, 15 is not read in; call 6 reads 20: 20/1 = 20.
    rows = run(
        [{"value": v} for v in (3.0, 6.0, 9.0, 12.0, 0.0)]
        + [{"value": 15.0, "windowSize": 4}, {"value": 20.0}],
        cyclicExecution=True,
        windowSize=3,
    )
    assert column(rows, "average") == [0.0, 6.0, 7.5, 9.0, 7.0, 0.0, 20.0]
    assert column(rows, "windowSizeReached") == [False] * 4 + [True, False, False]


def test_reset_is_a_level_and_reads_nothing():
    # §15.2 step 2: window 3; call 0 restarts; 2 -> 2; (2 + 4)/2 = 3; reset in calls 3 and 4:
    # 0.0, 10 and 20 are not read in; reset FALSE in call 5: 40 -> 40; then (40 + 60)/2 = 50.
    rows = run(
        [
            {"value": 2.0},
            {"value": 2.0},
            {"value": 4.0},
            {"reset": True, "value": 10.0},
            {"value": 20.0},
            {"reset": False, "value": 40.0},
            {"value": 60.0},
        ],
        cyclicExecution=True,
        windowSize=3,
    )
    assert column(rows, "average") == [0.0, 2.0, 3.0, 0.0, 0.0, 40.0, 50.0]


def test_reset_without_a_read_in_outputs_zero():
    # window 1: call 0 restarts; call 1 fills (2.0); call 2 slides: 2 + (2 - 2) = 2, TRUE;
    # call 3 reset: 0.0, FALSE; call 4: no read-in (cyclicExecution FALSE): 0.0 held.
    rows = run(
        [{"value": 2.0}, {}, {}, {"cyclicExecution": False, "reset": True}, {"reset": False}],
        cyclicExecution=True,
        windowSize=1,
    )
    assert column(rows, "average") == [0.0, 2.0, 2.0, 0.0, 0.0]
    assert column(rows, "windowSizeReached") == [False, False, True, False, False]


def test_values_are_lreal():
    # §15.1: value, the window, the sum and the average are LREAL: 0.1 is the double 0.1 (as a
    # REAL it would be 0.10000000149011612); 0.1 + 0.1 = 0.2, /2 = 0.1; 0.2 + 0.1 =
    # 0.30000000000000004, /3 = 0.10000000000000002. 1/3 in a window of 1: the double 1/3.
    rows = run(
        [{"value": 0.1}, {}, {}, {}, {"value": 1.0 / 3.0, "windowSize": 1}, {}],
        cyclicExecution=True,
        windowSize=3,
    )
    assert column(rows, "average") == [0.0, 0.1, 0.1, 0.10000000000000002, 0.0, 1.0 / 3.0]


def test_the_running_sum_keeps_its_rounding():
    # §15.3: window 1: 1e16 -> 1e16; then 1.0 replaces it: 1 - 1e16 = -9999999999999999, which
    # rounds to -1e16 (one ulp at 1e16 is 2, ties to even), 1e16 + -1e16 = 0; from then
    # 0 + (1 - 1) = 0: average 0.0 while value is 1.0, until a restart (which reads nothing).
    rows = run(
        [{"value": 1e16}, {}, {"value": 1.0}, {}, {}, {"reset": True}, {"reset": False}],
        cyclicExecution=True,
        windowSize=1,
    )
    assert column(rows, "average") == [0.0, 1e16, 0.0, 0.0, 0.0, 0.0, 1.0]


def test_the_sliding_sum_adds_the_difference():
    # §15.2 step 4: sum + (value - oldest), the difference first. Window 2: 1 then 1e16: sum
    # 1 + 1e16 = 1e16 (rounded), mean 5e15; then 3 replaces 1: 3 - 1 = 2, 1e16 + 2 =
    # 10000000000000002, /2 = 5000000000000001. ((1e16 + 3) - 1 would give 10000000000000004
    # and 5000000000000002.)
    rows = run(
        [{"value": 0.0}, {"value": 1.0}, {"value": 1e16}, {"value": 3.0}],
        cyclicExecution=True,
        windowSize=2,
    )
    assert column(rows, "average") == [0.0, 1.0, 5e15, 5000000000000001.0]


def test_infinity_and_the_nan_it_leaves():
    # §15.3, window 2: call 0 restarts; 1 -> 1; Inf: (1 + Inf)/2 = Inf; 3 replaces 1 (slot 0):
    # Inf + (3 - 1) = Inf; 3 replaces Inf (slot 1): Inf + (3 - Inf) = Inf + -Inf = NaN, which
    # stays until a restart; got as the positive quiet NaN (§1.4). reset: 0.0; then 3 -> 3.
    rows = run(
        [
            {"value": 1.0},
            {},
            {"value": math.inf},
            {"value": 3.0},
            {},
            {},
            {"reset": True},
            {"reset": False},
        ],
        cyclicExecution=True,
        windowSize=2,
    )
    got = column(rows, "average")
    assert got[:4] == [0.0, 1.0, math.inf, math.inf]
    for nan in got[4:6]:
        assert math.isnan(nan) and math.copysign(1.0, nan) == 1.0
    assert got[6:] == [0.0, 3.0]


def test_overflow_of_the_sum():
    # 1e308 + 1e308 overflows to +Inf (as a double; 3e38 no longer does, as in a REAL).
    rows = run([{"value": 1e308}, {}, {}], cyclicExecution=True, windowSize=2)
    assert column(rows, "average") == [0.0, 1e308, math.inf]
    rows = run([{"value": 3e38}, {}, {}], cyclicExecution=True, windowSize=2)
    assert column(rows, "average") == [0.0, 3e38, 3e38]


def test_nan_and_out_of_range_values_are_refused():
    s = Slave(BLOCK, {"cycleTime": CYCLE}, {"value": 2.0})
    assert status_of(s.fmu.setReal, [s.vr("value")], [math.nan]) == fmi2Error
    assert status_of(s.fmu.setInteger, [s.vr("windowSize")], [40000]) == fmi2Error  # INT range
    assert s.step(CYCLE)["average"] == 2.0  # nothing was applied: 2.0 read in call 1
    s.set({"value": 1e39})  # an LREAL: beyond float32, accepted
    assert s.step(CYCLE)["average"] == 5e38  # (2 + 1e39)/2, 2 + 1e39 = 1e39 in double
    s.free()
