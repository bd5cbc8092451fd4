"""Independent model of LGF_FloatingAverage (docs/behaviour.md §15), written from that section
(and the LGF manual) alone, never from the C.

REAL is float32 (§15.1 "Decision: REAL", §1.4): `value` is stored as the nearest float32, and
every addition, subtraction and division of §15.2 is one numpy float32 operation, rounded on its
own, in the order written there (§15.2 "Arithmetic").
"""

import math

import numpy as np

REAL = np.float32
STATUS_OK = 0x0000
STATUS_WRONG_WINDOW_SIZE = 0x8200  # §15.4: windowSize outside 1 ... 100
MAX_WINDOW = 100


class FloatingAverage:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §15: only the period of the calls
        # §15.1: every static 0 / 0.0 / FALSE before the first call
        self.statValues = [REAL(0.0)] * MAX_WINDOW
        self.statSum = REAL(0.0)
        self.statCount = 0
        self.statIndex = 0
        self.statWindowSizeOld = 0
        self.statTriggerOld = False
        # outputs keep their values between calls (§15.2 steps 3 and 4)
        self.average = REAL(0.0)
        self.windowSizeReached = False
        self.error = False
        self.status = STATUS_OK

    def _outputs(self) -> dict:
        average = float(self.average)
        if math.isnan(average):
            average = math.nan  # §1.4 / §15.3: got as the positive quiet NaN
        return {
            "average": average,
            "windowSizeReached": self.windowSizeReached,
            "error": self.error,
            "status": self.status,
        }

    def call(self, now_us: int, inputs: dict) -> dict:
        cyclic = bool(inputs["cyclicExecution"])
        trigger = bool(inputs["trigger"])
        value = REAL(float(inputs["value"]))  # §15.1: stored as the nearest float32
        window = int(inputs["windowSize"])
        reset = bool(inputs["reset"])

        # §15.2 step 1: the edge of trigger, memory updated in every call
        trigger_edge = trigger and not self.statTriggerOld
        self.statTriggerOld = trigger

        # §15.2 step 2: restart on reset (a level) or a change of windowSize
        if reset or window != self.statWindowSizeOld:
            self.statValues = [REAL(0.0)] * MAX_WINDOW
            self.statSum = REAL(0.0)
            self.statCount = 0
            self.statIndex = 0
            self.average = REAL(0.0)
            self.windowSizeReached = False
        self.statWindowSizeOld = window

        # §15.2 step 3: window size check; average and windowSizeReached keep their values
        if window < 1 or window > MAX_WINDOW:
            self.error = True
            self.status = STATUS_WRONG_WINDOW_SIZE
            return self._outputs()

        # §15.2 step 4: at most one read-in per call
        if cyclic or trigger_edge:
            with np.errstate(all="ignore"):  # overflow and Inf - Inf are IEEE results (§15.3)
                if self.statCount < window:  # filling
                    self.statValues[self.statIndex] = value
                    self.statSum = REAL(self.statSum + value)
                    self.statCount += 1
                    self.average = REAL(self.statSum / REAL(self.statCount))
                else:  # sliding: (sum + value) - oldest
                    s = REAL(self.statSum + value)
                    self.statSum = REAL(s - self.statValues[self.statIndex])
                    self.statValues[self.statIndex] = value
                    self.average = REAL(self.statSum / REAL(window))
            self.statIndex = (self.statIndex + 1) % window

        # §15.2 step 5
        self.windowSizeReached = self.statCount >= window
        self.error = False
        self.status = STATUS_OK
        return self._outputs()
