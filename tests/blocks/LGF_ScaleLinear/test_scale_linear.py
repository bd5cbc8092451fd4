"""LGF_ScaleLinear against the rules of docs/behaviour.md §19, with expectations traced by hand
from the block's original code (the arithmetic in the comments). The FMU is an FC: the outputs
after initialization are those of call 0, computed from the inputs set during initialization."""

import math
import struct

import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave

from .spec import START

BLOCK = "LGF_ScaleLinear"
OK, LIMITED_TO_YMIN, LIMITED_TO_YMAX, LIMITS_REVERSED = 0x0000, 0x6001, 0x6002, 0x8200
INF = math.inf

# A rising line through P1 (0, 0) and P2 (10, 100): slope (100 - 0) / (10 - 0) = 10.0 exactly.
LINE = {"x1": 0.0, "y1": 0.0, "x2": 10.0, "y2": 100.0, "yMin": 0.0, "yMax": 100.0}


def slave(**inputs):
    return Slave(BLOCK, {"cycleTime": 0.1}, inputs)


def result(y, status=OK, error=False):
    return {"y": y, "error": error, "status": status}


def scaled(**inputs):
    """The outputs of call 0 for these inputs (set during initialization)."""
    s = slave(**inputs)
    out = s.outputs()
    s.free()
    return out


def test_start_values_scale_half_of_the_analog_range_to_50():
    # §19.1: x 13824 on 0 ... 27648 -> 0 ... 100: slope (100.0 - 0.0) / (27648.0 - 0.0) =
    # 0.003616898148148148 (double); x - x1 = 13824.0; 0.003616898148148148 * 13824.0 = 50.0
    # after rounding; + y1 0.0 = 50.0; within 0 ... 100.
    s = Slave(BLOCK)
    assert s.get(list(START)) == START
    assert s.outputs() == result(50.0)
    assert [s.step(0.1) for _ in range(3)] == [result(50.0)] * 3  # constant inputs, constant y


@pytest.mark.parametrize(
    "x, y",
    [
        (2.5, 25.0),  # 10.0 * (2.5 - 0.0) + 0.0
        (0.0, 0.0),  # P1 itself: y1
        (10.0, 100.0),  # P2 itself: y2 (10.0 * 10.0 = 100.0, equal to yMax: not limited)
        (7.75, 77.5),  # 10.0 * 7.75 = 77.5 exactly
    ],
)
def test_points_on_the_line(x, y):
    assert scaled(x=x, **LINE) == result(y)


def test_below_ymin_is_limited_with_16_6001():
    # 10.0 * (-1.0 - 0.0) + 0.0 = -10.0 < yMin 0.0 -> yMin, warning 16#6001 = 24577, no error
    assert scaled(x=-1.0, **LINE) == result(0.0, LIMITED_TO_YMIN)


def test_above_ymax_is_limited_with_16_6002():
    # 10.0 * 11.0 = 110.0 > yMax 100.0 -> yMax, warning 16#6002 = 24578, no error
    assert scaled(x=11.0, **LINE) == result(100.0, LIMITED_TO_YMAX)


def test_warnings_are_not_logged():
    # §1.6: only a change to an error code (bit 15) is logged; 16#6001 and 16#6002 are warnings
    s = slave(x=-1.0, **LINE)
    s.set({"x": 11.0})
    s.step(0.1)
    assert not any("16#60" in text for _, _, text in s.log)


def test_limits_in_the_wrong_order_give_0_and_16_8200_then_recover():
    # §19.2 step 1: yMin 60 > yMax 50 -> y = 0.0, error TRUE, 16#8200 = 33280, nothing computed
    s = slave(x=2.5, **{**LINE, "yMin": 60.0, "yMax": 50.0})
    assert s.outputs() == result(0.0, LIMITS_REVERSED, True)
    assert any("16#8200" in text and category == "logStatusWarning" for _, category, text in s.log)
    assert s.step(0.1) == result(0.0, LIMITS_REVERSED, True)
    s.set({"yMin": 0.0})  # limits in order again: the next call computes 10.0 * 2.5 = 25.0
    assert s.step(0.1) == result(25.0)


def test_reversed_limits_win_over_equal_points_and_infinities():
    # step 1 comes first: neither x1 = x2 nor an infinite x changes y = 0.0
    inputs = {**LINE, "x2": 0.0, "y1": 5.0, "yMin": 1.0, "yMax": -1.0}
    assert scaled(x=INF, **inputs) == result(0.0, LIMITS_REVERSED, True)
    assert scaled(x=3.0, **{**LINE, "yMin": INF, "yMax": -INF}) == result(
        0.0, LIMITS_REVERSED, True
    )


def test_equal_limits_fix_y():
    # yMin = yMax = 5.0: 10.0 * 0.2 = 2.0 < 5 -> 5.0 (16#6001); 10.0 * 0.5 = 5.0 -> 5.0 (OK);
    # 10.0 * 0.9 = 9.0 > 5 -> 5.0 (16#6002)
    inputs = {**LINE, "yMin": 5.0, "yMax": 5.0}
    assert scaled(x=0.2, **inputs) == result(5.0, LIMITED_TO_YMIN)
    assert scaled(x=0.5, **inputs) == result(5.0)
    assert scaled(x=0.9, **inputs) == result(5.0, LIMITED_TO_YMAX)


def test_equal_x_coordinates_give_y1_still_limited():
    # §19.2 step 2: |x1 - x2| = 0 <= 1.0E-06 * 3.0 -> y = y1, whatever x; then step 3 limits it
    points = {"x1": 3.0, "x2": 3.0, "y2": 100.0, "yMin": 0.0, "yMax": 100.0}
    assert scaled(x=1e6, y1=42.0, **points) == result(42.0)
    assert scaled(x=-7.0, y1=150.0, **points) == result(100.0, LIMITED_TO_YMAX)
    assert scaled(x=-7.0, y1=-0.5, **points) == result(0.0, LIMITED_TO_YMIN)


@pytest.mark.parametrize(
    "x1, x2, y2, x, y",
    [
        # §19.2 step 2, the original's test: "the same x" is |x1 - x2| <= PRECISION * |x1|,
        # relative to x1, the limit included; then y = y1 = 7.0, else the line.
        # The example: |1e7 - 10000001| = 1 <= 1e-6 * 1e7 = 10.0 (the double product
        # rounds to 10.0 exactly) -> y1. The former absolute test (1 > 1e-6) gave the line, 8.0.
        (1e7, 1e7 + 1, 8.0, 1e7 + 1, 7.0),
        # the limit included: |-10| = 10 <= 10.0 -> y1
        (1e7, 1e7 + 10, 17.0, 1e7 + 5, 7.0),
        # beyond it: 11 > 10.0 -> the line: (18 - 7) / 11 = 1.0; * (x - x1) 5.0 = 5.0; + 7 = 12.0
        (1e7, 1e7 + 11, 18.0, 1e7 + 5, 12.0),
        # relative to x1, not x2: x1 9999990: 1e-6 * 9999990 = 9.99999 < 10 -> the line,
        # (17 - 7) / 10 = 1.0; * 5.0 + 7 = 12.0; the same points swapped: x1 1e7 -> 10 <= 10.0
        (9999990.0, 1e7, 17.0, 9999995.0, 12.0),
        (1e7, 9999990.0, 17.0, 9999995.0, 7.0),
        # the example: x1 = 0 makes the tolerance 0: |0 - 1e-7| = 1e-7 > 0 -> the line:
        # 1.0 / 1e-7 = 1e7 (the quotient of the doubles rounds to 1e7 exactly); * (1e-7 - 0) =
        # 0.99999999999999995 as a real number, rounded to 1.0; + 7 = 8.0 (the absolute test: y1)
        (0.0, 1e-7, 8.0, 1e-7, 8.0),
        # the same with 2^-20 = 9.5367431640625e-07: slope 2^20, * 2^-20 = 1.0, + 7 = 8.0
        (0.0, 2.0**-20, 8.0, 2.0**-20, 8.0),
        # |0 - 1e-6| > 0: the line, 1.0 / 1e-6 = 1e6 (rounded exactly), * 2^-20 =
        # 0.95367431640625 exactly, + 7 = 7.95367431640625
        (0.0, 1e-6, 8.0, 2.0**-20, 7.95367431640625),
        # x1 = x2 = 0 (or -0.0 and +0.0): |0| <= 0 -> y1
        (0.0, 0.0, 8.0, 5.0, 7.0),
        (-0.0, 0.0, 8.0, 5.0, 7.0),
        # x1 = +-Inf: |x1 - x2| = Inf <= 1e-6 * Inf = Inf -> y1 (x2 finite or the other infinity)
        (INF, 5.0, 8.0, 3.0, 7.0),
        (-INF, 5.0, 8.0, 3.0, 7.0),
        (-INF, INF, 8.0, 3.0, 7.0),
        # x2 = +Inf, x1 finite: Inf <= 5e-6 is false -> the line: 1.0 / (Inf - 5) = 0.0;
        # * (3 - 5) = -0.0; + 7 = 7.0
        (5.0, INF, 8.0, 3.0, 7.0),
    ],
)
def test_the_same_x_is_relative_to_x1(x1, x2, y2, x, y):
    inputs = {"x1": x1, "y1": 7.0, "x2": x2, "y2": y2, "yMin": -100.0, "yMax": 100.0}
    assert scaled(x=x, **inputs) == result(y)


def test_the_same_x_gives_y1_still_limited_at_infinite_x1():
    # x1 = +Inf takes y1 = 150.0 (step 2), then step 3 limits it to yMax 100.0 (16#6002)
    inputs = {"x1": INF, "y1": 150.0, "x2": 0.0, "y2": 0.0, "yMin": 0.0, "yMax": 100.0}
    assert scaled(x=1.0, **inputs) == result(100.0, LIMITED_TO_YMAX)
    # x = x1 = +Inf with x2 = 10 would make x - x1 NaN on the line, but x1 = +Inf takes y1 = 0.0
    # before (the former absolute test gave NaN here)
    assert scaled(**{**LINE, "x": INF, "x1": INF}) == result(0.0)


def test_falling_line_with_points_in_either_order():
    # P1 (4, 100), P2 (20, 0): slope (0 - 100) / (20 - 4) = -6.25; x 12: -6.25 * 8 = -50.0;
    # + 100 = 50.0. x 0: -6.25 * -4 = 25.0; + 100 = 125.0 > 90 -> 90.0 (16#6002).
    # x 24: -6.25 * 20 = -125.0; + 100 = -25.0 < 10 -> 10.0 (16#6001).
    falling = {"x1": 4.0, "y1": 100.0, "x2": 20.0, "y2": 0.0, "yMin": 10.0, "yMax": 90.0}
    assert scaled(x=12.0, **falling) == result(50.0)
    assert scaled(x=0.0, **falling) == result(90.0, LIMITED_TO_YMAX)
    assert scaled(x=24.0, **falling) == result(10.0, LIMITED_TO_YMIN)
    # P1 and P2 swapped: slope (100 - 0) / (4 - 20) = -6.25; x 12: -6.25 * (12 - 20) = 50.0; + 0
    swapped = {"x1": 20.0, "y1": 0.0, "x2": 4.0, "y2": 100.0, "yMin": 10.0, "yMax": 90.0}
    assert scaled(x=12.0, **swapped) == result(50.0)


def test_order_of_operations_slope_first():
    # §19.2: ((y2 - y1) / (x2 - x1)) * (x - x1) + y1. With P1 (0, 0), P2 (3, 0.3), x 5:
    # 0.3 / 3.0 = 0.09999999999999999 (double), * 5.0 = 0.49999999999999994. Multiplying first,
    # (0.3 * 5.0) / 3.0, would give 0.5.
    inputs = {"x1": 0.0, "y1": 0.0, "x2": 3.0, "y2": 0.3, "yMin": -1.0, "yMax": 1.0}
    assert scaled(x=5.0, **inputs) == result(0.49999999999999994)
    # y1 is added last: P1 (1, 0.25), P2 (4, 0.55): 0.55 - 0.25 = 0.30000000000000004;
    # / 3.0 = 0.10000000000000002; x 6: * (6 - 1) = 0.5000000000000001; + 0.25 = 0.7500000000000001
    inputs = {"x1": 1.0, "y1": 0.25, "x2": 4.0, "y2": 0.55, "yMin": -1.0, "yMax": 1.0}
    assert scaled(x=6.0, **inputs) == result(0.7500000000000001)


def test_infinite_limits_leave_a_side_open():
    open_line = {**LINE, "yMin": -INF, "yMax": INF}
    assert scaled(x=-1e300, **open_line) == result(-1e301)  # 10.0 * -1e300, no limit
    assert scaled(x=1e308, **open_line) == result(INF)  # 10.0 * 1e308 overflows to +Inf
    assert scaled(x=INF, **open_line) == result(INF)  # 10.0 * inf = inf, not limited
    assert scaled(x=-INF, **LINE) == result(0.0, LIMITED_TO_YMIN)  # -inf < 0.0


def quiet_nan_bits(value):
    return struct.pack(">d", value).hex()


@pytest.mark.parametrize(
    "inputs",
    [
        # x1 - x2 = inf - inf = NaN; NaN <= 1e-6 * inf is false: the line, (y2 - y1) / NaN
        {"x1": INF, "x2": INF},
        {"x1": -INF, "x2": -INF},
        {"y1": INF, "y2": INF},  # y2 - y1 = NaN
        {"y2": INF, "y1": 0.0, "x": 0.0},  # slope inf, * (0 - 0) = inf * 0 = NaN
    ],
)
def test_nan_from_infinities_is_output_unlimited_with_status_0(inputs):
    # §19.3: a NaN y is neither < yMin nor > yMax: output as the positive quiet NaN, status 0
    out = scaled(**{**LINE, "x": 5.0, **inputs})
    assert math.isnan(out["y"]) and quiet_nan_bits(out["y"]) == "7ff8000000000000"
    assert (out["error"], out["status"]) == (False, OK)


def test_nan_input_is_refused_and_not_applied():
    s = slave(x=2.5, **LINE)
    assert s.status_of(s.fmu.setReal, [s.vr("x")], [math.nan]) == fmi2Error
    assert s.get(["x"]) == {"x": 2.5}
    assert s.step(0.1) == result(25.0)


def test_an_input_reaches_y_at_the_next_call_of_the_step():
    # §1.3: an input set at communication point t reaches the calls in (t, t + h]
    s = slave(x=2.5, **LINE)
    s.set({"x": 4.0})
    assert s.outputs() == result(25.0)  # no call has seen x = 4.0 yet
    assert s.step(0.05) == result(25.0)  # no call in (0, 0.05]
    assert s.step(0.05) == result(40.0)  # the call at 0.1: 10.0 * 4.0


def test_model_exchange_computes_at_the_event_of_each_call():
    # §1.11, §19.3: an input set in event mode at the time of call k reaches call k; between
    # calls y keeps the value of the last call
    s = Slave(BLOCK, {"cycleTime": 0.1}, {"x": 2.5, **LINE}, model_exchange=True)
    fmu = s.fmu
    fmu.newDiscreteStates()
    fmu.enterContinuousTimeMode()
    assert s.outputs() == result(25.0)
    fmu.setTime(0.05)
    s.set({"x": 6.0})  # a Real set in continuous-time mode reaches no call yet
    assert s.outputs() == result(25.0)
    assert s.event(0.1, {"x": 7.0}) == result(70.0)  # call 1 at t = 0.1 with x = 7.0
