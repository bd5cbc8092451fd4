"""Independent model of LGF_LimRateOfChangeAdvancedCI, written from the original block's program
(the LGF V3.0.1 SCL, executed statement by statement) and docs/behaviour.md §1.1 (the cycle in
place of QRY_CINT), §1.4 (LREAL) and §21 (the interface); never from the C.

Statics: p, the output of the previous call (LREAL, 0.0 at first), and the manual-mode flag
(FALSE), which suspends the limits after manual mode. The outputs of an FB keep their values
in a call that ends early. dt := UDINT_TO_REAL(cycle in µs) / 1000000.0: the µs count rounded
to a float32 (to nearest, halves to even), then divided in double (REAL / LREAL is LREAL). All
other arithmetic is LREAL (Python float), operation by operation. One call, in the original's
order:

1. The six flags := FALSE; out := autoValue.
2. Checks (QRY_CINT's failures are not modelled, §1.6): setHighLim < setLowLim: error TRUE,
   status 16#8200; else a rate < 0: error TRUE, status 16#8202; either ends the call with
   subFunctionStatus 0 and every other output as the last call left it; p and the manual flag
   unchanged.
3. reset TRUE (a level): the manual flag := FALSE; with enDefaultOutValue out := defaultOutValue,
   then (two IFs one after the other) if out >= setHighLim: out := setHighLim, highLim TRUE; if
   out <= setLowLim: out := setLowLim, lowLim TRUE; without it out := 0.0 and no flag.
4. Else manOp TRUE: out := manualValue, the manual flag := TRUE. No limit, no flag.
5. Else (automatic):
   1. enDefaultOutValue: out := defaultOutValue; else track: out := autoValue; else the ramp
      (`ramp`), which starts from out = autoValue and may replace it and set rate flags.
   2. if out >= setHighLim: highLim TRUE, and unless the manual flag is set: out := setHighLim
      and, if out - p < setPosUpRateLim * dt, posUpRateLim := FALSE (the cut step is shorter
      than a rate step);
      else if out <= setLowLim: lowLim TRUE, and unless the manual flag is set: out :=
      setLowLim and, if p - out < setNegUpRateLim * dt, negUpRateLim := FALSE;
      else the manual flag := FALSE.
6. p := out; error FALSE, status 0, subFunctionStatus 0, outputValue := out and the flags.

The ramp (step 5.1), with a = autoValue; p < 0 is the negative range, p >= 0 (also -0.0) the
positive one:
- p < 0, p > a: v := p - setNegUpRateLim * dt; if a < v: negUpRateLim, out := v.
- p < 0, p <= a: if setNegDownRateLim = 0: negDownRateLim TRUE and out := a if a <= 0.0, else
  0.0. Else if a <= 0.0: v := p + setNegDownRateLim * dt; if a > v: negDownRateLim, out := v.
  Else (a > 0, towards the other range): v := -p / setNegDownRateLim (the time to zero); if v
  <= dt: v := (dt - v) * setPosUpRateLim, and if a > v: negDownRateLim FALSE, posUpRateLim
  TRUE, out := v; else negDownRateLim TRUE, posUpRateLim FALSE, out := p + dt *
  setNegDownRateLim.
- p >= 0, p < a: v := p + setPosUpRateLim * dt; if a > v: posUpRateLim, out := v.
- p >= 0, p >= a (a second IF on the same p and a): the mirror image: if setPosDownRateLim =
  0: posDownRateLim TRUE, out := a if a >= 0.0, else 0.0. Else if a >= 0.0: v := p -
  setPosDownRateLim * dt; if a < v: posDownRateLim, out := v. Else v := p /
  setPosDownRateLim; if v <= dt: v := -(dt - v) * setNegUpRateLim, and if a < v:
  posDownRateLim FALSE, negUpRateLim TRUE, out := v; else posDownRateLim TRUE, negUpRateLim
  FALSE, out := p - dt * setPosDownRateLim.

A NaN that ±Inf inputs make (∞ − ∞, 0 · ∞) compares FALSE everywhere and is output as the
positive quiet NaN (docs/behaviour.md §1.4). NaN inputs are refused by the FMU (ValueError
here).
"""

import math

import numpy as np

from tests.models.iec import cycle_us_of

STATUS_OK = 0x0000
STATUS_LIMITS = 0x8200  # ERR_NEG_RATE_LIM: setHighLim < setLowLim
STATUS_NEG_RATE = 0x8202  # ERR_NEG_RATE_OF_CHANGE: a rate < 0

FLAGS = ("posUpRateLim", "posDownRateLim", "negUpRateLim", "negDownRateLim", "highLim", "lowLim")
LREAL_INPUTS = (
    "autoValue",
    "manualValue",
    "setPosUpRateLim",
    "setPosDownRateLim",
    "setNegUpRateLim",
    "setNegDownRateLim",
    "setHighLim",
    "setLowLim",
    "defaultOutValue",
)


def dt_seconds(cycle_us: int) -> float:
    """UDINT_TO_REAL(cycle µs) / 1000000.0: a float32, then a double division."""
    return float(np.float32(cycle_us)) / 1000000.0


class LimRateOfChangeAdvancedCI:
    def __init__(self, cycle_us: int, **parameters):
        self.cycle_us = cycle_us_of(cycle_us)
        self.dt = dt_seconds(self.cycle_us)
        self.p = 0.0  # statPrevOutputValue
        self.man_op = False  # statManOp
        self.outputs = {  # an FB's outputs, kept by a call that ends early
            "outputValue": 0.0,
            **dict.fromkeys(FLAGS, False),
            "error": False,
            "status": STATUS_OK,
            "subFunctionStatus": 0,
        }

    def ramp(self, a: float, r: dict, f: dict) -> float:
        """Step 5.1's regular function from p towards a; sets flags in f; returns out."""
        p, dt = self.p, self.dt
        out = a
        if p < 0:  # the negative range
            if p > a:
                v = p - r["negUp"] * dt
                if a < v:
                    f["negUpRateLim"] = True
                    out = v
            elif r["negDown"] == 0.0:
                f["negDownRateLim"] = True
                out = a if a <= 0.0 else 0.0
            elif a <= 0.0:
                v = p + r["negDown"] * dt
                if a > v:
                    f["negDownRateLim"] = True
                    out = v
            else:  # towards the positive range
                v = -p / r["negDown"]  # the time until zero
                if v <= dt:
                    v = (dt - v) * r["posUp"]
                    if a > v:
                        f["negDownRateLim"] = False
                        f["posUpRateLim"] = True
                        out = v
                else:
                    f["negDownRateLim"] = True
                    f["posUpRateLim"] = False
                    out = p + dt * r["negDown"]
        else:  # the positive range and zero (both signs)
            if p < a:
                v = p + r["posUp"] * dt
                if a > v:
                    f["posUpRateLim"] = True
                    out = v
            if p >= a:
                if r["posDown"] == 0.0:
                    f["posDownRateLim"] = True
                    out = a if a >= 0.0 else 0.0
                elif a >= 0.0:
                    v = p - r["posDown"] * dt
                    if a < v:
                        f["posDownRateLim"] = True
                        out = v
                else:  # towards the negative range
                    v = p / r["posDown"]  # the time until zero
                    if v <= dt:
                        v = -(dt - v) * r["negUp"]
                        if a < v:
                            f["posDownRateLim"] = False
                            f["negUpRateLim"] = True
                            out = v
                    else:
                        f["posDownRateLim"] = True
                        f["negUpRateLim"] = False
                        out = p - dt * r["posDown"]
        return out

    def call(self, now_us: int, inputs: dict) -> dict:
        for name in LREAL_INPUTS:
            if math.isnan(float(inputs[name])):
                raise ValueError(f"{name} = NaN is refused (docs/behaviour.md §1.4)")
        a = float(inputs["autoValue"])
        r = {
            "posUp": float(inputs["setPosUpRateLim"]),
            "posDown": float(inputs["setPosDownRateLim"]),
            "negUp": float(inputs["setNegUpRateLim"]),
            "negDown": float(inputs["setNegDownRateLim"]),
        }
        high = float(inputs["setHighLim"])
        low = float(inputs["setLowLim"])
        default = float(inputs["defaultOutValue"])

        f = dict.fromkeys(FLAGS, False)  # 1.
        out = a
        dt = self.dt

        if high < low:  # 2.
            return self._end_early(STATUS_LIMITS)
        if r["negDown"] < 0.0 or r["negUp"] < 0.0 or r["posDown"] < 0.0 or r["posUp"] < 0.0:
            return self._end_early(STATUS_NEG_RATE)

        if inputs["reset"]:  # 3.
            self.man_op = False
            if inputs["enDefaultOutValue"]:
                out = default
                if out >= high:
                    out = high
                    f["highLim"] = True
                if out <= low:
                    out = low
                    f["lowLim"] = True
            else:
                out = 0.0
        elif inputs["manOp"]:  # 4.
            out = float(inputs["manualValue"])
            self.man_op = True
        else:  # 5.
            if inputs["enDefaultOutValue"]:
                out = default
            elif inputs["track"]:
                out = a
            else:
                out = self.ramp(a, r, f)
            if out >= high:  # 5.2
                f["highLim"] = True
                if not self.man_op:
                    out = high
                    if out - self.p < r["posUp"] * dt:
                        f["posUpRateLim"] = False
            elif out <= low:
                f["lowLim"] = True
                if not self.man_op:
                    out = low
                    if self.p - out < r["negUp"] * dt:
                        f["negUpRateLim"] = False
            else:
                self.man_op = False
        self.p = out  # 6.
        self.outputs = {
            "outputValue": math.nan if math.isnan(out) else out,  # the positive quiet NaN
            **f,
            "error": False,
            "status": STATUS_OK,
            "subFunctionStatus": 0,
        }
        return dict(self.outputs)

    def _end_early(self, status: int) -> dict:
        self.outputs.update(error=True, status=status, subFunctionStatus=0)
        return dict(self.outputs)
