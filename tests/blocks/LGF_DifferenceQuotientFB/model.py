"""Independent model of LGF_DifferenceQuotientFB (docs/behaviour.md §17), written from that
section (and the LGF manual) alone, never from the C.

The values, deltaT and the derivative are LREAL (Python float, IEEE double); the derivative is
formed in exactly the order of §17.2 step 3: num := ((y0 - 8.0*y1) + 8.0*y3) - y4;
den := 12.0*deltaT; num / den, each operation rounded on its own.
"""

import math

STATUS_NO_CALL = 0x7000  # §17.3: enable FALSE
STATUS_FIRST_CALL = 0x7001  # §17.3: enabled, no value read in yet
STATUS_SUBSEQUENT_CALL = 0x7002  # §17.3: a derivative was formed
STATUS_NOT_ENOUGH_VALUES = 0x7010  # §17.3: one to four values read in
STATUS_DELTA_T = 0x8200  # §17.3: five values and deltaT = 0.0 (ERR_DELTA_T)


class DifferenceQuotientFB:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §17: only the period of the calls
        # §17.1: statics 0 / 0.0 / FALSE before the first call, statStatus 16#7000
        self.statValues = [0.0] * 5
        self.statCount = 0
        self.statStatus = STATUS_NO_CALL
        self.statEnableOld = False
        self.statInsertOld = False
        self.derivatedValue = 0.0

    def call(self, now_us: int, inputs: dict) -> dict:
        enable = bool(inputs["enable"])
        insert = bool(inputs["insert"])
        value = float(inputs["value"])
        delta_t = float(inputs["deltaT"])

        # §17.2 step 1 (as §16.2 step 1): both edge memories updated in every call
        enable_edge = enable and not self.statEnableOld
        self.statEnableOld = enable
        insert_edge = insert and not self.statInsertOld
        self.statInsertOld = insert

        # §17.2 step 2: start with an empty buffer at the rising edge of enable
        if enable_edge:
            self.statValues = [0.0] * 5
            self.statCount = 0
            self.derivatedValue = 0.0
            self.statStatus = STATUS_FIRST_CALL

        if enable:
            # §17.2 step 3: only at a rising edge of insert
            if insert_edge:
                self.statValues = self.statValues[1:] + [value]
                if self.statCount < 5:
                    self.statCount += 1
                if self.statCount < 5:
                    self.statStatus = STATUS_NOT_ENOUGH_VALUES
                elif delta_t == 0.0:  # -0.0 included; derivatedValue keeps its value
                    self.statStatus = STATUS_DELTA_T
                else:
                    y0, y1, _y2, y3, y4 = self.statValues
                    a = 8.0 * y1
                    num = y0 - a
                    b = 8.0 * y3
                    num = num + b
                    num = num - y4
                    den = 12.0 * delta_t
                    # den != 0: deltaT != 0 and |12*deltaT| >= |deltaT|
                    self.derivatedValue = num / den
                    self.statStatus = STATUS_SUBSEQUENT_CALL
        else:
            # §17.2 step 4: disabled; the buffer is not cleared here
            self.derivatedValue = 0.0
            self.statStatus = STATUS_NO_CALL

        derivated = self.derivatedValue
        if math.isnan(derivated):
            derivated = math.nan  # §1.4 / §17.4: got as the positive quiet NaN
        # §17.2 step 5
        return {
            "derivatedValue": derivated,
            "error": bool(self.statStatus & 0x8000),
            "status": self.statStatus,
        }
