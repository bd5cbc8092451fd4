"""Independent model of LGF_Frequency, written from the original block's program (the LGF V3.0.1
SCL, executed statement by statement) and docs/behaviour.md §1.4 (REAL, TIME), §1.12 (the S7
IEC timers, with the update on read) and §10 (the interface and the values the FMU refuses);
never from the C.

Statics: the frequency and ratio of the last computation (REAL, 0.0 at first), the pulse and
pause times (TIME ms, 0 at first), and two S7 TOFs (tests/models/timers.py). One call, in the
original's order:

1. If `frequency` <= 0.0 or `pulsePauseRatio` <= 0.0: the temporary countdown is 0 ms; no timer
   is executed and no static changes. (The original also writes clock FALSE here, but its last
   statement overwrites clock in every call, see 4.)
2. Otherwise:
   1. If either input differs from the values of the last computation (float32 compare): both
      TOFs are reset (RESET_TIMER), then in REAL arithmetic, each operation rounded to float32:
      pulseRate := r / (r + 1.0); pauseRate := 1.0 - pulseRate; pulse time :=
      REAL_TO_UDINT(1000.0 * pulseRate / f) and pause time := REAL_TO_UDINT(1000.0 * pauseRate /
      f), left to right ((1000.0 * rate) / f), REAL_TO_UDINT rounding to nearest, halves to even
      (the S7 conversion, as docs/behaviour.md §6.2 and §10.2 take it), the UDINT taken as a
      TIME; f and r are stored.
   2. The pulse TOF with IN := NOT (the pause TOF's Q) and PT := pulse time. The pause TOF's Q
      is read before that timer runs in this call, so it is updated to this call's time
      (§1.12): a pause that elapsed since the last call is over already here.
   3. countdown := pulse time - the pulse TOF's ET.
   4. The pause TOF with IN := the pulse TOF's Q and PT := pause time.
   5. If countdown = 0 ms: countdown := pause time - the pause TOF's ET.
3. (TIME subtraction wraps in 32 bits; it never does here, ET being at most the PT taken.)
4. Outputs, in every call: clock := the pulse TOF's Q, read at this call's time (update on read),
   also when step 1 switched the block off: a pulse that is running goes on showing TRUE until
   it elapses; countdown := the temporary countdown.

Refused by the FMU (ValueError here, docs/behaviour.md §10.4): NaN in either input, finite
values beyond ±3.4028235e38, `pulsePauseRatio` +Inf; with both inputs positive, a time
(before REAL_TO_UDINT) of 2^31 ms or more, which a TIME cannot hold.
"""

import numpy as np

from tests.models.iec import cycle_us_of, time_ms_to_s
from tests.models.signal_ci import real
from tests.models.timers import TOF

REAL = np.float32
TIME_LIMIT = 2.0**31  # docs/behaviour.md §10.4: a time of 2^31 ms or more does not fit a TIME


def time32(ms: int) -> int:
    """TIME arithmetic wraps in signed 32 bits (docs/behaviour.md §1.4)."""
    return ((int(ms) + 2**31) % 2**32) - 2**31


def real_to_udint(x: np.float32) -> int:
    """REAL_TO_UDINT: to the nearest integer, halves to even (docs/behaviour.md §6.2)."""
    return int(np.rint(np.float64(x)))


def times_ms(f: np.float32, r: np.float32) -> tuple[int, int]:
    """(pulse time, pause time) in ms for f > 0 and 0 < r < +Inf, as the original computes them
    in REAL; a quotient of 2^31 or more is refused (docs/behaviour.md §10.4)."""
    one, thousand = REAL(1.0), REAL(1000.0)
    with np.errstate(all="ignore"):
        pulse_rate = REAL(r) / (REAL(r) + one)
        pause_rate = one - pulse_rate
        pulse = (thousand * pulse_rate) / REAL(f)
        pause = (thousand * pause_rate) / REAL(f)
    for name, t in (("pulse", pulse), ("pause", pause)):
        if not float(t) < TIME_LIMIT:
            raise ValueError(f"frequency {float(f)!r}, ratio {float(r)!r}: {name} {float(t)!r} ms")
    return real_to_udint(pulse), real_to_udint(pause)


class Frequency:
    def __init__(self, cycle_us: int):
        self.cycle_us = cycle_us_of(cycle_us)  # the TOFs measure the call times
        self.frequency_old = REAL(0.0)
        self.ratio_old = REAL(0.0)
        self.time_pulse = 0
        self.time_pause = 0
        self.tof_pulse = TOF()
        self.tof_pause = TOF()

    def call(self, now_us: int, inputs: dict) -> dict:
        f = real("frequency", inputs["frequency"])  # §1.4: the nearest float32
        r = real("pulsePauseRatio", inputs["pulsePauseRatio"])
        if np.isinf(r) and r > 0:
            raise ValueError("pulsePauseRatio +Inf is refused (docs/behaviour.md §10.4)")
        if f > 0.0 and r > 0.0:
            times = times_ms(f, r)  # §10.4: the FMU refuses a pair whose times overflow
        if f <= 0.0 or r <= 0.0:  # 1. switched off
            countdown = 0
        else:
            if self.frequency_old != f or self.ratio_old != r:  # 2.1 new settings
                self.tof_pause.reset()
                self.tof_pulse.reset()
                self.time_pulse, self.time_pause = times
                self.frequency_old, self.ratio_old = f, r
            pause_q = self.tof_pause.q_at(now_us)  # 2.2: read before the pause TOF runs
            self.tof_pulse(now_us, not pause_q, self.time_pulse)
            countdown = time32(self.time_pulse - self.tof_pulse.et_ms)  # 2.3
            self.tof_pause(now_us, self.tof_pulse.q, self.time_pause)  # 2.4
            if countdown == 0:  # 2.5
                countdown = time32(self.time_pause - self.tof_pause.et_ms)
        clock = self.tof_pulse.q_at(now_us)  # 4: the last statement, in every call
        return {"clock": clock, "countdown": time_ms_to_s(countdown)}
