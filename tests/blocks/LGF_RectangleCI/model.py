"""Reference model of LGF_RectangleCI (docs/behaviour.md §6), written from docs/behaviour.md only,
never from the C.

The shared rules R1-R9 and decisions D1-D6, D11 of the five signal generators (REAL = float32, UDINT
modulo 2^32, REAL_TO_UDINT halves to even, the checks of the inputs, the counter, Ts in whole
ms) are in tests/models/signal_ci.py. This block, per call:

- reset TRUE: "counter := REAL_TO_UDINT(phaseShift) MOD periode, value := 0.0" (§6): the value
  is 0.0, not the offset; the next call without reset advances from that counter.
- otherwise: counter := (counter + Ts) MOD periode; ps := REAL_TO_UDINT(phaseShift) MOD periode;
  "value := offset + amplitude if ps ≤ counter < periode / 2 + ps (integer division), else
  offset − amplitude" (§6), the sums in float32. The block uses the counter itself (not p). "The
  high window is not wrapped, so for ps > periode/2 the duty cycle falls below 50 %": high for
  counter in [ps, periode DIV 2 + ps) and counter < periode, i.e. periode - ps of the periode
  values of the counter when ps > periode DIV 2.

Decisions used (tests/models/signal_ci.py): D1, D2, D3, D4, D5, D11 (Ts from the whole-µs
cycle), and:
D7  periode / 2 + ps is a UDINT sum and wraps modulo 2^32 (R3); it can only wrap when periode
    exceeds 2^31 (FMI 3.0's UInt32), and then the window is empty.
D8  "periode / 2 + ps (integer division)" is (periode DIV 2) + ps, the usual precedence: for
    periode 7 the window is [ps, ps + 3). (REAL_TO_UDINT rounds halves to even, R4: phaseShift
    2.5 gives ps 2, 3.5 gives 4.)
"""

from tests.models.signal_ci import SignalCI, real_to_udint, udint


class RectangleCI(SignalCI):
    def reset_counter(self, periode, phase_shift):
        return real_to_udint(phase_shift) % periode

    def reset_value(self, amplitude, offset):
        return 0.0

    def sample(self, amplitude, offset, periode, phase_shift):
        ps = real_to_udint(phase_shift) % periode
        if ps <= self.counter < udint(periode // 2 + ps):
            return offset + amplitude
        return offset - amplitude
