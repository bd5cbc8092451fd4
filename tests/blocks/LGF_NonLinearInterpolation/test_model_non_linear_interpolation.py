"""Hand-traced tests of the NonLinearInterpolation model (docs/behaviour.md §20), without any
FMU."""

import math

import pytest

from .model import NonLinearInterpolation

INF = math.inf


def table(points):
    d = {"numberOfSetpoints": len(points)}
    for i, (x, y) in enumerate(points):
        d[f"setpoints[{i}].inputValue"] = x
        d[f"setpoints[{i}].outputValue"] = y
    return d


def inp(value=65.0, default=0.0, en=False, track=False, reset=False):
    return {
        "value": value,
        "defaultOutValue": default,
        "enDefaultOutValue": en,
        "track": track,
        "reset": reset,
    }


def line(x0, y0, x1, y1, v):
    """§20.3 step 3 in its order: slope := (y1 - y0)/(x1 - x0); slope*v + (y0 - slope*x0)."""
    slope = (y1 - y0) / (x1 - x0)
    return slope * v + (y0 - slope * x0)


def test_default_table_start_value():
    # §20.1: segment 50 ... 80: slope 60/30 = 2.0; 2.0*65 + (30 - 2.0*50) = 130 - 70 = 60.0
    b = NonLinearInterpolation(100_000)
    assert b.call(0, inp()) == {"outputValue": 60.0}
    assert b.statIndex == 3


@pytest.mark.parametrize(
    "v,seg",
    [(10.0, 1), (35.0, 2), (65.0, 3), (90.0, 4), (-10.0, 1), (150.0, 4)],
)
def test_default_table_segments_and_extrapolation(v, seg):
    # §20.3: below the table segment 1, above it segment n-1 (extrapolation)
    pts = [(0.0, 0.0), (20.0, 5.0), (50.0, 30.0), (80.0, 90.0), (100.0, 100.0)]
    b = NonLinearInterpolation(1000)
    o = b.call(0, inp(v))
    assert b.statIndex == seg
    (x0, y0), (x1, y1) = pts[seg - 1], pts[seg]
    assert o["outputValue"] == line(x0, y0, x1, y1, v)
    # e.g. v = 10: slope 0.25, 2.5 + (0 - 0) = 2.5; v = 150: slope 0.5, 75 + (90 - 40) = 125
    if v == 10.0:
        assert o["outputValue"] == 2.5
    if v == 150.0:
        assert o["outputValue"] == 125.0


def test_priority_default_reset_track_curve():
    # §20.2: default > reset > track > curve
    b = NonLinearInterpolation(1000)
    assert b.call(0, inp(65.0, default=7.0, en=True, track=True, reset=True)) == {
        "outputValue": 7.0
    }
    assert b.call(1000, inp(65.0, track=True, reset=True)) == {"outputValue": 0.0}
    assert b.call(2000, inp(65.0, track=True)) == {"outputValue": 65.0}
    assert b.call(3000, inp(65.0)) == {"outputValue": 60.0}


def test_reset_restarts_search_even_with_default():
    # §20.2 step 1: reset sets statIndex 1 whatever the other inputs are
    b = NonLinearInterpolation(1000)
    b.call(0, inp(90.0))
    assert b.statIndex == 4
    b.call(1000, inp(90.0, en=True, default=1.0, reset=True))
    assert b.statIndex == 1


def test_track_and_default_keep_the_segment():
    # §20.4: statIndex unchanged through track and enDefaultOutValue
    b = NonLinearInterpolation(1000)
    b.call(0, inp(90.0))
    b.call(1000, inp(10.0, track=True))
    b.call(2000, inp(10.0, en=True))
    assert b.statIndex == 4
    b.call(3000, inp(10.0))
    assert b.statIndex == 1


def test_hysteresis_on_an_inner_point():
    # §20.4: v = x[k] of an inner point: from above stays on segment k+1, from below on k.
    # Table (1.75, 0.0), (3.25, 1.1), (11.75, -0.6), v = 3.25:
    # segment 1: slope 1.1/1.5 = 0.7333333333333334, *3.25 = 2.3833333333333337,
    #   0.0 - slope*1.75 = -1.2833333333333334, sum 1.1000000000000003;
    # segment 2: slope -1.7/8.5 = -0.2, *3.25 = -0.65, 1.1 - (-0.2*3.25) = 1.75, sum 1.1
    pts = [(1.75, 0.0), (3.25, 1.1), (11.75, -0.6)]
    b = NonLinearInterpolation(1000, **table(pts))
    assert b.call(0, inp(3.25))["outputValue"] == 1.1000000000000003
    assert b.statIndex == 1
    b.call(1000, inp(8.0))
    assert b.statIndex == 2
    assert b.call(2000, inp(3.25))["outputValue"] == 1.1  # from above: segment 2
    assert b.statIndex == 2
    b.call(3000, inp(3.25, reset=True))  # reset: statIndex 1
    assert b.call(4000, inp(3.25))["outputValue"] == 1.1000000000000003
    assert line(1.75, 0.0, 3.25, 1.1, 3.25) == 1.1000000000000003
    assert line(3.25, 1.1, 11.75, -0.6, 3.25) == 1.1


def test_search_moves_several_segments_in_one_call():
    pts = [(float(i), float(i * i)) for i in range(8)]  # 0, 1, 4, 9, ... 49
    b = NonLinearInterpolation(1000, **table(pts))
    assert b.call(0, inp(6.5))["outputValue"] == line(6.0, 36.0, 7.0, 49.0, 6.5)  # 42.5
    assert b.statIndex == 7
    assert b.call(1000, inp(0.5))["outputValue"] == 0.5
    assert b.statIndex == 1


def test_only_the_first_n_entries_form_the_table():
    # §20.1: entries beyond numberOfSetpoints are ignored: n = 2 of the default table
    b = NonLinearInterpolation(1000, numberOfSetpoints=2)
    # segment (0,0)-(20,5) extrapolated: slope 0.25, 0.25*100 = 25
    assert b.call(0, inp(100.0)) == {"outputValue": 25.0}


def test_table_change_takes_effect_next_call():
    b = NonLinearInterpolation(1000)
    assert b.call(0, inp()) == {"outputValue": 60.0}
    b.set("setpoints[3].outputValue", 60.0)  # segment 50 ... 80: slope 1, 65 + (30 - 50) = 45
    assert b.call(1000, inp()) == {"outputValue": 45.0}


def test_statindex_validated_against_smaller_table():
    # §20.3 step 1: statIndex > n-1 (after a change of n it could be) -> 1
    b = NonLinearInterpolation(1000)
    b.call(0, inp(90.0))
    b.n = 3
    b.call(1000, inp(90.0))
    assert b.statIndex == 2


def test_infinities():
    # §20.4: +Inf on a rising last segment: +Inf; on a flat one slope 0 * Inf = NaN
    b = NonLinearInterpolation(1000)
    assert b.call(0, inp(INF)) == {"outputValue": INF}
    flat = NonLinearInterpolation(1000, **table([(0.0, 1.0), (1.0, 1.0)]))
    o = flat.call(0, inp(INF))["outputValue"]
    assert math.isnan(o) and math.copysign(1.0, o) == 1.0


def test_equal_input_values_divide_by_zero():
    # §20.5: two points with the same inputValue: (1 - 0)/(0) = +Inf; Inf*v + (0 - Inf*0) = NaN
    b = NonLinearInterpolation(1000, **table([(0.0, 0.0), (0.0, 1.0)]))
    o = b.call(0, inp(2.0))["outputValue"]
    assert math.isnan(o) and math.copysign(1.0, o) == 1.0
    # 0/0: NaN
    b = NonLinearInterpolation(1000, **table([(5.0, 3.0), (5.0, 3.0)]))
    assert math.isnan(b.call(0, inp(5.0))["outputValue"])


def test_unsorted_table_search_ends():
    # §20.5: an unsorted table is computed by the rules: (0,0), (10,10), (5,20), (20,0):
    # v 7 from statIndex 1: 7 > x[1]=10? no -> stays on segment 1: 7.0
    pts = [(0.0, 0.0), (10.0, 10.0), (5.0, 20.0), (20.0, 0.0)]
    b = NonLinearInterpolation(1000, **table(pts))
    assert b.call(0, inp(7.0)) == {"outputValue": 7.0}
    # v 12: 12 > 10 -> 2; 12 > x[2]=5 -> 3; at 3 (n-1), 12 < x[2]=5? no -> segment 3
    o = b.call(1000, inp(12.0))
    assert b.statIndex == 3 and o["outputValue"] == line(5.0, 20.0, 20.0, 0.0, 12.0)


def test_refused_numbers_of_setpoints():
    for n in (1, 65):
        with pytest.raises(ValueError):
            NonLinearInterpolation(1000, numberOfSetpoints=n)
