"""Hand-traced tests of the LimRateOfChangeAdvancedCI model (docs/behaviour.md §21), without any
FMU."""

import math

import pytest

from .model import FLAGS, STATUS_LIMITS, STATUS_NEG_RATE, LimRateOfChangeAdvancedCI

INF = math.inf
START = {
    "autoValue": 100.0,
    "manualValue": 0.0,
    "setPosUpRateLim": 20.0,
    "setPosDownRateLim": 40.0,
    "setNegUpRateLim": 20.0,
    "setNegDownRateLim": 40.0,
    "setHighLim": 80.0,
    "setLowLim": -80.0,
    "defaultOutValue": 0.0,
    "enDefaultOutValue": False,
    "track": False,
    "manOp": False,
    "reset": False,
}


def inp(**changes):
    return {**START, **changes}


def run(seq, cycle_us=100_000, block=None, k0=0):
    b = block or LimRateOfChangeAdvancedCI(cycle_us)
    return [b.call((k0 + k) * cycle_us, i) for k, i in enumerate(seq)]


def flags_set(o):
    return {f for f in FLAGS if o[f]}


def test_status_codes():
    assert (STATUS_LIMITS, STATUS_NEG_RATE) == (33280, 33282)


def test_start_values_ramp_and_high_limit():
    # §21.1: +2.0 per call of 0.1 s (20 * 0.1 = 2.0): 2.0 at t 0, 80.0 at t 3.9 s, then 80.0;
    # posUpRateLim TRUE throughout, highLim from t 4.0 s (c = 82 -> min(82, 100) = 82 > 80)
    outs = run([inp()] * 45)
    assert [o["outputValue"] for o in outs[:40]] == [2.0 * (k + 1) for k in range(40)]
    assert all(o["outputValue"] == 80.0 for o in outs[39:])
    assert all(o["posUpRateLim"] for o in outs)
    assert [o["highLim"] for o in outs] == [False] * 40 + [True] * 5
    assert all(
        o["error"] is False and o["status"] == 0 and o["subFunctionStatus"] == 0 for o in outs
    )


@pytest.mark.parametrize("cycle_us,step", [(1_000_000, 10.0), (100_000, 1.0), (10_000, 0.1)])
def test_documented_example(cycle_us, step):
    # §21.5: setPosUpRateLim 10 adds 10.0, 1.0, 0.1 per call at 1 s, 100 ms, 10 ms
    o = run([inp(setPosUpRateLim=10.0, setHighLim=1e9)], cycle_us)[0]
    assert o["outputValue"] == 10.0 * (cycle_us / 1e6) == step


def test_lands_exactly_on_auto_value():
    # §21.5: 1 s cycle, rate 20: 20, 40, 50, 50 (min(60, 50) = 50, flag FALSE)
    outs = run([inp(autoValue=50.0)] * 4, 1_000_000)
    assert [o["outputValue"] for o in outs] == [20.0, 40.0, 50.0, 50.0]
    assert [o["posUpRateLim"] for o in outs] == [True, True, False, False]


def test_four_ramps():
    b = LimRateOfChangeAdvancedCI(1_000_000)
    lim = {"setHighLim": 1e9, "setLowLim": -1e9}
    # p 0 -> rising: posUp 3: 3.0
    o = b.call(0, inp(autoValue=10.0, setPosUpRateLim=3.0, **lim))
    assert o["outputValue"] == 3.0 and flags_set(o) == {"posUpRateLim"}
    # p 3 -> falling positive: posDown 2: 1.0
    o = b.call(1, inp(autoValue=0.5, setPosDownRateLim=2.0, **lim))
    assert o["outputValue"] == 1.0 and flags_set(o) == {"posDownRateLim"}
    # p 1 -> falling to 0.5: c = 1 - 2 = -1 < 0 but t = 0.5 > 0: no crossing: max(-1, 0.5) = 0.5
    o = b.call(2, inp(autoValue=0.5, setPosDownRateLim=2.0, **lim))
    assert o["outputValue"] == 0.5 and flags_set(o) == set()
    # now go negative through track: -4
    b.call(3, inp(autoValue=-4.0, track=True, **lim))
    # p -4, t -10: falling negative (magnitude rises): negUp 1.5: -5.5
    o = b.call(4, inp(autoValue=-10.0, setNegUpRateLim=1.5, **lim))
    assert o["outputValue"] == -5.5 and flags_set(o) == {"negUpRateLim"}
    # p -5.5, t -1: rising negative (magnitude falls): negDown 2.5: -3.0
    o = b.call(5, inp(autoValue=-1.0, setNegDownRateLim=2.5, **lim))
    assert o["outputValue"] == -3.0 and flags_set(o) == {"negDownRateLim"}


def test_zero_belongs_to_the_ramp_that_leaves_it():
    # §21.3 Decision: from p 0 rising uses posUp, falling uses negUp (not posDown)
    o = run([inp(autoValue=-50.0, setPosDownRateLim=0.0, setNegUpRateLim=5.0)], 1_000_000)[0]
    assert o["outputValue"] == -5.0 and flags_set(o) == {"negUpRateLim"}
    o = run([inp(autoValue=50.0, setNegDownRateLim=0.0, setPosUpRateLim=5.0)], 1_000_000)[0]
    assert o["outputValue"] == 5.0 and flags_set(o) == {"posUpRateLim"}


def test_minus_zero_is_zero():
    # p = -0.0 (from track with autoValue -0.0): rising uses posUp
    b = LimRateOfChangeAdvancedCI(1_000_000)
    b.call(0, inp(autoValue=-0.0, track=True))
    assert math.copysign(1.0, b.p) == -1.0
    o = b.call(1, inp(autoValue=10.0, setPosUpRateLim=4.0, setNegDownRateLim=0.0))
    assert o["outputValue"] == 4.0 and o["posUpRateLim"]


def test_crossing_zero_upwards():
    # §21.3: 1 s cycle, p -1 (track), t 10, negDown 4, posUp 2: c = -1 + 4 = 3 > 0, t > 0:
    # z = (0 - -1)/4 = 0.25, r = 1 - 0.25 = 0.75, c2 = 0 + 2*0.75 = 1.5 < 10 -> posUpRateLim
    b = LimRateOfChangeAdvancedCI(1_000_000)
    b.call(0, inp(autoValue=-1.0, track=True))
    o = b.call(1, inp(autoValue=10.0, setNegDownRateLim=4.0, setPosUpRateLim=2.0))
    assert o["outputValue"] == 1.5 and flags_set(o) == {"posUpRateLim"}
    # t 1.0 < c2: out = 1.0, no flag
    b.call(2, inp(autoValue=-1.0, track=True))
    o = b.call(3, inp(autoValue=1.0, setNegDownRateLim=4.0, setPosUpRateLim=2.0))
    assert o["outputValue"] == 1.0 and flags_set(o) == set()


def test_crossing_zero_downwards():
    # p 1 (track), t -10, posDown 4, negUp 2: c = 1 - 4 = -3 < 0, t < 0:
    # z = 1/4 = 0.25, r = 0.75, c2 = 0 - 2*0.75 = -1.5 > -10 -> negUpRateLim
    b = LimRateOfChangeAdvancedCI(1_000_000)
    b.call(0, inp(autoValue=1.0, track=True))
    o = b.call(1, inp(autoValue=-10.0, setPosDownRateLim=4.0, setNegUpRateLim=2.0))
    assert o["outputValue"] == -1.5 and flags_set(o) == {"negUpRateLim"}


def test_crossing_with_rounding_order():
    # 100 ms: p -0.3, negDown 7, posUp 3: c = -0.3 + 0.7000000000000001 > 0; z = 0.3/7,
    # r = 0.1 - z, c2 = 0.0 + 3*r (all in double, in this order)
    dt = 0.1
    b = LimRateOfChangeAdvancedCI(100_000)
    b.call(0, inp(autoValue=-0.3, track=True))
    o = b.call(1, inp(autoValue=10.0, setNegDownRateLim=7.0, setPosUpRateLim=3.0))
    z = (0.0 - -0.3) / 7.0
    r = dt - z
    assert o["outputValue"] == 0.0 + 3.0 * r


def test_error_limits_first_then_rates_and_freeze():
    b = LimRateOfChangeAdvancedCI(100_000)
    o1 = b.call(0, inp())  # 2.0, posUpRateLim
    o = b.call(1, inp(setHighLim=-1.0, setLowLim=1.0, setPosUpRateLim=-1.0, reset=True))
    assert o == {**o1, "error": True, "status": STATUS_LIMITS}
    o = b.call(2, inp(setNegDownRateLim=-0.5, reset=True))
    assert o == {**o1, "error": True, "status": STATUS_NEG_RATE}
    assert b.p == 2.0
    # the first valid call continues from the frozen p: 4.0
    o = b.call(3, inp())
    assert o["outputValue"] == 4.0 and o["error"] is False and o["status"] == 0


def test_equal_limits_are_valid():
    o = run([inp(setHighLim=5.0, setLowLim=5.0)], 1_000_000)[0]
    # ramp 0 -> 20 (min(20, 100)), > 5 -> 5 with highLim and posUpRateLim
    assert o["outputValue"] == 5.0 and flags_set(o) == {"posUpRateLim", "highLim"}


def test_reset():
    # §21.2 step 3: reset: 0.0 (not limited); with enDefaultOutValue the default within limits
    b = LimRateOfChangeAdvancedCI(100_000)
    b.call(0, inp())
    assert b.call(1, inp(reset=True, manOp=True, track=True))["outputValue"] == 0.0
    o = b.call(2, inp(reset=True, enDefaultOutValue=True, defaultOutValue=500.0))
    assert o["outputValue"] == 80.0 and flags_set(o) == set()
    o = b.call(3, inp(reset=True, enDefaultOutValue=True, defaultOutValue=-500.0))
    assert o["outputValue"] == -80.0 and flags_set(o) == set()
    o = b.call(4, inp(reset=True, enDefaultOutValue=True, defaultOutValue=7.0))
    assert o["outputValue"] == 7.0
    # 0.0 outside the limits after reset is not cut
    o = b.call(5, inp(reset=True, setLowLim=10.0, setHighLim=20.0))
    assert o["outputValue"] == 0.0 and flags_set(o) == set()


def test_pre_assignment_and_track_in_automatic_are_limited():
    b = LimRateOfChangeAdvancedCI(100_000)
    o = b.call(0, inp(enDefaultOutValue=True, defaultOutValue=90.0, track=True, autoValue=5.0))
    assert o["outputValue"] == 80.0 and flags_set(o) == {"highLim"}
    o = b.call(1, inp(track=True, autoValue=-95.0))
    assert o["outputValue"] == -80.0 and flags_set(o) == {"lowLim"}
    # releasing track ramps from there: p -80, t 100: negDown 40*0.1 = 4 -> -76
    o = b.call(2, inp())
    assert o["outputValue"] == -76.0 and flags_set(o) == {"negDownRateLim"}


def test_manual_mode_and_suspended_limits():
    # §21.2 steps 4, 5.2, 5.3 / §21.5: manual 200 beyond the limits; after manOp falls the output
    # ramps down (posDown 40 * 1 s) with limits suspended until within -80 ... 80
    b = LimRateOfChangeAdvancedCI(1_000_000)
    o = b.call(0, inp(manOp=True, manualValue=200.0, enDefaultOutValue=True))
    assert o["outputValue"] == 200.0 and flags_set(o) == set() and b.statManOp
    seq = [inp(autoValue=0.0)] * 5
    outs = run(seq, 1_000_000, block=b, k0=1)
    # 160, 120, 80 (within: limits again), 40, 0
    assert [o["outputValue"] for o in outs] == [160.0, 120.0, 80.0, 40.0, 0.0]
    assert [o["highLim"] for o in outs] == [False] * 5
    assert [o["posDownRateLim"] for o in outs] == [True, True, True, True, False]
    assert b.statManOp is False


def test_manual_within_limits_then_ramp_beyond_them():
    # §21.2 step 5.2 tests the `out` of the automatic call (after the ramp), not the manual value:
    # manual 70 (within -80 ... 80), then auto 100 at rate 20 per s: c = 90 -> min(90, 100) = 90,
    # not within the limits, so statManOp stays TRUE and 90 is output uncut. (§21.5's "a manual
    # value within the limits re-enables them in the first automatic call" holds only where that
    # call's ramp stays within them; the steps of §21.2 are followed here.)
    b = LimRateOfChangeAdvancedCI(1_000_000)
    b.call(0, inp(manOp=True, manualValue=70.0))
    o = b.call(1, inp())
    assert o["outputValue"] == 90.0 and b.statManOp and not o["highLim"]
    # a later track into the limits re-enables them
    o = b.call(2, inp(track=True, autoValue=50.0))
    assert o["outputValue"] == 50.0 and not b.statManOp
    o = b.call(3, inp(track=True, autoValue=100.0))
    assert o["outputValue"] == 80.0 and o["highLim"]


def test_manual_within_limits_reenables_at_first_auto_call():
    # §21.5: manual 70, auto 75 at rate 20 per s: min(90, 75) = 75 within -> limits again
    b = LimRateOfChangeAdvancedCI(1_000_000)
    b.call(0, inp(manOp=True, manualValue=70.0))
    o = b.call(1, inp(autoValue=75.0))
    assert o["outputValue"] == 75.0 and not b.statManOp


def test_manual_suspension_with_zero_rates_holds():
    # §21.5: rates 0: the output stays beyond the limits until restart
    b = LimRateOfChangeAdvancedCI(1_000_000)
    b.call(0, inp(manOp=True, manualValue=-200.0))
    zero = {k: 0.0 for k in ("setPosUpRateLim", "setPosDownRateLim", "setNegUpRateLim",
                             "setNegDownRateLim")}  # fmt: skip
    outs = run([inp(**zero)] * 3, 1_000_000, block=b, k0=1)
    assert [o["outputValue"] for o in outs] == [-200.0] * 3
    assert all(o["negDownRateLim"] and not o["lowLim"] for o in outs)
    o = b.call(9, inp(reset=True, **zero))
    assert o["outputValue"] == 0.0 and not b.statManOp


def test_zero_rates_freeze():
    zero = {k: 0.0 for k in ("setPosUpRateLim", "setPosDownRateLim", "setNegUpRateLim",
                             "setNegDownRateLim")}  # fmt: skip
    outs = run([inp(**zero)] * 3)
    assert [o["outputValue"] for o in outs] == [0.0] * 3 and all(o["posUpRateLim"] for o in outs)


def test_flag_with_limit_holding():
    # §21.5: autoValue above setHighLim: at 80 each call ramps towards 100 then cuts
    b = LimRateOfChangeAdvancedCI(100_000)
    b.call(0, inp(track=True))
    o = b.call(1, inp())
    assert o["outputValue"] == 80.0 and flags_set(o) == {"posUpRateLim", "highLim"}


def test_nan_candidate_yields_target():
    # §21.3: p +Inf (track, limit +Inf), t 0, posDown +Inf: c = Inf - Inf*0.1 = NaN ->
    # max(NaN, 0) = 0, flag FALSE
    b = LimRateOfChangeAdvancedCI(100_000)
    b.call(0, inp(track=True, autoValue=INF, setHighLim=INF))
    assert b.p == INF
    o = b.call(1, inp(autoValue=0.0, setHighLim=INF, setPosDownRateLim=INF))
    assert o["outputValue"] == 0.0 and flags_set(o) == set()


def test_infinite_rate_jumps():
    # rate +Inf: c = 0 + Inf = Inf -> min(Inf, 50) = 50, flag FALSE
    o = run([inp(autoValue=50.0, setPosUpRateLim=INF)])[0]
    assert o["outputValue"] == 50.0 and flags_set(o) == set()


def test_dt_from_float32_cycle():
    # §3.3: 16777217 µs -> REAL 16777216 -> dt 16.777216 s
    assert LimRateOfChangeAdvancedCI(16_777_217).dt == 16.777216
    assert LimRateOfChangeAdvancedCI(100_000).dt == 0.1
