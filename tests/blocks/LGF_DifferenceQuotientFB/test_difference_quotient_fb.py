"""LGF_DifferenceQuotientFB against the rules of docs/behaviour.md §17, with hand-computed
expectations (the arithmetic in the comments)."""

import math

from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, column, run_calls, status_of

BLOCK = "LGF_DifferenceQuotientFB"
NO_CALL, FIRST_CALL, SUBSEQUENT_CALL, NOT_ENOUGH_VALUES = 0x7000, 0x7001, 0x7002, 0x7010
ERR_DELTA_T = 0x8200
CYCLE = 0.1


def run(calls: list[dict], **start) -> list[dict]:
    return run_calls(BLOCK, CYCLE, calls, **start)


def pulses(values: list[float], **first) -> list[dict]:
    """Call 0 with insert FALSE (and `first`), then per value a call with insert TRUE and that
    value and a call with insert FALSE: rising edges in calls 1, 3, 5, ..."""
    calls = [{"insert": False, **first}]
    for v in values:
        calls += [{"insert": True, "value": v}, {"insert": False}]
    return calls


def q(delta_t: float, num: float) -> float:
    """The original's derivative (§17.2): the factor 1 / (12 deltaT) first, times the sum, each
    operation rounded to double on its own (Python's floats are IEEE doubles)."""
    return (1.0 / (12.0 * delta_t)) * num


def test_worked_example():
    # §17.4, the original SCL traced: deltaT 0.5, values 1, 2, 4, 8, 16, 32, 64 at calls 1, 3,
    # ..., 13. Call 0 is the rising edge of enable: 7001. The read-ins at calls 1 ... 9 find
    # statCount 0 ... 4 (<= 4): they only count, 7010. Call 11 (32) finds statCount 5:
    # y = 2, 4, 8, 16, 32, sum (2 - 32 + 128) - 32 = 66, factor 1 / (12 * 0.5) = 1/6 rounded,
    # 66 * that = 11.0; call 13 (64): 4, 8, 16, 32, 64, sum 132, 22.0.
    rows = run(pulses([1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0], deltaT=0.5))
    assert column(rows, "status") == (
        [FIRST_CALL] + [NOT_ENOUGH_VALUES] * 10 + [SUBSEQUENT_CALL] * 4
    )
    assert column(rows, "derivatedValue") == [0.0] * 11 + [11.0, 11.0, 22.0, 22.0]
    assert (rows[9]["derivatedValue"], rows[9]["status"]) == (0.0, NOT_ENOUGH_VALUES)
    assert not any(column(rows, "error"))


def test_start_values_enabled_and_waiting():
    # §17.1: enable TRUE, insert FALSE, deltaT 1.0: status 16#7001 and 0.0 throughout.
    s = Slave(BLOCK)
    rows = [s.outputs()] + [s.step(CYCLE) for _ in range(5)]
    assert s.get(["deltaT"]) == {"deltaT": 1.0}
    s.free()
    assert rows == [{"derivatedValue": 0.0, "error": False, "status": FIRST_CALL}] * 6


def test_a_straight_line_gives_its_slope():
    # §17.4: the first value (9) only counts; y = t sampled at 0, 1, 2, 3, 4 (deltaT 1):
    # sum (0 - 8 + 24) - 4 = 12, factor 1/12 rounded, 12 * that = 1.0, at call 11
    rows = run(pulses([9.0, 0.0, 1.0, 2.0, 3.0, 4.0]))
    assert rows[11]["derivatedValue"] == 1.0 and rows[11]["status"] == SUBSEQUENT_CALL


def test_exact_for_a_polynomial_of_degree_four():
    # y = t^4 + t^3 + t^2 + t at t = -2 .. 2: 10, 0, 0, 4, 30 (after a first value that only
    # counts); y'(0) = 1: ((10 - 0) + 32) - 30 = 12, (1/12) * 12 = 1.0
    rows = run(pulses([-5.0, 10.0, 0.0, 0.0, 4.0, 30.0]))
    assert rows[11]["derivatedValue"] == 1.0


def test_the_order_of_the_arithmetic():
    # §17.2: factor := 1 / (12 deltaT); sum := ((y0 - 8 y1) + 8 y3) - y4; factor * sum, each
    # rounded on its own. The first value of each run only counts (call 1), the derivative is
    # at call 11.
    # The sum: y0 = 2^53, y3 = 0.125: 2^53 + 8 * 0.125 = 2^53 + 1 rounds to 2^53 (ties to even)
    rows = run(pulses([0.0, 2.0**53, 0.0, 0.0, 0.125, 0.0]))
    assert rows[11]["derivatedValue"] == q(1.0, 2.0**53) == 750599937895082.6
    # The factor first: deltaT 1, sum 7: 1/12 = 0.08333333333333333, * 7 = 0.5833333333333333,
    # where 7 / 12 would give 0.5833333333333334
    rows = run(pulses([0.0, 7.0, 0.0, 0.0, 0.0, 0.0]))
    assert rows[11]["derivatedValue"] == q(1.0, 7.0) == 0.5833333333333333
    assert rows[11]["derivatedValue"] != 7.0 / 12.0
    # deltaT 0.1: 12 * 0.1 = 1.2000000000000002, 1 / that = 0.8333333333333333 (0x1.aaaa...ap-1),
    # times the sum 12 of y = t: 10.0, where 12 / 1.2000000000000002 would give 9.999999999999998
    rows = run(pulses([0.0, 0.0, 1.0, 2.0, 3.0, 4.0], deltaT=0.1))
    assert rows[11]["derivatedValue"] == q(0.1, 12.0) == 10.0
    assert 12.0 / (12.0 * 0.1) == 9.999999999999998


def test_the_window_slides():
    # 1, 2, 4, 8, 16 only count; then 32, 64, 128 (deltaT 1): sums 66, 132, 264; 66 * (1/12)
    # = 5.5, 132 * (1/12) = 11.0, 264 * (1/12) = 22.0
    rows = run(pulses([1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0, 128.0]))
    assert [rows[k]["derivatedValue"] for k in (11, 13, 15)] == [
        q(1.0, 66.0),
        q(1.0, 132.0),
        q(1.0, 264.0),
    ]
    assert [rows[k]["derivatedValue"] for k in (11, 13, 15)] == [5.5, 11.0, 22.0]


def test_delta_t_zero_is_8200_when_a_derivative_is_due_and_not_latched():
    # §17.2, §17.3: deltaT 0 with five values or fewer: 16#7010; at the sixth: 16#8200, error
    # TRUE, derivatedValue keeps 0.0 (none yet); the value stays in the buffer, so with deltaT 1
    # the seventh value gives the derivative of values 3 ... 7.
    calls = pulses([1.0, 2.0, 4.0, 8.0, 16.0, 32.0], deltaT=0.0)  # calls 0-12
    calls += [{"insert": True, "value": 64.0, "deltaT": 1.0}]  # call 13: 4, 8, 16, 32, 64
    rows = run(calls)
    assert column(rows, "status")[9:] == [NOT_ENOUGH_VALUES] * 2 + [ERR_DELTA_T] * 2 + [
        SUBSEQUENT_CALL
    ]
    assert column(rows, "error")[9:] == [False, False, True, True, False]
    assert column(rows, "derivatedValue")[10:] == [0.0, 0.0, 0.0, q(1.0, 132.0)]


def test_delta_t_zero_keeps_the_last_derivative():
    calls = pulses([9.0, 0.0, 1.0, 2.0, 3.0, 4.0])  # call 11: 1.0
    calls += [{"deltaT": -0.0, "insert": True, "value": 5.0}]  # call 13: -0.0 counts as 0
    rows = run(calls)
    assert rows[-1] == {"derivatedValue": 1.0, "error": True, "status": ERR_DELTA_T}


def test_delta_t_is_read_only_when_a_derivative_is_due():
    # deltaT 0 between edges changes nothing: the status of the last event holds.
    calls = pulses([9.0, 0.0, 1.0, 2.0, 3.0, 4.0]) + [{"deltaT": 0.0}, {}]
    rows = run(calls)
    assert column(rows, "status")[-3:] == [SUBSEQUENT_CALL] * 3
    assert column(rows, "derivatedValue")[-3:] == [1.0] * 3


def test_negative_infinite_and_tiny_delta_t():
    # §17.4: a negative deltaT flips the sign: 1 / (12 * -0.5) = -1/6, * 12 = -2.0
    line = [9.0, 0.0, 1.0, 2.0, 3.0, 4.0]  # sum 12 at call 11
    rows = run(pulses(line, deltaT=-0.5))
    assert rows[11]["derivatedValue"] == -2.0
    # an infinite one: 1 / Inf = 0.0, * 12 = 0.0
    rows = run(pulses(line, deltaT=math.inf))
    assert rows[11]["derivatedValue"] == 0.0
    # 12 * 1e-310 = 1.2e-309 (subnormal), 1 / that overflows to Inf, * 12 = Inf
    rows = run(pulses(line, deltaT=1e-310))
    assert rows[11]["derivatedValue"] == math.inf
    # an overflowing factor times a sum of 0 (a constant signal) is Inf * 0 = NaN, the positive
    # quiet NaN (§1.4); 0 / 6e-323 would have been 0.0
    rows = run(pulses([1.0] * 6, deltaT=5e-324))
    nan = rows[11]["derivatedValue"]
    assert math.isnan(nan) and math.copysign(1.0, nan) == 1.0
    assert rows[11]["status"] == SUBSEQUENT_CALL


def test_disable_outputs_zero_and_a_new_enable_starts_empty():
    calls = pulses([9.0, 0.0, 1.0, 2.0, 3.0, 4.0])  # calls 0-12, derivative 1.0 from call 11
    calls += [{"enable": False}, {"insert": True, "value": 100.0}, {"insert": False}]  # 13-15
    calls += [{"enable": True}]  # 16: 16#7001, empty buffer
    calls += pulses([7.0, 0.0, 2.0, 4.0, 6.0, 8.0])[1:]  # edges in 17, 19, ..., 27
    rows = run(calls)
    assert column(rows, "status")[13:17] == [NO_CALL] * 3 + [FIRST_CALL]
    assert column(rows, "derivatedValue")[12:17] == [1.0] + [0.0] * 4
    assert column(rows, "status")[17:27] == [NOT_ENOUGH_VALUES] * 10
    # y = 0, 2, 4, 6, 8: sum (0 - 16 + 48) - 8 = 24, (1/12) * 24 = 2.0
    assert rows[27] == {"derivatedValue": 2.0, "error": False, "status": SUBSEQUENT_CALL}


def test_enable_and_insert_rising_together_lose_the_insert():
    # §17.2 step 2, the original SCL traced: the call of the rising edge of enable only starts
    # (16#7001); the rising edge of insert in it is not read in, and its memory is TRUE after
    # it, so the value (100) is lost. Then 9, 0, 1, 2, 3 only count (calls 2 ... 10) and 4 gives
    # y = 0, 1, 2, 3, 4: 1.0 at call 12 (with 100 read in, call 10 would already give one, of
    # y = 9, 0, 1, 2, 3: ((9 - 0) + 16) - 3 = 22, times 1/12).
    rows = run([{"insert": True, "value": 100.0}] + pulses([9.0, 0.0, 1.0, 2.0, 3.0, 4.0]))
    assert column(rows, "status")[:2] == [FIRST_CALL, FIRST_CALL]
    assert column(rows, "status")[2:12] == [NOT_ENOUGH_VALUES] * 10
    assert rows[10]["derivatedValue"] == 0.0
    assert rows[12] == {"derivatedValue": 1.0, "error": False, "status": SUBSEQUENT_CALL}
    # later in a run: enable falls in call 13, rises with insert in call 14: lost again
    calls = pulses([9.0, 0.0, 1.0, 2.0, 3.0, 4.0])  # calls 0-12
    calls += [{"enable": False}, {"enable": True, "insert": True, "value": 50.0}]  # 13, 14
    calls += pulses([7.0, 0.0, 2.0, 4.0, 6.0, 8.0])  # 15 (insert FALSE), reads at 16 ... 26
    rows = run(calls)
    assert column(rows, "status")[13:16] == [NO_CALL, FIRST_CALL, FIRST_CALL]
    assert column(rows, "status")[16:26] == [NOT_ENOUGH_VALUES] * 10
    assert rows[26]["derivatedValue"] == 2.0  # 0, 2, 4, 6, 8, without 50


def test_insert_held_while_enable_rises_is_no_edge():
    rows = run(
        [{"enable": False, "insert": True}, {"enable": True, "value": 1.0}, {"insert": False}]
    )
    assert column(rows, "status") == [NO_CALL, FIRST_CALL, FIRST_CALL]


def test_infinities_give_nan():
    # after a first value that only counts (9): y = 0, 0, 0, 0, Inf: -Inf (1/12 times it);
    # then 0, 0, 0, Inf, 1: 8 Inf - 1 = Inf; 0, 0, Inf, 1, 2 (the middle has weight 0):
    # (0 - 0 + 8) - 2 = 6, (1/12) * 6 = 0.5; then 0, Inf, 1, 2, 3: -Inf;
    # Inf, 1, 2, 3, -Inf: Inf - 8 + 24 + Inf = Inf
    rows = run(pulses([9.0, 0.0, 0.0, 0.0, 0.0, math.inf, 1.0, 2.0, 3.0, -math.inf]))
    got = [rows[k]["derivatedValue"] for k in (11, 13, 15, 17, 19)]
    assert got == [-math.inf, math.inf, 0.5, -math.inf, math.inf]
    rows = run(pulses([9.0, math.inf, 0.0, 0.0, 0.0, math.inf]))  # Inf - Inf: NaN
    nan = rows[11]["derivatedValue"]
    assert math.isnan(nan) and math.copysign(1.0, nan) == 1.0  # the positive quiet NaN


def test_nan_is_refused():
    s = Slave(BLOCK, {"cycleTime": CYCLE})
    assert status_of(s.fmu.setReal, [s.vr("value")], [math.nan]) == fmi2Error
    assert status_of(s.fmu.setReal, [s.vr("deltaT")], [math.nan]) == fmi2Error
    assert s.get(["deltaT"]) == {"deltaT": 1.0}
    s.free()


def test_the_change_to_8200_is_logged():
    s = Slave(BLOCK, {"cycleTime": CYCLE}, {"deltaT": 0.0})
    for v in range(6):  # the sixth value is the first with a derivative due
        s.set({"insert": True, "value": float(v)})
        s.step(CYCLE)
        s.set({"insert": False})
        s.step(CYCLE)
    assert s.outputs()["status"] == ERR_DELTA_T
    assert any("16#8200" in text and cat == "logStatusWarning" for _, cat, text in s.log)
    s.free()
