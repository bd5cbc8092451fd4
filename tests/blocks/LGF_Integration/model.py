"""Independent model of LGF_Integration (docs/behaviour.md §18), written from that section (and
the LGF manual) alone, never from the C.

Trapezoidal integration over the simulated time of the calls: the clock reading is the call
time since call 0 truncated to whole ms (§18.2 step 3, §18.3), the difference of two readings
converted to REAL (float32) and divided by 1000.0 in LREAL (§18.2 step 5), the rest LREAL
(Python float), each operation rounded on its own in the order of §18.2 step 7.
"""

import math

import numpy as np

CLEARED = None  # §18.1: statLastTime "cleared" (the original's CLEAR_TIME)


class Integration:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)
        # §18.1: statics before the first call
        self.statIntegral = 0.0
        self.statInputOldValue = 0.0
        self.statLastTime = CLEARED

    def _outputs(self) -> dict:
        integral = self.statIntegral
        if math.isnan(integral):
            integral = math.nan  # §1.4 / §18.4: got as the positive quiet NaN
        # §18.5: error always FALSE, status always 16#0000, subFunctionStatus always 0
        return {"integral": integral, "error": False, "status": 0, "subFunctionStatus": 0}

    def call(self, now_us: int, inputs: dict) -> dict:
        tau = int(now_us)  # §18.2: time of this call since call 0 in whole µs (call 0 at 0)
        value = float(inputs["value"])

        # §18.2 step 1: reset, priority over enable.
        if bool(inputs["reset"]):
            self.statInputOldValue = 0.0
            self.statIntegral = 0.0
            self.statLastTime = CLEARED
            return self._outputs()
        # §18.2 step 2: disabled: hold the integral, clear old value and last time.
        if not bool(inputs["enable"]):
            self.statInputOldValue = 0.0
            self.statLastTime = CLEARED
            return self._outputs()

        c = tau // 1000  # step 3: whole ms since call 0
        # step 4: T_DIFF; from CLEAR_TIME the difference is 0 (§18.3 decision)
        d = 0 if self.statLastTime is CLEARED else c - self.statLastTime
        # step 5: DINT_TO_REAL (float32, nearest even), widened, / 1000.0 in double
        dt = float(np.float32(d)) / 1000.0
        self.statLastTime = c  # step 6
        # step 7: ((value + old) * dt) / 2.0, each operation rounded to double
        s = value + self.statInputOldValue
        p = s * dt
        area = p / 2.0
        # step 8
        self.statIntegral = self.statIntegral + area
        self.statInputOldValue = value
        return self._outputs()  # step 9
