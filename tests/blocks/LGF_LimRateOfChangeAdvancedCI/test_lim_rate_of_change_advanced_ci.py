"""LGF_LimRateOfChangeAdvancedCI against the rules of docs/behaviour.md §21, with expectations
traced by hand through the block's original SCL (the reference for its behaviour). Most runs use
cycleTime 1 s (dt = 1.0) and rates that are exact in binary, so the expected values are exact."""

import math

import pytest
from fmpy.fmi2 import fmi2Error

from tests import harness
from tests.harness import Slave

BLOCK = "LGF_LimRateOfChangeAdvancedCI"
LIMITS = 0x8200  # 33280: setHighLim < setLowLim
RATE = 0x8202  # 33282: a negative rate
FLAGS = ("posUpRateLim", "posDownRateLim", "negUpRateLim", "negDownRateLim", "highLim", "lowLim")

# posUp 10, posDown 20, negUp 5, negDown 4 per s; limits -100 ... 100
BASE = {
    "autoValue": 0.0,
    "setPosUpRateLim": 10.0,
    "setPosDownRateLim": 20.0,
    "setNegUpRateLim": 5.0,
    "setNegDownRateLim": 4.0,
    "setHighLim": 100.0,
    "setLowLim": -100.0,
}

# every rate 0: the LGF defaults (§21.5)
RATES_ZERO = dict.fromkeys(
    ("setPosUpRateLim", "setPosDownRateLim", "setNegUpRateLim", "setNegDownRateLim"), 0.0
)


def slave(cycle=1.0, **inputs):
    return Slave(BLOCK, {"cycleTime": cycle}, {**BASE, **inputs})


def row(outputs):
    """(outputValue, the names of the flags that are TRUE)."""
    return outputs["outputValue"], {f for f in FLAGS if outputs[f]}


def now(s):
    return row(s.outputs())


def at(s, h=1.0, **inputs):
    s.set(inputs)
    return row(s.step(h))


# ---- start values (§21.1) ----


def test_start_values_ramp_to_the_high_limit():
    # autoValue 100, setPosUpRateLim 20 per s, cycle 0.1 s: +2.0 per call from the first call
    # (2.0 at t = 0). Call 39 (t = 3.9 s): c = 78 + 2 = 80 < 100, posUpRateLim; 80 >= 80:
    # highLim, and the step 80 - 78 = 2 is not < 2: the rate flag stays. From call 40 on: c = 82,
    # cut to 80, and the step 0 < 2 clears posUpRateLim (§21.2 step 5).
    s = Slave(BLOCK)
    assert s.get(["autoValue", "setPosUpRateLim", "setHighLim", "setLowLim"]) == {
        "autoValue": 100.0,
        "setPosUpRateLim": 20.0,
        "setHighLim": 80.0,
        "setLowLim": -80.0,
    }
    rows = [now(s)] + [row(s.step(0.1)) for _ in range(59)]
    assert [r[0] for r in rows] == [min(2.0 * (k + 1), 80.0) for k in range(60)]
    assert [r[1] for r in rows[:39]] == [{"posUpRateLim"}] * 39
    assert rows[39][1] == {"posUpRateLim", "highLim"}
    assert [r[1] for r in rows[40:]] == [{"highLim"}] * 20


# ---- the four ramps (§21.3) ----


def test_rising_in_the_positive_range_lands_exactly():
    s = slave(autoValue=25.0)  # from p = 0.0: the positive rising ramp, 10 per call
    assert [now(s), at(s), at(s), at(s)] == [
        (10.0, {"posUpRateLim"}),
        (20.0, {"posUpRateLim"}),
        (25.0, set()),  # c = 30 is not < 25: the target 25, not limited
        (25.0, set()),  # t = p
    ]


def test_falling_in_the_positive_range():
    s = slave(autoValue=25.0)
    at(s), at(s)  # 25.0
    assert [at(s, autoValue=3.0), at(s)] == [(5.0, {"posDownRateLim"}), (3.0, set())]


def test_falling_in_the_negative_range_from_zero():
    # p = 0 is in the positive range and falls towards t < 0: the time to zero z = 0 / 20 = 0,
    # so the whole call on the negative ramp of rising magnitude, 5 per call, then from p < 0 on
    s = slave(autoValue=-12.0)
    assert [now(s), at(s), at(s)] == [
        (-5.0, {"negUpRateLim"}),
        (-10.0, {"negUpRateLim"}),
        (-12.0, set()),
    ]


def test_rising_in_the_negative_range():
    s = slave(autoValue=-12.0)
    at(s), at(s)  # -12.0
    assert [at(s, autoValue=-3.0), at(s), at(s)] == [
        (-8.0, {"negDownRateLim"}),  # 4 per call
        (-4.0, {"negDownRateLim"}),
        (-3.0, set()),
    ]


def test_crossing_zero_downwards_spends_the_rest_of_the_cycle_on_the_negative_ramp():
    s = slave(autoValue=25.0)
    at(s), at(s)  # 25.0
    assert at(s, autoValue=-100.0) == (5.0, {"posDownRateLim"})  # 25 - 20
    # (25 before: z = 25 / 20 = 1.25 > 1, so 25 - 1 * 20 = 5 with posDownRateLim.) Now t < 0 and
    # z = 5 / 20 = 0.25 <= 1: c = -(1 - 0.25) * 5 = -3.75; only the second ramp's flag
    assert at(s) == (-3.75, {"negUpRateLim"})
    assert at(s) == (-8.75, {"negUpRateLim"})  # p < 0 now: -3.75 - 5


def test_crossing_zero_upwards_spends_the_rest_of_the_cycle_on_the_positive_ramp():
    s = slave(autoValue=100.0, defaultOutValue=-6.0, enDefaultOutValue=True)
    assert now(s) == (-6.0, set())
    # t > 0: z = 6 / 4 = 1.5 > 1, so -6 + 1 * 4 = -2 with negDownRateLim
    assert at(s, enDefaultOutValue=False) == (-2.0, {"negDownRateLim"})
    # z = 2 / 4 = 0.5 <= 1: c = (1 - 0.5) * 10 = 5 < 100, posUpRateLim
    assert at(s) == (5.0, {"posUpRateLim"})
    assert at(s) == (15.0, {"posUpRateLim"})


def test_a_crossing_that_reaches_the_target_on_the_other_side():
    s = slave(autoValue=5.0)
    assert now(s) == (5.0, set())
    # t = -1 < 0: z = 5 / 20 = 0.25 <= 1, c = -(1 - 0.25) * 5 = -3.75; -1 < -3.75 is FALSE:
    # the target, not limited
    assert at(s, autoValue=-1.0) == (-1.0, set())


def test_crossings_and_non_crossings_near_zero():
    s = slave(autoValue=5.0)
    # t = 0 is not < 0: c = 5 - 20 = -15, and 0 < -15 is FALSE: the target 0, not limited
    assert at(s, autoValue=0.0) == (0.0, set())
    s2 = slave(autoValue=100.0, defaultOutValue=-2.0, enDefaultOutValue=True)
    # t = 0.5 > 0: z = 2 / 4 = 0.5 <= 1, c = (1 - 0.5) * 10 = 5; 0.5 > 5 is FALSE: the
    # target, not limited
    assert at(s2, enDefaultOutValue=False, autoValue=0.5) == (0.5, set())
    s3 = slave(autoValue=100.0, defaultOutValue=-2.0, enDefaultOutValue=True)
    # t = 0.0 is not > 0: within the negative range, c = -2 + 4 = 2; 0 > 2 is FALSE: 0
    assert at(s3, enDefaultOutValue=False, autoValue=0.0) == (0.0, set())


def test_zero_belongs_to_the_positive_range():
    # §21.3: the original tests p < 0 for the negative range, so p = 0.0 falls on the positive
    # range's down-rate. setPosDownRateLim 0 from 0 towards -10: the jump of a down-rate 0 to
    # 0.0 across the sign, with its flag, in every call.
    s = slave(autoValue=-10.0, setPosDownRateLim=0.0)
    assert [now(s), at(s)] == [(0.0, {"posDownRateLim"})] * 2
    # from 0 with setPosUpRateLim 0 towards 10: c = 0 + 0 = 0 < 10, limited by rate 0
    s2 = slave(autoValue=10.0, setPosUpRateLim=0.0)
    assert [now(s2), at(s2)] == [(0.0, {"posUpRateLim"})] * 2


def test_minus_zero_belongs_to_the_positive_range_too():
    # -0.0 < 0 is FALSE: p = -0.0 (tracked) takes the positive range's ramps
    s = slave(track=True, autoValue=-0.0, setPosDownRateLim=0.0, setNegDownRateLim=0.0)
    out, flags = now(s)
    assert (out, math.copysign(1.0, out), flags) == (0.0, -1.0, set())
    # towards -10 with setPosDownRateLim 0: the jump to +0.0 (not the negative ramp to -5)
    out, flags = at(s, track=False, autoValue=-10.0)
    assert (out, math.copysign(1.0, out), flags) == (0.0, 1.0, {"posDownRateLim"})
    s2 = slave(track=True, autoValue=-0.0, setNegDownRateLim=0.0)
    now(s2)
    # towards 25: the positive rising ramp, c = -0.0 + 10 = 10 (not the jump of the negative
    # range's down-rate 0 to 0.0)
    assert at(s2, track=False, autoValue=25.0) == (10.0, {"posUpRateLim"})


def test_a_down_rate_of_zero_jumps_with_its_flag():
    # the example, cycle 0.1 s: up-rates 100, down-rates 0 (the LGF default), limits
    # +-100. Call 0: p = 0 < 5, c = 0 + 100 * 0.1 = 10 > 5: 5.0, no flag. Calls 1-4: p >= t
    # and setPosDownRateLim = 0: posDownRateLim TRUE and the output jumps to autoValue, or to
    # 0.0 when autoValue < 0; from p = 0.0 it stays there (the positive range again).
    s = slave(
        0.1,
        autoValue=5.0,
        setPosUpRateLim=100.0,
        setNegUpRateLim=100.0,
        setPosDownRateLim=0.0,
        setNegDownRateLim=0.0,
    )
    rows = [now(s)] + [at(s, 0.1, autoValue=v) for v in (5.0, 2.0, -3.0, -3.0)]
    assert rows == [
        (5.0, set()),
        (5.0, {"posDownRateLim"}),  # t = p: the flag all the same
        (2.0, {"posDownRateLim"}),
        (0.0, {"posDownRateLim"}),
        (0.0, {"posDownRateLim"}),
    ]


def test_a_negative_down_rate_of_zero_jumps_with_its_flag():
    # dt = 1: from 0 towards -12 on setNegUpRateLim 5 (the crossing from p = 0: z = 0 / 20 = 0,
    # c = -(1 - 0) * 5 = -5), then setNegDownRateLim 0 in the negative range: a jump to
    # autoValue if it is <= 0, else to 0.0, with negDownRateLim TRUE, also while t = p
    s = slave(autoValue=-12.0, setNegDownRateLim=0.0)
    assert [now(s), at(s), at(s)] == [
        (-5.0, {"negUpRateLim"}),
        (-10.0, {"negUpRateLim"}),
        (-12.0, set()),  # c = -15 < -12: not limited
    ]
    assert at(s) == (-12.0, {"negDownRateLim"})  # p = t
    assert at(s, autoValue=-3.0) == (-3.0, {"negDownRateLim"})
    assert at(s, autoValue=7.0) == (0.0, {"negDownRateLim"})  # not across the sign
    assert at(s) == (7.0, set())  # p = 0.0: the positive rising ramp, c = 10 > 7


def test_a_ramp_that_reaches_zero_at_the_end_of_the_call_crosses():
    # §21.3: the crossing is decided on the time to zero, z <= dt. Upwards: p = -4,
    # setNegDownRateLim 4, t = 3: z = 4 / 4 = 1 <= 1, c = (1 - 1) * 10 = 0 < 3: posUpRateLim
    s = slave(defaultOutValue=-4.0, enDefaultOutValue=True)
    assert now(s) == (-4.0, set())
    assert at(s, enDefaultOutValue=False, autoValue=3.0) == (0.0, {"posUpRateLim"})
    assert at(s) == (3.0, set())  # p = 0.0: c = 10 > 3
    # downwards: p = 20, setPosDownRateLim 20, t = -1: z = 20 / 20 = 1 <= 1,
    # c = -(1 - 1) * 5 = -0.0 > -1: negUpRateLim, and the output is -0.0
    s2 = slave(autoValue=20.0)
    assert [now(s2), at(s2)] == [(10.0, {"posUpRateLim"}), (20.0, set())]
    out, flags = at(s2, autoValue=-1.0)
    assert (out, math.copysign(1.0, out), flags) == (0.0, -1.0, {"negUpRateLim"})
    # p = -0.0 is in the positive range: z = -0.0 / 20, c = -(1 + 0) * 5 = -5 < -1: the target
    assert at(s2) == (-1.0, set())


def test_all_rates_zero_keep_the_output_at_zero():
    # the LGF defaults: "the output remains at 0.0" (§21.5): from 0 up, c = 0 + 0 < t
    # (posUpRateLim); from 0 down, setPosDownRateLim 0 jumps to 0.0 across the sign
    s = slave(autoValue=50.0, **RATES_ZERO)
    assert [now(s)[0]] + [at(s, autoValue=v)[0] for v in (-50.0, 3.0)] == [0.0, 0.0, 0.0]


@pytest.mark.parametrize("cycle, per_call", [(1.0, 10.0), (0.1, 1.0), (0.01, 0.1)])
def test_example_of_the_documentation(cycle, per_call):
    # setPosUpRateLim 10.0 adds 10.0 / 1.0 / 0.1 per call at 1 s / 100 ms / 10 ms; dt = 1.0,
    # 0.1, 0.01 (REAL(µs) / 1e6), so k calls give k * (10.0 * dt) summed in double
    s = slave(cycle, autoValue=1000.0, setHighLim=1000.0)
    values = [now(s)[0]] + [at(s, cycle)[0] for _ in range(4)]
    expected, p = [], 0.0
    for _ in range(5):
        p = p + 10.0 * cycle
        expected.append(p)
    assert values == expected
    assert values == pytest.approx([per_call * k for k in range(1, 6)], rel=1e-12)


def test_dt_is_the_microseconds_rounded_to_a_real():
    # 16777217 µs rounds to the REAL 16777216.0, so dt = 16.777216 s (§3.3)
    s = slave(16.777217, autoValue=1e9, setPosUpRateLim=1.0, setHighLim=1e9)
    assert now(s)[0] == 16.777216


# ---- limits (§21.2 step 5) ----


def test_high_limit_flag_at_greater_or_equal():
    # autoValue 10 = setHighLim: c = 0 + 10 = 10 is not < 10, so out 10, no rate flag; 10 >= 10
    # sets highLim (the old rule wanted > and gave no flag)
    s = slave(autoValue=10.0, setHighLim=10.0)
    assert [now(s), at(s)] == [(10.0, {"highLim"})] * 2  # then p = t: still 10 >= 10


def test_low_limit_flag_at_less_or_equal():
    # autoValue -5 = setLowLim: from p = 0 (positive range) z = 0 / 20 = 0, c = -(1 - 0) * 5 = -5
    # is not > -5: out -5, no rate flag; -5 <= -5 sets lowLim; p - out = 5 is not < 5
    s = slave(autoValue=-5.0, setLowLim=-5.0)
    assert now(s) == (-5.0, {"lowLim"})


def test_the_up_rate_flag_is_cleared_when_the_cut_step_is_shorter_than_a_rate_step():
    s = slave(autoValue=100.0, setPosUpRateLim=30.0, setHighLim=50.0)
    assert [now(s), at(s), at(s)] == [
        (30.0, {"posUpRateLim"}),
        # c = 60 > 50: cut to 50; the step 50 - 30 = 20 < 30 * 1: posUpRateLim cleared
        (50.0, {"highLim"}),
        (50.0, {"highLim"}),  # c = 80, cut; 0 < 30
    ]
    # t = p = 50: c = 50 - 20 = 30 is not > 50, out 50; 50 >= 50: highLim
    assert at(s, autoValue=50.0) == (50.0, {"highLim"})
    # a cut step of exactly one rate step keeps the flag: 10 -> c = 20, cut at 20, 20 - 10 = 10
    # is not < 10
    s2 = slave(autoValue=100.0, setHighLim=20.0)
    assert [now(s2), at(s2), at(s2)] == [
        (10.0, {"posUpRateLim"}),
        (20.0, {"posUpRateLim", "highLim"}),
        (20.0, {"highLim"}),
    ]


def test_the_negative_up_rate_flag_is_cleared_at_the_low_limit():
    s = slave(autoValue=-100.0, setNegUpRateLim=30.0, setLowLim=-40.0)
    assert [now(s), at(s), at(s)] == [
        (-30.0, {"negUpRateLim"}),  # from p = 0: z = 0, c = -(1 - 0) * 30
        # c = -60 < -40: cut to -40; the step -30 - -40 = 10 < 30: negUpRateLim cleared
        (-40.0, {"lowLim"}),
        (-40.0, {"lowLim"}),
    ]


def test_only_the_two_up_rate_flags_are_corrected():
    # low limit 40, autoValue 50, from 0: c = 10 < 50, posUpRateLim; 10 <= 40: cut up to 40,
    # lowLim; the correction at the low limit concerns negUpRateLim only, so posUpRateLim stays
    s = slave(autoValue=50.0, setLowLim=40.0)
    assert now(s) == (40.0, {"posUpRateLim", "lowLim"})
    assert at(s) == (50.0, set())  # c = 50 is not < 50
    # towards 0: c = 50 - 20 = 30 > 0, posDownRateLim; 30 <= 40: cut to 40; the flag stays
    assert at(s, autoValue=0.0) == (40.0, {"posDownRateLim", "lowLim"})


def test_equal_limits_are_valid_and_hold_the_output():
    s = slave(autoValue=100.0, setHighLim=7.0, setLowLim=7.0)
    # c = 10 >= 7: cut to 7, highLim; 7 - 0 < 10: posUpRateLim cleared
    assert now(s) == (7.0, {"highLim"})
    # c = 7 - 20 = -13 < 0 and t < 0: z = 7/20 = 0.35 <= 1, c = -(1 - 0.35) * 5 = -3.25,
    # negUpRateLim; -3.25 <= 7: cut to 7, lowLim, and 7 - 7 = 0 < 5 clears negUpRateLim
    assert at(s, autoValue=-100.0) == (7.0, {"lowLim"})
    # out = 7: 7 >= 7 comes first, so highLim alone (the low test is its else branch)
    assert at(s, autoValue=7.0) == (7.0, {"highLim"})


# ---- errors (§21.4) ----


def test_high_below_low_is_16_8200_and_freezes_everything():
    s = slave(autoValue=100.0, setHighLim=50.0)
    at(s), at(s)  # 30.0
    before = s.outputs()
    out = at(s, setHighLim=-1.0, setLowLim=0.0, reset=True)  # reset does not act either
    assert out == row(before)
    got = s.outputs()
    assert (got["error"], got["status"], got["subFunctionStatus"]) == (True, LIMITS, 0)
    # the change to 16#8200 is logged as a warning naming the code, '#' escaped as sent
    assert any("16#8200" in text and category == "logStatusWarning" for _, category, text in s.log)
    assert any("16##8200" in raw for raw in s.raw_log)
    # valid again: the call goes on from the frozen p = 30 (reset released)
    s.set({"reset": False, "setLowLim": -100.0, "setHighLim": 50.0})
    got = s.step(1.0)
    assert row(got) == (40.0, {"posUpRateLim"})
    assert (got["error"], got["status"]) == (False, 0)


@pytest.mark.parametrize(
    "rate", ["setPosUpRateLim", "setPosDownRateLim", "setNegUpRateLim", "setNegDownRateLim"]
)
def test_a_negative_rate_is_16_8202(rate):
    s = slave(autoValue=5.0)
    s.set({rate: -1e-9})
    got = s.step(1.0)
    assert (got["outputValue"], got["error"], got["status"]) == (5.0, True, RATE)
    assert any("16#8202" in text for _, _, text in s.log)


def test_the_limits_are_checked_before_the_rates():
    s = slave(setHighLim=-1.0, setLowLim=1.0, setNegUpRateLim=-3.0)
    got = s.outputs()
    assert (got["outputValue"], got["error"], got["status"]) == (0.0, True, LIMITS)
    s.set({"setLowLim": -2.0})
    assert s.step(1.0)["status"] == RATE


def test_an_error_in_the_first_call_leaves_the_outputs_at_zero():
    s = slave(autoValue=50.0, setPosUpRateLim=-5.0)
    got = s.outputs()
    assert row(got) == (0.0, set()) and got["error"]


# ---- restart (§21.2 step 3) ----


def test_reset_outputs_zero_and_clears_the_flags():
    s = slave(autoValue=100.0, setHighLim=15.0)
    at(s)  # 15.0, highLim
    assert [at(s, reset=True), at(s)] == [(0.0, set()), (0.0, set())]  # a level
    assert at(s, reset=False) == (10.0, {"posUpRateLim"})


def test_reset_with_pre_assignment_cuts_the_default_with_the_limit_flags():
    s = slave(defaultOutValue=500.0, enDefaultOutValue=True, reset=True)
    assert now(s) == (100.0, {"highLim"})
    assert at(s, defaultOutValue=-500.0) == (-100.0, {"lowLim"})
    assert at(s, defaultOutValue=42.0) == (42.0, set())
    assert at(s, defaultOutValue=100.0) == (100.0, {"highLim"})  # at >=
    assert at(s, defaultOutValue=-100.0) == (-100.0, {"lowLim"})  # at <=


def test_reset_with_equal_limits_sets_both_limit_flags():
    # the restart tests both limits one after the other: 500 >= 7 -> 7, then 7 <= 7
    s = slave(defaultOutValue=500.0, enDefaultOutValue=True, reset=True, setHighLim=7.0)
    s.set({"setLowLim": 7.0})
    assert at(s) == (7.0, {"highLim", "lowLim"})


def test_reset_zero_is_not_brought_within_the_limits():
    s = slave(setLowLim=10.0, setHighLim=20.0, reset=True)
    assert now(s) == (0.0, set())
    # 0 + 10 = 10 < 15: posUpRateLim; 10 <= 10: lowLim (the cut to 10 changes nothing)
    assert at(s, reset=False, autoValue=15.0) == (10.0, {"posUpRateLim", "lowLim"})


def test_reset_comes_before_manual_mode_and_ends_its_suspension():
    s = slave(manOp=True, manualValue=300.0)
    assert now(s) == (300.0, set())
    assert at(s, reset=True) == (0.0, set())
    # reset FALSE, manOp FALSE: 0 is within the limits anyway; the limits apply
    assert at(s, reset=False, manOp=False, track=True, autoValue=250.0) == (100.0, {"highLim"})


# ---- manual mode (§21.2 step 4, §21.5) ----


def test_manual_value_goes_beyond_the_limits_and_ramps_back_with_them_suspended():
    s = slave(autoValue=0.0, setPosDownRateLim=50.0, manOp=True, manualValue=300.0)
    assert now(s) == (300.0, set())  # manual mode: no flag, not even a limit's
    assert at(s, manualValue=-250.0) == (-250.0, set())  # no ramp either
    assert at(s, manualValue=300.0) == (300.0, set())
    # released: ramps down from 300 by 50, not cut, until strictly within -100 ... 100; the
    # limit flag shows while the limits are suspended
    assert [at(s, manOp=False) for _ in range(6)] == [
        (250.0, {"posDownRateLim", "highLim"}),
        (200.0, {"posDownRateLim", "highLim"}),
        (150.0, {"posDownRateLim", "highLim"}),
        (100.0, {"posDownRateLim", "highLim"}),  # 100 >= 100: not within yet
        (50.0, {"posDownRateLim"}),  # within: the limits apply again
        (0.0, set()),
    ]
    assert at(s, track=True, autoValue=200.0) == (100.0, {"highLim"})  # the limits are back


def test_at_the_limit_the_suspension_goes_on():
    # manual 300, released towards 0 at 200 per call: c = 100, posDownRateLim; 100 >= 100:
    # highLim, and the limits stay suspended (only a value strictly within ends it) ...
    s = slave(setPosDownRateLim=200.0, manOp=True, manualValue=300.0)
    assert at(s, manOp=False) == (100.0, {"posDownRateLim", "highLim"})
    # ... so a tracked 200 is output uncut
    assert at(s, track=True, autoValue=200.0) == (200.0, {"highLim"})


def test_tracking_and_pre_assignment_stay_unlimited_while_suspended():
    s = slave(manOp=True, manualValue=300.0)
    # still suspended: uncut, with the limit's flag
    assert at(s, manOp=False, track=True, autoValue=200.0) == (200.0, {"highLim"})
    assert at(s, autoValue=60.0) == (60.0, set())  # within: limits back
    assert at(s, autoValue=200.0) == (100.0, {"highLim"})
    s2 = slave(manOp=True, manualValue=-300.0)
    assert at(s2, manOp=False, enDefaultOutValue=True, defaultOutValue=-150.0) == (
        -150.0,
        {"lowLim"},
    )


def test_after_a_manual_value_within_the_limits_the_first_result_decides():
    # §21.5: the check is on each automatic call's result before the cut
    s = slave(manOp=True, manualValue=50.0, autoValue=200.0)
    assert at(s, manOp=False) == (60.0, {"posUpRateLim"})  # the ramp stays within: limits back
    assert at(s, track=True) == (100.0, {"highLim"})
    s2 = slave(manOp=True, manualValue=50.0)
    # tracked 200 is beyond the limit while they are still suspended: output uncut, flagged
    assert at(s2, manOp=False, track=True, autoValue=200.0) == (200.0, {"highLim"})


def test_manual_mode_ignores_ramps_limits_and_pre_assignment():
    s = slave(manOp=True, manualValue=-1e6, enDefaultOutValue=True, defaultOutValue=1.0)
    assert now(s) == (-1e6, set())


def test_with_rates_zero_a_manual_value_falls_back_at_once():
    # all rates 0, released from manual 300 towards autoValue 0: p >= t and
    # setPosDownRateLim = 0, so the jump to autoValue with posDownRateLim; 0 is within the
    # limits, which apply again
    s = slave(manOp=True, manualValue=300.0, **RATES_ZERO)
    assert [at(s, manOp=False) for _ in range(3)] == [(0.0, {"posDownRateLim"})] * 3


def test_with_up_rates_zero_the_limits_stay_suspended():
    # released from manual 300 towards 500 with every rate 0: c = 300 + 0 < 500,
    # posUpRateLim, out 300; 300 >= 100: highLim, still suspended, uncut
    s = slave(manOp=True, manualValue=300.0, autoValue=500.0, **RATES_ZERO)
    assert [at(s, manOp=False) for _ in range(3)] == [(300.0, {"posUpRateLim", "highLim"})] * 3


# ---- pre-assignment and tracking (§21.2 step 5) ----


def test_pre_assignment_jumps_and_the_ramp_goes_on_from_it():
    s = slave(autoValue=60.0)
    at(s)  # 20
    assert at(s, enDefaultOutValue=True, defaultOutValue=-30.0) == (-30.0, set())
    assert at(s, defaultOutValue=150.0) == (100.0, {"highLim"})  # within the limits
    assert at(s, defaultOutValue=-3.0) == (-3.0, set())
    # released: from -3 up by 4 (negDown): c = 1 > 0 and t > 0, z = 3/4 = 0.75, r = 0.25,
    # c2 = 10 * 0.25 = 2.5
    assert at(s, enDefaultOutValue=False) == (2.5, {"posUpRateLim"})


def test_pre_assignment_comes_before_tracking():
    s = slave(autoValue=60.0, track=True, enDefaultOutValue=True, defaultOutValue=7.0)
    assert now(s) == (7.0, set())
    assert at(s, enDefaultOutValue=False) == (60.0, set())
    assert at(s, track=False, autoValue=0.0) == (40.0, {"posDownRateLim"})  # 60 - 20


# ---- infinities (§1.4, §21.3) ----


def test_infinities_follow_ieee_and_a_nan_candidate_gives_the_target():
    s = slave(
        autoValue=math.inf, setPosUpRateLim=math.inf, setHighLim=math.inf, setLowLim=-math.inf
    )
    # c = 0 + Inf = Inf is not < Inf: out Inf, no rate flag; Inf >= Inf: highLim
    assert now(s) == (math.inf, {"highLim"})
    # c = Inf - 20 = Inf > 0: posDownRateLim, out Inf; highLim; the correction Inf - Inf = NaN
    # < ... is FALSE
    assert at(s, autoValue=0.0) == (math.inf, {"posDownRateLim", "highLim"})
    # with an infinite falling rate: c = Inf - Inf = NaN; 0 < NaN is FALSE, so out is the
    # target 0, no flag
    assert at(s, setPosDownRateLim=math.inf) == (0.0, set())


def test_an_infinite_down_rate_from_minus_infinity_gives_nan():
    # manual -Inf, then towards 1 with setNegDownRateLim Inf: z = -(-Inf) / Inf = NaN, and
    # NaN <= dt is FALSE, so the branch of a crossing beyond this call: negDownRateLim TRUE,
    # out = -Inf + 1 * Inf = NaN (within no limit: the suspension ends). The next call: NaN < 0
    # and NaN < 1 and NaN >= 1 are all FALSE, so the output is autoValue.
    s = slave(manOp=True, manualValue=-math.inf)
    assert now(s) == (-math.inf, set())
    out, flags = at(s, manOp=False, autoValue=1.0, setNegDownRateLim=math.inf)
    assert math.isnan(out) and flags == {"negDownRateLim"}
    state, time = s.fmu.getFMUstate(), s.time  # a NaN static is a state a run produces (§1.9)
    assert at(s) == (1.0, set())
    s.fmu.setFMUstate(state)
    s.time = time
    s.fmu.freeFMUstate(state)
    assert at(s) == (1.0, set())


# ---- misuse (§1.7) ----


@pytest.fixture
def initializing():
    yield from harness.initializing(BLOCK)


@pytest.mark.parametrize(
    "name", ["autoValue", "manualValue", "setNegDownRateLim", "setLowLim", "defaultOutValue"]
)
def test_nan_is_refused(initializing, name):
    s = initializing
    before = s.get([name])[name]
    assert s.status_of(s.fmu.setReal, [s.vr(name)], [math.nan]) == fmi2Error
    assert s.get([name])[name] == before and s.log[-1][0] == fmi2Error and name in s.log[-1][2]


def test_cycle_time_outside_1_us_to_60_s_is_refused(initializing):
    s = initializing
    for value in (0.0, 5e-7, 60.5):
        assert s.status_of(s.fmu.setReal, [s.vr("cycleTime")], [value]) == fmi2Error
    assert "16#8600" in s.log[-1][2] or "16##8600" in s.raw_log[-1]


def test_outputs_cannot_be_set():
    s = slave()
    assert s.status_of(s.fmu.setBoolean, [s.vr("highLim")], [True]) == fmi2Error
    assert s.status_of(s.fmu.setReal, [s.vr("outputValue")], [1.0]) == fmi2Error
