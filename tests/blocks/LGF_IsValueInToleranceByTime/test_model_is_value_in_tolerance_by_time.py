"""Hand traces of the IsValueInToleranceByTime model against docs/behaviour.md §13 (no FMU): call
k at k · 100 ms. Flags per call are written as strings of the letters O (overHighLimit), B
(belowLowLimit), I (inLimits), S (setpointChange), "-" for none."""

import math

import numpy as np
import pytest

from .model import IsValueInToleranceByTime, limits

C = "configuration."
CYCLE_US = 100_000

BASE = {
    "value": 60.0,
    "setpoint": 50.0,
    "lowerMinimum": 10.0,
    "upperMaximum": 10.0,
    "reset": False,
    C + "disableLimits": False,
    C + "limitsAsAbsoluteValues": False,
    C + "toleranceAsAbsoluteValues": False,
    C + "upperLimitMonitoringTime": 1.0,
    C + "lowerLimitMonitoringTime": 1.0,
    C + "setpointChangeMonitoringTime": 2.0,
}


def flags(o):
    s = "".join(c for c, n in zip("OBIS", ("overHighLimit", "belowLowLimit", "inLimits",
                                           "setpointChange")) if o[n])  # fmt: skip
    return s or "-"


def run(changes, n, **base):
    """Flags per call for n calls; changes maps a call number to the inputs changed from there."""
    m = IsValueInToleranceByTime(CYCLE_US)
    inputs = {**BASE, **{k.replace("__", "."): v for k, v in base.items()}}
    out = []
    for k in range(n):
        inputs.update(changes.get(k, {}))
        out.append(flags(m.call(k * CYCLE_US, dict(inputs))))
    return out


def first(out, flag):
    return next(k for k, f in enumerate(out) if flag in f)


def test_start_values_show_the_timing():
    # §13.1: call 0 sees the change 0.0 -> 50.0 (band 45 … 55, value 60 never inside):
    # setpointChange until the grace TON (2 s, started in call 0) elapses in call 20; from then
    # the high TON runs (IN = above AND grace) and elapses 1 s later, call 30.
    out = run({}, 35)
    assert out[:20] == ["S"] * 20
    assert out[20:30] == ["-"] * 10
    assert out[30:] == ["O"] * 5


def test_percent_limits_in_float32():
    # §13.2 step 2: 50 · (1.0 + 10/100) = 55.0, 50 · (1.0 - 10/100) = 45.0 in float32; 3 · (1.0 +
    # 5/100): 5/100 = 0.05 (0.0500000007), 1.05 -> 1.04999995, · 3 = 3.1499999 (not 3.15).
    assert limits(np.float32(50), np.float32(10), np.float32(10), False, False) == (55.0, 45.0)
    high, low = limits(np.float32(3), np.float32(7), np.float32(5), False, False)
    assert high == np.float32(3.1499999) and high < np.float32(3.15)
    assert low == np.float32(2.79)
    # absolute tolerances: setpoint ± tolerance; absolute limits: the inputs themselves
    assert limits(np.float32(100), np.float32(5), np.float32(20), False, True) == (120.0, 95.0)
    assert limits(np.float32(100), np.float32(5), np.float32(20), True, True) == (20.0, 5.0)


def test_value_arriving_ends_the_setpoint_change():
    # §13.3: value 60 in calls 0-4, 50 from call 5: within -> wasWithinTolerance, setpointChange
    # FALSE, inLimits TRUE.
    out = run({5: {"value": 50.0}}, 10)
    assert out == ["S"] * 5 + ["I"] * 5


def test_change_into_a_band_that_holds_the_value_shows_no_setpoint_change():
    # §13.3: steps 6.1 and 6.2 in the same call.
    assert run({}, 3, value=50.0) == ["I"] * 3


def test_short_violations_are_hidden():
    # §13.3: arrived in call 0; value 60 in calls 3-11 (9 calls: the high TON starts in call 3 at
    # 0.3 s and would elapse at 1.3 s = call 13): never reported, inLimits stays TRUE. Then 60
    # from call 15: reported in call 25 (2.5 - 1.5 >= 1.0), inLimits FALSE.
    changes = {3: {"value": 60.0}, 12: {"value": 50.0}, 15: {"value": 60.0}}
    out = run(changes, 27, value=50.0)
    assert out[:25] == ["I"] * 25
    assert out[25:] == ["O", "O"]


def test_violation_timer_restarts_after_one_call_inside():
    # §13.3: value 60 from call 1 (TON 0.1 s), back inside in call 8 only, 60 again from call 9
    # (TON restarts at 0.9 s): reported in call 19, not 11.
    changes = {1: {"value": 60.0}, 8: {"value": 50.0}, 9: {"value": 60.0}}
    out = run(changes, 21, value=50.0)
    assert first(out, "O") == 19
    assert out[18] == "I" and out[19] == "O"


def test_below_with_its_own_time():
    # §13.2 step 6.5: value 40 from call 1, lowerLimitMonitoringTime 0.5 s: belowLowLimit in
    # call 6; upperLimitMonitoringTime plays no part.
    out = run({1: {"value": 40.0}}, 8, value=50.0, configuration__lowerLimitMonitoringTime=0.5)
    assert out == ["I"] * 6 + ["B", "B"]


def test_never_arriving_below_is_reported_after_grace_plus_lower_time():
    # §13.3: value 0, setpoint 50: grace 2 s (call 20), then the low TON 1 s: call 30.
    out = run({}, 32, value=0.0)
    assert first(out, "B") == 30 and out[19] == "S" and out[20] == "-"


def test_start_without_a_setpoint_change_still_runs_the_grace():
    # §13.3: setpoint 0.0 in the first call is no change (no setpointChange); absolute tolerances
    # of 1, value 5: above; grace elapses in call 20, high TON in call 30. A setpoint of -0.0 is no
    # change either (IEEE: -0.0 = 0.0).
    for sp in (0.0, -0.0):
        kw = dict(value=5.0, setpoint=sp, lowerMinimum=1.0, upperMaximum=1.0)
        out = run({}, 31, configuration__toleranceAsAbsoluteValues=True, **kw)
        assert out[:30] == ["-"] * 30 and out[30] == "O"


def test_further_change_before_arrival_does_not_restart_the_grace():
    # §13.3: setpoint 52 in call 10 (band 46.8 … 57.2, value 60 still above): setpointChange TRUE
    # again (it already was), the grace TON keeps its start (call 0) and elapses in call 20; over
    # in call 30. A change in call 25, after the grace elapsed, shows no setpointChange (6.3 clears
    # it in the same call) and does not delay the report.
    out = run({10: {"setpoint": 52.0}, 25: {"setpoint": 53.0}}, 31)
    assert out[:20] == ["S"] * 20 and out[20:30] == ["-"] * 10 and out[30] == "O"


def test_change_after_arrival_restarts_the_grace_and_stops_the_violation_timers():
    # §13.3: arrived in call 0 (value 50); value 60 from call 2 (high TON from 0.2 s, would elapse
    # in call 12); setpoint 51 in call 5 (band 45.9 … 56.1, 60 above): was := FALSE, the grace
    # restarts (IN FALSE -> TRUE at 0.5 s), the high TON's IN is FALSE (reset). setpointChange from
    # call 5 until the grace elapses in call 25; the high TON restarts there: over in call 35.
    changes = {2: {"value": 60.0}, 5: {"setpoint": 51.0}}
    out = run(changes, 37, value=50.0)
    assert out[:5] == ["I"] * 5
    assert out[5:25] == ["S"] * 20
    assert out[25:35] == ["-"] * 10 and out[35:] == ["O", "O"]


def test_change_after_arrival_with_no_grace_time_keeps_timing():
    # §13.3 "unless setpointChangeMonitoringTime <= 0": the grace TON gives Q in its rising call,
    # so the violation timer goes on: high TON from 0.2 s elapses in call 12.
    changes = {2: {"value": 60.0}, 5: {"setpoint": 51.0}}
    out = run(changes, 13, value=50.0, configuration__setpointChangeMonitoringTime=0.0)
    assert out[5:12] == ["-"] * 7 and out[12] == "O"


def test_reset_is_a_level_and_absorbs_a_setpoint_change():
    # §13.3: arrived (value 50); reset in calls 3-5 with a setpoint change to 52 in call 4: all
    # four flags FALSE; in call 6 no change is seen (setpointPrevious followed), the grace starts
    # again: value 50 is inside the new band 46.8 … 57.2 at once: inLimits in call 6.
    out = run({3: {"reset": True}, 4: {"setpoint": 52.0}, 6: {"reset": False}}, 8, value=50.0)
    assert out == ["I"] * 3 + ["-"] * 3 + ["I"] * 2
    # with the value outside after the reset: the grace runs from call 6 (no setpointChange, as no
    # change is seen), over in call 6 + 20 + 10 = 36.
    out = run({3: {"reset": True, "value": 60.0}, 6: {"reset": False}}, 37, value=50.0)
    assert out[6:36] == ["-"] * 30 and out[36] == "O"


def test_reset_stops_a_running_violation_timer():
    # §13.2 step 5: the TONs are executed with IN FALSE: the high TON from 0.1 s is reset in call
    # 5; after the reset (call 6) the grace runs again (2 s), then the high TON (1 s): call 36.
    out = run({1: {"value": 60.0}, 5: {"reset": True}, 6: {"reset": False}}, 37, value=50.0)
    assert "O" not in "".join(out[:36]) and out[36] == "O"


def test_disable_limits_reports_the_position_at_once():
    # §13.3: disableLimits: over/below/in = above/below/within in every call, setpointChange FALSE;
    # released in call 4: starts over as after a reset (grace from call 4, value 60 above: over in
    # call 4 + 20 + 10 = 34).
    changes = {1: {"value": 40.0}, 2: {"value": 60.0}, 4: {C + "disableLimits": False}}
    out = run(changes, 35, **{"configuration__disableLimits": True}, value=50.0)
    assert out[:4] == ["I", "B", "O", "O"]
    assert out[4:34] == ["-"] * 30 and out[34] == "O"


def test_status_codes():
    m = IsValueInToleranceByTime(CYCLE_US)

    def status(**kw):
        o = m.call(0, {**BASE, **{k.replace("__", "."): v for k, v in kw.items()}})
        assert o["error"] == (o["status"] != 0)
        if o["error"]:
            assert flags(o) == "-"  # §13.4: the four flags FALSE
        return o["status"]

    # §13.3: percent tolerance of a negative setpoint: high -110 < low -90: 16#8401
    assert status(setpoint=-100.0) == 0x8401
    # a NaN limit: setpoint +Inf with 100 % lower tolerance: Inf · (1.0 - 1.0) = Inf · 0 = NaN
    assert status(setpoint=math.inf, lowerMinimum=100.0) == 0x8401
    # absolute limits: low 10 > high 5: 16#8401 first, even with the setpoint above both
    abs_ = {"configuration__limitsAsAbsoluteValues": True}
    assert status(setpoint=50.0, lowerMinimum=10.0, upperMaximum=5.0, **abs_) == 0x8401
    assert status(setpoint=50.0, lowerMinimum=10.0, upperMaximum=40.0, **abs_) == 0x8402
    assert status(setpoint=5.0, lowerMinimum=10.0, upperMaximum=40.0, **abs_) == 0x8403
    assert status(setpoint=10.0, lowerMinimum=10.0, upperMaximum=40.0, **abs_) == 0
    # relative limits never give 16#8402/16#8403: an absolute tolerance of -5 on both sides gives
    # high 45 < low 55: 16#8401
    tol = {"configuration__toleranceAsAbsoluteValues": True}
    assert status(lowerMinimum=-5.0, upperMaximum=-5.0, **tol) == 0x8401
    assert status(lowerMinimum=0.0, upperMaximum=0.0, **tol) == 0


def test_error_clears_the_monitoring_as_reset_does():
    # §13.4: arrived (value 50); in calls 3-4 the setpoint is -100 (16#8401); back to 50 in call 5
    # (a change: setpointChange TRUE unless the value is inside; it is: inLimits at once).
    out = run({3: {"setpoint": -100.0}, 5: {"setpoint": 50.0}}, 7, value=50.0)
    assert out == ["I"] * 3 + ["-"] * 2 + ["I"] * 2
    # an error that leaves the setpoint unchanged: absolute limits out of order in calls 3-4; the
    # grace restarts in call 5 (no change seen, value 60 above: no setpointChange).
    changes = {
        2: {"value": 60.0},
        3: {C + "limitsAsAbsoluteValues": True},
        5: {C + "limitsAsAbsoluteValues": False},
    }
    out = run(changes, 36, value=50.0)
    assert out[:2] == ["I", "I"] and out[2] == "I" and out[3:5] == ["-", "-"]
    assert out[5:35] == ["-"] * 30 and out[35] == "O"


def test_zero_and_negative_monitoring_times():
    # §13.2: a PT of 0 (or negative) gives Q in the rising call: the violation is reported at once.
    out = run({2: {"value": 60.0}}, 4, value=50.0, configuration__upperLimitMonitoringTime=-1.0)
    assert out == ["I", "I", "O", "O"]


def test_infinite_value_is_above():
    # §13.3: value +Inf is above any finite high limit; -Inf below any finite low limit.
    out = run({1: {"value": math.inf}, 3: {"value": -math.inf}}, 4, value=50.0,
              configuration__upperLimitMonitoringTime=0.0,
              configuration__lowerLimitMonitoringTime=0.0)  # fmt: skip
    assert out == ["I", "O", "O", "B"]


def test_refused_values():
    m = IsValueInToleranceByTime(CYCLE_US)
    for name, bad in (
        ("value", float("nan")),
        ("setpoint", 3.5e38),
        ("upperMaximum", float("nan")),
        (C + "setpointChangeMonitoringTime", float("nan")),
        (C + "upperLimitMonitoringTime", 2147483.648),
    ):
        with pytest.raises(ValueError):
            m.call(0, {**BASE, name: bad})
