"""Reference model of LGF_SinusCI (docs/behaviour.md §6), written from docs/behaviour.md only,
never from the C.

The shared rules R1-R9 and decisions D1-D6, D11 of the five signal generators (REAL = float32, UDINT
modulo 2^32, REAL_TO_UDINT halves to even, the checks of the inputs, the counter, Ts in whole
ms, SIN) are in tests/models/signal_ci.py. The sine and cosine share this module: they differ
only in the function.

- reset TRUE: "counter := 0, value := 0.0" (§6): 0.0, not the offset.
- otherwise: counter := (counter + Ts) MOD periode; P := REAL(periode);
  "rad := REAL(counter) · 6.283185 / P; shift := (phaseShift · 6.283185) / P;
  value := SIN|COS(rad + shift) · amplitude + offset" (§6), in float32, left to right:
  x := ((REAL(counter) · 6.283185) / P) + ((phaseShift · 6.283185) / P); value :=
  (SIN(x) · amplitude) + offset. phaseShift enters as the REAL itself (not REAL_TO_UDINT), so
  a fractional or huge shift gives a large argument as written.
- SIN/COS (R9): the double sin/cos of the float32 x widened to double, rounded to float32. The
  FMU's own routine may differ within the tolerance of §6 ("tested within 1 float32 ulp of a
  correctly rounded value"); `value` is a TrigValue carrying, besides the model's value, the
  values that a SIN/COS one float32 ulp below or above give after · amplitude + offset, which
  the comparison of tests/signal_generators.py accepts.

Decisions used (tests/models/signal_ci.py): D1, D2, D3, D4, D5, D11 (Ts from the whole-µs
cycle), and:
D9  6.283185 is a REAL literal: float32 6.28318500518798828125 (R1), not the double 2π.
D10 The tolerance of SIN/COS is applied to SIN/COS itself, before · amplitude + offset, and
    besides that `value` may differ from the model's by one float32 ulp (what the project asked
    for); everything else must be exact.
D12 The interface line "phaseShift ... ≥ 0: the original converts it to UDINT" describes the
    REAL_TO_UDINT of SawToothCI, TriangleCI and RectangleCI; the sine's formula is written with
    the REAL phaseShift, "shift := (phaseShift · 6.283185) / P", and is taken as written: a
    phaseShift of 0.5 ms shifts the sine by 0.5 ms, not by REAL_TO_UDINT(0.5) = 0. Its range
    check (0 … 4294967295) is the same for all five.
"""

from tests.models.signal_ci import (
    COS,
    REAL,
    SIN,
    TWO_PI,
    SignalCI,
    TrigValue,
    next_down,
    next_up,
    udint_to_real,
)


class Trigonometric(SignalCI):
    FUNCTION = staticmethod(SIN)

    def reset_value(self, amplitude, offset):
        return 0.0

    def argument(self, periode, phase_shift):
        P = udint_to_real(periode)
        rad = udint_to_real(self.counter) * TWO_PI / P
        shift = (phase_shift * TWO_PI) / P
        return rad + shift

    def sample(self, amplitude, offset, periode, phase_shift):
        s = self.FUNCTION(self.argument(periode, phase_shift))
        value = s * amplitude + offset
        others = [t * amplitude + offset for t in (next_down(s), next_up(s))]
        return TrigValue(float(value), [float(REAL(v)) for v in others])


class SinusCI(Trigonometric):
    FUNCTION = staticmethod(SIN)


class CosinusCI(Trigonometric):
    FUNCTION = staticmethod(COS)
