"""Independent model of LGF_Impulse (docs/behaviour.md §9), written from that section, §1.4 and
§1.12 only, never from the C.

Statics (§9.2): statFrequencyOld (REAL, 0.0), statTimePulse (TIME ms, 0), the TOF of
tests/models/timers.py and Q (the TOF's Q as its last execution left it, FALSE). One call:

1. `frequency` <= 0.0 (and -Inf): impulse FALSE, countdown 0 s; nothing else (the TOF is not
   executed, no static changes).
2. `frequency` != statFrequencyOld (float32 comparison): a := frequency * 1000.0;
   q := 1000000.0 / a (each rounded to float32); statTimePulse := TRUNC(q) ms;
   statFrequencyOld := frequency. (+Inf: a = +Inf, q = 0.0, period 0 ms.)
3. TOF with IN := NOT Q, PT := statTimePulse; Q := its Q. Its ET: 0 while IN TRUE, else whole ms
   since its start, at most the PT it took.
4. impulse := NOT Q; countdown := statTimePulse - ET (ms; may be negative, §9.3).

Refused (ValueError, §9.4, §1.4): NaN; finite values beyond ±3.4028235e38; a positive frequency
whose q (float32) is 2^31 or more. +Inf, -Inf, 0 and negative values are accepted.
"""

import numpy as np

from tests.models.iec import time_ms_to_s
from tests.models.signal_ci import real
from tests.models.timers import TOF

REAL = np.float32
Q_LIMIT = 2.0**31  # §9.4: q >= 2^31 does not fit a DINT


def period_ms(frequency: np.float32) -> int:
    """§9.2 step 2 in float32, operation by operation; §9.4: q >= 2^31 refused."""
    with np.errstate(all="ignore"):
        a = REAL(frequency) * REAL(1000.0)
        q = REAL(1000000.0) / a
    if not float(q) < Q_LIMIT:
        raise ValueError(f"frequency {float(frequency)!r}: period {float(q)!r} ms does not fit")
    return int(float(q))  # TRUNC towards zero (q >= 0 here)


class Impulse:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §1.1: 1 µs … 60 s; the TOF measures the call times
        if not 1 <= self.cycle_us <= 60_000_000:
            raise ValueError(f"cycleTime {self.cycle_us} µs outside 1 µs … 60 s")
        self.freq_old = REAL(0.0)  # statFrequencyOld
        self.time_pulse = 0  # statTimePulse, ms
        self.tof = TOF()
        self.q = False

    def call(self, now_us: int, inputs: dict) -> dict:
        f = real("frequency", inputs["frequency"])  # §1.4: NaN, beyond ±FLT_MAX refused
        if f > 0.0:
            p = period_ms(f)  # §9.4: checked whenever the value is held (it is refused on set)
        if not f > 0.0:  # step 1
            return {"impulse": False, "countdown": 0.0}
        if f != self.freq_old:  # step 2 (float32 comparison)
            self.time_pulse = p
            self.freq_old = f
        self.q = self.tof(now_us, not self.q, self.time_pulse)  # step 3
        countdown = self.time_pulse - self.tof.et_ms  # step 4
        return {"impulse": not self.q, "countdown": time_ms_to_s(countdown)}
