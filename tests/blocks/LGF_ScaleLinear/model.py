"""Independent model of LGF_ScaleLinear (docs/behaviour.md §19), written from that section (and
the LGF manual) alone, never from the C.

An FC: the outputs are a function of the inputs of the call alone (§19, "The FMU has no
statics"). All arithmetic is LREAL (Python float = IEEE double), each operation rounded on its
own in the order §19.2 writes it.
"""

import math

STATUS_OK = 0x0000
STATUS_LIMITED_LOW = 0x6001  # §19.4: y limited to yMin
STATUS_LIMITED_HIGH = 0x6002  # §19.4: y limited to yMax
STATUS_LIMITS = 0x8200  # §19.4: yMin > yMax

PRECISION = 1.0e-06  # §19.2: the LREAL constant, the double nearest 10^-6


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

        # §19.2 step 1: yMin > yMax -> y 0.0, 16#8200, error; nothing else is computed.
        if y_min > y_max:
            return {"y": 0.0, "error": True, "status": STATUS_LIMITS}

        # §19.2 step 2: the line. |x2 - x1| <= PRECISION (limit included; NaN compares false).
        if abs(x2 - x1) <= PRECISION:
            y = y1
        else:
            s = y2 - y1
            d = x2 - x1
            m = s / d  # d is never 0 here: |0| <= PRECISION took the first branch
            y = m * (x - x1)
            y = y + y1

        # §19.2 step 3: the clip, the low limit first; a NaN y passes both (§19.3).
        if y < y_min:
            y, status = y_min, STATUS_LIMITED_LOW
        elif y > y_max:
            y, status = y_max, STATUS_LIMITED_HIGH
        else:
            status = STATUS_OK
        if math.isnan(y):
            y = math.nan  # §1.4: the positive quiet NaN
        # §19.2 step 4: error FALSE for every code of step 3.
        return {"y": y, "error": False, "status": status}
