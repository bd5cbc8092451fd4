"""Independent model of LGF_Frequency (docs/behaviour.md §10), written from that section, §1.4,
§1.12 and §6.2 (REAL_TO_UDINT) only, never from the C.

Statics (§10.2): statFrequencyOld, statPulsePauseRatioOld (REAL, 0.0), statTimePulse,
statTimePause (TIME ms, 0), the pulse TOF and the pause TOF (tests/models/timers.py), pulseQ and
pauseQ (FALSE). One call:

1. `frequency` <= 0.0 or `pulsePauseRatio` <= 0.0: clock FALSE, countdown 0 s; nothing else.
2. New settings (f != statFrequencyOld or r != statPulsePauseRatioOld, float32): both TOFs
   RESET_TIMER, pulseQ = pauseQ = FALSE; pulseRate := r / (r + 1.0); pauseRate := 1.0 -
   pulseRate; statTimePulse := REAL_TO_UDINT((1000.0 * pulseRate) / f); statTimePause :=
   REAL_TO_UDINT((1000.0 * pauseRate) / f); every operation rounded to float32, REAL_TO_UDINT
   to the nearest integer, halves to even; store f and r.
3. pulse TOF (IN := NOT pauseQ, PT := statTimePulse); pulseQ := Q.
4. countdown := statTimePulse - pulse ET.
5. pause TOF (IN := pulseQ, PT := statTimePause); pauseQ := Q.
6. countdown = 0: countdown := statTimePause - pause ET.
7. clock := pulseQ.

Refused (ValueError, §10.4, §1.4): NaN in either input; finite values beyond ±3.4028235e38;
`pulsePauseRatio` +Inf; with both inputs positive, a time (before REAL_TO_UDINT) of 2^31 or more.
"""

import math

import numpy as np

from tests.models.iec import time_ms_to_s
from tests.models.signal_ci import real
from tests.models.timers import TOF

REAL = np.float32
TIME_LIMIT = 2.0**31  # §10.4: a time of 2^31 ms or more does not fit a TIME


def real_to_udint(x: np.float32) -> int:
    """§6.2: the float32 value rounded to the nearest integer, halves to even."""
    return int(np.rint(np.float64(x)))


def times_ms(f: np.float32, r: np.float32) -> tuple[int, int]:
    """§10.2 step 2.2-2.3 for f > 0 and r > 0 (finite r): (statTimePulse, statTimePause) in ms;
    §10.4: a quotient of 2^31 or more is refused."""
    with np.errstate(all="ignore"):
        pulse_rate = REAL(r) / (REAL(r) + REAL(1.0))
        pause_rate = REAL(1.0) - pulse_rate
        pulse = (REAL(1000.0) * pulse_rate) / REAL(f)
        pause = (REAL(1000.0) * pause_rate) / REAL(f)
    for name, t in (("pulse", pulse), ("pause", pause)):
        if not float(t) < TIME_LIMIT:
            raise ValueError(f"frequency {float(f)!r}, ratio {float(r)!r}: {name} {float(t)!r} ms")
    return real_to_udint(pulse), real_to_udint(pause)


class Frequency:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §1.1: 1 µs … 60 s; the TOFs measure the call times
        if not 1 <= self.cycle_us <= 60_000_000:
            raise ValueError(f"cycleTime {self.cycle_us} µs outside 1 µs … 60 s")
        self.f_old = REAL(0.0)
        self.r_old = REAL(0.0)
        self.time_pulse = 0
        self.time_pause = 0
        self.tof_pulse = TOF()
        self.tof_pause = TOF()
        self.pulse_q = False
        self.pause_q = False

    def call(self, now_us: int, inputs: dict) -> dict:
        f = real("frequency", inputs["frequency"])  # §1.4
        r = real("pulsePauseRatio", inputs["pulsePauseRatio"])
        if math.isinf(r) and r > 0:
            raise ValueError("pulsePauseRatio +Inf is refused (§10.4)")
        if f > 0.0 and r > 0.0:
            times = times_ms(f, r)  # §10.4: checked on the pair the FMU holds
        else:  # step 1: off
            return {"clock": False, "countdown": 0.0}
        if f != self.f_old or r != self.r_old:  # step 2
            self.tof_pulse.reset()
            self.tof_pause.reset()
            self.pulse_q = self.pause_q = False
            self.time_pulse, self.time_pause = times
            self.f_old, self.r_old = f, r
        self.pulse_q = self.tof_pulse(now_us, not self.pause_q, self.time_pulse)  # step 3
        countdown = self.time_pulse - self.tof_pulse.et_ms  # step 4
        self.pause_q = self.tof_pause(now_us, self.pulse_q, self.time_pause)  # step 5
        if countdown == 0:  # step 6
            countdown = self.time_pause - self.tof_pause.et_ms
        return {"clock": self.pulse_q, "countdown": time_ms_to_s(countdown)}  # step 7
