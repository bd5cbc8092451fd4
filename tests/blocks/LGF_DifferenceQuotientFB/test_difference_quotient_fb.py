"""LGF_DifferenceQuotientFB against the rules of docs/behaviour.md §17, with hand-computed
expectations (the arithmetic in the comments)."""

import math

from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of

BLOCK = "LGF_DifferenceQuotientFB"
NO_CALL, FIRST_CALL, SUBSEQUENT_CALL, NOT_ENOUGH_VALUES = 0x7000, 0x7001, 0x7002, 0x7010
ERR_DELTA_T = 0x8200
CYCLE = 0.1


def run(calls: list[dict], **start) -> list[dict]:
    """Outputs of calls 0, 1, ...: calls[0] (with start) is set during initialization and reaches
    call 0, calls[k] is set before the step that executes call k (docs/behaviour.md §1.3)."""
    s = Slave(BLOCK, {"cycleTime": CYCLE}, {**start, **calls[0]})
    rows = [s.outputs()]
    for changes in calls[1:]:
        s.set(changes)
        rows.append(s.step(CYCLE))
    s.free()
    return rows


def column(rows, name):
    return [row[name] for row in rows]


def pulses(values: list[float], **first) -> list[dict]:
    """Call 0 with insert FALSE (and `first`), then per value a call with insert TRUE and that
    value and a call with insert FALSE: rising edges in calls 1, 3, 5, ..."""
    calls = [{"insert": False, **first}]
    for v in values:
        calls += [{"insert": True, "value": v}, {"insert": False}]
    return calls


def test_worked_example():
    # §17.4: deltaT 0.5, values 1, 2, 4, 8, 16, 32 at calls 1, 3, ..., 11: 16#7010 after the
    # first four, then (1 - 16 + 64 - 16) / (12 * 0.5) = 33 / 6 = 5.5 from call 9, and
    # (2 - 32 + 128 - 32) / 6 = 66 / 6 = 11.0 from call 11.
    rows = run(pulses([1.0, 2.0, 4.0, 8.0, 16.0, 32.0], deltaT=0.5))
    assert column(rows, "status") == [FIRST_CALL] + [NOT_ENOUGH_VALUES] * 8 + [SUBSEQUENT_CALL] * 4
    assert column(rows, "derivatedValue") == [0.0] * 9 + [5.5, 5.5, 11.0, 11.0]
    assert not any(column(rows, "error"))


def test_start_values_enabled_and_waiting():
    # §17.1: enable TRUE, insert FALSE, deltaT 1.0: status 16#7001 and 0.0 throughout.
    s = Slave(BLOCK)
    rows = [s.outputs()] + [s.step(CYCLE) for _ in range(5)]
    assert s.get(["deltaT"]) == {"deltaT": 1.0}
    s.free()
    assert rows == [{"derivatedValue": 0.0, "error": False, "status": FIRST_CALL}] * 6


def test_a_straight_line_gives_its_slope():
    # §17.4: y = t sampled at 0, 1, 2, 3, 4 (deltaT 1): (0 - 8 + 24 - 4) / 12 = 1
    rows = run(pulses([0.0, 1.0, 2.0, 3.0, 4.0]))
    assert rows[9]["derivatedValue"] == 1.0 and rows[9]["status"] == SUBSEQUENT_CALL


def test_exact_for_a_polynomial_of_degree_four():
    # y = t^4 + t^3 + t^2 + t at t = -2 .. 2: 10, 0, 0, 4, 30; y'(0) = 1:
    # ((10 - 0) + 32) - 30 = 12, / 12 = 1
    rows = run(pulses([10.0, 0.0, 0.0, 4.0, 30.0]))
    assert rows[9]["derivatedValue"] == 1.0


def test_the_order_of_the_arithmetic():
    # §17.2: num = ((y0 - 8 y1) + 8 y3) - y4, den = 12 deltaT, num / den, each rounded on its
    # own; a y0 of 2^53 shows the rounding of the sums.
    rows = run(pulses([2.0**53, 1.0, 0.0, 0.0, 0.0]))
    # (2^53 - 8) + 0 - 0 = 2^53 - 8, exact; / 12
    assert rows[9]["derivatedValue"] == (2.0**53 - 8.0) / 12.0
    rows = run(pulses([2.0**53, 0.0, 0.0, 0.125, 0.0]))
    # y0 + 8 * 0.125 = 2^53 + 1, which rounds to 2^53 (ties to even): 2^53 / 12
    assert rows[9]["derivatedValue"] == 2.0**53 / 12.0
    # and the denominator is 12 * deltaT, not 12 times the quotient: deltaT 0.1 -> 12 * 0.1 =
    # 1.2000000000000002, so (0 - 8 + 24 - 4) / that
    rows = run(pulses([0.0, 1.0, 2.0, 3.0, 4.0], deltaT=0.1))
    assert rows[9]["derivatedValue"] == 12.0 / (12.0 * 0.1)
    assert rows[9]["derivatedValue"] == 9.999999999999998


def test_the_window_slides():
    # 1, 2, 4, 8, 16, then 32 and 64: (2 - 32 + 128 - 32) = 66; (4 - 64 + 256 - 64) = 132
    rows = run(pulses([1.0, 2.0, 4.0, 8.0, 16.0, 32.0, 64.0]))
    assert [rows[k]["derivatedValue"] for k in (9, 11, 13)] == [33 / 12, 66 / 12, 132 / 12]


def test_delta_t_zero_is_8200_when_a_derivative_is_due_and_not_latched():
    # §17.2, §17.3: deltaT 0 with fewer than five values: 16#7010; at the fifth: 16#8200,
    # error TRUE, derivatedValue keeps 0.0 (none yet); the value stays in the buffer, so with
    # deltaT 1 the sixth value gives the derivative of values 2 ... 6.
    calls = pulses([1.0, 2.0, 4.0, 8.0, 16.0], deltaT=0.0)
    calls += [{"insert": True, "value": 32.0, "deltaT": 1.0}]  # call 11
    rows = run(calls)
    assert column(rows, "status")[7:] == [NOT_ENOUGH_VALUES] * 2 + [ERR_DELTA_T] * 2 + [
        SUBSEQUENT_CALL
    ]
    assert column(rows, "error")[7:] == [False, False, True, True, False]
    assert column(rows, "derivatedValue")[8:] == [0.0, 0.0, 0.0, 66.0 / 12.0]


def test_delta_t_zero_keeps_the_last_derivative():
    calls = pulses([0.0, 1.0, 2.0, 3.0, 4.0])  # call 9: 1.0
    calls += [{"deltaT": -0.0, "insert": True, "value": 5.0}]  # call 11: -0.0 counts as 0
    rows = run(calls)
    assert rows[-1] == {"derivatedValue": 1.0, "error": True, "status": ERR_DELTA_T}


def test_delta_t_is_read_only_when_a_derivative_is_due():
    # deltaT 0 between edges changes nothing: the status of the last event holds.
    calls = pulses([0.0, 1.0, 2.0, 3.0, 4.0]) + [{"deltaT": 0.0}, {}]
    rows = run(calls)
    assert column(rows, "status")[-3:] == [SUBSEQUENT_CALL] * 3
    assert column(rows, "derivatedValue")[-3:] == [1.0] * 3


def test_negative_and_infinite_delta_t():
    # §17.4: a negative deltaT flips the sign; an infinite one gives 0.0.
    rows = run(pulses([0.0, 1.0, 2.0, 3.0, 4.0], deltaT=-0.5))
    assert rows[9]["derivatedValue"] == -2.0  # 12 / -6
    rows = run(pulses([0.0, 1.0, 2.0, 3.0, 4.0], deltaT=math.inf))
    assert rows[9]["derivatedValue"] == 0.0
    rows = run(pulses([0.0, 1.0, 2.0, 3.0, 4.0], deltaT=1e-310))
    assert rows[9]["derivatedValue"] == math.inf  # 12 / 1.2e-309 overflows


def test_disable_outputs_zero_and_a_new_enable_starts_empty():
    calls = pulses([0.0, 1.0, 2.0, 3.0, 4.0])  # calls 0-10, derivative 1.0 from call 9
    calls += [{"enable": False}, {"insert": True, "value": 100.0}, {"insert": False}]  # 11-13
    calls += [{"enable": True}]  # 14: 16#7001, empty buffer
    calls += pulses([0.0, 2.0, 4.0, 6.0, 8.0])[1:]  # edges in 15, 17, 19, 21, 23
    rows = run(calls)
    assert column(rows, "status")[11:15] == [NO_CALL] * 3 + [FIRST_CALL]
    assert column(rows, "derivatedValue")[10:15] == [1.0] + [0.0] * 4
    assert column(rows, "status")[15:23] == [NOT_ENOUGH_VALUES] * 8
    assert rows[23] == {"derivatedValue": 2.0, "error": False, "status": SUBSEQUENT_CALL}


def test_enable_and_insert_rising_together_read_in():
    rows = run([{"enable": True, "insert": True, "value": 4.0}])
    assert rows[0]["status"] == NOT_ENOUGH_VALUES


def test_insert_held_while_enable_rises_is_no_edge():
    rows = run(
        [{"enable": False, "insert": True}, {"enable": True, "value": 1.0}, {"insert": False}]
    )
    assert column(rows, "status") == [NO_CALL, FIRST_CALL, FIRST_CALL]


def test_infinities_give_nan():
    # y = 0, 0, 0, 0, Inf: -Inf; then 0, 0, 0, Inf, 1: 8 Inf - 1 = Inf; 0, 0, Inf, 1, 2 (the
    # middle has weight 0): (0 - 0 + 8 - 2) / 12 = 0.5; then 0, Inf, 1, 2, 3: -Inf;
    # Inf, 1, 2, 3, -Inf: Inf - 8 + 24 + Inf = Inf
    rows = run(pulses([0.0, 0.0, 0.0, 0.0, math.inf, 1.0, 2.0, 3.0, -math.inf]))
    got = [rows[k]["derivatedValue"] for k in (9, 11, 13, 15, 17)]
    assert got == [-math.inf, math.inf, 0.5, -math.inf, math.inf]
    rows = run(pulses([math.inf, 0.0, 0.0, 0.0, math.inf]))  # Inf - Inf: NaN
    nan = rows[9]["derivatedValue"]
    assert math.isnan(nan) and math.copysign(1.0, nan) == 1.0  # the positive quiet NaN


def test_nan_is_refused():
    s = Slave(BLOCK, {"cycleTime": CYCLE})
    assert status_of(s.fmu.setReal, [s.vr("value")], [math.nan]) == fmi2Error
    assert status_of(s.fmu.setReal, [s.vr("deltaT")], [math.nan]) == fmi2Error
    assert s.get(["deltaT"]) == {"deltaT": 1.0}
    s.free()


def test_the_change_to_8200_is_logged():
    s = Slave(BLOCK, {"cycleTime": CYCLE}, {"deltaT": 0.0})
    for v in range(5):
        s.set({"insert": True, "value": float(v)})
        s.step(CYCLE)
        s.set({"insert": False})
        s.step(CYCLE)
    assert s.outputs()["status"] == ERR_DELTA_T
    assert any("16#8200" in text and cat == "logStatusWarning" for _, cat, text in s.log)
    s.free()
