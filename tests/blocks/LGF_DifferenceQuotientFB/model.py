"""Independent model of LGF_DifferenceQuotientFB, written from the original block's logic (the
Siemens LGF V3.0.1 FB), never from the C. docs/behaviour.md §17 describes the block; where the
two disagree the original wins.

The values, deltaT and the derivative are LREAL (Python float, IEEE double), each operation
rounded on its own, in the original's order:
    (1.0 / (12.0 * deltaT)) * (((y0 - 8 * y1) + 8 * y3) - y4)
(the old model, from the manual, divided the bracket by 12 * deltaT instead: another rounding).

The original, in order, in every call:
1. rising edge of enable: clear the five values and the count, status 16#7001 -- nothing
   else: a rising edge of insert in the same call is not looked at, and since the insert
   memory is updated at the end of the call, that edge is lost (the old model read it in);
2. else, enable held TRUE: at a rising edge of insert, shift the value in; while the count is
   <= 4 count it and status 16#7010 (read-ins 1 to 5); from the 6th read-in on: deltaT = 0
   gives status 16#8200 and keeps the derivative, else the derivative and status 16#7002
   (the old model gave the first derivative at the 5th read-in);
3. else (enable FALSE): derivative 0.0, status 16#7000;
4. both edge memories take this call's inputs;
5. error is bit 15 of the status (16#8200 only).
"""

import math

STATUS_NO_CALL = 0x7000
STATUS_FIRST_CALL = 0x7001
STATUS_SUBSEQUENT_CALL = 0x7002
STATUS_NOT_ENOUGH_VALUES = 0x7010
STATUS_DELTA_T = 0x8200  # the original's ERR_DELTA_T
MINIMUM_NUMBER_OF_VALUES = 4  # the original's constant: the count is compared with it


class DifferenceQuotientFB:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §17: only the period of the calls
        # the original's statics: no start values, so 0 / 0.0 / FALSE
        self.statValues = [0.0] * 5
        self.statCount = 0
        self.statDerivatedValue = 0.0
        self.statStatus = 0
        self.statEnableOld = False
        self.statInsertOld = False

    def call(self, now_us: int, inputs: dict) -> dict:
        enable = bool(inputs["enable"])
        insert = bool(inputs["insert"])
        value = float(inputs["value"])
        delta_t = float(inputs["deltaT"])

        if enable and not self.statEnableOld:
            # the start: the values and the count cleared; an insert edge now is not read
            self.statCount = 0
            self.statValues = [0.0] * 5
            self.statStatus = STATUS_FIRST_CALL
        elif enable and self.statEnableOld:
            if insert and not self.statInsertOld:
                v = self.statValues
                v[0] = v[1]
                v[1] = v[2]
                v[2] = v[3]
                v[3] = v[4]
                v[4] = value
                if self.statCount <= MINIMUM_NUMBER_OF_VALUES:
                    self.statCount += 1  # INT, at most 5: no wrap
                    self.statStatus = STATUS_NOT_ENOUGH_VALUES
                elif delta_t == 0.0:  # -0.0 too; the derivative keeps its value
                    self.statStatus = STATUS_DELTA_T
                else:
                    factor = 1.0 / (12.0 * delta_t)  # 12 * deltaT may be +-Inf: factor 0
                    bracket = v[0] - 8.0 * v[1]
                    bracket = bracket + 8.0 * v[3]
                    bracket = bracket - v[4]
                    self.statDerivatedValue = factor * bracket
                    self.statStatus = STATUS_SUBSEQUENT_CALL
        else:
            self.statDerivatedValue = 0.0
            self.statStatus = STATUS_NO_CALL

        # the edge memories, at the end of the call
        self.statEnableOld = enable
        self.statInsertOld = insert

        derivated = self.statDerivatedValue
        if math.isnan(derivated):
            derivated = math.nan  # §1.4: got as the positive quiet NaN
        return {
            "derivatedValue": derivated,
            "error": bool(self.statStatus & 0x8000),
            "status": self.statStatus,
        }
