"""Small helpers for IEC 61131-3 / PLC data-type semantics (docs/behaviour.md §1.4), shared by
the independent models of the blocks and their tests."""

import math
from decimal import ROUND_HALF_UP, Decimal

INT_MIN, INT_MAX = -32768, 32767
TIME_MS_MIN, TIME_MS_MAX = -(2**31), 2**31 - 1  # IEC TIME: signed 32-bit count of ms (§1.4)
TIME_S_LIMIT = 2147483.647  # a TIME input beyond ± this is refused (§1.4)


def cycle_us_of(cycle_us: int) -> int:
    """cycleTime as a block holds it, in whole µs: 1 µs … 60 s (docs/behaviour.md §1.1), else
    ValueError, as the FMU refuses it."""
    cycle_us = int(cycle_us)
    if not 1 <= cycle_us <= 60_000_000:
        raise ValueError(f"cycleTime {cycle_us} µs outside 1 µs … 60 s")
    return cycle_us


def int16(v: int) -> int:
    """INT arithmetic wraps in 16-bit two's complement (§1.4): 32767 + 1 = -32768."""
    return ((int(v) + 32768) & 0xFFFF) - 32768


def check_int(name: str, v: int) -> int:
    """FMI Integer input of IEC type INT: must lie in -32768 .. 32767 (docs/behaviour.md §1.4)."""
    if not INT_MIN <= v <= INT_MAX:
        raise ValueError(f"{name}={v} outside INT range")
    return int(v)


def time_s_to_ms(seconds: float) -> int:
    """TIME (FMI Real, s) -> IEC TIME (integer ms): multiplied by 1000 and rounded to the
    nearest integer, halves away from zero (§1.4: 0.0025 s -> 3 ms, -0.0025 s -> -3 ms).

    The product is formed in IEEE double (seconds*1000.0, as C would) and then rounded exactly,
    which is what C's round(x*1000.0) does; 0.3 s -> 300 ms.
    NaN or |value| > 2147483.647 s raises ValueError (the FMU refuses such a value).
    """
    x = float(seconds)
    if math.isnan(x) or abs(x) > TIME_S_LIMIT:
        raise ValueError(f"TIME value {x!r} s is NaN or outside +-2147483.647 s")
    return int(Decimal(x * 1000.0).quantize(Decimal(1), rounding=ROUND_HALF_UP))


def time_ms_to_s(ms: int) -> float:
    """TIME output (integer ms) -> FMI Real seconds, an exact multiple of 0.001 s (§1.4)."""
    return ms / 1000
