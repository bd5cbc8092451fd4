"""What the independent models of the five LGF signal generators share (LGF_SawToothCI,
LGF_TriangleCI, LGF_RectangleCI, LGF_SinusCI, LGF_CosinusCI; docs/behaviour.md §6): the REAL and
UDINT data types, the checks of the inputs, the call with its static `counter`, and SIN/COS.

Written from docs/behaviour.md §1.1–1.3, §1.4 (REAL, UDINT), §1.7, §4.2 and §6 only, never from
the C. Each block's model (tests/blocks/<Block>/model.py) adds its reset value and its formula.

Rules (the docs/behaviour.md sentence behind each in quotes):

R1  REAL is float32. "stored as the nearest float32 (round to nearest even)" (§1.2): every REAL
    input is np.float32(x) of the double the FMI caller set. "all REAL arithmetic in float32,
    evaluated left to right as written" (§6): each operation is one numpy float32 operation
    whose result is rounded to float32 before the next one; REAL literals (2.0, 4.0, 6.283185)
    are float32 constants, so 6.283185 is 6.28318500518798828125.
R2  "NaN and finite values beyond ±3.4028235e38 are fmi2Error; ±Inf accepted" (§1.2): the model
    raises ValueError (the FMU refuses the value, so a call never sees it); ±Inf goes through
    IEEE float32 arithmetic ("±Inf follow IEEE arithmetic as on the PLC").
R3  UDINT arithmetic "wraps modulo 2^32 as on the PLC" (§1.2): counter + Ts, counter +
    REAL_TO_UDINT(phaseShift) and periode / 2 + ps are taken modulo 2^32.
R4  "REAL_TO_UDINT(x) = x rounded to the nearest integer (halves to even, as the CPU's
    conversion does)" (§6). REAL(udint) is the nearest float32 (halves to even), the CPU's
    conversion as well.
R5  "`periode` = 0 is refused" and "so is a `phaseShift` outside 0 … 4294967295 ms" (§6):
    ValueError for periode < 1 and for a phaseShift whose float32 value lies outside
    0 … 4294967295 (so 4294967295.0, whose float32 is 4294967296, is refused; the largest
    accepted is 4294967040 = 2^32 - 256).
R6  Cycle: "Ts = cycleTime in whole ms, truncated; below 1 ms refused" (§6, §4.5); the model
    gets the cycle as whole µs (§1.1: "held internally as a whole number of microseconds") and
    accepts 1 ms … 60 s (§1.1: "Allowed range: 1 µs to 60 s", narrowed to 1 ms by §4.5).
R7  "a static `counter` (UDINT, 0 before the first call)"; reset TRUE sets counter and value as
    each block says; otherwise "counter := (counter + Ts) MOD periode; so the first computed
    sample is at counter = Ts, not 0". `reset` acts on every call on which it is TRUE (a level,
    as written: "reset TRUE:"), not on an edge.
R8  "No block-level error can occur: `error` FALSE, `status` 0, `subFunctionStatus` 0 on every
    call" (§6).
R9  SIN/COS of a REAL: "the PLC's own routine is not public; the FMU computes it so that linux64
    and win64 give the same bits ... e.g. the double sin/cos rounded to float32 ... and tested
    within 1 float32 ulp of a correctly rounded value" (§6). The model takes the double-precision
    math.sin/math.cos (the C library's) of the float32 argument widened to double and rounds the
    result to float32. The FMU may differ from it by that tolerance: see `TrigValue` and
    tests/signal_generators.py.

Decisions where docs/behaviour.md leaves room (each block's model docstring names those it uses):

D1  The limit "beyond ±3.4028235e38" is taken literally, on the double that is set: |x| >
    3.4028235e38 is refused, so 3.4028235e38 itself (a double slightly above FLT_MAX) is accepted
    and stored as FLT_MAX = 3.4028234663852886e38. The property tests stay at or below FLT_MAX,
    where both readings agree.
D2  The phaseShift range: its float32 value must lie in 0 … 4294967295 ("allowed 0 …
    4294967295 after rounding to float32"), and, as the project decided (docs/behaviour.md §5:
    every range is checked on the value set, as the modelDescription declares it), the value
    set must not be negative: -0.0 is accepted (REAL_TO_UDINT(-0.0) = 0), a tiny negative
    double is not; +Inf and -Inf are refused (outside the range).
D3  The model accepts periode up to 4294967295 (the UDINT range, FMI 3.0's UInt32); the FMI 2.0
    Integer stops at 2147483647, which the FMU enforces and the property tests respect.
D4  A change of periode between calls applies at the next call as written: counter :=
    (counter + Ts) MOD periode with the new periode, even if the old counter is beyond it.
D5  The formulas' order is the one of §6 as written, left to right, e.g. SawToothCI's
    `2.0 · amplitude / P · p − amplitude` is ((2·a)/P)·p − a, and "then + offset" is one more
    float32 addition after it; reset's `0.0 + offset` is the float32 addition 0.0 + offset (so
    offset -0.0 gives +0.0).
D6  The worked examples of §6 are given in rounded decimals; the exact values are those of the
    float32 arithmetic of D5, which are not always the float32 nearest to the decimal: e.g. the
    ninth SawToothCI value "0.8" is 0.800000071525573730 (one ulp above float32(0.8)), the
    third "−0.4" is −0.399999976158142090.
D11 Ts comes from the cycle as the FMU holds it, in whole µs (§1.1: rounded), truncated to
    whole ms (§4.5): Ts = cycle_us DIV 1000. So 0.0015 s runs on 1 ms, and a cycleTime a hair
    below 3 ms that rounds to 3000 µs runs on 3 ms.
(D7-D8 are RectangleCI's, D9, D10 and D12 the sine's and cosine's, in their models.)
"""

from __future__ import annotations

import math

import numpy as np

REAL = np.float32
REAL_LIMIT = 3.4028235e38  # R2/D1: finite values beyond ± this are refused
UDINT_MOD = 2**32  # R3
UDINT_MAX = UDINT_MOD - 1
PHASE_SHIFT_MAX = 4294967295  # R5
TWO_PI = REAL(6.283185)  # R1: the REAL literal of the original
CYCLE_US_MIN, CYCLE_US_MAX = 1000, 60_000_000  # R6


def real(name: str, x) -> np.float32:
    """A REAL input: the nearest float32 of the double set (R1), NaN and finite values beyond
    ±3.4028235e38 refused (R2, D1)."""
    x = float(x)
    if math.isnan(x):
        raise ValueError(f"{name} = NaN is refused")
    if math.isfinite(x) and abs(x) > REAL_LIMIT:
        raise ValueError(f"{name} = {x!r} is beyond ±3.4028235e38")
    return REAL(x)


def udint(n: int) -> int:
    """UDINT arithmetic wraps modulo 2^32 (R3)."""
    return int(n) % UDINT_MOD


def real_to_udint(x: np.float32) -> int:
    """REAL_TO_UDINT: the float32 value rounded to the nearest integer, halves to even (R4).
    The float32 widens exactly to double, and np.rint rounds halves to even."""
    n = int(np.rint(np.float64(x)))
    if not 0 <= n <= UDINT_MAX:
        raise ValueError(f"REAL_TO_UDINT({float(x)!r}) is outside 0 … 4294967295")
    return n


def udint_to_real(n: int) -> np.float32:
    """REAL(udint): the nearest float32, halves to even (R4); exact through the double, since a
    UDINT has fewer than 53 bits."""
    return REAL(float(n))


def periode_input(periode) -> int:
    """R5, D3: periode 1 … 4294967295 ms."""
    if isinstance(periode, float) and not periode.is_integer():
        raise ValueError(f"periode = {periode!r} is not an integer")
    periode = int(periode)
    if not 1 <= periode <= UDINT_MAX:
        raise ValueError(f"periode = {periode} is outside 1 … 4294967295 ms (0 divides by zero)")
    return periode


def phase_shift_input(x) -> np.float32:
    """R5, D2: a REAL whose float32 value lies in 0 … 4294967295 ms."""
    ps = real("phaseShift", x)
    # The value set must not be negative (-0.0 is not; docs/behaviour.md §5: the range is that
    # of the value set, as the modelDescription declares it), and its REAL must convert.
    if not (0.0 <= float(x) and float(ps) <= PHASE_SHIFT_MAX):
        raise ValueError(
            f"phaseShift = {float(x)!r} (float32 {float(ps)!r}) is outside 0 … 4294967295 ms"
        )
    return ps


def SIN(x: np.float32) -> np.float32:
    """R9: the double sin of the float32 argument, rounded to float32."""
    return REAL(math.sin(float(x)))


def COS(x: np.float32) -> np.float32:
    """R9: the double cos of the float32 argument, rounded to float32."""
    return REAL(math.cos(float(x)))


def next_up(x: np.float32) -> np.float32:
    return np.nextafter(REAL(x), REAL(np.inf))


def next_down(x: np.float32) -> np.float32:
    return np.nextafter(REAL(x), REAL(-np.inf))


class TrigValue(float):
    """`value` of SinusCI/CosinusCI: the model's value (a float, equal to it in every comparison)
    that also carries in `allowed` the values the block gives when its SIN/COS result is one
    float32 ulp below or above the model's (R9: "tested within 1 float32 ulp of a correctly
    rounded value"). After `· amplitude + offset` one ulp of SIN can be more than one ulp of
    the value (amplitude not a power of 2, cancellation against offset), so the comparison of
    model and FMU (tests/signal_generators.py) accepts these too."""

    allowed: tuple = ()

    def __new__(cls, value: float, allowed=()):
        self = super().__new__(cls, value)
        self.allowed = tuple(float(v) for v in allowed)
        return self

    def __reduce__(self):  # pickles (Hypothesis may copy examples) as itself
        return (TrigValue, (float(self), self.allowed))


def outputs(value) -> dict:
    """The outputs of one call (R8)."""
    return {"value": value, "error": False, "status": 0, "subFunctionStatus": 0}


class SignalCI:
    """One LGF signal generator: the inputs, the static counter and the call of §6. A block
    defines reset_value (the value of a call with reset TRUE), reset_counter (the counter then)
    and sample (the value of a call without reset, after the counter has advanced)."""

    def __init__(self, cycle_us: int, parameters: dict | None = None):
        cycle_us = int(cycle_us)
        if not CYCLE_US_MIN <= cycle_us <= CYCLE_US_MAX:
            raise ValueError(f"cycleTime {cycle_us} µs is outside 1 ms … 60 s")
        if parameters:
            raise KeyError(f"no parameters besides cycleTime: {sorted(parameters)}")
        self.ts = cycle_us // 1000  # R6: whole ms, truncated
        self.counter = 0  # R7: UDINT, 0 before the first call

    # --- the block's own parts ---
    def reset_counter(self, periode: int, phase_shift: np.float32) -> int:
        return 0

    def reset_value(self, amplitude, offset):
        raise NotImplementedError

    def sample(self, amplitude, offset, periode: int, phase_shift: np.float32):
        raise NotImplementedError

    # --- shared ---
    def p(self, periode: int, phase_shift: np.float32) -> np.float32:
        """p := REAL((counter + REAL_TO_UDINT(phaseShift)) MOD periode), the sum a UDINT (R3)."""
        return udint_to_real(udint(self.counter + real_to_udint(phase_shift)) % periode)

    def call(self, now_us: int, inputs: dict) -> dict:
        amplitude = real("amplitude", inputs["amplitude"])
        offset = real("offset", inputs["offset"])
        periode = periode_input(inputs["periode"])
        phase_shift = phase_shift_input(inputs["phaseShift"])
        reset = bool(inputs["reset"])
        with np.errstate(all="ignore"):  # overflow to ±Inf and Inf - Inf = NaN are IEEE results
            if reset:
                self.counter = self.reset_counter(periode, phase_shift)
                value = self.reset_value(amplitude, offset)
            else:
                self.counter = udint(self.counter + self.ts) % periode
                value = self.sample(amplitude, offset, periode, phase_shift)
        if not isinstance(value, TrigValue):
            value = float(REAL(value))
        return outputs(value)
