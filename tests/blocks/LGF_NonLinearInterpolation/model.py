"""Independent model of LGF_NonLinearInterpolation (docs/behaviour.md §20), written from that
section (and the LGF manual) alone, never from the C.

All arithmetic is LREAL (Python float, IEEE double), each operation rounded on its own in the
order of §20.3 step 3. The table comes as the FMU's parameters: `numberOfSetpoints` and
`setpoints[i].inputValue` / `setpoints[i].outputValue` (i = 0 ... 63, tunable, §20.1).
"""

import math
import re

MAX_SETPOINTS = 64
# §20.1 Decision: the start table, entries 5 ... 63 are (0.0, 0.0)
DEFAULT_TABLE = [(0.0, 0.0), (20.0, 5.0), (50.0, 30.0), (80.0, 90.0), (100.0, 100.0)]
_NAME = re.compile(r"setpoints\[(\d+)\]\.(inputValue|outputValue)")


def ieee_div(a: float, b: float) -> float:
    """a / b in IEEE double arithmetic (Python raises on b == 0): §20.5, two points with the same
    inputValue give slope ±Inf, or NaN for 0/0."""
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
        self.statIndex = 0  # §20.3: INT, 0 before the first call

    def set(self, name: str, value) -> None:
        """A tunable table entry (§20.1); takes effect at the next call (§20.4)."""
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

    def _curve(self, v: float) -> float:
        n, x, y = self.n, self.x, self.y
        # §20.3 step 1: validate statIndex
        if self.statIndex < 1 or self.statIndex > n - 1:
            self.statIndex = 1
        # §20.3 step 2: search, repeated until neither rule applies
        while True:
            k = self.statIndex
            if k > 1 and v < x[k - 1]:
                self.statIndex = k - 1
            elif k < n - 1 and v > x[k]:
                self.statIndex = k + 1
            else:
                break
        k = self.statIndex
        # §20.3 step 3, in exactly this order
        slope = ieee_div(y[k] - y[k - 1], x[k] - x[k - 1])
        a = slope * v
        b = slope * x[k - 1]
        c = y[k - 1] - b
        return a + c

    def call(self, now_us: int, inputs: dict) -> dict:
        v = float(inputs["value"])
        reset = bool(inputs["reset"])
        # §20.2 step 1: reset restarts the search whatever the other inputs are
        if reset:
            self.statIndex = 1
        # §20.2 step 2: default > reset > track > curve
        if bool(inputs["enDefaultOutValue"]):
            out = float(inputs["defaultOutValue"])
        elif reset:
            out = 0.0
        elif bool(inputs["track"]):
            out = v
        else:
            out = self._curve(v)
        if math.isnan(out):
            out = math.nan  # §1.4: got as the positive quiet NaN
        return {"outputValue": out}
