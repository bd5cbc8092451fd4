"""Independent model of LGF_StoreMinMax, written from the original block's logic (the Siemens
LGF V3.0.1 FB), never from the C. docs/behaviour.md §14 describes the block; where the two
disagree the original wins (see below).

Two LREAL statics and comparisons of doubles only: nothing is rounded.

The original, in order, in every call:
1. compares the call's value with the stored minimum (strictly less: store it) and, in a separate
   IF, with the stored maximum (strictly greater: store it);
2. only then, if `reset` is TRUE, puts both statics back to their sentinels, the largest finite
   LREAL for the minimum and its negative for the maximum;
3. copies the statics to the outputs.

So a call with `reset` TRUE outputs the sentinels and its own value is not counted: the value
is compared first and the reset throws the result away. (The old model, written from the
manual, reset first and then counted the value.)
"""

LREAL_MAX = 1.7976931348623157e308  # the original's constant: the largest finite LREAL
LREAL_MIN = -1.7976931348623157e308  # the original's "LREAL_MIN" constant: the most negative one


class StoreMinMax:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §14.1: the block itself does not use it
        # the original declares its statics with the sentinels as start values
        self.statStoreMinValue = LREAL_MAX
        self.statStoreMaxValue = LREAL_MIN

    def call(self, now_us: int, inputs: dict) -> dict:
        value = float(inputs["value"])
        reset = bool(inputs["reset"])
        # the original compares first: two separate strict comparisons (not ELSIF)
        if value < self.statStoreMinValue:
            self.statStoreMinValue = value
        if value > self.statStoreMaxValue:
            self.statStoreMaxValue = value
        # ... and resets after: the reset call's value is lost, the sentinels are output
        if reset:
            self.statStoreMinValue = LREAL_MAX
            self.statStoreMaxValue = LREAL_MIN
        return {"minValue": self.statStoreMinValue, "maxValue": self.statStoreMaxValue}
