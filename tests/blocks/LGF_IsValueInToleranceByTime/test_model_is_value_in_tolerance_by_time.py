"""Hand traces of the IsValueInToleranceByTime model against the original block's program (no
FMU): call k at k · 100 ms. Flags per call are written as strings of the letters O
(overHighLimit), B (belowLowLimit), I (inLimits), S (setpointChange), "-" for none; a call that
ends with an error is written as its status in hex, followed by the flags."""

import math

import numpy as np
import pytest

from . import spec
from .model import IsValueInToleranceByTime, position

C = "configuration."
CYCLE_US = 100_000

BASE = spec.START
ABS_LIMITS = C + "limitsAsAbsoluteValues"
ABS_TOLERANCE = C + "toleranceAsAbsoluteValues"
DISABLE = C + "disableLimits"


def flags(o):
    names = ("overHighLimit", "belowLowLimit", "inLimits", "setpointChange")
    s = "".join(c for c, n in zip("OBIS", names) if o[n]) or "-"
    assert o["error"] == (o["status"] != 0)
    return f"{o['status']:X}{s}" if o["error"] else s


def run(changes, n, **base):
    """Flags per call for n calls; changes maps a call number to the inputs changed from there."""
    m = IsValueInToleranceByTime(CYCLE_US)
    inputs = {**BASE, **base}
    out = []
    for k in range(n):
        inputs.update(changes.get(k, {}))
        out.append(flags(m.call(k * CYCLE_US, dict(inputs))))
    return out


def test_start_values():
    # Band 45 … 55 (float32: 50 · 1.1 = 55.0, 50 · 0.9 = 45.0), value 60. Call 0: setpoint 0.0
    # -> 50.0 is a change; the value is outside: the change TON runs (2 s). Call 20 (2.0 s): its
    # Q, read before it runs, is TRUE, so the upper TON starts (1 s): overHighLimit from call
    # 30. setpointChange = change AND NOT was stays TRUE, since the value never arrived.
    out = run({}, 35)
    assert out[:30] == ["S"] * 30
    assert out[30:] == ["OS"] * 5


def test_percent_limits_use_the_magnitude_of_the_tolerances():
    # ABS(-10) = 10: the same band 45 … 55.
    f = np.float32
    for lo, up in ((10.0, 10.0), (-10.0, -10.0)):
        assert position(f(55.0), f(50.0), f(lo), f(up), False, False) == (False, False, False)
        assert position(f(55.00001), f(50.0), f(lo), f(up), False, False)[:2] == (True, False)
        assert position(f(44.99999), f(50.0), f(lo), f(up), False, False)[:2] == (False, True)
    # absolute tolerances: 50 + 5, 50 - 5; absolute limits: the values themselves
    assert position(f(55.5), f(50.0), f(5.0), f(5.0), False, True) == (True, False, False)
    assert position(f(44.5), f(50.0), f(45.0), f(55.0), True, False) == (False, True, False)


def test_the_value_arriving_ends_the_setpoint_change():
    # value inside from call 5: was TRUE, change cleared: inLimits.
    out = run({5: {"value": 50.0}}, 8)
    assert out == ["S"] * 5 + ["I"] * 3


def test_a_change_into_a_band_that_holds_the_value_shows_no_setpoint_change():
    assert run({}, 3, value=50.0) == ["I"] * 3


def test_short_violations_are_hidden_and_a_long_one_reported():
    # inside until call 4; above from call 5 (the upper TON starts at 0.5 s); back in call 10:
    # never reported. Above again from call 12: reported from call 22 (1.0 s later).
    out = run({5: {"value": 60.0}, 10: {"value": 50.0}, 12: {"value": 60.0}}, 24, value=50.0)
    assert out[:22] == ["I"] * 22
    assert out[22:] == ["O", "O"]


def test_below_with_its_own_time():
    out = run({3: {"value": 40.0}}, 10, value=50.0, **{C + "lowerLimitMonitoringTime": 0.5})
    assert out == ["I"] * 8 + ["B"] * 2


def test_the_setpoint_0_at_the_start_is_no_change():
    # setpoint 0.0 = the previous setpoint's start value: no change flag, the change TON never
    # runs, the value (outside the band 0 … 0) never was within: nothing is ever monitored.
    assert run({}, 40, setpoint=0.0) == ["-"] * 40


def test_a_further_change_before_arrival_does_not_restart_the_change_timer():
    # 50 -> 80 in call 5 (band 72 … 88, value 60 below): the change TON, IN TRUE since call 0,
    # elapses at 2.0 s; the lower TON starts in call 20, reports in call 30.
    out = run({5: {"setpoint": 80.0}}, 32)
    assert out[:30] == ["S"] * 30
    assert out[30:] == ["BS", "BS"]


def test_a_change_after_arrival():
    # inside (50) in calls 0-4; setpoint 80 in call 5: was FALSE, change TRUE, the change TON
    # starts at 0.5 s; the lower TON's IN is FALSE (nothing monitored) until call 25 (2.5 s),
    # reported in call 35.
    out = run({5: {"setpoint": 80.0}}, 37, value=50.0)
    assert out[:5] == ["I"] * 5
    assert out[5:35] == ["S"] * 30
    assert out[35:] == ["BS", "BS"]
    # with a change time of 0: the change TON's Q is TRUE in call 5 itself (after the lower TON
    # ran); the lower TON starts in call 6 (0.6 s) and reports in call 16.
    out = run({5: {"setpoint": 80.0}}, 18, value=50.0, **{C + "setpointChangeMonitoringTime": 0.0})
    assert out[5:] == ["S"] * 11 + ["BS", "BS"]


def test_reset_is_an_edge():
    # inside until call 4, above from call 5, overHighLimit from call 15. reset TRUE from call 20
    # on: its rising edge clears was and change; the value is outside, so nothing is monitored
    # any more (the upper TON gets IN FALSE) and reset held does nothing more. The value back
    # inside in call 30: inLimits.
    changes = {5: {"value": 60.0}, 20: {"reset": True}, 30: {"value": 50.0}}
    out = run(changes, 32, value=50.0)
    assert out[:15] == ["I"] * 15
    assert out[15:20] == ["O"] * 5
    assert out[20:30] == ["-"] * 10
    assert out[30:] == ["I", "I"]
    # a reset while inside changes nothing visible (was is set again in the same call)
    assert run({3: {"reset": True}}, 6, value=50.0) == ["I"] * 6


def test_a_reset_edge_absorbs_a_setpoint_change():
    # setpoint 80 and reset rise together in call 5 (value 50 below the new band): the change
    # flag is set and then cleared: no setpointChange, nothing monitored.
    out = run({5: {"setpoint": 80.0, "reset": True}}, 30, value=50.0)
    assert out == ["I"] * 5 + ["-"] * 25


def test_disable_limits():
    # outside: all flags FALSE, the timers get IN FALSE; inside: was is set again after the
    # clear, so inLimits is TRUE. Released: the value outside was never within since, nothing
    # is monitored (as after a reset).
    out = run({5: {DISABLE: True}, 8: {"value": 60.0}, 11: {DISABLE: False}}, 30, value=50.0)
    assert out == ["I"] * 8 + ["-"] * 22
    # a running violation timer stops: inside, above from call 2 (upper TON from 0.2 s, inLimits
    # meanwhile), disabled in calls 5-6 with the value outside (was cleared, the TONs get IN
    # FALSE), enabled from call 7: nothing is monitored until the value is within again.
    out = run({2: {"value": 60.0}, 5: {DISABLE: True}, 7: {DISABLE: False}}, 20, value=50.0)
    assert out == ["I"] * 5 + ["-"] * 15


def test_setpoint_outside_absolute_limits():
    # absolute limits 45 … 55; call 2: upperMaximum 40 < setpoint 50: 16#8402, the limit flags
    # FALSE and setpointChange as the last call left it (TRUE); call 4: lowerMinimum 60 too:
    # still 16#8402 (checked first); upperMaximum back to 70 in call 5: 16#8403.
    abs_base = {ABS_LIMITS: True, "lowerMinimum": 45.0, "upperMaximum": 55.0}
    changes = {2: {"upperMaximum": 40.0}, 4: {"lowerMinimum": 60.0}, 5: {"upperMaximum": 70.0}}
    out = run(changes, 6, **abs_base)
    assert out == ["S", "S", "8402S", "8402S", "8402S", "8403S"]
    # an error in the first call keeps the output's start value FALSE
    assert run({}, 2, **{ABS_LIMITS: True, "upperMaximum": 40.0}) == ["8402-"] * 2


def test_limits_out_of_order_are_no_error():
    # -100 with 10 %: high -110, low -90 (out of order), the value -100 is both over and under.
    # No status: the change TON runs for 2 s, then both violation TONs; reported at 3.0 s.
    out = run({}, 31, setpoint=-100.0, value=-100.0)
    assert out[:30] == ["S"] * 30
    assert out[30] == "OBS"
    # negative absolute tolerances: high 40, low 60, the same
    neg = {ABS_TOLERANCE: True, "lowerMinimum": -10.0, "upperMaximum": -10.0, "value": 50.0}
    assert run({}, 31, **neg)[30] == "OBS"


def test_a_floating_point_fault_in_the_limits_gives_8401():
    # overflow: 3e38 · 1.2 = 3.6e38 beyond the REAL range; Inf - Inf: NaN.
    out = run({}, 2, setpoint=3e38, upperMaximum=20.0, value=0.0)
    assert out == ["8401-", "8401-"]
    big = {ABS_TOLERANCE: True, "setpoint": -math.inf, "upperMaximum": math.inf}
    assert run({}, 1, **big) == ["8401-"]
    # an infinite operand gives an infinite limit, no valid REAL either
    assert run({}, 1, **{ABS_TOLERANCE: True, "setpoint": math.inf}) == ["8401-"]
    # absolute limits compute nothing: an infinite limit is no fault
    inf = {ABS_LIMITS: True, "lowerMinimum": -math.inf, "upperMaximum": math.inf, "value": 50.0}
    assert run({}, 1, **inf) == ["I"]


def test_the_timers_run_on_through_an_error():
    # absolute tolerances 45 … 55; inside until call 4, above from call 5 (the upper TON starts
    # at 0.5 s with IN TRUE). Calls 8-9: absolute limits 5 … 5 with setpoint 50: 16#8402, no
    # timer is executed. From call 10 the upper TON runs on with IN TRUE: reported in call 15.
    changes = {5: {"value": 60.0}, 8: {ABS_LIMITS: True}, 10: {ABS_LIMITS: False}}
    tol = {ABS_TOLERANCE: True, "lowerMinimum": 5.0, "upperMaximum": 5.0, "value": 50.0}
    out = run(changes, 17, **tol)
    assert out == ["I"] * 8 + ["8402-"] * 2 + ["I"] * 5 + ["O", "O"]


def test_zero_and_negative_monitoring_times():
    # PT 0 (or negative, taken as 0): a TON's Q in its rising call.
    times = {C + "upperLimitMonitoringTime": -0.05, C + "setpointChangeMonitoringTime": 0.0}
    out = run({3: {"value": 60.0}}, 5, value=50.0, **times)
    assert out == ["I"] * 3 + ["O", "O"]
    # from the start, value outside: the change TON's Q in call 0 (after the upper TON ran),
    # the upper TON starts in call 1 and reports at once.
    assert run({}, 3, **times) == ["S", "OS", "OS"]


def test_an_infinite_value_is_above():
    assert run({3: {"value": math.inf}}, 14, value=50.0)[12:] == ["I", "O"]


def test_refused_values():
    m = IsValueInToleranceByTime(CYCLE_US)
    for name, bad in (
        ("value", math.nan),
        ("setpoint", 1e39),
        (C + "upperLimitMonitoringTime", math.nan),
        (C + "setpointChangeMonitoringTime", 2147484.0),
    ):
        with pytest.raises(ValueError):
            m.call(0, {**BASE, name: bad})
