"""What the originals of LGF_SimpleSmoothingFB (docs/behaviour.md §16) and
LGF_DifferenceQuotientFB (§17) share: they keep the last n values read in at a rising edge of
insert while enabled, and differ only in what they compute from a full buffer.

The original, in order, in every call:
1. rising edge of enable (enable AND NOT the old enable): clear the values and the count,
   status 16#7001 -- and nothing else: a rising edge of insert in the same call is not looked
   at, and since the insert memory is updated at the end of the call, that edge is lost;
2. else, enable held TRUE: at a rising edge of insert, shift the value in; while the count is
   <= n - 1 (the original's MINIMUM_NUMBER_OF_VALUES) count it and status 16#7010; from the
   (n + 1)th read-in on the block computes its result;
3. else (enable FALSE): status 16#7000, the result 0.0;
4. both edge memories take this call's inputs;
5. error is bit 15 of the status, status and the result the statics.
"""

import math

STATUS_NO_CALL = 0x7000
STATUS_FIRST_CALL = 0x7001
STATUS_SUBSEQUENT_CALL = 0x7002
STATUS_NOT_ENOUGH_VALUES = 0x7010

FULL, OFF = "full", "off"  # what read_in leaves the block to do


class History:
    """The statics of such a block (the original's have no start values: 0 / 0.0 / FALSE) and
    steps 1 to 4 of its call."""

    def __init__(self, cycle_us: int, n: int):
        self.cycle_us = int(cycle_us)  # only the period of the calls
        self.n = n
        self.statValues = [0.0] * n
        self.statCount = 0
        self.statStatus = 0
        self.statEnableOld = False
        self.statInsertOld = False

    def read_in(self, inputs: dict) -> str | None:
        """Steps 1 to 4: FULL when the block computes its result from statValues (the newest
        last), OFF when it sets it to 0.0, else None."""
        enable = bool(inputs["enable"])
        insert = bool(inputs["insert"])
        step = None
        if enable and not self.statEnableOld:
            # the start: the values and the count cleared; an insert edge now is not read
            self.statCount = 0
            self.statValues = [0.0] * self.n
            self.statStatus = STATUS_FIRST_CALL
        elif enable and self.statEnableOld:
            if insert and not self.statInsertOld:
                self.statValues = self.statValues[1:] + [float(inputs["value"])]
                if self.statCount <= self.n - 1:
                    self.statCount += 1  # INT, at most n: no wrap
                    self.statStatus = STATUS_NOT_ENOUGH_VALUES
                else:
                    step = FULL
        else:
            self.statStatus = STATUS_NO_CALL
            step = OFF
        # the edge memories, at the end of the call
        self.statEnableOld = enable
        self.statInsertOld = insert
        return step

    def outputs(self, name: str, result: float) -> dict:
        """Step 5: the result as output `name` (a NaN as the positive quiet NaN, §1.4), error
        and status."""
        return {
            name: math.nan if math.isnan(result) else result,
            "error": bool(self.statStatus & 0x8000),
            "status": self.statStatus,
        }
