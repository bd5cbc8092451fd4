"""Independent model of LGF_LimRateOfChangeAdvancedCI (docs/behaviour.md §21), written from that
section (and the LGF manual) alone, never from the C.

All arithmetic is LREAL (Python float, IEEE double), each operation rounded on its own (§21.2);
dt = UDINT_TO_REAL(cycle in whole µs) / 1e6 as in §3.3: the µs count rounded to float32 first,
then divided in double.
"""

import math

import numpy as np

STATUS_OK = 0x0000
STATUS_LIMITS = 0x8200  # §21.4: setHighLim < setLowLim (ERR_NEG_RATE_LIM)
STATUS_NEG_RATE = 0x8202  # §21.4: a rate < 0 (ERR_NEG_RATE_OF_CHANGE)

FLAGS = ("posUpRateLim", "posDownRateLim", "negUpRateLim", "negDownRateLim", "highLim", "lowLim")


def _min(c: float, t: float) -> float:
    """§21.3: min(c, t) is "c if c <= t, else t" (a NaN c yields t)."""
    return c if c <= t else t


def _max(c: float, t: float) -> float:
    """§21.3: max(c, t) is "c if c >= t, else t" (a NaN c yields t)."""
    return c if c >= t else t


class LimRateOfChangeAdvancedCI:
    def __init__(self, cycle_us: int, **parameters):
        self.cycle_us = int(cycle_us)
        self.dt = float(np.float32(self.cycle_us)) / 1e6  # §21 / §3.3
        # §21.2: statics before the first call
        self.p = 0.0  # statPrevOutputValue
        self.statManOp = False
        # outputs, kept through an error call (§21.2 step 1)
        self.outputValue = 0.0
        self.flags = dict.fromkeys(FLAGS, False)
        self.error = False
        self.status = STATUS_OK

    def _outputs(self) -> dict:
        return {
            "outputValue": self.outputValue,
            **self.flags,
            "error": self.error,
            "status": self.status,
            "subFunctionStatus": 0,  # §21.2: 0 in every call
        }

    def _ramp(self, t: float, rates: dict) -> float:
        """§21.3: the ramp from p towards t; sets at most one rate flag."""
        p, dt, f = self.p, self.dt, self.flags
        if t == p:
            return p
        if t > p and p >= 0.0:  # rising in the positive range (zero included, -0.0 too)
            c = p + rates["up"] * dt
            f["posUpRateLim"] = c < t
            return _min(c, t)
        if t > p:  # p < 0: rising in the negative range
            c = p + rates["negDown"] * dt
            if c > 0.0 and t > 0.0:  # crossing zero within the call
                z = (0.0 - p) / rates["negDown"]
                r = dt - z
                c2 = 0.0 + rates["up"] * r
                f["posUpRateLim"] = c2 < t
                return _min(c2, t)
            f["negDownRateLim"] = c < t
            return _min(c, t)
        if p <= 0.0:  # t < p, falling in the negative range (magnitude rises)
            c = p - rates["negUp"] * dt
            f["negUpRateLim"] = c > t
            return _max(c, t)
        # t < p, p > 0: falling in the positive range
        c = p - rates["down"] * dt
        if c < 0.0 and t < 0.0:  # crossing zero
            z = p / rates["down"]
            r = dt - z
            c2 = 0.0 - rates["negUp"] * r
            f["negUpRateLim"] = c2 > t
            return _max(c2, t)
        f["posDownRateLim"] = c > t
        return _max(c, t)

    def call(self, now_us: int, inputs: dict) -> dict:
        auto = float(inputs["autoValue"])
        manual = float(inputs["manualValue"])
        rates = {
            "up": float(inputs["setPosUpRateLim"]),
            "down": float(inputs["setPosDownRateLim"]),
            "negUp": float(inputs["setNegUpRateLim"]),
            "negDown": float(inputs["setNegDownRateLim"]),
        }
        high = float(inputs["setHighLim"])
        low = float(inputs["setLowLim"])
        default = float(inputs["defaultOutValue"])
        en_default = bool(inputs["enDefaultOutValue"])
        track = bool(inputs["track"])
        man_op = bool(inputs["manOp"])
        reset = bool(inputs["reset"])

        # §21.2 step 1: checks, limits first; an error call freezes everything else
        if high < low:
            self.error, self.status = True, STATUS_LIMITS
            return self._outputs()
        if any(r < 0.0 for r in rates.values()):
            self.error, self.status = True, STATUS_NEG_RATE
            return self._outputs()

        # §21.2 step 2
        self.error, self.status = False, STATUS_OK
        self.flags = dict.fromkeys(FLAGS, False)

        if reset:
            # §21.2 step 3: restart; the pre-assignment within the limits, else 0.0; no flag
            self.statManOp = False
            if en_default:
                if default > high:
                    out = high
                elif default < low:
                    out = low
                else:
                    out = default
            else:
                out = 0.0
        elif man_op:
            # §21.2 step 4: manual, nothing else applies
            out = manual
            self.statManOp = True
        else:
            # §21.2 step 5.1
            if en_default:
                out = default
            elif track:
                out = auto
            else:
                out = self._ramp(auto, rates)
            # step 5.2: limits suspended after manual mode until out is within them
            if self.statManOp and low <= out <= high:
                self.statManOp = False
            # step 5.3
            if not self.statManOp:
                if out > high:
                    out = high
                    self.flags["highLim"] = True
                elif out < low:
                    out = low
                    self.flags["lowLim"] = True

        # §21.2 step 6
        self.p = out
        self.outputValue = out
        result = self._outputs()
        if math.isnan(result["outputValue"]):
            result["outputValue"] = math.nan  # §1.4 (cannot occur: see the ramp's comparisons)
        return result
