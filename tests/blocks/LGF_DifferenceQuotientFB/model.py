"""Independent model of LGF_DifferenceQuotientFB, written from the original block's logic (the
Siemens LGF V3.0.1 FB), never from the C. docs/behaviour.md §17 describes the block; where the
two disagree the original wins.

The values, deltaT and the derivative are LREAL (Python float, IEEE double), each operation
rounded on its own, in the original's order:
    (1.0 / (12.0 * deltaT)) * (((y0 - 8 * y1) + 8 * y3) - y4)
(the old model, from the manual, divided the bracket by 12 * deltaT instead: another rounding).

The call is the one tests/models/history.py describes, with n = 5: from the 6th read-in on,
deltaT = 0 gives status 16#8200 and keeps the derivative, else the derivative and status
16#7002 (the old model gave the first derivative at the 5th read-in); error is set by 16#8200
only.
"""

from tests.models.history import FULL, OFF, STATUS_SUBSEQUENT_CALL, History

STATUS_DELTA_T = 0x8200  # the original's ERR_DELTA_T


class DifferenceQuotientFB(History):
    def __init__(self, cycle_us: int):
        super().__init__(cycle_us, 5)
        self.statDerivatedValue = 0.0

    def call(self, now_us: int, inputs: dict) -> dict:
        step = self.read_in(inputs)
        if step == FULL:
            delta_t = float(inputs["deltaT"])
            v = self.statValues
            if delta_t == 0.0:  # -0.0 too; the derivative keeps its value
                self.statStatus = STATUS_DELTA_T
            else:
                factor = 1.0 / (12.0 * delta_t)  # 12 * deltaT may be +-Inf: factor 0
                bracket = v[0] - 8.0 * v[1]
                bracket = bracket + 8.0 * v[3]
                bracket = bracket - v[4]
                self.statDerivatedValue = factor * bracket
                self.statStatus = STATUS_SUBSEQUENT_CALL
        elif step == OFF:
            self.statDerivatedValue = 0.0
        return self.outputs("derivatedValue", self.statDerivatedValue)
