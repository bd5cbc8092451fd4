"""Hand-traced tests of the ScaleLinear model against the original block's logic, without any
FMU. An FC: each call stands alone (cycle 0.1 s, calls numbered from 0)."""

import math

import pytest

from .model import (
    PRECISION,
    STATUS_LIMITED_HIGH,
    STATUS_LIMITED_LOW,
    STATUS_LIMITS,
    STATUS_OK,
    ScaleLinear,
)

INF = math.inf
START = {"x": 13824.0, "x1": 0.0, "y1": 0.0, "x2": 27648.0, "y2": 100.0, "yMin": 0.0, "yMax": 100.0}
FREE = {"yMin": -INF, "yMax": INF}


def call(**changes):
    return ScaleLinear(100_000).call(0, {**START, **changes})


def ok(y):
    return {"y": y, "error": False, "status": STATUS_OK}


def test_status_codes():
    assert (STATUS_OK, STATUS_LIMITED_LOW, STATUS_LIMITED_HIGH, STATUS_LIMITS) == (
        0,
        24577,
        24578,
        33280,
    )
    assert PRECISION == 1.0e-06


def test_start_values_give_half_scale():
    # (100 - 0) / (27648 - 0) = 0.003616898148148148; * (13824 - 0) = 50.0; + 0.0 = 50.0
    assert call() == ok(50.0)


def test_relative_same_x_takes_y1():
    # x1 = 1e7, x2 = x = 1e7 + 1: |x1 - x2| = 1 <= 1e-6 * 1e7 = 10 -> y1 (here 7.0),
    # although the line through (1e7, 7) and (1e7 + 1, 9) would give 9 at x
    o = call(x=1e7 + 1, x1=1e7, y1=7.0, x2=1e7 + 1, y2=9.0, **FREE)
    assert o == ok(7.0)


def test_relative_tolerance_is_zero_at_x1_zero():
    # x1 = 0, x2 = x = 1e-7: |0 - 1e-7| = 1e-7 <= 1e-6 * 0 = 0 is false -> the line:
    # (100 - 0) / (1e-7 - 0) = 1e9 (as a double: 100.0/1e-7), * (1e-7 - 0), + 0 -> 100.0
    o = call(x=1e-7, x1=0.0, y1=0.0, x2=1e-7, y2=100.0, **FREE)
    assert o == ok((100.0 / 1e-7) * 1e-7 + 0.0)
    assert o["y"] == 100.0
    # x1 = x2 = 0 exactly: |0| <= 0 -> y1
    assert call(x=5.0, x1=0.0, y1=40.0, x2=0.0, y2=90.0) == ok(40.0)


def test_tolerance_limit_included():
    # x1 = 1e6: 1e-6 * 1e6 = 1.0 exactly; x2 = 1e6 + 1: |-1| = 1 <= 1 -> y1
    assert 1e-6 * 1e6 == 1.0
    assert call(x=3.0, x1=1e6, y1=40.0, x2=1e6 + 1, y2=90.0) == ok(40.0)
    # x2 = 1e6 + 1.5: 1.5 > 1 -> the line: (90 - 40) / 1.5 = 33.333333333333336,
    # * (1e6 + 1.5 - 1e6) = 1.5 -> 50.00000000000001? computed step by step, + 40
    o = call(x=1e6 + 1.5, x1=1e6, y1=40.0, x2=1e6 + 1.5, y2=90.0, **FREE)
    m = (90.0 - 40.0) / ((1e6 + 1.5) - 1e6)
    assert o == ok(m * ((1e6 + 1.5) - 1e6) + 40.0)


def test_absolute_1e6_is_not_the_test():
    # x1 = 0.1, x2 = 0.1 + 5e-7: an absolute tolerance of 1e-6 would take y1; the original's is
    # 1e-6 * 0.1 = 1e-7 here, and 5e-7 is beyond it -> the line, which gives y2 at x = x2
    x2 = 0.1 + 5e-7
    o = call(x=x2, x1=0.1, y1=1.0, x2=x2, y2=2.0, **FREE)
    m = (2.0 - 1.0) / (x2 - 0.1)
    assert o == ok(m * (x2 - 0.1) + 1.0)
    assert abs(o["y"] - 2.0) < 1e-9


@pytest.mark.parametrize("x1", [INF, -INF])
def test_infinite_x1_takes_y1(x1):
    # |Inf - x2| = Inf <= 1e-6 * Inf = Inf -> y1, for every finite x2
    assert call(x=3.0, x1=x1, y1=40.0, x2=5.0, y2=90.0) == ok(40.0)
    # and y1 is still clipped: 150 > yMax 100
    assert call(x1=x1, y1=150.0) == {"y": 100.0, "error": False, "status": STATUS_LIMITED_HIGH}


def test_same_infinity_for_x1_and_x2_is_nan():
    # x1 = x2 = Inf: Inf - Inf = NaN, NaN <= Inf false -> the line, (100 - 0) / NaN = NaN;
    # NaN is neither < yMin nor > yMax: output NaN (positive quiet), 16#0000
    o = call(x1=INF, x2=INF)
    assert math.isnan(o["y"]) and math.copysign(1.0, o["y"]) == 1.0
    assert (o["error"], o["status"]) == (False, STATUS_OK)


def test_operation_order_of_the_line():
    # ((y2 - y1) / (x2 - x1)) * (x - x1) + y1, left to right, each rounded:
    # x1 0.1, y1 0.2, x2 0.7, y2 0.3, x 0.4
    m = (0.3 - 0.2) / (0.7 - 0.1)
    y = m * (0.4 - 0.1)
    y = y + 0.2
    assert call(x=0.4, x1=0.1, y1=0.2, x2=0.7, y2=0.3, **FREE) == ok(y)


def test_points_in_either_order():
    # P1 (10, 0), P2 (0, 100), x 2.5: m = 100 / -10 = -10, -10 * (2.5 - 10) = 75, + 0 = 75
    assert call(x=2.5, x1=10.0, y1=0.0, x2=0.0, y2=100.0) == ok(75.0)


def test_clip_low_and_high_strict():
    # x -13824 -> -50 < 0 -> 0.0, 16#6001; x 41472 -> 150 > 100 -> 100.0, 16#6002
    assert call(x=-13824.0) == {"y": 0.0, "error": False, "status": STATUS_LIMITED_LOW}
    assert call(x=41472.0) == {"y": 100.0, "error": False, "status": STATUS_LIMITED_HIGH}
    # on a limit is not limited
    assert call(x=27648.0) == ok(100.0)
    assert call(x=0.0) == ok(0.0)


def test_equal_limits():
    lim = {"yMin": 30.0, "yMax": 30.0}
    assert call(x=0.0, **lim) == {"y": 30.0, "error": False, "status": STATUS_LIMITED_LOW}
    assert call(x=27648.0, **lim) == {"y": 30.0, "error": False, "status": STATUS_LIMITED_HIGH}
    # P1 (0, 0), P2 (10, 100), x 3: 10 * 3 = 30 = both limits -> 16#0000
    assert call(x=3.0, x1=0.0, y1=0.0, x2=10.0, y2=100.0, **lim) == ok(30.0)


def test_limits_in_wrong_order_win_over_everything():
    assert call(yMin=10.0, yMax=5.0) == {"y": 0.0, "error": True, "status": STATUS_LIMITS}
    assert call(x1=INF, x2=INF, yMin=INF, yMax=-INF) == {
        "y": 0.0,
        "error": True,
        "status": STATUS_LIMITS,
    }


def test_fc_has_no_memory():
    b = ScaleLinear(100_000)
    assert b.call(0, {**START, "yMin": 1.0, "yMax": 0.0})["status"] == STATUS_LIMITS
    assert b.call(100_000, START) == ok(50.0)


def test_infinite_limits_and_infinite_y():
    assert call(x=-27648.0, yMin=-INF) == ok(-100.0)
    assert call(x=55296.0, yMax=INF) == ok(200.0)
    # x = +Inf on a rising line: Inf, clipped to yMax; with yMax = +Inf output +Inf
    assert call(x=INF) == {"y": 100.0, "error": False, "status": STATUS_LIMITED_HIGH}
    assert call(x=-INF) == {"y": 0.0, "error": False, "status": STATUS_LIMITED_LOW}
    assert call(x=INF, yMax=INF) == ok(INF)


@pytest.mark.parametrize(
    "changes",
    [
        {"y1": -INF, "y2": INF, "x": 0.0},  # m = Inf / 27648 = Inf, Inf * (0 - 0) = NaN
        {"y1": INF, "y2": INF},  # Inf - Inf = NaN
        {"x1": 0.0, "x2": INF, "x": INF},  # |0 - Inf| <= 0 false; 100 / Inf = 0, 0 * Inf = NaN
        {"y1": INF, "y2": 0.0, "x": 2.0 * 27648.0},  # -Inf * 27648 = -Inf, + Inf = NaN
    ],
)
def test_nan_from_infinities_is_output_with_status_0(changes):
    o = call(**changes)
    assert math.isnan(o["y"]) and math.copysign(1.0, o["y"]) == 1.0
    assert o["error"] is False and o["status"] == STATUS_OK


def test_outputs_are_exactly_the_interface_names():
    assert set(call()) == {"y", "error", "status"}
