"""LGF_IsValueInToleranceByTime against the rules of docs/behaviour.md §13, with hand-computed
expectations (each trace is worked out from the block's original SCL, as §13.2 states it, in the
comments, never taken from the FMU).

Call k happens at k·0.1 s unless said otherwise; the inputs of call k are set before the step
that ends there (call 0: in initialization). "TON from call a, PT p" means Q from the first call
at or after a·0.1 s + p (§1.12). The names of §13.2: `arrived` (the original's "was within
tolerance"), `waiting` (its setpoint-change flag), the upper, lower and change timers; "armed"
is arrived OR the change timer's Q, read before the change timer runs in that call."""

import math

import numpy as np
import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of

from . import spec

BLOCK = "LGF_IsValueInToleranceByTime"
INF = math.inf
FLAGS = ("overHighLimit", "belowLowLimit", "inLimits", "setpointChange")
C = "configuration."
START = {**spec.START, "value": 50.0}  # inside the band


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


# ---- limits (§13.2 step 1) ----------------------------------------------------------------


ZERO_TIMES = {
    C + "upperLimitMonitoringTime": 0.0,
    C + "lowerLimitMonitoringTime": 0.0,
    C + "setpointChangeMonitoringTime": 0.0,
}


def position(**inputs):
    """overHighLimit, belowLowLimit, inLimits, status of call 1, all three times 0, the inputs
    from call 0 on (setpoint not 0.0). Call 0: a setpoint change (0.0 -> setpoint), arrived iff
    the value is inside; the change timer (PT 0) runs last and has Q at once if not arrived.
    Call 1: armed (arrived, or the change timer's Q read TRUE), so the upper or lower TON (PT 0)
    has Q in the call its IN rises: the flags show the position of the value."""
    rows = run(2, **{**ZERO_TIMES, **inputs})
    r = rows[1]
    return r["overHighLimit"], r["belowLowLimit"], r["inLimits"], r["status"]


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


def test_percent_tolerances_are_taken_as_magnitudes():
    # the original takes ABS of each percent tolerance: -10 % is 10 %, band 45 ... 55 as above
    # (without ABS an upper tolerance of -10 % would give a high limit of 45 and 54 above it)
    assert position(value=54.0, upperMaximum=-10.0) == (False, False, True, 0)
    assert position(value=56.0, upperMaximum=-10.0) == (True, False, False, 0)
    assert position(value=46.0, lowerMinimum=-10.0) == (False, False, True, 0)
    assert position(value=44.0, lowerMinimum=-10.0) == (False, True, False, 0)


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


def test_limits_out_of_order_are_no_error():
    # percent of a negative setpoint: high = -100 * 1.1 = -110, low = -100 * 0.9 = -90. No
    # fault, no status: -100 is both above -110 and below -90, so both TONs run (PT 0) and both
    # flags are TRUE; inLimits FALSE (never arrived)
    assert position(setpoint=-100.0, value=-100.0) == (True, True, False, 0)
    # absolute tolerances with a negative upper tolerance: high 50 - 20 = 30 < low 50 - 10 = 40;
    # 50 is above 30 only; 35 is above 30 and below 40
    tol = {C + "toleranceAsAbsoluteValues": True, "upperMaximum": -20.0}
    assert position(**tol) == (True, False, False, 0)
    assert position(value=35.0, **tol) == (True, True, False, 0)


def test_infinite_values():
    # value +Inf is only compared (no arithmetic, no fault): above the finite high limit 55;
    # -Inf below 45
    assert position(value=INF) == (True, False, False, 0)
    assert position(value=-INF) == (False, True, False, 0)
    # absolute limits compute nothing: infinite limits are no fault, 50 lies inside
    lim = {C + "limitsAsAbsoluteValues": True, "lowerMinimum": -INF, "upperMaximum": INF}
    assert position(**lim) == (False, False, True, 0)


# ---- status codes (§13.2 step 5, §13.4) ------------------------------------------------------


@pytest.mark.parametrize(
    "inputs, status",
    [
        # percent, setpoint +Inf: high = Inf * 1.1 = Inf, not finite: fault
        ({"setpoint": INF}, 0x8401),
        # percent, upperMaximum +Inf: ABS(Inf) / 100 = Inf, 1 + Inf = Inf, 50 * Inf = Inf
        ({"upperMaximum": INF}, 0x8401),
        # percent, an overflow of finite operands: 3e38 * (1 + 50/100) = 4.5e38 -> Inf
        ({"setpoint": 3e38, "upperMaximum": 50.0, "value": 3e38}, 0x8401),
        # absolute tolerances: Inf + (-Inf) = NaN as the high limit
        ({C + "toleranceAsAbsoluteValues": True, "setpoint": INF, "upperMaximum": -INF}, 0x8401),
        # absolute tolerances: 3e38 + 3e38 overflows to Inf
        ({C + "toleranceAsAbsoluteValues": True, "setpoint": 3e38, "upperMaximum": 3e38}, 0x8401),
        # absolute tolerances: -Inf - 1.0 = -Inf (an infinite operand)
        ({C + "toleranceAsAbsoluteValues": True, "setpoint": -INF, "lowerMinimum": 1.0}, 0x8401),
        # absolute limits out of order: low 60, high 40: setpoint 100 > 40 -> 16#8402 ...
        (
            {
                C + "limitsAsAbsoluteValues": True,
                "lowerMinimum": 60.0,
                "upperMaximum": 40.0,
                "setpoint": 100.0,
            },
            0x8402,
        ),
        # ... setpoint 30: not above 40, below 60 -> 16#8403
        (
            {
                C + "limitsAsAbsoluteValues": True,
                "lowerMinimum": 60.0,
                "upperMaximum": 40.0,
                "setpoint": 30.0,
            },
            0x8403,
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
        # limits out of order without a fault: no error (above)
        ({"setpoint": -100.0, "value": -100.0}, 0),
        ({C + "toleranceAsAbsoluteValues": True, "upperMaximum": -20.0}, 0),
        # a zero band is in order: setpoint 50, 0 %: 45 ... 55 becomes 50 ... 50
        ({"lowerMinimum": 0.0, "upperMaximum": 0.0}, 0),
    ],
)
def test_status_codes(inputs, status):
    rows = run(3, **inputs)
    for r in rows:
        assert (r["status"], r["error"]) == (status, status != 0)
        if status:  # an error from call 0: the position flags FALSE, setpointChange never written
            assert not any(r[name] for name in FLAGS)


def test_an_error_keeps_the_monitoring_and_is_logged():
    # value 50 inside from call 0 (arrived, inLimits). Calls 3 ... 5: absolute limits 10 ... 10,
    # status 16#8402: the three position flags FALSE, the timers not executed; arrived stays
    # TRUE (an error clears nothing). Call 6: back to tolerances, value 60 (above): armed, the
    # upper TON rises at call 6 -> overHighLimit from call 16; inLimits calls 6 ... 15.
    lim = {C + "limitsAsAbsoluteValues": True}
    s = Slave(BLOCK, {"cycleTime": 0.1}, START)
    rows = [s.outputs()]
    for k in range(1, 20):
        s.set(
            lim
            if k == 3
            else {C + "limitsAsAbsoluteValues": False, "value": 60.0}
            if k == 6
            else {}
        )
        rows.append(s.step(0.1))
    assert [r["status"] for r in rows] == [0] * 3 + [0x8402] * 3 + [0] * 14
    assert true_in(rows, "error") == [3, 4, 5]
    assert true_in(rows, "inLimits") == [0, 1, 2] + list(range(6, 16))
    assert true_in(rows, "overHighLimit") == list(range(16, 20))
    assert true_in(rows, "setpointChange") == []
    assert any("16#8402" in text for _, _, text in s.log)  # §1.6: the change is logged
    s.free()


def test_an_error_leaves_the_timers_unexecuted_and_they_elapse_meanwhile():
    # value 58 from call 1: the upper TON rises at call 1 (Q at call 11). Calls 4 ... 14: status
    # 16#8402 (absolute limits 10 ... 10), the timers are not executed. Call 15, tolerances
    # again: the upper TON is executed with IN TRUE, no edge, so it still counts from call 1:
    # Q at once, overHighLimit from call 15. (A timer reset by the error would give call 25.)
    lim = {C + "limitsAsAbsoluteValues": True}
    rows = run(18, {1: {"value": 58.0}, 4: lim, 15: {C + "limitsAsAbsoluteValues": False}})
    assert true_in(rows, "error") == list(range(4, 15))
    assert true_in(rows, "overHighLimit") == [15, 16, 17]
    assert true_in(rows, "inLimits") == [0, 1, 2, 3]


def test_setpoint_change_keeps_its_value_through_an_error():
    # call 3: setpoint 80 (band 72 ... 88), value 50 below: waiting, setpointChange TRUE, the
    # change TON rises at call 3 (PT 2 s: Q at call 23). Calls 5 ... 7: 16#8402 (absolute
    # limits 10 ... 10, 80 above them): the call ends before the outputs setpointChange is
    # written in, so it stays TRUE; the position flags are FALSE. Call 8: tolerances again,
    # still waiting: setpointChange TRUE on (the value never arrives). The change TON, not
    # executed in calls 5 ... 7, still counts from call 3: Q read TRUE at call 23, the lower TON
    # rises there -> belowLowLimit from call 33.
    lim = {C + "limitsAsAbsoluteValues": True}
    rows = run(35, {3: {"setpoint": 80.0}, 5: lim, 8: {C + "limitsAsAbsoluteValues": False}})
    assert true_in(rows, "error") == [5, 6, 7]
    assert true_in(rows, "setpointChange") == list(range(3, 35))
    assert true_in(rows, "belowLowLimit") == [33, 34]
    assert true_in(rows, "inLimits") == [0, 1, 2]


# ---- timing (§13.2 step 6, §13.3) --------------------------------------------------------------


def test_the_start_values_wait_two_seconds_then_time_the_violation():
    # §13.1: value 60, setpoint 50 (a change from 0.0 in call 0): waiting, setpointChange from
    # call 0 on, and for good, as the value never arrives. The change TON rises at call 0 (PT
    # 2 s): its Q, read at call 20 before it runs, is TRUE: armed, the upper TON rises at call
    # 20 (PT 1 s) -> overHighLimit from call 30; inLimits never (never arrived)
    s = Slave(BLOCK)
    rows = [s.outputs()] + [s.step(0.1) for _ in range(34)]
    assert true_in(rows, "setpointChange") == list(range(0, 35))
    assert true_in(rows, "overHighLimit") == list(range(30, 35))
    assert true_in(rows, "inLimits") == [] and true_in(rows, "belowLowLimit") == []
    s.free()


def test_a_value_inside_from_the_start_is_in_limits_at_once():
    # call 0: change 0 -> 50 sets waiting, but the value is inside in the same call: arrived,
    # waiting cleared: setpointChange never TRUE, inLimits from call 0
    rows = run(5)
    assert true_in(rows, "inLimits") == [0, 1, 2, 3, 4]
    assert true_in(rows, "setpointChange") == []


def test_without_a_setpoint_change_a_value_outside_is_never_timed():
    # setpoint 0.0 from call 0 (no change from the start value 0.0), absolute tolerances
    # +-5, value 10 above: never arrived, never waiting, so the change TON never runs and
    # nothing is armed: no flag at all
    rows = run(
        30,
        setpoint=0.0,
        value=10.0,
        upperMaximum=5.0,
        lowerMinimum=5.0,
        **{C + "toleranceAsAbsoluteValues": True},
    )
    assert not any(r[name] for r in rows for name in FLAGS)


def test_a_short_peak_is_hidden():
    # value 57 (above 55) in calls 1 ... 5 (0.5 s < 1 s): upper TON from call 1 would give Q at
    # call 11; it falls in call 6. Nothing reported, inLimits stays TRUE.
    rows = run(15, {1: {"value": 57.0}, 6: {"value": 50.0}})
    assert true_in(rows, "overHighLimit") == []
    assert true_in(rows, "inLimits") == list(range(15))


def test_a_violation_is_reported_after_its_monitoring_time():
    # value 58 from call 1: upper TON from call 1, PT 1 s -> overHighLimit from call 11;
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
    # call 3: setpoint 80 (band 72 ... 88), value 50 below: not arrived, waiting: setpointChange
    # TRUE, change TON from call 3 (Q at call 23); call 8: value 75 inside: arrived, waiting
    # cleared (the change TON's IN FALSE), setpointChange FALSE, inLimits
    rows = run(12, {3: {"setpoint": 80.0}, 8: {"value": 75.0}})
    assert true_in(rows, "setpointChange") == [3, 4, 5, 6, 7]
    assert true_in(rows, "inLimits") == [0, 1, 2, 8, 9, 10, 11]
    assert true_in(rows, "belowLowLimit") == []


def test_a_value_that_never_arrives_is_reported_after_change_and_monitoring_time():
    # call 3: setpoint 80, value stays 50: setpointChange from call 3 on (waiting ends only when
    # the value arrives). The change TON rises at call 3: at call 23 (0.3 + 2 s) its Q, read
    # before it runs in that call, is already TRUE (the S7 update on read): armed, the lower TON
    # rises at call 23 (PT 1 s) -> belowLowLimit from call 33 (a Q kept from the previous
    # execution would have armed it one call later, 34)
    rows = run(36, {3: {"setpoint": 80.0}})
    assert true_in(rows, "setpointChange") == list(range(3, 36))
    assert true_in(rows, "belowLowLimit") == [33, 34, 35]
    assert true_in(rows, "inLimits") == [0, 1, 2]


def test_the_change_timer_arms_the_violation_timers_one_call_after_it_elapses():
    # all times 0. Call 3: setpoint 80, value 50 below 72: waiting; the lower TON runs first,
    # with armed FALSE (the change TON has not run yet: its Q read FALSE); then the change TON
    # rises with PT 0: Q at once. Call 4: its Q read TRUE: armed, the lower TON rises with PT 0:
    # belowLowLimit from call 4
    rows = run(6, {3: {"setpoint": 80.0}}, **ZERO_TIMES)
    assert true_in(rows, "belowLowLimit") == [4, 5]
    assert true_in(rows, "setpointChange") == [3, 4, 5]


def test_a_change_into_a_band_that_holds_the_value_shows_nothing():
    # call 3: setpoint 51 (10 %: 45.9 ... 56.1 in REAL), value 50 inside in the same call
    rows = run(6, {3: {"setpoint": 51.0}})
    assert true_in(rows, "setpointChange") == []
    assert true_in(rows, "inLimits") == list(range(6))


def test_a_change_stops_a_violation_being_timed():
    # value 58 from call 1 (upper TON from call 1); call 5: setpoint 52 (46.8 ... 57.2), 58 still
    # above: not arrived, nothing armed (the change TON's Q read FALSE), so the upper TON's IN is
    # FALSE (reset); the change TON rises at call 5 (Q at call 25); setpointChange from call 5
    # on; the upper TON rises again at call 25 -> overHighLimit from call 35
    rows = run(37, {1: {"value": 58.0}, 5: {"setpoint": 52.0}})
    assert true_in(rows, "setpointChange") == list(range(5, 37))
    assert true_in(rows, "overHighLimit") == [35, 36]
    assert true_in(rows, "inLimits") == [0, 1, 2, 3, 4]


def test_a_further_change_before_arrival_does_not_restart_the_change_timer():
    # call 3: setpoint 80 (change TON from call 3, Q at call 23); call 10: setpoint 90 (band 81
    # ... 99), the value 50 still out: the change TON's IN stays TRUE, so it still elapses at
    # call 23; the lower TON rises there -> belowLowLimit from call 33 (not 40)
    rows = run(35, {3: {"setpoint": 80.0}, 10: {"setpoint": 90.0}})
    assert true_in(rows, "setpointChange") == list(range(3, 35))
    assert true_in(rows, "belowLowLimit") == [33, 34]


def test_reset_is_an_edge():
    # value 60 from call 1 (arrived since call 0): overHighLimit from call 11. Reset TRUE in
    # calls 13 ... 14: its rising edge at call 13 clears arrived and waiting; 60 is outside, so
    # not arrived, nothing armed: the upper TON's IN FALSE, all flags FALSE, and so on after the
    # reset falls (call 15): nothing is timed until the value arrives. Call 20: 50 inside,
    # arrived, inLimits. Call 25: 60, the upper TON rises -> overHighLimit from call 35.
    rows = run(
        40,
        {
            1: {"value": 60.0},
            13: {"reset": True},
            15: {"reset": False},
            20: {"value": 50.0},
            25: {"value": 60.0},
        },
    )
    assert true_in(rows, "overHighLimit") == [11, 12] + list(range(35, 40))
    assert true_in(rows, "inLimits") == list(range(0, 11)) + list(range(20, 35))
    for k in range(13, 20):
        assert not any(rows[k][name] for name in FLAGS)
    # with the value inside, the reset edge clears arrived and the same call sets it again:
    # inLimits in every call
    rows = run(8, {3: {"reset": True}, 6: {"reset": False}})
    assert true_in(rows, "inLimits") == list(range(8))
    # a reset held TRUE does nothing after its edge: a setpoint change at call 5 is waited out
    rows = run(8, {3: {"reset": True}, 5: {"setpoint": 80.0}})
    assert true_in(rows, "setpointChange") == [5, 6, 7]
    # a change in the call of the reset edge is cleared by it: no setpointChange; the value 50
    # is outside 72 ... 88 and never arrives, so nothing at all until call 6 brings 75
    rows = run(10, {3: {"reset": True, "setpoint": 80.0}, 6: {"value": 75.0}})
    assert true_in(rows, "setpointChange") == []
    assert true_in(rows, "inLimits") == [0, 1, 2, 6, 7, 8, 9]
    # a second edge needs the reset released: TRUE 3 ... 4, FALSE 5, TRUE 6 (edge again)
    rows = run(
        10,
        {
            1: {"value": 60.0},
            3: {"reset": True, "value": 50.0},
            4: {"value": 60.0},
            5: {"reset": False},
            6: {"reset": True},
        },
    )
    # calls 1, 2 above (arrived since 0): inLimits; call 3 edge with 50 inside: arrived again;
    # call 4: 60 above, still arrived: the upper TON rises (inLimits meanwhile); call 6: edge,
    # 60 outside: not arrived, the upper TON's IN FALSE: all FALSE from call 6
    assert true_in(rows, "inLimits") == [0, 1, 2, 3, 4, 5]


def test_disable_limits_clears_the_flags_but_in_limits():
    d = C + "disableLimits"
    # disabled from call 0: arrived and waiting cleared in every call, then arrived set again
    # when the value is inside; the three TONs get IN FALSE. So overHighLimit, belowLowLimit and
    # setpointChange are FALSE, and inLimits is TRUE exactly while the value is inside: calls 0,
    # 1 (50), 4 (50); not 2 (60) and 3 (40). Call 5, released with 60: arrived from call 4
    # stays, armed: the upper TON rises at call 5 -> overHighLimit from call 15, inLimits
    # calls 5 ... 14.
    rows = run(
        17,
        {2: {"value": 60.0}, 3: {"value": 40.0}, 4: {"value": 50.0}, 5: {d: False, "value": 60.0}},
        **{d: True},
    )
    assert true_in(rows, "overHighLimit") == [15, 16]
    assert true_in(rows, "belowLowLimit") == []
    assert true_in(rows, "inLimits") == [0, 1, 4] + list(range(5, 15))
    assert true_in(rows, "setpointChange") == []
    # released while the value is outside (60 from call 2, released at call 5): not arrived,
    # nothing armed: no flag at all
    rows = run(10, {2: {"value": 60.0}, 5: {d: False}}, **{d: True})
    assert true_in(rows, "inLimits") == [0, 1]
    assert not any(r[name] for r in rows for name in ("overHighLimit", "belowLowLimit"))
    # a violation being timed is stopped: value 58 from call 1 (upper TON from call 1),
    # disabled in calls 5 ... 14 (its IN FALSE), released at call 15 with 58 still above: not
    # arrived (cleared while disabled): nothing
    rows = run(20, {1: {"value": 58.0}, 5: {d: True}, 15: {d: False}})
    assert true_in(rows, "overHighLimit") == []
    assert true_in(rows, "inLimits") == [0, 1, 2, 3, 4]


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


def test_high_and_low_and_in_limits_with_a_positive_setpoint():
    # a run through every position (the hand traces above); with a positive setpoint the band
    # is in order, so at most one of the three is TRUE
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
