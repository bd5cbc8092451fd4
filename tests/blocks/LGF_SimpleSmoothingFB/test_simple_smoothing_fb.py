"""LGF_SimpleSmoothingFB against the rules of docs/behaviour.md §16, with hand-computed
expectations (the arithmetic in the comments)."""

import math

from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, column, run_calls, status_of

BLOCK = "LGF_SimpleSmoothingFB"
NO_CALL, FIRST_CALL, SUBSEQUENT_CALL, NOT_ENOUGH_VALUES = 0x7000, 0x7001, 0x7002, 0x7010
CYCLE = 0.1


def run(calls: list[dict], **start) -> list[dict]:
    return run_calls(BLOCK, CYCLE, calls, **start)


def pulses(values: list[float]) -> list[dict]:
    """Call 0 with insert FALSE, then per value a call with insert TRUE and that value and a call
    with insert FALSE: a rising edge in calls 1, 3, 5, ..."""
    calls = [{"insert": False}]
    for v in values:
        calls += [{"insert": True, "value": v}, {"insert": False}]
    return calls


def test_worked_example():
    # §16.4, the original SCL traced: values 3, 6, 9, 12 at edges in calls 1, 3, 5, 7. Call 0 is
    # the rising edge of enable (its memory starts FALSE): 7001. The read-ins at calls 1, 3, 5
    # find statCount 0, 1, 2 (<= 2): they only count, 7010. The one at call 7 finds statCount 3:
    # (6 + 9) + 12 = 27, / 3 = 9.0, 7002.
    rows = run(pulses([3.0, 6.0, 9.0, 12.0]))
    assert column(rows, "status") == [FIRST_CALL] + [NOT_ENOUGH_VALUES] * 6 + [SUBSEQUENT_CALL] * 2
    assert column(rows, "smoothedValue") == [0.0] * 7 + [9.0, 9.0]
    assert (rows[5]["smoothedValue"], rows[5]["status"]) == (0.0, NOT_ENOUGH_VALUES)
    assert not any(column(rows, "error"))


def test_start_values_enabled_and_waiting():
    # §16.1: enable starts TRUE, insert FALSE: status 16#7001, smoothedValue 0.0 throughout.
    s = Slave(BLOCK)
    rows = [s.outputs()] + [s.step(CYCLE) for _ in range(5)]
    s.free()
    assert rows == [{"smoothedValue": 0.0, "error": False, "status": FIRST_CALL}] * 6


def test_insert_held_true_reads_once():
    # Only the rising edge reads: insert TRUE in calls 1-4 reads once (7010, count 1).
    rows = run([{"insert": False}] + [{"insert": True, "value": float(k)} for k in range(4)])
    assert column(rows, "status") == [FIRST_CALL] + [NOT_ENOUGH_VALUES] * 4
    # calls: 0 -, 1 reads 0, 2 held (5 not read), 3 (insert FALSE), 4 reads 7, 5 -, 6 reads 8
    # (the third value: 7010), 7 -, 8 reads 9: (7 + 8) + 9 = 24, / 3 = 8
    rows = run(
        [{"insert": False}, {"insert": True, "value": 0.0}, {"insert": True, "value": 5.0}]
        + pulses([7.0, 8.0, 9.0])
    )
    assert rows[6]["smoothedValue"] == 0.0 and rows[6]["status"] == NOT_ENOUGH_VALUES
    assert rows[8]["smoothedValue"] == 8.0 and rows[8]["status"] == SUBSEQUENT_CALL


def test_the_mean_is_summed_left_to_right_in_lreal():
    # §16.4: (0.1 + 0.2) + 0.3 = 0.6000000000000001, / 3 = 0.20000000000000004 (doubles); the
    # first value (5.0) only counts, the mean comes with the fourth, in call 7.
    rows = run(pulses([5.0, 0.1, 0.2, 0.3]))
    assert rows[7]["smoothedValue"] == 0.20000000000000004
    # the other order, 0.1 + (0.2 + 0.3) = 0.6, would give 0.19999999999999998
    assert rows[7]["smoothedValue"] != (0.1 + (0.2 + 0.3)) / 3.0


def test_the_window_slides_over_the_last_three():
    # 1, 2, 4, 8, 16, 32 in calls 1, 3, ..., 11: means from the fourth value on (calls 7, 9,
    # 11): 14/3, 28/3, 56/3 as doubles
    rows = run(pulses([1.0, 2.0, 4.0, 8.0, 16.0, 32.0]))
    assert [rows[k]["smoothedValue"] for k in (7, 9, 11)] == [
        ((2.0 + 4.0) + 8.0) / 3.0,
        ((4.0 + 8.0) + 16.0) / 3.0,
        ((8.0 + 16.0) + 32.0) / 3.0,
    ]
    assert rows[7]["smoothedValue"] == 4.666666666666667


def test_disable_outputs_zero_and_no_call_and_a_new_enable_starts_empty():
    # §16.2 steps 2 and 4: enable FALSE gives 0.0 and 16#7000 at once; edges of insert while
    # disabled are not read; the next rising edge of enable clears the buffer (16#7001), so the
    # next smoothed value needs four new values.
    calls = pulses([3.0, 6.0, 9.0, 12.0])  # calls 0-8, smoothed 9 from call 7
    calls += [{"enable": False}, {"insert": True, "value": 100.0}, {"insert": False}]  # 9-11
    calls += [{"enable": True}] + pulses([30.0, 60.0, 90.0])[1:]  # 12: 7001; 13, 15, 17 count
    calls += [{"insert": True, "value": 120.0}]  # 19: (60 + 90) + 120 = 270, / 3 = 90
    rows = run(calls)
    assert column(rows, "status")[9:] == (
        [NO_CALL] * 3 + [FIRST_CALL] + [NOT_ENOUGH_VALUES] * 6 + [SUBSEQUENT_CALL]
    )
    assert column(rows, "smoothedValue")[8:] == [9.0] + [0.0] * 10 + [90.0]


def test_enable_and_insert_rising_together_lose_the_insert():
    # §16.2 step 2, the original SCL traced: the call with the rising edge of enable only starts
    # (16#7001); its rising edge of insert is not read in, and the insert memory is TRUE
    # afterwards, so the value is lost. Call 0: enable (memory FALSE) and insert rise, 100.0 lost;
    # then 3, 6, 9, 12 at calls 2, 4, 6, 8: 7010 and 0.0 at call 6, (6 + 9) + 12 = 27, / 3 = 9.0
    # at call 8 (with 100 read in, call 6 would already give (3 + 6 + 9) / 3 = 6.0).
    rows = run([{"insert": True, "value": 100.0}] + pulses([3.0, 6.0, 9.0, 12.0]))
    assert column(rows, "status") == (
        [FIRST_CALL] * 2 + [NOT_ENOUGH_VALUES] * 6 + [SUBSEQUENT_CALL] * 2
    )
    assert column(rows, "smoothedValue") == [0.0] * 8 + [9.0, 9.0]
    # the same later in a run: enable falls in call 9, rises with insert in call 10
    calls = pulses([3.0, 6.0, 9.0, 12.0])  # calls 0-8
    calls += [{"enable": False}, {"enable": True, "insert": True, "value": 50.0}]  # 9, 10
    calls += pulses([1.0, 2.0, 3.0, 4.0])  # 11 (insert FALSE), reads at 12, 14, 16, 18
    rows = run(calls)
    assert column(rows, "status")[9:12] == [NO_CALL, FIRST_CALL, FIRST_CALL]
    assert rows[16]["status"] == NOT_ENOUGH_VALUES and rows[16]["smoothedValue"] == 0.0
    assert rows[18]["smoothedValue"] == 3.0  # (2 + 3) + 4 = 9, / 3 = 3, without 50


def test_insert_held_while_enable_rises_is_no_edge():
    # §16.2 step 1: the insert memory follows insert while disabled.
    rows = run(
        [{"enable": False, "insert": True}, {"enable": True, "value": 1.0}, {"insert": False}]
    )
    assert column(rows, "status") == [NO_CALL, FIRST_CALL, FIRST_CALL]


def test_infinities_and_nan():
    # ±Inf go through IEEE arithmetic (the first value, 0, only counts): 1 + 2 + Inf = Inf;
    # -Inf joins: NaN (the positive quiet NaN, §1.4); three values later the NaN is gone.
    rows = run(pulses([0.0, 1.0, 2.0, math.inf, -math.inf, 5.0, 6.0, 7.0]))
    got = [rows[k]["smoothedValue"] for k in (7, 9, 11, 13, 15)]
    assert got[0] == math.inf
    assert math.isnan(got[1]) and math.copysign(1.0, got[1]) == 1.0
    assert math.isnan(got[2])  # (Inf + -Inf) + 5
    assert got[3] == -math.inf  # (-Inf + 5) + 6
    assert got[4] == 6.0  # (5 + 6) + 7 = 18


def test_nan_is_refused():
    s = Slave(BLOCK, {"cycleTime": CYCLE}, {"value": 2.0})
    assert status_of(s.fmu.setReal, [s.vr("value")], [math.nan]) == fmi2Error
    s.free()
