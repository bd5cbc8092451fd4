"""Reference model of LGF_SawToothCI (docs/behaviour.md §6), written from docs/behaviour.md only,
never from the C.

The shared rules R1-R9 and decisions D1-D6, D11 of the five signal generators (REAL = float32, UDINT
modulo 2^32, REAL_TO_UDINT halves to even, the checks of the inputs, the counter, Ts in whole
ms) are in tests/models/signal_ci.py. This block, per call:

- reset TRUE: "counter := 0, value := 0.0 + offset" (§6): the float32 sum 0.0 + offset (D5:
  offset -0.0 gives +0.0).
- otherwise: counter := (counter + Ts) MOD periode; p := REAL((counter + REAL_TO_UDINT(phaseShift))
  MOD periode), the sum a UDINT that wraps modulo 2^32; P := REAL(periode);
  "value := 2.0 · amplitude / P · p − amplitude, then + offset" (§6), in float32, left to right:
  ((((2.0 · a) / P) · p) − a) + offset (D5).

Decisions used (tests/models/signal_ci.py): D1 (±3.4028235e38 literally), D2 (phaseShift
checked on its float32 value), D3 (periode up to 4294967295 in the model), D4 (a new periode
applies at the next call), D5 (left-to-right order, 0.0 + offset), D6 (the worked example's
decimals are rounded: its exact float32 values are those of D5, e.g. the third value is
-0.399999976158142090 and the ninth 0.800000071525573730), D11 (Ts from the whole-µs cycle).
"""

from tests.models.signal_ci import REAL, SignalCI, udint_to_real


class SawToothCI(SignalCI):
    def reset_value(self, amplitude, offset):
        return REAL(0.0) + offset

    def sample(self, amplitude, offset, periode, phase_shift):
        p = self.p(periode, phase_shift)
        P = udint_to_real(periode)
        return REAL(2.0) * amplitude / P * p - amplitude + offset
