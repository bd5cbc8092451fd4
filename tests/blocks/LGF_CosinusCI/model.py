"""Reference model of LGF_CosinusCI (docs/behaviour.md §6), written from docs/behaviour.md only,
never from the C.

The sine and the cosine have one formula and differ only in the function, so the model is the
one of tests/blocks/LGF_SinusCI/model.py (its docstring gives the rules and the decisions D1-D5,
D9-D12) with COS in place of SIN:

- reset TRUE: "counter := 0, value := 0.0" (§6).
- otherwise: counter := (counter + Ts) MOD periode; x := ((REAL(counter) · 6.283185) / P) +
  ((phaseShift · 6.283185) / P); value := (COS(x) · amplitude) + offset, COS the double cos of
  the float32 x rounded to float32 (R9 of tests/models/signal_ci.py).
"""

from tests.blocks.LGF_SinusCI.model import CosinusCI

__all__ = ["CosinusCI"]
