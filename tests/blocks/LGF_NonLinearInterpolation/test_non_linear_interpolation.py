"""LGF_NonLinearInterpolation against the rules of docs/behaviour.md §20, with expectations
traced by hand from the block's original code. Where an expectation is not a round number, the
test writes the formula of §20.3 for the segment the search must stop at, in double precision as
the PLC's LREAL, so that the segment (not only the value) is checked: the two neighbouring
segments differ in the last bits on a point (§20.4). Where the segment the search keeps matters
(the mode priority, reset), a table out of order makes it visible: on an ascending table the
segment depends on the value alone (§20.3)."""

import math

import pytest
from fmpy.fmi2 import fmi2Error, fmi2OK

from src.blocks.LGF_NonLinearInterpolation.table import DEFAULT_TABLE, table
from tests import harness
from tests.harness import Slave, refused
from tests.setpoint_tables import (  # noqa: F401 (run here, on this block)
    test_number_of_setpoints_at_the_limits_is_accepted,
    test_number_of_setpoints_outside_2_to_64_is_refused,
)

BLOCK = "LGF_NonLinearInterpolation"


def line(x0, y0, x1, y1, v):
    """§20.3 step 2 on the segment (x0, y0) - (x1, y1), in exactly the order written there."""
    slope = (y1 - y0) / (x1 - x0)
    return slope * v + (y0 - slope * x0)


def slave(points=DEFAULT_TABLE, cycle=0.1, **inputs):
    return Slave(BLOCK, {"cycleTime": cycle, **table(*points)}, inputs)


def out(s):
    return s.get(["outputValue"])["outputValue"]


def at(s, **inputs):
    """Set inputs, run one call (one step of one cycle), return outputValue."""
    s.set(inputs)
    return s.step(0.1)["outputValue"]


# A table out of order, inputValues 0, 10, 5, 20: the segment the search stops at depends on the
# segment it starts from. Segment 1 (0,0)-(10,10): slope 1.0, v. Segment 2 (10,10)-(5,50):
# slope 40/-5 = -8.0, -8v + (10 + 80). Segment 3 (5,50)-(20,200): slope 150/15 = 10.0,
# 10v + (50 - 50) = 10v.
UNSORTED = [(0.0, 0.0), (10.0, 10.0), (5.0, 50.0), (20.0, 200.0)]


def on_segment_3():
    """value 30 from segment 1 (call 0): 30 > 0 and 30 > 10: up to 2; 30 > 10 and 30 > 5: up to
    3; 30 > 5 and 30 > 20 but 3 is the last segment: stop. 10 * 30 = 300.0."""
    s = slave(UNSORTED, value=30.0)
    assert out(s) == 300.0
    return s


# ---- start values (§20.1) ----


def test_start_values_give_60_at_once_and_hold_it():
    # default table (0,0) (20,5) (50,30) (80,90) (100,100), value 65: segment 3 (50 ... 80),
    # slope 60/30 = 2.0, 2.0*65 + (30 - 2.0*50) = 130 - 70 = 60.0, in every call.
    s = Slave(BLOCK)
    assert s.get(["numberOfSetpoints", "value"]) == {"numberOfSetpoints": 5, "value": 65.0}
    names = [f"setpoints[{i}].{m}" for i in range(6) for m in ("inputValue", "outputValue")]
    got = s.get(names)
    assert [(got[names[2 * i]], got[names[2 * i + 1]]) for i in range(6)] == [
        *DEFAULT_TABLE,
        (0.0, 0.0),
    ]
    assert [out(s)] + [s.step(0.1)["outputValue"] for _ in range(5)] == [60.0] * 6


# ---- the curve (§20.3) ----


@pytest.mark.parametrize(
    "value, expected",
    [
        (10.0, 2.5),  # segment 1: slope 5/20 = 0.25, 0.25*10 + (0 - 0) = 2.5
        (0.0, 0.0),  # the first point itself
        (35.0, 17.5),  # segment 2: slope 25/30 = 0.8333..., 29.1666... - 11.6666... = 17.5
        (65.0, 60.0),  # segment 3, as above
        (90.0, 95.0),  # segment 4: slope 10/20 = 0.5, 45 + (90 - 40) = 95
        (100.0, 100.0),  # the last point: 50 + 50
        (-10.0, -2.5),  # below the table: segment 1 continued, 0.25*-10 = -2.5
        (120.0, 110.0),  # above the table: segment 4 continued, 60 + 50 = 110
    ],
)
def test_points_lines_and_extrapolation_of_the_default_table(value, expected):
    s = slave(value=value)
    assert out(s) == expected


def test_segment_2_at_35_is_the_formula_bit_for_bit():
    s = slave(value=35.0)
    assert out(s) == line(20.0, 5.0, 50.0, 30.0, 35.0) == 17.5


def test_search_walks_both_ways_over_several_segments():
    # from segment 1 (first call, statIndex validated from 0 to 1) up to segment 4, then down to
    # segment 1 again, then below the table: one search per call, as many steps as needed.
    s = slave(value=95.0)
    assert out(s) == 97.5  # segment 4: 0.5*95 + 50 = 97.5
    assert at(s, value=5.0) == 1.25  # segment 1: 0.25*5 = 1.25
    assert at(s, value=-100.0) == -25.0  # segment 1 continued
    assert at(s, value=1000.0) == 550.0  # segment 4 continued: 500 + 50


# ---- on a point (§20.4) ----


def test_on_an_inner_point_the_search_uses_the_segment_ending_there():
    # v = 50 is the right end of segment 2 and the left end of segment 3.
    # Segment 2: slope 25/30 = 0.8333333333333334; 41.66666666666667 + (5 - 16.666666666666668)
    # = 30.000000000000004 (the rounding of the formula). Segment 3 would give 2.0*50 + (30 -
    # 100) = 30.0 exactly.
    seg2 = line(20.0, 5.0, 50.0, 30.0, 50.0)
    seg3 = line(50.0, 30.0, 80.0, 90.0, 50.0)
    assert (seg2, seg3) == (30.000000000000004, 30.0)

    s = slave(value=65.0)  # segment 3
    # from above: at segment 3, 50 <= x[2] = 50: down to 2; 50 > 20, 50 <= 50: stop
    assert at(s, value=50.0) == seg2
    assert at(s, value=10.0) == 2.5  # segment 1
    # from below: at 1, 50 > 0 and 50 > 20: up to 2; 50 > 20, 50 <= 50: stop
    assert at(s, value=50.0) == seg2
    assert at(s, value=95.0) == 97.5  # segment 4
    # from segment 4: 50 <= 80: down to 3; 50 <= 50: down to 2; stop
    assert at(s, value=50.0) == seg2


def test_the_first_and_last_points():
    s = slave(value=95.0)  # segment 4
    # 0 = x[0] from above: down to segment 1 (0 <= 80, 50, 20), then 0 <= x[0] at segment 1:
    # stop there: 0.25 * 0 + 0 = 0.0
    assert at(s, value=0.0) == 0.0
    # 100 = x[4] from below: up to segment 4 (100 > 20, 50, 80), 100 <= 100: stop: 50 + 50
    assert at(s, value=100.0) == 100.0


# ---- priority of the modes and reset (§20.2) ----


@pytest.mark.parametrize(
    "default, reset, track, expected",
    [
        (True, True, True, 7.5),  # pre-assignment first
        (True, True, False, 7.5),
        (True, False, False, 7.5),
        (False, True, True, 35.0),  # then tracking, before reset: the value itself
        (False, False, True, 35.0),
        (False, True, False, 0.0),  # then reset: 0.0
        (False, False, False, 17.5),  # then the curve
    ],
)
def test_priority_default_then_track_then_reset_then_curve(default, reset, track, expected):
    s = slave(value=35.0, defaultOutValue=7.5, enDefaultOutValue=default, reset=reset, track=track)
    assert out(s) == expected
    assert s.step(0.1)["outputValue"] == expected  # levels: the same in every call


def test_reset_with_track_outputs_the_value():
    # the example: track comes before reset, so value 5 gives 5.0, not 0.0
    s = slave(value=5.0, track=True, reset=True)
    assert out(s) == 5.0


def test_reset_restarts_the_search_at_segment_1():
    s = on_segment_3()
    # 7 from segment 3: 7 > x[2] = 5 and 7 <= 20: stays, 10 * 7 = 70.0
    assert at(s, value=7.0) == 70.0
    assert at(s, reset=True) == 0.0  # reset: output 0.0, statIndex := 1
    # 7 from segment 1: 7 > 0, 7 <= 10: stop, 7.0
    assert at(s, reset=False) == 7.0


def test_a_reset_under_the_pre_assignment_leaves_the_search():
    # §20.2: the pre-assignment ends the call before the reset: statIndex stays 3
    s = on_segment_3()
    assert at(s, enDefaultOutValue=True, defaultOutValue=1.5, reset=True, value=7.0) == 1.5
    assert at(s, enDefaultOutValue=False, reset=False) == 70.0  # still segment 3, not 7.0


def test_a_reset_under_tracking_leaves_the_search():
    # §20.2: tracking ends the call before the reset: value 5 gives 5.0 and statIndex stays 3
    s = on_segment_3()
    assert at(s, track=True, reset=True, value=5.0) == 5.0
    assert at(s, track=False, reset=False, value=7.0) == 70.0  # still segment 3, not 7.0


def test_track_and_pre_assignment_keep_the_segment():
    s = on_segment_3()
    assert at(s, track=True, value=7.0) == 7.0  # tracking: the value itself, no search
    assert at(s, track=False) == 70.0  # still segment 3
    s2 = on_segment_3()
    assert at(s2, enDefaultOutValue=True, defaultOutValue=-1.0, value=7.0) == -1.0
    assert at(s2, enDefaultOutValue=False) == 70.0


def test_reset_is_a_level():
    s = slave(value=35.0, reset=True)
    assert [out(s)] + [s.step(0.1)["outputValue"] for _ in range(3)] == [0.0] * 4
    assert at(s, reset=False) == 17.5


# ---- the table at run time (§20.1, §20.4) ----


def test_a_changed_table_takes_effect_at_the_next_call_without_reset():
    s = slave(value=65.0)
    s.set({"setpoints[3].outputValue": 60.0})  # tunable: segment 3 now (50,30) - (80,60)
    assert s.step(0.1)["outputValue"] == 45.0  # slope 1.0: 65 + (30 - 50) = 45
    s.set({"setpoints[2].inputValue": 70.0, "setpoints[2].outputValue": 50.0})
    # points 20 | 70 | 80: 65 now lies in segment 2 (20,5) - (70,50): the search steps down
    assert s.step(0.1)["outputValue"] == line(20.0, 5.0, 70.0, 50.0, 65.0)


def test_entries_beyond_number_of_setpoints_are_ignored():
    # 3 points; entries 3 ... 63 hold the start table's rest, (80,90) (100,100), and zeros
    s = slave([(0.0, 0.0), (10.0, 10.0), (20.0, 0.0)], value=30.0)
    assert out(s) == -10.0  # segment 2 continued: slope -1, -30 + (10 + 10) = -10


def test_two_points_are_one_straight_line():
    s = slave([(1.0, 3.0), (3.0, 7.0)], value=-1.0)  # slope 2: -2 + (3 - 2) = -1
    assert out(s) == -1.0
    assert at(s, value=10.0) == 21.0  # 20 + 1


def test_the_cycle_time_changes_nothing():
    assert out(slave(cycle=1e-6, value=35.0)) == out(slave(cycle=60.0, value=35.0)) == 17.5


# ---- tables the original does not support (§20.5) ----


def test_a_table_out_of_order_is_computed_by_the_search_of_the_original():
    # inputValues 0, 10, 5, 20 (not ascending), outputValues 0, 10, 20, 30.
    points = [(0.0, 0.0), (10.0, 10.0), (5.0, 20.0), (20.0, 30.0)]
    s = slave(points, value=7.0)
    # from segment 1: 7 > x[0] = 0, 7 <= x[1] = 10: stop at segment 1, slope 1: 7.0
    assert out(s) == 7.0
    # 25: 25 > 0, 25 > 10: up to 2; 25 > 10, 25 > 5: up to 3, the last; slope 10/15
    assert at(s, value=25.0) == line(5.0, 20.0, 20.0, 30.0, 25.0)
    # 7 from segment 3: 7 > x[2] = 5, 7 <= 20: stays on segment 3 (not the 7.0 of segment 1)
    assert at(s, value=7.0) == line(5.0, 20.0, 20.0, 30.0, 7.0) != 7.0
    # 5 from segment 3: 5 <= x[2] = 5: down to 2; 5 <= x[1] = 10: down to 1; 5 > 0, 5 <= 10:
    # stop at segment 1: 5.0 (keeping segment 3 on its point would give 20.0)
    assert at(s, value=5.0) == 5.0


def test_out_of_order_the_search_steps_up_only_above_both_points():
    # inputValues 10, 0, 20, outputValues 0, 10, 30. value 5 in call 0, from segment 1:
    # 5 > x[0] = 10 is false and segment 1 is the first: stop, although 5 > x[1] = 0.
    # Segment 1 (10,0)-(0,10): slope 10/-10 = -1.0, -5 + (0 + 10) = 5.0 (segment 2 would give
    # 15.0).
    s = slave([(10.0, 0.0), (0.0, 10.0), (20.0, 30.0)], value=5.0)
    assert out(s) == 5.0


def test_equal_input_values_divide_by_zero_to_nan():
    # points (0,0) (10,5) (10,8): 12 goes up to segment 2 (12 > 0, 12 > 10), the last, whose
    # slope is 3/0 = +Inf, so Inf*12 + (5 - Inf*10) = Inf - Inf = NaN, got as the positive quiet
    # NaN (§1.4).
    s = slave([(0.0, 0.0), (10.0, 5.0), (10.0, 8.0)], value=12.0)
    got = out(s)
    assert math.isnan(got) and math.copysign(1.0, got) == 1.0
    # 10 from segment 2: 10 <= x[1] = 10: down to segment 1; 10 > 0, 10 <= 10: stop: 0.5*10
    assert at(s, value=10.0) == 5.0
    assert at(s, value=5.0) == 2.5  # segment 1: 0.5*5


def test_infinite_values_follow_ieee():
    s = slave(value=math.inf)
    assert out(s) == math.inf  # segment 4 continued, slope 0.5 > 0
    assert at(s, value=-math.inf) == -math.inf  # segment 1 continued, slope 0.25
    flat = slave([(0.0, 1.0), (1.0, 1.0)], value=math.inf)
    got = out(flat)  # slope 0: 0*Inf = NaN
    assert math.isnan(got) and math.copysign(1.0, got) == 1.0


# ---- misuse (§1.7, §20.5) ----


@pytest.fixture
def initializing():
    yield from harness.initializing(BLOCK)


@pytest.mark.parametrize(
    "name", ["value", "defaultOutValue", "setpoints[0].inputValue", "setpoints[63].outputValue"]
)
def test_nan_is_refused(initializing, name):
    assert refused(initializing, initializing.fmu.setReal, name, math.nan)


def test_number_of_setpoints_is_fixed_the_table_tunable():
    s = slave(value=35.0)
    assert s.status_of(s.fmu.setInteger, [s.vr("numberOfSetpoints")], [3]) == fmi2Error
    assert s.status_of(s.fmu.setReal, [s.vr("setpoints[1].outputValue")], [6.0]) == fmi2OK
    assert s.step(0.1)["outputValue"] == line(20.0, 6.0, 50.0, 30.0, 35.0)
