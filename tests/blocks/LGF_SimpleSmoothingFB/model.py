"""Independent model of LGF_SimpleSmoothingFB (docs/behaviour.md §16), written from that section
(and the LGF manual) alone, never from the C.

The values and the smoothed value are LREAL (Python float, IEEE double), each operation rounded
on its own in the order of §16.2 step 3: ((oldest + middle) + newest) / 3.0.
"""

import math

STATUS_NO_CALL = 0x7000  # §16.3: enable FALSE
STATUS_FIRST_CALL = 0x7001  # §16.3: enabled, no value read in yet
STATUS_SUBSEQUENT_CALL = 0x7002  # §16.3: a smoothed value is output
STATUS_NOT_ENOUGH_VALUES = 0x7010  # §16.3: one or two values read in


class SimpleSmoothingFB:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §16: only the period of the calls
        # §16.1: statics 0 / 0.0 / FALSE before the first call, statStatus 16#7000
        self.statValues = [0.0, 0.0, 0.0]
        self.statCount = 0
        self.statStatus = STATUS_NO_CALL
        self.statEnableOld = False
        self.statInsertOld = False
        self.smoothedValue = 0.0

    def call(self, now_us: int, inputs: dict) -> dict:
        enable = bool(inputs["enable"])
        insert = bool(inputs["insert"])
        value = float(inputs["value"])

        # §16.2 step 1: both edge memories updated in every call
        enable_edge = enable and not self.statEnableOld
        self.statEnableOld = enable
        insert_edge = insert and not self.statInsertOld
        self.statInsertOld = insert

        # §16.2 step 2: start with an empty buffer at the rising edge of enable
        if enable_edge:
            self.statValues = [0.0, 0.0, 0.0]
            self.statCount = 0
            self.smoothedValue = 0.0
            self.statStatus = STATUS_FIRST_CALL

        if enable:
            # §16.2 step 3: only at a rising edge of insert
            if insert_edge:
                self.statValues = [self.statValues[1], self.statValues[2], value]
                if self.statCount <= 2:
                    self.statCount += 1
                if self.statCount <= 2:
                    self.statStatus = STATUS_NOT_ENOUGH_VALUES
                else:
                    y0, y1, y2 = self.statValues
                    s = y0 + y1
                    s = s + y2
                    self.smoothedValue = s / 3.0
                    self.statStatus = STATUS_SUBSEQUENT_CALL
        else:
            # §16.2 step 4: disabled; the buffer is not cleared here
            self.smoothedValue = 0.0
            self.statStatus = STATUS_NO_CALL

        smoothed = self.smoothedValue
        if math.isnan(smoothed):
            smoothed = math.nan  # §1.4 / §16.4: got as the positive quiet NaN
        # §16.2 step 5
        return {
            "smoothedValue": smoothed,
            "error": bool(self.statStatus & 0x8000),
            "status": self.statStatus,
        }
