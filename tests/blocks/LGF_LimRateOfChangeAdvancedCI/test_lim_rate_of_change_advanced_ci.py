"""LGF_LimRateOfChangeAdvancedCI against the rules of docs/behaviour.md §21, with hand-computed
expectations. Most runs use cycleTime 1 s (dt = 1.0) and rates that are exact in binary, so the
expected values are exact."""

import math

import pytest
from fmpy.fmi2 import fmi2Error

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
    # (2.0 at t = 0); 80.0 in call 39 (t = 3.9 s), cut at setHighLim 80 from call 40 on.
    s = Slave(BLOCK)
    assert s.get(["autoValue", "setPosUpRateLim", "setHighLim", "setLowLim"]) == {
        "autoValue": 100.0,
        "setPosUpRateLim": 20.0,
        "setHighLim": 80.0,
        "setLowLim": -80.0,
    }
    rows = [now(s)] + [row(s.step(0.1)) for _ in range(59)]
    assert [r[0] for r in rows] == [min(2.0 * (k + 1), 80.0) for k in range(60)]
    assert [r[1] for r in rows[:40]] == [{"posUpRateLim"}] * 40
    assert [r[1] for r in rows[40:]] == [{"posUpRateLim", "highLim"}] * 20


# ---- the four ramps (§21.3) ----


def test_rising_in_the_positive_range_lands_exactly():
    s = slave(autoValue=25.0)  # from p = 0.0: the positive rising ramp, 10 per call
    assert [now(s), at(s), at(s), at(s)] == [
        (10.0, {"posUpRateLim"}),
        (20.0, {"posUpRateLim"}),
        (25.0, set()),  # c = 30 > 25: min gives 25, not limited
        (25.0, set()),  # t = p
    ]


def test_falling_in_the_positive_range():
    s = slave(autoValue=25.0)
    at(s), at(s)  # 25.0
    assert [at(s, autoValue=3.0), at(s)] == [(5.0, {"posDownRateLim"}), (3.0, set())]


def test_falling_in_the_negative_range_from_zero():
    # p = 0, t < p: p <= 0, so the negative ramp of rising magnitude, 5 per call (§21.3 decision)
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
    # c = 5 - 20 = -15 < 0 and t < 0: z = 5 / 20 = 0.25 s, r = 1 - 0.25 = 0.75 s,
    # c2 = 0.0 - 5 * 0.75 = -3.75; only the second ramp's flag
    assert at(s) == (-3.75, {"negUpRateLim"})
    assert at(s) == (-8.75, {"negUpRateLim"})  # p <= 0 now: -3.75 - 5


def test_crossing_zero_upwards_spends_the_rest_of_the_cycle_on_the_positive_ramp():
    s = slave(autoValue=100.0, defaultOutValue=-6.0, enDefaultOutValue=True)
    assert now(s) == (-6.0, set())
    assert at(s, enDefaultOutValue=False) == (-2.0, {"negDownRateLim"})  # -6 + 4
    # c = -2 + 4 = 2 > 0 and t > 0: z = (0 - -2) / 4 = 0.5 s, r = 0.5 s, c2 = 0 + 10 * 0.5 = 5
    assert at(s) == (5.0, {"posUpRateLim"})
    assert at(s) == (15.0, {"posUpRateLim"})


def test_a_crossing_that_reaches_the_target_on_the_other_side():
    s = slave(autoValue=5.0)
    assert now(s) == (5.0, set())
    # c = 5 - 20 = -15 < 0, t = -1 < 0: z = 0.25, r = 0.75, c2 = -3.75; max(-3.75, -1) = -1
    assert at(s, autoValue=-1.0) == (-1.0, set())


def test_crossings_and_non_crossings_near_zero():
    s = slave(autoValue=5.0)
    # c = -15 but t = 0 is not < 0: max(-15, 0) = 0, not limited
    assert at(s, autoValue=0.0) == (0.0, set())
    s2 = slave(autoValue=100.0, defaultOutValue=-2.0, enDefaultOutValue=True)
    # c = -2 + 4 = 2 > 0 and t = 0.5 > 0: a crossing, z = 0.5, r = 0.5, c2 = 10 * 0.5 = 5;
    # min(5, 0.5) = 0.5, not limited
    assert at(s2, enDefaultOutValue=False, autoValue=0.5) == (0.5, set())
    s3 = slave(autoValue=100.0, defaultOutValue=-2.0, enDefaultOutValue=True)
    # t = 0.0 is not > 0: no crossing, min(2, 0) = 0
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
    # the LGF defaults: "the output remains at 0.0" (§21.5)
    s = slave(
        autoValue=50.0,
        setPosUpRateLim=0.0,
        setPosDownRateLim=0.0,
        setNegUpRateLim=0.0,
        setNegDownRateLim=0.0,
    )
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


def test_high_limit_cuts_with_the_rate_flag_still_set():
    s = slave(autoValue=100.0, setPosUpRateLim=30.0, setHighLim=50.0)
    assert [now(s), at(s), at(s), at(s)] == [
        (30.0, {"posUpRateLim"}),
        (50.0, {"posUpRateLim", "highLim"}),  # c = 60 -> cut to 50
        (50.0, {"posUpRateLim", "highLim"}),  # each call ramps from 50 towards 100, then cuts
        (50.0, {"posUpRateLim", "highLim"}),
    ]
    assert at(s, autoValue=50.0) == (50.0, set())  # t = p: neither flag


def test_low_limit():
    s = slave(autoValue=-100.0, setNegUpRateLim=30.0, setLowLim=-40.0)
    assert [now(s), at(s), at(s)] == [
        (-30.0, {"negUpRateLim"}),
        (-40.0, {"negUpRateLim", "lowLim"}),
        (-40.0, {"negUpRateLim", "lowLim"}),
    ]


def test_equal_limits_are_valid_and_hold_the_output():
    s = slave(autoValue=100.0, setHighLim=7.0, setLowLim=7.0)
    assert now(s) == (7.0, {"posUpRateLim", "highLim"})  # c = 10 -> cut to 7
    # c = 7 - 20 = -13 < 0 and t < 0, a crossing: z = 7/20 = 0.35, r = 0.65, c2 = -3.25
    # (flag negUpRateLim, the second ramp's), then -3.25 < 7 -> cut to 7, lowLim
    assert at(s, autoValue=-100.0) == (7.0, {"negUpRateLim", "lowLim"})


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


def test_reset_with_pre_assignment_outputs_the_default_within_the_limits_without_flag():
    s = slave(defaultOutValue=500.0, enDefaultOutValue=True, reset=True)
    assert now(s) == (100.0, set())
    assert at(s, defaultOutValue=-500.0) == (-100.0, set())
    assert at(s, defaultOutValue=42.0) == (42.0, set())


def test_reset_zero_is_not_brought_within_the_limits():
    s = slave(setLowLim=10.0, setHighLim=20.0, reset=True)
    assert now(s) == (0.0, set())
    assert at(s, reset=False, autoValue=15.0) == (10.0, {"posUpRateLim"})  # 0 + 10, within


def test_reset_comes_before_manual_mode_and_ends_its_suspension():
    s = slave(manOp=True, manualValue=300.0)
    assert now(s) == (300.0, set())
    assert at(s, reset=True) == (0.0, set())
    # reset FALSE, manOp FALSE: 0 is within the limits anyway; the limits apply
    assert at(s, reset=False, manOp=False, track=True, autoValue=250.0) == (100.0, {"highLim"})


# ---- manual mode (§21.2 step 4, §21.5) ----


def test_manual_value_goes_beyond_the_limits_and_ramps_back_with_them_suspended():
    s = slave(autoValue=0.0, setPosDownRateLim=50.0, manOp=True, manualValue=300.0)
    assert now(s) == (300.0, set())
    assert at(s, manualValue=-250.0) == (-250.0, set())  # no ramp either
    assert at(s, manualValue=300.0) == (300.0, set())
    # released: ramps down from 300 by 50, not cut, until first within -100 ... 100
    assert [at(s, manOp=False) for _ in range(6)] == [
        (250.0, {"posDownRateLim"}),
        (200.0, {"posDownRateLim"}),
        (150.0, {"posDownRateLim"}),
        (100.0, {"posDownRateLim"}),  # within: the limits apply again (100 is not > 100)
        (50.0, {"posDownRateLim"}),
        (0.0, set()),
    ]
    assert at(s, track=True, autoValue=200.0) == (100.0, {"highLim"})  # the limits are back


def test_tracking_and_pre_assignment_stay_unlimited_while_suspended():
    s = slave(manOp=True, manualValue=300.0)
    assert at(s, manOp=False, track=True, autoValue=200.0) == (200.0, set())  # still suspended
    assert at(s, autoValue=60.0) == (60.0, set())  # within: limits back
    assert at(s, autoValue=200.0) == (100.0, {"highLim"})
    s2 = slave(manOp=True, manualValue=-300.0)
    assert at(s2, manOp=False, enDefaultOutValue=True, defaultOutValue=-150.0) == (-150.0, set())


def test_after_a_manual_value_within_the_limits_the_first_result_decides():
    # §21.5: the check is on each automatic call's result before the cut
    s = slave(manOp=True, manualValue=50.0, autoValue=200.0)
    assert at(s, manOp=False) == (60.0, {"posUpRateLim"})  # the ramp stays within: limits back
    assert at(s, track=True) == (100.0, {"highLim"})
    s2 = slave(manOp=True, manualValue=50.0)
    # tracked 200 is beyond the limit while they are still suspended: output uncut
    assert at(s2, manOp=False, track=True, autoValue=200.0) == (200.0, set())


def test_manual_mode_ignores_ramps_limits_and_pre_assignment():
    s = slave(manOp=True, manualValue=-1e6, enDefaultOutValue=True, defaultOutValue=1.0)
    assert now(s) == (-1e6, set())


def test_with_rates_zero_a_manual_value_falls_back_at_once():
    # all rates 0, released from manual 300 towards autoValue 0: p >= t and
    # setPosDownRateLim = 0, so the jump to autoValue with posDownRateLim; 0 is within the
    # limits, which apply again
    s = slave(
        manOp=True,
        manualValue=300.0,
        setPosUpRateLim=0.0,
        setPosDownRateLim=0.0,
        setNegUpRateLim=0.0,
        setNegDownRateLim=0.0,
    )
    assert [at(s, manOp=False) for _ in range(3)] == [(0.0, {"posDownRateLim"})] * 3


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
    assert now(s) == (math.inf, set())  # c = Inf, min(Inf, Inf) = Inf; Inf < Inf is FALSE
    assert at(s, autoValue=0.0) == (math.inf, {"posDownRateLim"})  # Inf - 20 = Inf > 0
    # with an infinite falling rate: c = Inf - Inf = NaN; NaN < 0 is FALSE, so no crossing,
    # max(NaN, 0) gives the target 0, and NaN > 0 is FALSE: no flag
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
    s = Slave(BLOCK, initialize=False)
    s.fmu.setupExperiment(startTime=0.0)
    s.fmu.enterInitializationMode()
    yield s
    s.fmu.exitInitializationMode()
    s.free()


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
