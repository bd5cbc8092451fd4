"""Small helpers for IEC 61131-3 / PLC data-type semantics (docs/behaviour.md §1.4)."""
import math
from decimal import Decimal, ROUND_HALF_UP

INT_MIN, INT_MAX = -32768, 32767
TIME_MS_MAX = 2**31 - 1  # IEC TIME: signed 32-bit count of ms (docs/behaviour.md §1.4)


def int16(v: int) -> int:
    """INT arithmetic wraps in 16-bit two's complement (§1.4): 32767 + 1 = -32768."""
    return ((int(v) + 32768) & 0xFFFF) - 32768


def check_int(name: str, v: int) -> int:
    """FMI Integer input of IEC type INT: must lie in -32768 .. 32767 (docs/behaviour.md §1.4)."""
    if not INT_MIN <= v <= INT_MAX:
        raise ValueError(f"{name}={v} outside INT range")
    return int(v)


def time_s_to_ms(seconds: float) -> int:
    """TIME input (FMI Real, s) -> integer ms, rounded to nearest, half away from zero (§1.4).

    The product is formed in IEEE double (seconds*1000.0, as C would) and then rounded exactly,
    which is what C's round(x*1000.0) does; 0.3 s -> 300 ms.
    NaN or |value| > 2147483.647 s is an error.
    """
    x = float(seconds)
    if math.isnan(x):
        raise ValueError("TIME input is NaN")
    ms = int(Decimal(x * 1000.0).quantize(Decimal(1), rounding=ROUND_HALF_UP))
    if abs(ms) > TIME_MS_MAX:
        raise ValueError(f"TIME input {x} s outside +-2147483.647 s")
    return ms


def time_ms_to_s(ms: int) -> float:
    """TIME output (integer ms) -> FMI Real seconds, an exact multiple of 0.001 s (§1.4)."""
    return ms / 1000
