"""Hand-traced tests of the NonLinearInterpolation model against the original block's logic,
without any FMU. Calls are numbered from 0, cycle 0.1 s; the array's bounds are
0 ... numberOfSetpoints - 1."""

import math

import pytest

from src.blocks.LGF_NonLinearInterpolation.table import table

from .model import NonLinearInterpolation

INF = math.inf
CYCLE = 100_000


def inp(value=65.0, default=0.0, en=False, track=False, reset=False):
    return {
        "value": value,
        "defaultOutValue": default,
        "enDefaultOutValue": en,
        "track": track,
        "reset": reset,
    }


def line(x0, y0, x1, y1, v):
    """The original's formula: factor := (y1 - y0) / (x1 - x0);
    (factor * v) + (y0 - (factor * x0))."""
    f = (y1 - y0) / (x1 - x0)
    return (f * v) + (y0 - (f * x0))


def test_default_table_start_value():
    # statIndex 0 -> 1; 65 > 0 and > 20 -> 2; 65 > 20 and > 50 -> 3; 65 > 50, not > 80: end.
    # factor (90 - 30) / (80 - 50) = 2.0; 2.0 * 65 + (30 - 2.0 * 50) = 130 - 70 = 60.0
    b = NonLinearInterpolation(CYCLE)
    assert b.call(0, inp()) == {"outputValue": 60.0}
    assert b.statIndex == 3


@pytest.mark.parametrize(
    "v,seg,out",
    [(10.0, 1, 2.5), (35.0, 2, None), (65.0, 3, 60.0), (90.0, 4, 95.0), (-10.0, 1, -2.5),
     (150.0, 4, 125.0)],
)  # fmt: skip
def test_default_table_segments_and_extrapolation(v, seg, out):
    # below the table segment 1, above it segment 4 (the line continued)
    # v 10: 0.25 * 10 + (0 - 0) = 2.5; v 150: 0.5 * 150 + (90 - 40) = 125
    pts = [(0.0, 0.0), (20.0, 5.0), (50.0, 30.0), (80.0, 90.0), (100.0, 100.0)]
    b = NonLinearInterpolation(CYCLE)
    o = b.call(0, inp(v))["outputValue"]
    assert b.statIndex == seg
    (x0, y0), (x1, y1) = pts[seg - 1], pts[seg]
    assert o == line(x0, y0, x1, y1, v)
    if out is not None:
        assert o == out


def test_priority_default_then_track_then_reset():
    # call 0: 90 -> segment 4, 95.0
    # call 1: enDefaultOutValue with track and reset: the default 7.0; the index stays 4
    # call 2: reset and track, value 5: track wins -> 5.0; the index still 4
    # call 3: reset alone: 0.0 and the index back to 1
    # call 4: 90 again climbs from segment 1 to 4
    b = NonLinearInterpolation(CYCLE)
    assert b.call(0, inp(90.0)) == {"outputValue": 95.0}
    assert b.statIndex == 4
    assert b.call(1 * CYCLE, inp(90.0, default=7.0, en=True, track=True, reset=True)) == {
        "outputValue": 7.0
    }
    assert b.statIndex == 4
    assert b.call(2 * CYCLE, inp(5.0, track=True, reset=True)) == {"outputValue": 5.0}
    assert b.statIndex == 4
    assert b.call(3 * CYCLE, inp(5.0, default=7.0, reset=True)) == {"outputValue": 0.0}
    assert b.statIndex == 1
    assert b.call(4 * CYCLE, inp(90.0)) == {"outputValue": 95.0}
    assert b.statIndex == 4


def test_first_call_in_a_mode_validates_the_index():
    # the index check comes before the modes: 0 -> 1 even in a call that outputs the default
    b = NonLinearInterpolation(CYCLE)
    assert b.call(0, inp(5.0, default=3.0, en=True)) == {"outputValue": 3.0}
    assert b.statIndex == 1


def test_track_and_default_keep_the_segment():
    b = NonLinearInterpolation(CYCLE)
    b.call(0, inp(90.0))
    b.call(1 * CYCLE, inp(10.0, track=True))
    b.call(2 * CYCLE, inp(10.0, en=True))
    assert b.statIndex == 4
    b.call(3 * CYCLE, inp(10.0))  # the search goes down from 4 to 1
    assert b.statIndex == 1


def test_on_an_inner_point_the_search_steps_down():
    # Table (1.75, 0.0), (3.25, 1.1), (11.75, -0.6), v = 3.25 = x[1]:
    # segment 1: factor 1.1 / 1.5 = 0.7333333333333334, 2.3833333333333337 + (0.0 - 1.2833...)
    #   = 1.1000000000000003; segment 2 would give -0.65 + (1.1 + 0.65) = 1.1.
    # call 0 from the start: 3.25 > 1.75, not > 3.25: segment 1.
    # call 1: 8.0 -> segment 2.
    # call 2: 3.25 on segment 2: 3.25 <= x[1] = 3.25 and 2 > 1 -> down to segment 1.
    pts = [(1.75, 0.0), (3.25, 1.1), (11.75, -0.6)]
    assert line(1.75, 0.0, 3.25, 1.1, 3.25) == 1.1000000000000003
    assert line(3.25, 1.1, 11.75, -0.6, 3.25) == 1.1
    b = NonLinearInterpolation(CYCLE, **table(*pts))
    assert b.call(0, inp(3.25))["outputValue"] == 1.1000000000000003
    assert b.statIndex == 1
    b.call(1 * CYCLE, inp(8.0))
    assert b.statIndex == 2
    assert b.call(2 * CYCLE, inp(3.25))["outputValue"] == 1.1000000000000003
    assert b.statIndex == 1


def test_on_the_first_point_stays_on_segment_1():
    # v = x[0]: v <= x[0] but the index is already 1 (lower bound + 1): the search ends
    b = NonLinearInterpolation(CYCLE)
    b.call(0, inp(90.0))
    assert b.call(1 * CYCLE, inp(0.0)) == {"outputValue": 0.0}
    assert b.statIndex == 1


def test_search_moves_several_segments_in_one_call():
    pts = [(float(i), float(i * i)) for i in range(8)]  # 0, 1, 4, 9, ... 49
    b = NonLinearInterpolation(CYCLE, **table(*pts))
    assert b.call(0, inp(6.5))["outputValue"] == line(6.0, 36.0, 7.0, 49.0, 6.5) == 42.5
    assert b.statIndex == 7
    assert b.call(1 * CYCLE, inp(0.5))["outputValue"] == 0.5
    assert b.statIndex == 1


def test_only_the_first_n_entries_form_the_table():
    # n = 2 of the default table: segment (0, 0)-(20, 5) continued: 0.25 * 100 = 25
    b = NonLinearInterpolation(CYCLE, numberOfSetpoints=2)
    assert b.call(0, inp(100.0)) == {"outputValue": 25.0}


def test_table_change_takes_effect_next_call():
    b = NonLinearInterpolation(CYCLE)
    assert b.call(0, inp()) == {"outputValue": 60.0}
    b.set("setpoints[3].outputValue", 60.0)  # segment 50 ... 80: factor 1, 65 + (30 - 50) = 45
    assert b.call(1 * CYCLE, inp()) == {"outputValue": 45.0}


def test_index_beyond_the_upper_bound_restarts_at_1():
    b = NonLinearInterpolation(CYCLE)
    b.call(0, inp(90.0))
    b.n = 3  # as if the array were shorter: index 4 > upper bound 2 -> 1, then up to 2
    b.call(1 * CYCLE, inp(90.0))
    assert b.statIndex == 2


def test_infinities():
    # +Inf climbs to segment 4: 0.5 * Inf + (90 - 40) = Inf; -Inf stays on 1: -Inf
    b = NonLinearInterpolation(CYCLE)
    assert b.call(0, inp(INF)) == {"outputValue": INF}
    assert b.call(1 * CYCLE, inp(-INF)) == {"outputValue": -INF}
    # a flat segment: 0 * Inf = NaN, the positive quiet NaN
    flat = NonLinearInterpolation(CYCLE, **table((0.0, 1.0), (1.0, 1.0)))
    o = flat.call(0, inp(INF))["outputValue"]
    assert math.isnan(o) and math.copysign(1.0, o) == 1.0


def test_equal_input_values_divide_by_zero():
    # (0, 0), (0, 1), v 2: 1 / 0 = +Inf; Inf * 2 + (0 - Inf * 0) = Inf + NaN = NaN
    b = NonLinearInterpolation(CYCLE, **table((0.0, 0.0), (0.0, 1.0)))
    o = b.call(0, inp(2.0))["outputValue"]
    assert math.isnan(o) and math.copysign(1.0, o) == 1.0
    # 0 / 0: NaN
    b = NonLinearInterpolation(CYCLE, **table((5.0, 3.0), (5.0, 3.0)))
    assert math.isnan(b.call(0, inp(5.0))["outputValue"])


def test_table_out_of_order_is_searched_by_the_same_rules():
    # (0, 0), (10, 10), (5, 20), (20, 0):
    # call 0, v 7 from index 1: 7 > 0, not > 10: segment 1 -> 7.0
    # call 1, v 12: 12 > 0 and > 10 -> 2; 12 > 10 and > 5 -> 3; 12 > 5, not > 20: segment 3,
    #   factor -20 / 15 = -1.3333333333333333, -16 + (20 + 6.666...) = 10.666666666666664
    # call 2, v 7 on segment 3: 7 > 5, not > 20: stays on segment 3 -> 17.333333333333332
    # call 3, v 4: 4 <= 5 -> 2; 4 <= 10 -> 1; 4 > 0, not > 10: segment 1 -> 4.0
    pts = [(0.0, 0.0), (10.0, 10.0), (5.0, 20.0), (20.0, 0.0)]
    b = NonLinearInterpolation(CYCLE, **table(*pts))
    assert b.call(0, inp(7.0)) == {"outputValue": 7.0}
    assert b.call(1 * CYCLE, inp(12.0)) == {"outputValue": 10.666666666666664}
    assert b.statIndex == 3
    assert b.call(2 * CYCLE, inp(7.0)) == {"outputValue": 17.333333333333332}
    assert b.statIndex == 3
    assert b.call(3 * CYCLE, inp(4.0)) == {"outputValue": 4.0}
    assert b.statIndex == 1


def test_refused_numbers_of_setpoints():
    for n in (1, 65):
        with pytest.raises(ValueError):
            NonLinearInterpolation(CYCLE, numberOfSetpoints=n)
