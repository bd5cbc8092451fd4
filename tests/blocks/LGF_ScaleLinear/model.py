"""Independent model of LGF_ScaleLinear, written from the original block's logic (the Siemens
LGF V3.0.1 FC), never from the C. docs/behaviour.md §19 describes the block; where the two
disagree the original wins.

An FC: the outputs are a function of the inputs of the call alone. All arithmetic is LREAL
(Python float = IEEE double), each operation rounded on its own, in the original's order.

The original, in order:
1. the result starts at 0.0 and the status at 16#0000;
2. if yMin > yMax: result 0.0, status 16#8200, nothing else;
3. otherwise, if |x1 - x2| <= PRECISION * |x1| (PRECISION the LREAL 1.0E-06): "the same x",
   the result is y1. The tolerance is RELATIVE to x1 (the old model, from the manual, used an
   absolute 1e-6): x1 = 0 takes y1 only for x2 = 0 exactly, and x1 = +-Inf always takes y1
   (|Inf - x2| = Inf <= 1e-6 * Inf = Inf), unless x2 is the same infinity (Inf - Inf = NaN:
   the comparison is false and the line is computed, giving NaN);
   else the line ((y2 - y1) / (x2 - x1)) * (x - x1) + y1, left to right;
4. the clip: below yMin -> yMin, 16#6001; else above yMax -> yMax, 16#6002;
5. status the code, error its bit 15 (TRUE only for 16#8200), the return value the result.
"""

import math

STATUS_OK = 0x0000
STATUS_LIMITED_LOW = 0x6001  # the original's warning: y limited to yMin
STATUS_LIMITED_HIGH = 0x6002  # the original's warning: y limited to yMax
STATUS_LIMITS = 0x8200  # the original's error: yMin > yMax

PRECISION = 1.0e-06  # the original's LREAL constant, the double nearest 10^-6


class ScaleLinear:
    def __init__(self, cycle_us: int):
        # §19 / §1.1: the cycle only decides when the FC is evaluated; it enters no formula.
        self.cycle_us = int(cycle_us)

    def call(self, now_us: int, inputs: dict) -> dict:
        x = float(inputs["x"])
        x1 = float(inputs["x1"])
        y1 = float(inputs["y1"])
        x2 = float(inputs["x2"])
        y2 = float(inputs["y2"])
        y_min = float(inputs["yMin"])
        y_max = float(inputs["yMax"])

        y = 0.0
        status = STATUS_OK
        if y_min > y_max:
            y = 0.0
            status = STATUS_LIMITS
        else:
            # the original's "same x": relative to x1, the limit included; NaN compares false
            if abs(x1 - x2) <= PRECISION * abs(x1):
                y = y1
            else:
                m = (y2 - y1) / (x2 - x1)  # x2 - x1 is never 0 here: 0 <= 1e-6*|x1| held
                y = m * (x - x1)
                y = y + y1
            # the clip, the low limit first; a NaN y passes both
            if y < y_min:
                y = y_min
                status = STATUS_LIMITED_LOW
            elif y > y_max:
                y = y_max
                status = STATUS_LIMITED_HIGH
        if math.isnan(y):
            y = math.nan  # §1.4: got as the positive quiet NaN
        return {"y": y, "error": bool(status & 0x8000), "status": status}
