"""Independent model of LGF_IsValueInToleranceByTime (docs/behaviour.md §13), written from that
section, §1.4 and §1.12 only, never from the C.

Statics (§13.1): setpointPrevious (REAL, 0.0), wasWithinTolerance (FALSE), setpointChangeActive
(FALSE) and three S7 TONs (tests/models/timers.py): grace, high and low. One call (§13.2), all
arithmetic and comparisons in float32, operation by operation:

1. changed := setpoint != setpointPrevious (IEEE: -0.0 = 0.0); setpointPrevious := setpoint.
2. Limits: absolute limits: high := upperMaximum, low := lowerMinimum; else absolute tolerances:
   high := setpoint + upperMaximum, low := setpoint - lowerMinimum; else percent:
   high := setpoint * (1.0 + upperMaximum / 100.0), low := setpoint * (1.0 - lowerMinimum / 100.0).
3. status: NOT (low <= high) -> 16#8401; else absolute limits and setpoint > high -> 16#8402;
   else absolute limits and setpoint < low -> 16#8403; else 0. error := status != 0.
4. above := value > high; below := value < low; within := NOT above AND NOT below.
5. reset OR error OR disableLimits: wasWithinTolerance := FALSE, setpointChangeActive := FALSE,
   the three TONs executed with IN FALSE; setpointChange FALSE; with disableLimits (and neither
   reset nor error) overHighLimit/belowLowLimit/inLimits := above/below/within, else all FALSE.
6. Otherwise: 1. changed: active := TRUE, was := FALSE. 2. within: was := TRUE, active := FALSE.
   3. grace := TON(NOT was, setpointChangeMonitoringTime); grace: active := FALSE.
   4. monitored := was OR grace. 5. overHighLimit := TON_high(above AND monitored,
   upperLimitMonitoringTime); belowLowLimit := TON_low(below AND monitored,
   lowerLimitMonitoringTime). 6. inLimits := was AND NOT over AND NOT below;
   setpointChange := active.

Refused (ValueError, §13.1, §1.4): a REAL that is NaN or finite beyond ±3.4028235e38 (±Inf
accepted); a TIME that is NaN or beyond ±2147483.647 s.
"""

import numpy as np

from tests.models.iec import time_s_to_ms
from tests.models.signal_ci import real
from tests.models.timers import TON

REAL = np.float32
STATUS_OK = 0x0000
ERR_LIMITS = 0x8401  # 33793: NOT (low <= high), a NaN limit included
ERR_ABOVE = 0x8402  # 33794: absolute limits, setpoint above the high limit
ERR_BELOW = 0x8403  # 33795: absolute limits, setpoint below the low limit

C = "configuration."


def limits(setpoint, lower, upper, absolute_limits: bool, absolute_tolerance: bool):
    """§13.2 step 2 in float32: (high, low)."""
    with np.errstate(all="ignore"):  # Inf and NaN follow IEEE arithmetic (§13.3)
        if absolute_limits:
            return REAL(upper), REAL(lower)
        if absolute_tolerance:
            return REAL(setpoint) + REAL(upper), REAL(setpoint) - REAL(lower)
        high = REAL(setpoint) * (REAL(1.0) + REAL(upper) / REAL(100.0))
        low = REAL(setpoint) * (REAL(1.0) - REAL(lower) / REAL(100.0))
        return high, low


class IsValueInToleranceByTime:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §13.1: 1 µs … 60 s; the TONs measure the call times
        if not 1 <= self.cycle_us <= 60_000_000:
            raise ValueError(f"cycleTime {self.cycle_us} µs outside 1 µs … 60 s")
        self.setpoint_previous = REAL(0.0)
        self.was_within = False
        self.change_active = False
        self.grace = TON()
        self.high = TON()
        self.low = TON()

    def call(self, now_us: int, inputs: dict) -> dict:
        value = real("value", inputs["value"])
        setpoint = real("setpoint", inputs["setpoint"])
        lower = real("lowerMinimum", inputs["lowerMinimum"])
        upper = real("upperMaximum", inputs["upperMaximum"])
        reset = bool(inputs["reset"])
        disable = bool(inputs[C + "disableLimits"])
        abs_limits = bool(inputs[C + "limitsAsAbsoluteValues"])
        abs_tol = bool(inputs[C + "toleranceAsAbsoluteValues"])
        t_upper = time_s_to_ms(inputs[C + "upperLimitMonitoringTime"])
        t_lower = time_s_to_ms(inputs[C + "lowerLimitMonitoringTime"])
        t_change = time_s_to_ms(inputs[C + "setpointChangeMonitoringTime"])

        changed = bool(setpoint != self.setpoint_previous)  # step 1
        self.setpoint_previous = setpoint
        high, low = limits(setpoint, lower, upper, abs_limits, abs_tol)  # step 2
        if not low <= high:  # step 3
            status = ERR_LIMITS
        elif abs_limits and setpoint > high:
            status = ERR_ABOVE
        elif abs_limits and setpoint < low:
            status = ERR_BELOW
        else:
            status = STATUS_OK
        error = status != STATUS_OK
        above = bool(value > high)  # step 4
        below = bool(value < low)
        within = not above and not below

        if reset or error or disable:  # step 5: monitoring off
            self.was_within = False
            self.change_active = False
            self.grace(now_us, False, t_change)
            self.high(now_us, False, t_upper)
            self.low(now_us, False, t_lower)
            at_once = disable and not reset and not error
            return {
                "overHighLimit": above and at_once,
                "belowLowLimit": below and at_once,
                "inLimits": within and at_once,
                "setpointChange": False,
                "error": error,
                "status": status,
            }

        if changed:  # step 6.1
            self.change_active = True
            self.was_within = False
        if within:  # 6.2
            self.was_within = True
            self.change_active = False
        grace = self.grace(now_us, not self.was_within, t_change)  # 6.3
        if grace:
            self.change_active = False
        monitored = self.was_within or grace  # 6.4
        over = self.high(now_us, above and monitored, t_upper)  # 6.5
        under = self.low(now_us, below and monitored, t_lower)
        return {
            "overHighLimit": over,
            "belowLowLimit": under,
            "inLimits": self.was_within and not over and not under,  # 6.6
            "setpointChange": self.change_active,
            "error": False,
            "status": STATUS_OK,
        }
