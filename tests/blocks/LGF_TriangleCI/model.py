"""Reference model of LGF_TriangleCI (docs/behaviour.md §6), written from docs/behaviour.md only,
never from the C.

The shared rules R1-R9 and decisions D1-D6, D11 of the five signal generators (REAL = float32, UDINT
modulo 2^32, REAL_TO_UDINT halves to even, the checks of the inputs, the counter, Ts in whole
ms) are in tests/models/signal_ci.py. This block, per call:

- reset TRUE: "counter := 0, value := 0.0 + offset" (§6): the float32 sum 0.0 + offset (D5).
- otherwise: counter := (counter + Ts) MOD periode; p := REAL((counter + REAL_TO_UDINT(phaseShift))
  MOD periode), the sum a UDINT that wraps modulo 2^32; P := REAL(periode);
  "value := ABS((4.0 / P · p − 2.0) · amplitude) − amplitude, then + offset" (§6), in float32,
  left to right: (ABS((((4.0 / P) · p) − 2.0) · a) − a) + offset (D5). ABS of a float32 is
  exact (it clears the sign, so ABS(-0.0) = +0.0 and ABS(-Inf) = +Inf).

Decisions used (tests/models/signal_ci.py): D1, D2, D3, D4, D5, D6 (the worked example's
decimals are rounded: e.g. its second value "0.2" is exactly 0.200000047683715820 and its
sixth "−0.6" is -0.599999904632568359), D11 (Ts from the whole-µs cycle).
"""

import numpy as np

from tests.models.signal_ci import REAL, SignalCI, udint_to_real


class TriangleCI(SignalCI):
    def reset_value(self, amplitude, offset):
        return REAL(0.0) + offset

    def sample(self, amplitude, offset, periode, phase_shift):
        p = self.p(periode, phase_shift)
        P = udint_to_real(periode)
        return np.abs((REAL(4.0) / P * p - REAL(2.0)) * amplitude) - amplitude + offset
