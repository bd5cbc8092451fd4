"""Independent model of LGF_IecTimerOnOff (docs/behaviour.md §8), written from that section and
§1.12 only, never from the C.

One call (§8.2), with the S7 timers of tests/models/timers.py (§1.12):
1. TON with IN = `in`, PT = `timeOnDelay` (TIME, whole ms, §1.4; a negative PT taken as 0 at the
   rising edge).
2. TOF with IN = the TON's Q of this same call, PT = `timeOffDelay` (taken at the falling edge).
3. `out` := the TOF's Q.
Call 0 is a call like the others (an `in` TRUE there is a rising edge). No error or status
output; refused values (NaN or |TIME| > 2147483.647 s) raise ValueError (§8, §1.4).
"""

from tests.models.iec import cycle_us_of, time_s_to_ms
from tests.models.timers import TOF, TON


class IecTimerOnOff:
    def __init__(self, cycle_us: int):
        self.cycle_us = cycle_us_of(cycle_us)  # §8: the timers measure the call times
        self.ton = TON()
        self.tof = TOF()

    def call(self, now_us: int, inputs: dict) -> dict:
        on_ms = time_s_to_ms(inputs["timeOnDelay"])  # §1.4 rounding and refusals
        off_ms = time_s_to_ms(inputs["timeOffDelay"])
        q_ton = self.ton(now_us, bool(inputs["in"]), on_ms)  # §8.2 step 1
        q_tof = self.tof(now_us, q_ton, off_ms)  # step 2: the TON's Q of this same call
        return {"out": q_tof}  # step 3
