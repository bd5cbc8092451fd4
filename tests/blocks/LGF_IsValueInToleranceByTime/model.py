"""Independent model of LGF_IsValueInToleranceByTime, written from the original block's program
(the LGF SCL, executed statement by statement) and docs/behaviour.md §1.4 (REAL, TIME), §1.12
(the S7 IEC timers, with the update on read) and §13 (the interface); never from the C.

Statics: the previous setpoint (REAL, 0.0 at first), the previous reset (FALSE), the flags
"setpoint change" and "was within tolerance" (FALSE), three S7 TONs (tests/models/timers.py):
upper, lower and change, and the output setpointChange, which the original leaves as it was in
a call that ends with an error (an FB's outputs keep their values). One call, in the original's
order, all arithmetic in REAL (float32), operation by operation:

1. Where the value is, by the configuration:
   - absolute limits: over := value > upperMaximum; under := value < lowerMinimum (no
     arithmetic);
   - else absolute tolerances: over := value > setpoint + upperMaximum; under := value <
     setpoint - lowerMinimum;
   - else percent: over := value > setpoint * (1.0 + ABS(upperMaximum) / 100.0); under :=
     value < setpoint * (1.0 - ABS(lowerMinimum) / 100.0) (the tolerances taken by their
     magnitude).
   A floating-point fault of this arithmetic clears ENO (see `fault`), which step 5 reads.
2. If setpoint <> the previous setpoint (IEEE: -0.0 = 0.0): was := FALSE, change := TRUE. The
   previous setpoint := setpoint.
3. If disableLimits, or reset rose (reset AND NOT the previous reset, an edge): was := FALSE,
   change := FALSE. The previous reset := reset.
4. If NOT (under OR over) AND NOT was: was := TRUE. (So even with disableLimits a value within
   the band sets it.)
5. The call ends early, the first that applies, with error TRUE, the three limit outputs FALSE,
   setpointChange as it was, the timers neither executed nor read:
   - ENO FALSE (a floating-point fault in step 1): 16#8401;
   - absolute limits and setpoint > upperMaximum: 16#8402;
   - absolute limits and setpoint < lowerMinimum: 16#8403.
   Limits out of order (low > high) are no error: nothing compares them.
6. upper TON: IN := over AND (was OR change TON's Q) AND NOT disableLimits, PT :=
   upperLimitMonitoringTime; lower TON: IN := under AND (was OR change TON's Q) AND NOT
   disableLimits, PT := lowerLimitMonitoringTime. The change TON's Q is read before that timer
   runs in this call, so with the update on read (§1.12) it is the TON at this call's time.
   change TON: IN := change AND NOT was AND NOT disableLimits, PT := setpointChangeMonitoringTime.
   If change AND was: change := FALSE.
7. inLimits := NOT (lower Q OR upper Q) AND NOT (change AND NOT change TON's Q) AND was;
   overHighLimit := upper Q; belowLowLimit := lower Q; setpointChange := change AND NOT was;
   error FALSE, status 16#0000.

Refused by the FMU (ValueError here, docs/behaviour.md §1.4): a REAL that is NaN or finite
beyond ±3.4028235e38 (±Inf accepted); a TIME that is NaN or beyond ±2147483.647 s.
"""

import numpy as np

from tests.models.iec import cycle_us_of, time_s_to_ms
from tests.models.signal_ci import real
from tests.models.timers import TON

REAL = np.float32
STATUS_OK = 0x0000
ERR_RANGE_LIMIT_VALUE_CALC = 0x8401  # 33793: a floating-point fault in the limit arithmetic
ERR_SETPOINT_ABOVE_HIGH_LIMIT = 0x8402  # 33794
ERR_SETPOINT_BELOW_LOW_LIMIT = 0x8403  # 33795

C = "configuration."


def fault(result: np.float32) -> bool:
    """Whether one REAL operation of the limit arithmetic clears ENO: its result is no valid
    REAL, ±Inf (out of the REAL range, also when an operand was infinite already) or NaN (an
    invalid operation such as Inf - Inf or 0 * Inf)."""
    return not np.isfinite(result)


def position(value, setpoint, lower, upper, absolute_limits: bool, absolute_tolerance: bool):
    """Step 1 in float32: (over, under, fault)."""
    results = []

    def op(x):
        results.append(x)
        return x

    with np.errstate(all="ignore"):  # Inf and NaN follow IEEE arithmetic
        if absolute_limits:
            high, low = upper, lower
        elif absolute_tolerance:
            high = op(setpoint + upper)
            low = op(setpoint - lower)
        else:
            one, hundred = REAL(1.0), REAL(100.0)
            high = op(setpoint * op(one + op(op(abs(upper)) / hundred)))
            low = op(setpoint * op(one - op(op(abs(lower)) / hundred)))
    return bool(value > high), bool(value < low), any(fault(r) for r in results)


class IsValueInToleranceByTime:
    def __init__(self, cycle_us: int):
        self.cycle_us = cycle_us_of(cycle_us)  # the TONs measure the call times
        self.setpoint_previous = REAL(0.0)
        self.reset_previous = False
        self.setpoint_change = False
        self.was_within = False
        self.upper = TON()
        self.lower = TON()
        self.change = TON()
        self.out_setpoint_change = False  # the output, kept by a call that ends in an error

    def call(self, now_us: int, inputs: dict) -> dict:
        value = real("value", inputs["value"])
        setpoint = real("setpoint", inputs["setpoint"])
        lower = real("lowerMinimum", inputs["lowerMinimum"])
        upper = real("upperMaximum", inputs["upperMaximum"])
        reset = bool(inputs["reset"])
        disable = bool(inputs[C + "disableLimits"])
        abs_limits = bool(inputs[C + "limitsAsAbsoluteValues"])
        abs_tolerance = bool(inputs[C + "toleranceAsAbsoluteValues"])
        t_upper = time_s_to_ms(inputs[C + "upperLimitMonitoringTime"])
        t_lower = time_s_to_ms(inputs[C + "lowerLimitMonitoringTime"])
        t_change = time_s_to_ms(inputs[C + "setpointChangeMonitoringTime"])

        over, under, eno_cleared = position(  # 1.
            value, setpoint, lower, upper, abs_limits, abs_tolerance
        )
        if self.setpoint_previous != setpoint:  # 2.
            self.was_within = False
            self.setpoint_change = True
        self.setpoint_previous = setpoint
        if disable or (reset and not self.reset_previous):  # 3.
            self.was_within = False
            self.setpoint_change = False
        self.reset_previous = reset
        if not (under or over) and not self.was_within:  # 4.
            self.was_within = True

        status = STATUS_OK  # 5.
        if eno_cleared:
            status = ERR_RANGE_LIMIT_VALUE_CALC
        elif abs_limits and setpoint > upper:
            status = ERR_SETPOINT_ABOVE_HIGH_LIMIT
        elif abs_limits and setpoint < lower:
            status = ERR_SETPOINT_BELOW_LOW_LIMIT
        if status != STATUS_OK:
            return {
                "overHighLimit": False,
                "belowLowLimit": False,
                "inLimits": False,
                "setpointChange": self.out_setpoint_change,
                "error": True,
                "status": status,
            }

        change_q = self.change.q_at(now_us)  # 6.: read before the change TON runs
        monitored = self.was_within or change_q
        self.upper(now_us, over and monitored and not disable, t_upper)
        self.lower(now_us, under and monitored and not disable, t_lower)
        self.change(now_us, self.setpoint_change and not self.was_within and not disable, t_change)
        if self.setpoint_change and self.was_within:
            self.setpoint_change = False

        in_limits = (  # 7.
            not (self.lower.q or self.upper.q)
            and not (self.setpoint_change and not self.change.q)
            and self.was_within
        )
        self.out_setpoint_change = self.setpoint_change and not self.was_within
        return {
            "overHighLimit": self.upper.q,
            "belowLowLimit": self.lower.q,
            "inLimits": in_limits,
            "setpointChange": self.out_setpoint_change,
            "error": False,
            "status": STATUS_OK,
        }
