"""Hand-traced tests of the ScaleLinear model (docs/behaviour.md §19), without any FMU."""

import math

import pytest

from .model import (
    STATUS_LIMITED_HIGH,
    STATUS_LIMITED_LOW,
    STATUS_LIMITS,
    STATUS_OK,
    ScaleLinear,
)

INF = math.inf
START = {"x": 13824.0, "x1": 0.0, "y1": 0.0, "x2": 27648.0, "y2": 100.0, "yMin": 0.0, "yMax": 100.0}


def call(**changes):
    return ScaleLinear(100_000).call(0, {**START, **changes})


def test_start_values_give_half_scale():
    # §19.1: (100 - 0)/(27648 - 0) = 0.003616898148148148; * (13824 - 0) = 50.0; + 0.0 = 50.0
    assert 100.0 / 27648.0 == 0.003616898148148148
    assert call() == {"y": 50.0, "error": False, "status": STATUS_OK}


def test_operation_order_of_step_2():
    # §19.2 step 2: s = y2 - y1; d = x2 - x1; m = s / d; y = m * (x - x1); y = y + y1.
    # x1 0.1, y1 0.2, x2 0.7, y2 0.3, x 0.4: s = 0.3 - 0.2 = 0.09999999999999998,
    # d = 0.7 - 0.1 = 0.6, m = s/d = 0.16666666666666663, x - x1 = 0.30000000000000004,
    # m*(x-x1) = 0.049999999999999996, + 0.2 = 0.25 (in doubles step by step).
    s = 0.3 - 0.2
    d = 0.7 - 0.1
    m = s / d
    y = m * (0.4 - 0.1)
    y = y + 0.2
    o = call(x=0.4, x1=0.1, y1=0.2, x2=0.7, y2=0.3, yMin=-INF, yMax=INF)
    assert o == {"y": y, "error": False, "status": STATUS_OK}
    # another order (x - x1) * s / d + y1 may differ in the last bit; the model keeps §19.2's
    assert o["y"] == (((0.3 - 0.2) / (0.7 - 0.1)) * (0.4 - 0.1)) + 0.2


def test_points_in_either_order():
    # §19.3: x2 < x1 is a line like any other: P1 (10, 0), P2 (0, 100), x 2.5:
    # s = 100, d = -10, m = -10, (2.5 - 10) = -7.5, -10 * -7.5 = 75, + 0 = 75
    assert call(x=2.5, x1=10.0, y1=0.0, x2=0.0, y2=100.0) == {
        "y": 75.0,
        "error": False,
        "status": STATUS_OK,
    }


def test_clip_low_and_high():
    # §19.2 step 3: x -13824 -> line -50.0 < yMin 0 -> 0.0, 16#6001;
    # x 41472 -> 150.0 > yMax 100 -> 100.0, 16#6002
    assert call(x=-13824.0) == {"y": 0.0, "error": False, "status": STATUS_LIMITED_LOW}
    assert call(x=41472.0) == {"y": 100.0, "error": False, "status": STATUS_LIMITED_HIGH}
    assert STATUS_LIMITED_LOW == 24577 and STATUS_LIMITED_HIGH == 24578


def test_exactly_on_a_limit_is_not_limited():
    # §19.2 step 3: y < yMin and y > yMax are strict: x 27648 -> 100.0 = yMax -> 16#0000
    assert call(x=27648.0) == {"y": 100.0, "error": False, "status": STATUS_OK}
    assert call(x=0.0) == {"y": 0.0, "error": False, "status": STATUS_OK}


def test_limits_in_wrong_order_win_over_everything():
    # §19.2 step 1: yMin 10 > yMax 5 -> y 0.0, error TRUE, 16#8200 (whatever the line gives)
    assert call(yMin=10.0, yMax=5.0) == {"y": 0.0, "error": True, "status": STATUS_LIMITS}
    assert call(x=INF, x1=INF, x2=INF, yMin=INF, yMax=-INF) == {
        "y": 0.0,
        "error": True,
        "status": STATUS_LIMITS,
    }
    assert STATUS_LIMITS == 33280


def test_fc_has_no_memory():
    # §19.3: after 16#8200 the next call with limits in order computes normally
    b = ScaleLinear(1000)
    assert b.call(0, {**START, "yMin": 1.0, "yMax": 0.0})["status"] == STATUS_LIMITS
    assert b.call(1000, START) == {"y": 50.0, "error": False, "status": STATUS_OK}


@pytest.mark.parametrize("x2", [0.0, 1e-6, -1e-6, 5e-7])
def test_same_x_within_precision_gives_y1(x2):
    # §19.2 step 2 / §19.5: |x2 - x1| <= 1.0E-06 (limit included) -> y = y1 = 40.0
    assert abs(x2 - 0.0) <= 1.0e-06
    assert call(x=7.0, x1=0.0, y1=40.0, x2=x2, y2=90.0) == {
        "y": 40.0,
        "error": False,
        "status": STATUS_OK,
    }


def test_just_beyond_precision_computes_the_line():
    # x2 = 1.0000000000000002e-06 > PRECISION: s = 1, d = x2, m = 1/d, x - x1 = 0 -> 0 + 0 = 0
    x2 = math.nextafter(1e-6, 1.0)
    o = call(x=0.0, x1=0.0, y1=0.0, x2=x2, y2=1.0, yMin=-INF, yMax=INF)
    assert o == {"y": 0.0, "error": False, "status": STATUS_OK}
    # and x = x2 gives (1/x2)*x2 + 0
    o = call(x=x2, x1=0.0, y1=0.0, x2=x2, y2=1.0, yMin=-INF, yMax=INF)
    assert o["y"] == (1.0 / x2) * x2


def test_same_x_clips_y1():
    # §19.3 / §19.5: x1 = x2, y1 = 150 outside 0 ... 100 -> 100.0 with 16#6002; y1 -5 -> 0, 6001
    assert call(x1=3.0, x2=3.0, y1=150.0) == {"y": 100.0, "error": False, "status": 0x6002}
    assert call(x1=3.0, x2=3.0, y1=-5.0) == {"y": 0.0, "error": False, "status": 0x6001}


def test_equal_limits():
    # §19.3: yMin = yMax = 30: every x gives 30; below 16#6001, above 16#6002, on it 16#0000
    # (the line y = x/276.48: x 8294.4 -> 30.000000000000004? computed exactly below)
    lim = {"yMin": 30.0, "yMax": 30.0}
    assert call(x=0.0, **lim) == {"y": 30.0, "error": False, "status": STATUS_LIMITED_LOW}
    assert call(x=27648.0, **lim) == {"y": 30.0, "error": False, "status": STATUS_LIMITED_HIGH}
    # a line that meets it exactly: P1 (0, 0), P2 (10, 100), x 3: m 10, 10*3 = 30.0
    o = call(x=3.0, x1=0.0, y1=0.0, x2=10.0, y2=100.0, **lim)
    assert o == {"y": 30.0, "error": False, "status": STATUS_OK}


def test_infinite_limits_disable_a_side():
    # §19.3: yMin -Inf never clips low, yMax +Inf never clips high
    assert call(x=-27648.0, yMin=-INF) == {"y": -100.0, "error": False, "status": STATUS_OK}
    assert call(x=55296.0, yMax=INF) == {"y": 200.0, "error": False, "status": STATUS_OK}


def test_infinite_y_is_clipped():
    # §19.3: x +Inf on a rising line: m*(Inf - 0) = Inf, + 0 = Inf > 100 -> 100.0, 16#6002
    assert call(x=INF) == {"y": 100.0, "error": False, "status": STATUS_LIMITED_HIGH}
    assert call(x=-INF) == {"y": 0.0, "error": False, "status": STATUS_LIMITED_LOW}
    # with yMax +Inf: y = +Inf, 16#0000
    assert call(x=INF, yMax=INF) == {"y": INF, "error": False, "status": STATUS_OK}


@pytest.mark.parametrize(
    "changes",
    [
        {"x1": INF, "x2": INF},  # x2 - x1 = Inf - Inf = NaN, NaN <= PRECISION false -> formula
        {"y1": -INF, "y2": INF, "x": 0.0},  # s = Inf, m = Inf, m*(0 - 0) = Inf*0 = NaN
        {"y1": INF, "y2": INF},  # s = Inf - Inf = NaN
        {"x1": 0.0, "x2": INF, "x": INF},  # d = Inf, m = 100/Inf = 0, 0 * (Inf - 0) = NaN
        {"y1": -INF, "y2": -INF, "x1": 0.0, "x2": 1.0, "x": 2.0},  # s NaN
        {"y1": INF, "y2": 0.0, "x": 2.0 * 27648.0},  # s -Inf, m -Inf, *27648*2 -Inf, +Inf: NaN
    ],
)
def test_nan_from_infinities_is_output_with_status_0(changes):
    # §19.3: a NaN y is neither < yMin nor > yMax: output NaN (positive quiet), 16#0000, FALSE
    o = call(**changes)
    assert math.isnan(o["y"]) and math.copysign(1.0, o["y"]) == 1.0
    assert o["error"] is False and o["status"] == STATUS_OK


def test_outputs_are_exactly_the_interface_names():
    # §19.1: outputs y, error, status
    assert set(call()) == {"y", "error", "status"}
