"""LGF_IsValueInToleranceByTime against the rules of docs/behaviour.md §13, with hand-computed
expectations (each trace is worked out from §13.2 in the comments, never taken from the FMU).

Call k happens at k·0.1 s unless said otherwise; the inputs of call k are set before the step
that ends there (call 0: in initialization). "TON from call a, PT p" means Q from the first call
at or after a·0.1 s + p (§1.12)."""

import math

import numpy as np
import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of

BLOCK = "LGF_IsValueInToleranceByTime"
INF = math.inf
FLAGS = ("overHighLimit", "belowLowLimit", "inLimits", "setpointChange")
C = "configuration."
START = {
    "value": 50.0,
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


def run(calls, changes=None, cycle=0.1, **initial):
    """The outputs of calls 0 ... calls-1; changes[k] is set before call k."""
    changes = changes or {}
    s = Slave(BLOCK, {"cycleTime": cycle}, {**START, **initial, **changes.get(0, {})})
    rows = [s.outputs()]
    for k in range(1, calls):
        s.set(changes.get(k, {}))
        rows.append(s.step(cycle))
    s.free()
    return rows


def true_in(rows, name):
    """The calls in which output `name` is TRUE."""
    return [k for k, r in enumerate(rows) if r[name]]


def f32(x):
    return np.float32(x)


# ---- limits (§13.2 steps 2 and 4), seen through disableLimits (positions at once) ----------


def position(**inputs):
    """overHighLimit, belowLowLimit, inLimits of one call with disableLimits (§13.2 step 5)."""
    [row] = run(1, **{C + "disableLimits": True, **inputs})
    return row["overHighLimit"], row["belowLowLimit"], row["inLimits"], row["status"]


def test_percent_limits_in_real():
    # setpoint 50, 10 %: 10/100 -> 0.1f; 1 + 0.1f = 1.10000002f; 50 * 1.10000002f = 55.0000012,
    # rounded to float32: 55.0 (its neighbours are 3.8e-6 apart). 1 - 0.1f = 0.899999976f;
    # 50 * 0.899999976f = 44.9999988 -> 45.0. So the band is 45.0 ... 55.0, both ends inside.
    above_55 = float(np.nextafter(f32(55.0), f32(INF)))
    below_45 = float(np.nextafter(f32(45.0), f32(-INF)))
    assert position(value=55.0) == (False, False, True, 0)
    assert position(value=above_55) == (True, False, False, 0)
    assert position(value=45.0) == (False, False, True, 0)
    assert position(value=below_45) == (False, True, False, 0)
    # setpoint 0.3f, 10 %: high = 0.3f * 1.1f, low = 0.3f * 0.9f (0.899999976f), each rounded
    sp = f32(0.3)
    high = sp * (f32(1.0) + f32(10.0) / f32(100.0))
    low = sp * (f32(1.0) - f32(10.0) / f32(100.0))
    assert position(value=float(high), setpoint=0.3) == (False, False, True, 0)
    assert position(value=float(np.nextafter(high, f32(INF))), setpoint=0.3)[0]
    assert position(value=float(low), setpoint=0.3) == (False, False, True, 0)
    assert position(value=float(np.nextafter(low, f32(-INF))), setpoint=0.3)[1]


def test_absolute_tolerances_and_absolute_limits():
    tol = {C + "toleranceAsAbsoluteValues": True, "upperMaximum": 2.0, "lowerMinimum": 3.0}
    # setpoint 50: high 50 + 2 = 52, low 50 - 3 = 47
    assert position(value=52.0, **tol)[:3] == (False, False, True)
    assert position(value=52.5, **tol)[:3] == (True, False, False)
    assert position(value=46.5, **tol)[:3] == (False, True, False)
    # absolute limits 40 ... 60, whatever the setpoint (here 50 and 41); the tolerance flag has
    # no effect then
    lim = {C + "limitsAsAbsoluteValues": True, "lowerMinimum": 40.0, "upperMaximum": 60.0}
    assert position(value=59.0, **lim)[:3] == (False, False, True)
    assert position(value=61.0, **lim)[:3] == (True, False, False)
    assert position(value=39.0, setpoint=41.0, **lim, **{C + "toleranceAsAbsoluteValues": True})[
        :3
    ] == (False, True, False)


def test_infinite_values():
    # +Inf is above the finite high limit 55, -Inf below 45
    assert position(value=INF)[:3] == (True, False, False)
    assert position(value=-INF)[:3] == (False, True, False)
    # setpoint +Inf, 10 %: high = Inf * 1.1 = Inf, low = Inf * 0.9 = Inf; low <= high: no
    # error; 50 < Inf: below
    assert position(setpoint=INF) == (False, True, False, 0)


# ---- status codes (§13.2 step 3, §13.4) ------------------------------------------------------


@pytest.mark.parametrize(
    "inputs, status",
    [
        # percent of a negative setpoint: high = -100 * 1.1 = -110, low = -100 * 0.9 = -90
        ({"setpoint": -100.0, "value": -100.0}, 0x8401),
        # absolute tolerances with a negative upper tolerance: high 50 - 20 = 30 < low 40
        ({C + "toleranceAsAbsoluteValues": True, "upperMaximum": -20.0}, 0x8401),
        # absolute tolerances: Inf + (-Inf) = NaN as the high limit
        ({C + "toleranceAsAbsoluteValues": True, "setpoint": INF, "upperMaximum": -INF}, 0x8401),
        # absolute limits out of order: low 60 > high 40 (8401 before 8402 although 100 > 40)
        (
            {
                C + "limitsAsAbsoluteValues": True,
                "lowerMinimum": 60.0,
                "upperMaximum": 40.0,
                "setpoint": 100.0,
            },
            0x8401,
        ),
        # absolute limits 10 ... 10 (the start tolerances): setpoint 50 above the high limit
        ({C + "limitsAsAbsoluteValues": True}, 0x8402),
        # absolute limits 40 ... 60, setpoint 30 below the low limit
        (
            {
                C + "limitsAsAbsoluteValues": True,
                "lowerMinimum": 40.0,
                "upperMaximum": 60.0,
                "setpoint": 30.0,
                "value": 50.0,
            },
            0x8403,
        ),
        # a zero band is in order: setpoint 50, 0 %: 45 ... 55 becomes 50 ... 50
        ({"lowerMinimum": 0.0, "upperMaximum": 0.0}, 0),
    ],
)
def test_status_codes(inputs, status):
    rows = run(3, **inputs)
    for r in rows:
        assert (r["status"], r["error"]) == (status, status != 0)
        if status:  # an error call: all four flags FALSE
            assert not any(r[name] for name in FLAGS)


def test_an_error_clears_the_monitoring_and_is_logged():
    # value 50 inside from call 0 (inLimits). Calls 3 ... 5: absolute limits 10 ... 10, status
    # 16#8402, everything FALSE. Call 6: back to tolerances, value 60 (outside): the monitoring
    # starts over: grace TON from call 6 (PT 2 s) -> Q at call 26; high TON from call 26 (1 s)
    # -> overHighLimit from call 36. setpointChange stays FALSE (no setpoint change).
    lim = {C + "limitsAsAbsoluteValues": True}
    s = Slave(BLOCK, {"cycleTime": 0.1}, START)
    rows = [s.outputs()]
    for k in range(1, 40):
        s.set(
            lim
            if k == 3
            else {C + "limitsAsAbsoluteValues": False, "value": 60.0}
            if k == 6
            else {}
        )
        rows.append(s.step(0.1))
    assert [r["status"] for r in rows] == [0] * 3 + [0x8402] * 3 + [0] * 34
    assert true_in(rows, "error") == [3, 4, 5]
    assert true_in(rows, "inLimits") == [0, 1, 2]
    assert true_in(rows, "overHighLimit") == list(range(36, 40))
    assert true_in(rows, "setpointChange") == []
    assert any("16#8402" in text for _, _, text in s.log)  # §1.6: the change is logged
    s.free()


# ---- timing (§13.2 step 6, §13.3) --------------------------------------------------------------


def test_the_start_values_wait_two_seconds_then_time_the_violation():
    # §13.1: value 60, setpoint 50 (a change from 0.0 in call 0): setpointChange from call 0;
    # grace TON from call 0, PT 2 s -> Q at call 20, ends the waiting; high TON from call 20,
    # PT 1 s -> overHighLimit from call 30; inLimits never (the value never arrived)
    s = Slave(BLOCK)
    rows = [s.outputs()] + [s.step(0.1) for _ in range(34)]
    assert true_in(rows, "setpointChange") == list(range(0, 20))
    assert true_in(rows, "overHighLimit") == list(range(30, 35))
    assert true_in(rows, "inLimits") == [] and true_in(rows, "belowLowLimit") == []
    s.free()


def test_a_value_inside_from_the_start_is_in_limits_at_once():
    # call 0: change 0 -> 50 sets setpointChange, but the value is inside in the same call:
    # arrived, waiting over: setpointChange never TRUE, inLimits from call 0
    rows = run(5)
    assert true_in(rows, "inLimits") == [0, 1, 2, 3, 4]
    assert true_in(rows, "setpointChange") == []


def test_a_short_peak_is_hidden():
    # value 57 (above 55) in calls 1 ... 5 (0.5 s < 1 s): high TON from call 1 would give Q at
    # call 11; it falls in call 6. Nothing reported, inLimits stays TRUE.
    rows = run(15, {1: {"value": 57.0}, 6: {"value": 50.0}})
    assert true_in(rows, "overHighLimit") == []
    assert true_in(rows, "inLimits") == list(range(15))


def test_a_violation_is_reported_after_its_monitoring_time():
    # value 58 from call 1: high TON from call 1, PT 1 s -> overHighLimit from call 11;
    # inLimits until call 10 (hidden so far); back inside at call 15: overHighLimit FALSE
    rows = run(18, {1: {"value": 58.0}, 15: {"value": 50.0}})
    assert true_in(rows, "overHighLimit") == [11, 12, 13, 14]
    assert true_in(rows, "inLimits") == list(range(0, 11)) + [15, 16, 17]
    # value 40 from call 1 with a low time of 0.5 s: belowLowLimit from call 6
    rows = run(9, {1: {"value": 40.0}}, **{C + "lowerLimitMonitoringTime": 0.5})
    assert true_in(rows, "belowLowLimit") == [6, 7, 8]
    assert true_in(rows, "overHighLimit") == []


def test_a_violation_timer_restarts_when_the_value_comes_back_for_one_call():
    # above in calls 1 ... 7, inside in call 8, above from call 9: the TON restarts at call 9,
    # overHighLimit from call 19 (not 11)
    rows = run(21, {1: {"value": 58.0}, 8: {"value": 50.0}, 9: {"value": 58.0}})
    assert true_in(rows, "overHighLimit") == [19, 20]


def test_a_setpoint_change_is_waited_out_until_the_value_arrives():
    # call 3: setpoint 80 (band 72 ... 88), value 50 below: setpointChange TRUE, grace TON from
    # call 3 (Q at call 23); call 8: value 75 inside: arrived, setpointChange FALSE, inLimits
    rows = run(12, {3: {"setpoint": 80.0}, 8: {"value": 75.0}})
    assert true_in(rows, "setpointChange") == [3, 4, 5, 6, 7]
    assert true_in(rows, "inLimits") == [0, 1, 2, 8, 9, 10, 11]
    assert true_in(rows, "belowLowLimit") == []


def test_a_value_that_never_arrives_is_reported_after_grace_and_monitoring_time():
    # call 3: setpoint 80, value stays 50: setpointChange calls 3 ... 22; grace Q at call 23
    # (3·0.1 + 2 s); low TON from call 23, PT 1 s -> belowLowLimit from call 33
    rows = run(36, {3: {"setpoint": 80.0}})
    assert true_in(rows, "setpointChange") == list(range(3, 23))
    assert true_in(rows, "belowLowLimit") == [33, 34, 35]
    assert true_in(rows, "inLimits") == [0, 1, 2]


def test_a_change_into_a_band_that_holds_the_value_shows_nothing():
    # call 3: setpoint 51 (10 %: 45.9 ... 56.1 in REAL), value 50 inside in the same call
    rows = run(6, {3: {"setpoint": 51.0}})
    assert true_in(rows, "setpointChange") == []
    assert true_in(rows, "inLimits") == list(range(6))


def test_a_change_stops_a_violation_being_timed():
    # value 58 from call 1 (high TON from call 1); call 5: setpoint 52 (46.8 ... 57.2), 58 still
    # above: wasWithinTolerance FALSE, grace TON from call 5 (Q at call 25), the high TON's IN
    # FALSE (reset); setpointChange calls 5 ... 24; high TON again from call 25 -> call 35
    rows = run(37, {1: {"value": 58.0}, 5: {"setpoint": 52.0}})
    assert true_in(rows, "setpointChange") == list(range(5, 25))
    assert true_in(rows, "overHighLimit") == [35, 36]
    assert true_in(rows, "inLimits") == [0, 1, 2, 3, 4]


def test_a_further_change_before_arrival_does_not_restart_the_grace():
    # call 3: setpoint 80 (grace TON from call 3, Q at call 23); call 10: setpoint 90 (band 81 ...
    # 99), the value 50 still out: the grace timer's IN stays TRUE, so it still ends at call 23
    rows = run(26, {3: {"setpoint": 80.0}, 10: {"setpoint": 90.0}})
    assert true_in(rows, "setpointChange") == list(range(3, 23))


def test_reset_is_a_level_and_restarts_the_monitoring():
    # value 60 from call 1: overHighLimit from call 11; reset in calls 13, 14: all FALSE;
    # call 15: monitoring on again, not arrived: grace TON from call 15 (Q at call 35), high TON
    # from call 35 -> overHighLimit from call 45
    rows = run(47, {1: {"value": 60.0}, 13: {"reset": True}, 15: {"reset": False}})
    assert true_in(rows, "overHighLimit") == [11, 12] + [45, 46]
    for k in (13, 14):
        assert not any(rows[k][name] for name in FLAGS)
    # with the value inside, the first call after the reset is inLimits again
    rows = run(8, {3: {"reset": True}, 6: {"reset": False}})
    assert true_in(rows, "inLimits") == [0, 1, 2, 6, 7]
    # a setpoint change during the reset is absorbed: no setpointChange after it
    rows = run(8, {3: {"reset": True, "setpoint": 80.0, "value": 75.0}, 5: {"reset": False}})
    assert true_in(rows, "setpointChange") == []
    assert true_in(rows, "inLimits") == [0, 1, 2, 5, 6, 7]


def test_disable_limits_reports_at_once_and_restarts_on_release():
    d = C + "disableLimits"
    # calls 0, 1 inside: inLimits; call 2: 60 -> overHighLimit at once; call 3: 40 ->
    # belowLowLimit; call 4: 50 inside. Call 5 released with 60: not arrived, grace TON from
    # call 5 (Q at call 25), high TON from call 25 -> call 35. setpointChange always FALSE.
    rows = run(
        37,
        {2: {"value": 60.0}, 3: {"value": 40.0}, 4: {"value": 50.0}, 5: {d: False, "value": 60.0}},
        **{d: True},
    )
    assert true_in(rows, "overHighLimit") == [2, 35, 36]
    assert true_in(rows, "belowLowLimit") == [3]
    assert true_in(rows, "inLimits") == [0, 1, 4]
    assert true_in(rows, "setpointChange") == []
    # disableLimits with reset: all FALSE
    [row] = run(1, **{d: True, "reset": True})
    assert not any(row[name] for name in FLAGS)


def test_monitoring_times_follow_the_s7_rules():
    up = C + "upperLimitMonitoringTime"
    # a negative time counts as 0: a TON with PT 0 gives Q in the rising call (call 2)
    rows = run(4, {2: {"value": 60.0}}, **{up: -0.5})
    assert true_in(rows, "overHighLimit") == [2, 3]
    # a new time while the timer runs waits for its next start: PT 1 s taken at call 1 -> 11
    rows = run(13, {1: {"value": 60.0}, 3: {up: 0.2}})
    assert true_in(rows, "overHighLimit") == [11, 12]
    # the time in whole ms: 0.3004 s -> 300 ms from call 1 at cycle 0.05 s (call 1 = 0.05 s):
    # Q at the first call at or after 0.35 s, call 7; 0.3006 s -> 301 ms: call 8
    rows = run(10, {1: {"value": 60.0}}, cycle=0.05, **{up: 0.3004})
    assert true_in(rows, "overHighLimit")[0] == 7
    rows = run(10, {1: {"value": 60.0}}, cycle=0.05, **{up: 0.3006})
    assert true_in(rows, "overHighLimit")[0] == 8


def test_high_and_low_and_in_limits_exclude_each_other():
    # a run through every position (the hand traces above): at most one of the three is TRUE
    changes = {1: {"value": 60.0}, 15: {"value": 40.0}, 30: {"value": 50.0}, 32: {"value": 58.0}}
    rows = run(45, changes)
    for r in rows:
        assert r["overHighLimit"] + r["belowLowLimit"] + r["inLimits"] <= 1
    # 60 from call 1 -> high from 11; 40 from call 15 -> low TON from 15 -> 25; 50 at 30
    assert true_in(rows, "overHighLimit") == list(range(11, 15)) + list(range(42, 45))
    assert true_in(rows, "belowLowLimit") == list(range(25, 30))
    assert true_in(rows, "inLimits") == list(range(0, 11)) + list(range(15, 25)) + list(
        range(30, 42)
    )


# ---- refused values (§1.4, §1.7) -----------------------------------------------------------


@pytest.mark.parametrize(
    "name, value",
    [
        ("value", math.nan),
        ("setpoint", 3.5e38),  # beyond the largest REAL
        ("lowerMinimum", -1e39),
        ("upperMaximum", math.nan),
        (C + "upperLimitMonitoringTime", math.nan),
        (C + "lowerLimitMonitoringTime", 2147483.648),
        (C + "setpointChangeMonitoringTime", -3e6),
    ],
)
def test_values_outside_their_type_are_refused(name, value):
    s = Slave(BLOCK, {"cycleTime": 0.1}, START)
    before = s.get([name])[name]
    assert status_of(s.fmu.setReal, [s.vr(name)], [value]) == fmi2Error
    assert s.get([name])[name] == before
    assert any(name in text for _, _, text in s.log)
    s.free()


def test_outputs_are_not_settable():
    s = Slave(BLOCK)
    assert status_of(s.fmu.setBoolean, [s.vr("inLimits")], [True]) == fmi2Error
    assert status_of(s.fmu.setInteger, [s.vr("status")], [0]) == fmi2Error
    s.free()
