"""Independent model of LGF_SimpleSmoothingFB, written from the original block's logic (the
Siemens LGF V3.0.1 FB), never from the C. docs/behaviour.md §16 describes the block; where the
two disagree the original wins.

The values and the smoothed value are LREAL (Python float, IEEE double), each operation rounded
on its own: ((oldest + middle) + newest) / 3.0 (the original's UDINT constant 3 as LREAL).

The original, in order, in every call:
1. rising edge of enable (enable AND NOT the old enable): clear the three values and the
   count, status 16#7001 -- and nothing else: a rising edge of insert in the same call is not
   looked at, and since the insert memory is updated at the end of the call, that edge is lost
   (the old model, from the manual, read it in);
2. else, enable held TRUE: at a rising edge of insert, shift the value in; while the count is
   <= 2 count it and status 16#7010; once the count is 3 (from the 4th read-in on) the mean
   of the three values and status 16#7002. So the first smoothed value comes at the 4th
   read-in, not the 3rd (the old model's);
3. else (enable FALSE): status 16#7000, smoothed value 0.0;
4. both edge memories take this call's inputs;
5. error is bit 15 of the status (never set), status and smoothedValue the statics.
"""

import math

STATUS_NO_CALL = 0x7000
STATUS_FIRST_CALL = 0x7001
STATUS_SUBSEQUENT_CALL = 0x7002
STATUS_NOT_ENOUGH_VALUES = 0x7010
MINIMUM_NUMBER_OF_VALUES = 2  # the original's constant: the count is compared with it
NUMBER_OF_VALUES = 3.0  # the original's UDINT 3, converted to LREAL in the division


class SimpleSmoothingFB:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §16: only the period of the calls
        # the original's statics: no start values, so 0 / 0.0 / FALSE
        self.statValues = [0.0, 0.0, 0.0]
        self.statCount = 0
        self.statSmoothedValue = 0.0
        self.statStatus = 0
        self.statEnableOld = False
        self.statInsertOld = False

    def call(self, now_us: int, inputs: dict) -> dict:
        enable = bool(inputs["enable"])
        insert = bool(inputs["insert"])
        value = float(inputs["value"])

        if enable and not self.statEnableOld:
            # the start: the values and the count cleared; an insert edge now is not read
            self.statCount = 0
            self.statValues = [0.0, 0.0, 0.0]
            self.statStatus = STATUS_FIRST_CALL
        elif enable and self.statEnableOld:
            if insert and not self.statInsertOld:
                v = self.statValues
                v[0] = v[1]
                v[1] = v[2]
                v[2] = value
                if self.statCount <= MINIMUM_NUMBER_OF_VALUES:
                    self.statCount += 1  # INT, at most 3: no wrap
                    self.statStatus = STATUS_NOT_ENOUGH_VALUES
                else:
                    self.statSmoothedValue = (v[0] + v[1] + v[2]) / NUMBER_OF_VALUES
                    self.statStatus = STATUS_SUBSEQUENT_CALL
        else:
            self.statStatus = STATUS_NO_CALL
            self.statSmoothedValue = 0.0

        # the edge memories, at the end of the call
        self.statEnableOld = enable
        self.statInsertOld = insert

        smoothed = self.statSmoothedValue
        if math.isnan(smoothed):
            smoothed = math.nan  # §1.4: got as the positive quiet NaN
        return {
            "smoothedValue": smoothed,
            "error": bool(self.statStatus & 0x8000),
            "status": self.statStatus,
        }
