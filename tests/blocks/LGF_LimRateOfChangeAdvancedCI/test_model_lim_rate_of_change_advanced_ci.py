"""Hand traces of the LimRateOfChangeAdvancedCI model against the original block's program (no
FMU): call k at k · cycle, the output value and the set flags after each call."""

import math
import struct

import pytest

from .model import FLAGS, STATUS_LIMITS, STATUS_NEG_RATE, LimRateOfChangeAdvancedCI, dt_seconds

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
SHORT = {  # the names of the flags in the traces
    "posUpRateLim": "pu",
    "posDownRateLim": "pd",
    "negUpRateLim": "nu",
    "negDownRateLim": "nd",
    "highLim": "hi",
    "lowLim": "lo",
}


def run(seq, cycle_us=100_000, **base):
    """(outputValue, set flags) per call; seq is a list of input changes per call, each applied
    from that call on."""
    m = LimRateOfChangeAdvancedCI(cycle_us)
    inputs = {**START, **base}
    out = []
    for k, changes in enumerate(seq):
        inputs.update(changes)
        o = m.call(k * cycle_us, dict(inputs))
        assert o["subFunctionStatus"] == 0
        flags = " ".join(SHORT[f] for f in FLAGS if o[f])
        out.append((o["outputValue"], flags) if not o["error"] else (o["status"], o["outputValue"]))
    return out


def test_start_values_ramp_and_the_high_limit():
    # 2.0 per call (20 · 0.1 = 2.0 exactly in double) from 0: 2.0 in call 0 … 78.0 in call 38.
    # Call 39: 80.0 >= setHighLim: highLim already at equality; the cut step 80 - 78 = 2 is not
    # shorter than a rate step: posUpRateLim stays. Call 40: the ramp gives 82, cut to 80, the
    # step 80 - 80 = 0 < 2: posUpRateLim cleared; highLim alone from then on.
    out = run([{}] * 42)
    assert out[:39] == [(2.0 * (k + 1), "pu") for k in range(39)]
    assert out[39] == (80.0, "pu hi")
    assert out[40:] == [(80.0, "hi"), (80.0, "hi")]


def test_a_down_rate_of_0_jumps_and_sets_its_flag():
    # up-rates 100, down-rates 0, limits ±100; autoValue 5, 5, 2, -3, -3. Call 0: 0 + 10 = 10 is
    # beyond 5: 5.0, no flag. Call 1: p = 5 >= 5, the down-rate 0: posDownRateLim, out 5.0.
    # Call 2: 2.0. Call 3: autoValue < 0 across the sign: 0.0. Call 4: p = 0.0 is in the positive
    # range: 0.0 again.
    rates = {"setPosUpRateLim": 100.0, "setNegUpRateLim": 100.0}
    rates |= {"setPosDownRateLim": 0.0, "setNegDownRateLim": 0.0}
    limits = {"setHighLim": 100.0, "setLowLim": -100.0}
    seq = [{"autoValue": a} for a in (5.0, 5.0, 2.0, -3.0, -3.0)]
    out = run(seq, **rates, **limits)
    assert out == [(5.0, ""), (5.0, "pd"), (2.0, "pd"), (0.0, "pd"), (0.0, "pd")]
    # the negative range: from -10 (tracked) towards 5 with setNegDownRateLim 0: 0.0 and the
    # flag; then from 0.0 in the positive range up to 5 (10 per call, 5 reached at once).
    seq = [{"track": True, "autoValue": -10.0}, {"track": False, "autoValue": 5.0}, {}]
    out = run(seq, **rates, **limits)
    assert out == [(-10.0, ""), (0.0, "nd"), (5.0, "")]
    # towards -3 from -10: -3.0 at once, with the flag
    seq = [{"track": True, "autoValue": -10.0}, {"track": False, "autoValue": -3.0}]
    assert run(seq, **rates, **limits)[1] == (-3.0, "nd")


def test_the_negative_ramp_and_the_low_limit():
    # from 0 towards -100: p = 0 is the positive range, p >= a, a < 0: the time to zero 0 / 40
    # = 0 <= 0.1, so -(0.1 - 0) · 20 = -2.0 with negUpRateLim (posDownRateLim cleared). Then -2
    # per call; -80 in call 39 (lowLim, the cut step 2 not shorter: negUpRateLim stays); call
    # 40: cut from -82, step 0 < 2: negUpRateLim cleared.
    out = run([{"autoValue": -100.0}] + [{}] * 41)
    assert out[:39] == [(-2.0 * (k + 1), "nu") for k in range(39)]
    assert out[39:] == [(-80.0, "nu lo"), (-80.0, "lo"), (-80.0, "lo")]


def test_crossing_zero():
    # cycle 1 s (dt 1.0). From 1.0 (tracked) towards -100, setPosDownRateLim 4: zero after
    # 0.25 s, then -(1 - 0.25) · 20 = -15 with negUpRateLim.
    seq = [{"track": True, "autoValue": 1.0}, {"track": False, "autoValue": -100.0}]
    assert run(seq, 1_000_000, setPosDownRateLim=4.0)[1] == (-15.0, "nu")
    # the target between: -5 > -15: out = autoValue, no flag
    seq[1] = {"track": False, "autoValue": -5.0}
    assert run(seq, 1_000_000, setPosDownRateLim=4.0)[1] == (-5.0, "")
    # from 10: 2.5 s to zero, longer than the cycle: 10 - 1 · 4 = 6 with posDownRateLim
    seq = [{"track": True, "autoValue": 10.0}, {"track": False, "autoValue": -100.0}]
    assert run(seq, 1_000_000, setPosDownRateLim=4.0)[1] == (6.0, "pd")
    # and the mirror image from the negative range with setNegDownRateLim 4
    seq = [{"track": True, "autoValue": -1.0}, {"track": False, "autoValue": 100.0}]
    assert run(seq, 1_000_000, setNegDownRateLim=4.0)[1] == (15.0, "pu")
    seq = [{"track": True, "autoValue": -10.0}, {"track": False, "autoValue": 100.0}]
    assert run(seq, 1_000_000, setNegDownRateLim=4.0)[1] == (-6.0, "nd")


def test_plus_and_minus_zero_are_the_positive_range():
    # p = -0.0 (tracked) towards -10: the positive range's falling branch: the time to zero
    # -0.0 / 40 = -0.0, -(0.1 + 0.0) · 20 = -2.0 with negUpRateLim.
    seq = [{"track": True, "autoValue": -0.0}, {"track": False, "autoValue": -10.0}]
    out = run(seq)
    assert out[0] == (0.0, "") and math.copysign(1.0, out[0][0]) == -1.0
    assert out[1] == (-2.0, "nu")
    # with setPosDownRateLim 0 the positive range's rule holds -0.0 at 0.0 with posDownRateLim
    assert run(seq, setPosDownRateLim=0.0)[1] == (0.0, "pd")


def test_limit_flags_in_the_reset_call():
    reset = {"reset": True, "enDefaultOutValue": True}
    assert run([{**reset, "defaultOutValue": 200.0}]) == [(80.0, "hi")]
    assert run([{**reset, "defaultOutValue": -200.0}]) == [(-80.0, "lo")]
    assert run([{**reset, "defaultOutValue": 80.0}]) == [(80.0, "hi")]  # at >=
    assert run([{**reset, "defaultOutValue": 50.0}]) == [(50.0, "")]
    # equal limits: both IFs apply
    assert run([{**reset, "defaultOutValue": 10.0, "setHighLim": 10.0, "setLowLim": 10.0}]) == [
        (10.0, "hi lo")
    ]
    # without the pre-assignment: 0.0, no limit applied, no flag (limits 10 … 20)
    assert run([{"reset": True, "setHighLim": 20.0, "setLowLim": 10.0}]) == [(0.0, "")]
    # reset is a level, and it ends the manual mode
    out = run([{"manOp": True, "manualValue": 200.0}, {"reset": True}, {}])
    assert out == [(200.0, ""), (0.0, ""), (0.0, "")]


def test_manual_mode_then_the_limits_suspended():
    # manOp with 100 (beyond 80): no limit, no flag. Back in automatic towards 50: the ramp
    # down by 4 per call with posDownRateLim; highLim TRUE while >= 80 but no cut (suspended),
    # also at 80 itself (call 5); in call 6 (76) the output is within: the limits apply again.
    seq = [{"manOp": True, "manualValue": 100.0}, {"manOp": False, "autoValue": 50.0}] + [{}] * 12
    out = run(seq)
    assert out[0] == (100.0, "")
    assert out[1:6] == [(96.0, "pd hi"), (92.0, "pd hi"), (88.0, "pd hi"), (84.0, "pd hi")] + [
        (80.0, "pd hi")
    ]
    assert out[6:] == [(76.0 - 4 * k, "pd") for k in range(6)] + [(52.0, "pd"), (50.0, "")]
    # a tracked autoValue beyond the limit after manual mode stays uncut with highLim
    seq = [{"manOp": True}, {"manOp": False, "track": True, "autoValue": 200.0}, {}]
    assert run(seq) == [(0.0, ""), (200.0, "hi"), (200.0, "hi")]
    # manual mode itself: no limit flag
    assert run([{"manOp": True, "manualValue": -500.0}]) == [(-500.0, "")]


def test_the_pre_assignment_and_tracking_in_automatic_mode_are_limited():
    out = run([{"enDefaultOutValue": True, "defaultOutValue": 90.0}, {"enDefaultOutValue": False}])
    # call 0: 90 cut to 80 with highLim; the cut step 80 - 0 is not shorter than 2: no rate flag
    # was set anyway. Call 1: from 80 towards 100: 82 cut to 80, step 0: highLim only.
    assert out == [(80.0, "hi"), (80.0, "hi")]
    assert run([{"track": True, "autoValue": -90.0}]) == [(-80.0, "lo")]


def test_errors_keep_the_outputs():
    # two calls (2.0, 4.0), then setHighLim < setLowLim: 16#8200 with outputValue 4.0 and the
    # flag kept; a negative rate: 16#8202 (the limits are checked first); valid again: 6.0
    # from p = 4.0.
    seq = [{}, {}, {"setHighLim": -90.0}, {"setPosDownRateLim": -1.0}, {"setHighLim": 80.0}]
    seq += [{"setPosDownRateLim": 40.0}]
    m = LimRateOfChangeAdvancedCI(100_000)
    inputs = dict(START)
    outs = []
    for k, changes in enumerate(seq):
        inputs.update(changes)
        outs.append(m.call(k * 100_000, dict(inputs)))
    assert [(o["error"], o["status"]) for o in outs] == [
        (False, 0),
        (False, 0),
        (True, STATUS_LIMITS),
        (True, STATUS_LIMITS),
        (True, STATUS_NEG_RATE),
        (False, 0),
    ]
    assert [o["outputValue"] for o in outs] == [2.0, 4.0, 4.0, 4.0, 4.0, 6.0]
    assert [o["posUpRateLim"] for o in outs] == [True] * 6
    # an error in the first call: the outputs' start values; reset does not act
    assert run([{"setNegUpRateLim": -1.0, "reset": True}]) == [(STATUS_NEG_RATE, 0.0)]


def test_dt_is_a_real_count_of_microseconds():
    assert dt_seconds(100_000) == 0.1
    assert dt_seconds(16_777_217) == 16.777216  # 2^24 + 1 rounds to 2^24 in a REAL
    assert dt_seconds(7) == 7 / 1e6


def test_infinities_and_the_nan_they_make():
    # autoValue +Inf: 2.0 per call as usual
    assert run([{"autoValue": INF}])[0] == (2.0, "pu")
    # an infinite up-rate: the ramp's value is +Inf, not below the target: out = +Inf, cut to 80
    assert run([{"autoValue": INF, "setPosUpRateLim": INF}]) == [(80.0, "hi")]
    # limits ±Inf, tracked -Inf: out -Inf (lowLim at <=). Then towards 5 with setNegDownRateLim
    # +Inf: the time to zero Inf / Inf = NaN is not <= dt, so out = -Inf + 0.1 · Inf = NaN with
    # negDownRateLim; then from p = NaN every comparison is FALSE: out = autoValue.
    seq = [{"track": True, "autoValue": -INF}, {"track": False, "autoValue": 5.0}, {}]
    out = run(seq, setHighLim=INF, setLowLim=-INF, setNegDownRateLim=INF)
    assert out[0] == (-INF, "lo")
    assert math.isnan(out[1][0]) and out[1][1] == "nd"
    assert struct.pack(">d", out[1][0]) == bytes.fromhex("7ff8000000000000")  # §1.4
    assert out[2] == (5.0, "")


def test_nan_is_refused():
    m = LimRateOfChangeAdvancedCI(100_000)
    for name in ("autoValue", "setHighLim", "defaultOutValue"):
        with pytest.raises(ValueError):
            m.call(0, {**START, name: math.nan})
