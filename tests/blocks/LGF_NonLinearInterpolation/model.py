"""Independent model of LGF_NonLinearInterpolation, written from the original block's logic (the
Siemens LGF V3.0.1 FB), never from the C. docs/behaviour.md §20 describes the block; where the
two disagree the original wins.

All arithmetic is LREAL (Python float, IEEE double), each operation rounded on its own in the
original's order. The table comes as the FMU's parameters: `numberOfSetpoints` and
`setpoints[i].inputValue` / `setpoints[i].outputValue` (i = 0 ... 63, tunable, §20.1); the
original's Array[*] then has the bounds 0 ... numberOfSetpoints - 1.

The original, in order, in every call (L, U the array's bounds, here 0 and n - 1):
1. statIndex (INT) outside L ... U, or 0, is set to L + 1;
2. the modes, the first that applies ends the call:
   enDefaultOutValue: output defaultOutValue; else track: output value; else reset:
   statIndex := L + 1 and output 0.0. So reset restarts the search only when neither
   enDefaultOutValue nor track is TRUE (the old model, from the manual, reset the index
   always and ranked reset above track);
3. the search, repeated: with start = x[statIndex - 1], end = x[statIndex]:
   value > start and value > end and statIndex < U: one segment up;
   value <= start and statIndex > L + 1: one segment down (so a value ON an inner point
   x[k - 1] steps down from segment k to segment k - 1: the test is "<=", not "<");
   otherwise the search ends;
4. the line through the ends of segment statIndex:
   factor := (y_end - y_start) / (x_end - x_start);
   output := (factor * value) + (y_start - (factor * x_start)).
A table out of order is searched by these same rules: a step down needs value <= x[k - 1],
after which a step up would need value > x[k - 1], and the other way round, so the search
moves one way only and ends.
"""

import math
import re

MAX_SETPOINTS = 64
# §20.1 Decision: the start table, entries 5 ... 63 are (0.0, 0.0)
DEFAULT_TABLE = [(0.0, 0.0), (20.0, 5.0), (50.0, 30.0), (80.0, 90.0), (100.0, 100.0)]
_NAME = re.compile(r"setpoints\[(\d+)\]\.(inputValue|outputValue)")


def ieee_div(a: float, b: float) -> float:
    """a / b in IEEE double arithmetic as the CPU divides LREALs (Python raises on b == 0): two
    points with the same inputValue give ±Inf, or NaN for 0/0."""
    if b == 0.0:
        if a == 0.0 or math.isnan(a):
            return math.nan
        return math.copysign(math.inf, a) * math.copysign(1.0, b)
    return a / b


class NonLinearInterpolation:
    def __init__(self, cycle_us: int, numberOfSetpoints: int = 5, **setpoints):
        self.cycle_us = int(cycle_us)  # §20.1: used by no rule
        self.x = [0.0] * MAX_SETPOINTS
        self.y = [0.0] * MAX_SETPOINTS
        for i, (xi, yi) in enumerate(DEFAULT_TABLE):
            self.x[i], self.y[i] = xi, yi
        n = int(numberOfSetpoints)
        if not 2 <= n <= MAX_SETPOINTS:  # §20.5: refused by the FMU
            raise ValueError(f"numberOfSetpoints {n} outside 2 .. {MAX_SETPOINTS}")
        self.n = n
        for name, value in setpoints.items():
            self.set(name, value)
        self.statIndex = 0  # INT static, 0 before the first call

    def set(self, name: str, value) -> None:
        """A tunable table entry (§20.1); takes effect at the next call."""
        m = _NAME.fullmatch(name)
        if not m or int(m.group(1)) >= MAX_SETPOINTS:
            raise KeyError(name)
        v = float(value)
        if math.isnan(v):
            raise ValueError(f"{name} NaN")  # §20.1: NaN refused
        i = int(m.group(1))
        if m.group(2) == "inputValue":
            self.x[i] = v
        else:
            self.y[i] = v

    def call(self, now_us: int, inputs: dict) -> dict:
        value = float(inputs["value"])
        lower, upper = 0, self.n - 1  # the bounds of the FMU's setpoints array
        x, y = self.x, self.y

        # the original first checks the index: outside the bounds, or 0 -> lower + 1
        if self.statIndex < lower or self.statIndex > upper or self.statIndex == 0:
            self.statIndex = lower + 1

        # the modes: each ends the call; reset touches the index only in its own branch
        if bool(inputs["enDefaultOutValue"]):
            return {"outputValue": float(inputs["defaultOutValue"])}
        if bool(inputs["track"]):
            return {"outputValue": value}
        if bool(inputs["reset"]):
            self.statIndex = lower + 1
            return {"outputValue": 0.0}

        # the search, as the original's REPEAT loop: the start and end points are reloaded
        # from the table at the top of every round
        end_of_search = False
        while not end_of_search:
            start_x = x[self.statIndex - 1]
            end_x = x[self.statIndex]
            if value > start_x:
                if value > end_x and self.statIndex < upper:
                    self.statIndex += 1
                else:
                    end_of_search = True
            elif self.statIndex > lower + 1:  # value <= start_x: one segment down
                self.statIndex -= 1
            else:
                end_of_search = True
        k = self.statIndex
        start_x, end_x = x[k - 1], x[k]
        start_y, end_y = y[k - 1], y[k]
        factor = ieee_div(end_y - start_y, end_x - start_x)
        out = (factor * value) + (start_y - (factor * start_x))
        if math.isnan(out):
            out = math.nan  # §1.4: got as the positive quiet NaN
        return {"outputValue": out}
