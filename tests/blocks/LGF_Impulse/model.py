"""Independent model of LGF_Impulse, written from the original block's program (the LGF V3.0.1
SCL, executed statement by statement) and docs/behaviour.md §1.4 (REAL, TIME), §1.12 (the S7
IEC timers, with the update on read) and §9 (the interface); never from the C.

Statics: the frequency of the last computation (REAL, 0.0 at first), the period (TIME ms, 0 at
first) and an S7 TOF (tests/models/timers.py). One call, in the original's order:

1. If `frequency` <= 0.0: impulse FALSE, countdown 0 ms; the TOF is neither executed nor read,
   no static changes.
2. Otherwise:
   1. If `frequency` differs from the stored one (float32 compare): the period := T#1000s
      (1000000 ms) / TRUNC(`frequency` * 1000.0), the product in REAL (rounded to float32),
      TRUNC towards zero to a DINT, and TIME / DINT an integer division truncating towards zero.
      So 0.0123 Hz gives TRUNC(12.3) = 12 and 1000000 / 12 = 83333 ms; 0.8 Hz (the float32
      0.800000011…) gives 800.0 and 1250 ms; above 1000 Hz the divisor exceeds 1000000 and the
      period is 0 ms. The frequency is stored.
   2. impulse := NOT (the TOF's Q), read *before* the TOF is executed in this call, so updated to
      this call's time (§1.12): in the call in which the running TOF has elapsed, the read sees
      FALSE and the call gives the pulse. In the very first call the TOF never ran: Q FALSE, so
      the block pulses in call 0.
   3. The TOF with IN := NOT (its Q, read again at the same time, the same value) and PT := the
      period: IN TRUE in the pulse call stops it (Q TRUE), IN FALSE in the next call is the
      falling edge that starts it with the PT of that call.
   4. countdown := period - the TOF's ET (TIME arithmetic in ms). The TOF keeps the PT it took at
      its start, so after a new frequency the difference may be negative.

Cases the original's arithmetic leaves to the CPU (the rules of docs/scl.md §3.3, the project's
SCL decisions, which docs/behaviour.md §9 is to state for this block):
- `frequency` below 0.001 Hz (TRUNC(f * 1000.0) = 0): TIME / 0. The CPU reports an integer
  division by zero on ENO only; the project's rule is that a divisor of 0 gives 0, so the
  period is 0 ms (DIVISION_BY_ZERO_MS).
- `frequency` * 1000.0 beyond the DINT range (from 2147483.6 Hz, and +Inf): TRUNC gives the
  range's limit 2147483647 (docs/scl.md §3.3), and 1000000 / that is 0 ms, as for any
  divisor above 1000000.

Refused by the FMU (ValueError here, docs/behaviour.md §1.4): NaN and finite values beyond
±3.4028235e38.
"""

import numpy as np

from tests.models.iec import cycle_us_of, time_ms_to_s
from tests.models.signal_ci import real
from tests.models.timers import TOF

REAL = np.float32
THOUSAND_SECONDS_MS = 1_000_000  # T#1000s
DINT_MIN, DINT_MAX = -(2**31), 2**31 - 1
DIVISION_BY_ZERO_MS = 0  # TIME / 0 (docs/scl.md §3.3: a divisor of 0 gives 0)


def time32(ms: int) -> int:
    """TIME arithmetic wraps in signed 32 bits (docs/behaviour.md §1.4)."""
    return ((int(ms) + 2**31) % 2**32) - 2**31


def trunc_dint(x: np.float32) -> int:
    """TRUNC of a REAL to a DINT: towards zero; beyond the range its limit (docs/scl.md §3.3)."""
    if np.isnan(x):
        return 0
    if np.isinf(x):
        return DINT_MAX if x > 0 else DINT_MIN
    return max(DINT_MIN, min(DINT_MAX, int(float(x))))  # int() truncates towards zero


def time_div_dint(t_ms: int, d: int) -> int:
    """TIME / DINT: integer division truncating towards zero; a divisor of 0 gives
    DIVISION_BY_ZERO_MS."""
    if d == 0:
        return DIVISION_BY_ZERO_MS
    q = abs(t_ms) // abs(d)
    return time32(q if (t_ms < 0) == (d < 0) else -q)


def period_ms(frequency: np.float32) -> int:
    """Step 2.1: T#1000s / TRUNC(frequency * 1000.0) for a positive frequency."""
    with np.errstate(all="ignore"):
        product = REAL(frequency) * REAL(1000.0)  # REAL * REAL, rounded to float32
    return time_div_dint(THOUSAND_SECONDS_MS, trunc_dint(product))


class Impulse:
    def __init__(self, cycle_us: int):
        self.cycle_us = cycle_us_of(cycle_us)  # the TOF measures the call times
        self.frequency_old = REAL(0.0)
        self.time_pulse = 0  # ms
        self.tof = TOF()

    def call(self, now_us: int, inputs: dict) -> dict:
        f = real("frequency", inputs["frequency"])  # §1.4: the nearest float32
        if f <= 0.0:  # 1.
            return {"impulse": False, "countdown": 0.0}
        if f != self.frequency_old:  # 2.1
            self.time_pulse = period_ms(f)
            self.frequency_old = f
        impulse = not self.tof.q_at(now_us)  # 2.2: read before the TOF runs
        self.tof(now_us, not self.tof.q_at(now_us), self.time_pulse)  # 2.3
        countdown = time32(self.time_pulse - self.tof.et_ms)  # 2.4
        return {"impulse": impulse, "countdown": time_ms_to_s(countdown)}
