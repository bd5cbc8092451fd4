"""Reference model of LGF_LimRateOfChangeCI (docs/behaviour.md §3, seed 001)."""

import numpy as np

STATUS_OK = 0x0000
STATUS_NEG_RATE = 0x8200  # 33280: negative rate of change


def _max(a: float, b: float) -> float:
    # MAX(a, b); a tie returns a (numerically equal anyway), a NaN in a returns b (like C fmax).
    return a if a >= b else b


def _min(a: float, b: float) -> float:
    return a if a <= b else b


class LimRateOfChangeCI:
    def __init__(self, cycle_us: int):
        # docs/behaviour.md §1.1: cycleTime held as whole microseconds; §3.3: dt =
        # UDINT_TO_REAL(cycle in us) / 1e6 as the original computes it: the us count is first
        # rounded to a 32-bit REAL (nearest, halves to even), then divided in LREAL (double).
        # Exact for every whole-ms cycle up to 60 s; 16777217 us gives dt 16.777216 s.
        self.cycle_us = int(cycle_us)
        self.dt = float(np.float32(self.cycle_us)) / 1e6
        self.prev = 0.0  # internal previous output, 0.0 before the first call (§3.2)
        self.delayedValue = 0.0
        self.error = False
        self.status = STATUS_OK
        self.subFunctionStatus = 0

    def _write(self, out: float) -> dict:
        """A call without error: out is the new output and the new previous output."""
        self.prev = out
        self.delayedValue = out
        self.error = False
        self.status = STATUS_OK
        self.subFunctionStatus = 0
        return self._outputs()

    def _outputs(self) -> dict:
        return {
            "delayedValue": self.delayedValue,
            "error": self.error,
            "status": self.status,
            "subFunctionStatus": self.subFunctionStatus,
        }

    def call(self, now_us: int, inputs: dict) -> dict:
        value = float(inputs["value"])
        rate = float(inputs["setChangeRate"])
        default = float(inputs["defaultOutValue"])
        en_default = bool(inputs["enDefaultOutValue"])

        # docs/behaviour.md §3.2 rule 1: negative rate -> error, output and previous output frozen.
        if rate < 0.0:
            self.error = True
            self.status = STATUS_NEG_RATE
            self.subFunctionStatus = 0
            return self._outputs()

        # docs/behaviour.md §3.2 rule 2: pre-assignment (jump to defaultOutValue).
        if en_default:
            return self._write(default)

        # docs/behaviour.md §3.2 rule 3: rate-limited ramp from the previous output p, landing
        # exactly on value.
        p = self.prev
        if value < p:
            out = _max(p - rate * self.dt, value)
        elif value > p:
            out = _min(p + rate * self.dt, value)
        else:
            out = p
        return self._write(out)
