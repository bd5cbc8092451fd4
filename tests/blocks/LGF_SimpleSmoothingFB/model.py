"""Independent model of LGF_SimpleSmoothingFB, written from the original block's logic (the
Siemens LGF V3.0.1 FB), never from the C. docs/behaviour.md §16 describes the block; where the
two disagree the original wins.

The values and the smoothed value are LREAL (Python float, IEEE double), each operation rounded
on its own: ((oldest + middle) + newest) / 3.0 (the original's UDINT constant 3 as LREAL).

The call is the one tests/models/history.py describes, with n = 3: the first smoothed value
comes at the 4th read-in, not the 3rd (the old model's).
"""

from tests.models.history import FULL, OFF, STATUS_SUBSEQUENT_CALL, History

NUMBER_OF_VALUES = 3.0  # the original's UDINT 3, converted to LREAL in the division


class SimpleSmoothingFB(History):
    def __init__(self, cycle_us: int):
        super().__init__(cycle_us, 3)
        self.statSmoothedValue = 0.0

    def call(self, now_us: int, inputs: dict) -> dict:
        step = self.read_in(inputs)
        if step == FULL:
            v = self.statValues
            self.statSmoothedValue = (v[0] + v[1] + v[2]) / NUMBER_OF_VALUES
            self.statStatus = STATUS_SUBSEQUENT_CALL
        elif step == OFF:
            self.statSmoothedValue = 0.0
        return self.outputs("smoothedValue", self.statSmoothedValue)
