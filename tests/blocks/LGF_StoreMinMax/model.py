"""Independent model of LGF_StoreMinMax (docs/behaviour.md §14), written from that section (and
the LGF manual) alone, never from the C.

Two LREAL statics, comparisons of doubles only: nothing is rounded (§14.2).
"""

LREAL_MAX = 1.7976931348623157e308  # §14.1: the largest finite double
LREAL_MIN = -1.7976931348623157e308  # §14.4: "LREAL_MIN" read as the most negative finite LREAL


class StoreMinMax:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §14.1: the block itself does not use it
        # §14.1 / §14.4: before the first call the statics hold the values of a reset
        self.statStoreMinValue = LREAL_MAX
        self.statStoreMaxValue = LREAL_MIN

    def call(self, now_us: int, inputs: dict) -> dict:
        value = float(inputs["value"])
        # §14.2 step 1: reset (a level) restarts the extremes; the call goes on with step 2.
        if bool(inputs["reset"]):
            self.statStoreMinValue = LREAL_MAX
            self.statStoreMaxValue = LREAL_MIN
        # §14.2 steps 2 and 3: two separate strict comparisons (not ELSIF).
        if value < self.statStoreMinValue:
            self.statStoreMinValue = value
        if value > self.statStoreMaxValue:
            self.statStoreMaxValue = value
        # §14.2 step 4
        return {"minValue": self.statStoreMinValue, "maxValue": self.statStoreMaxValue}
