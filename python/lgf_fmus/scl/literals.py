"""The values of SCL's literals (docs/scl.md §3.2, §3.3), as the parser reads them: integers
with their base (16#FF, 2#1010, INT#5) and underscores, TIME in ms and LTIME in ns, exact in
integers."""

from __future__ import annotations

import re


def integer(text: str) -> int:
    """16#FF -> 255, 1_000 -> 1000, INT#16#7F -> 127."""
    text = text.replace("_", "")
    if "#" in text:
        base, digits = text.rsplit("#", 1)
        return int(digits, int(base.rsplit("#", 1)[-1]))
    return int(text)


TIME_UNITS = {
    "d": 86_400_000_000_000,
    "h": 3_600_000_000_000,
    "m": 60_000_000_000,
    "s": 1_000_000_000,
    "ms": 1_000_000,
    "us": 1000,
    "ns": 1,
}
_TIME_PART = re.compile(r"([0-9]+(?:\.[0-9]+)?)(ms|us|ns|d|h|m|s)", re.I)


def time_ms(text: str) -> int | None:
    """T#1s200ms -> 1200 (IEC TIME in ms, docs/scl.md §3.3); None if it is no TIME literal."""
    if re.search(r"[0-9](us|ns)", text, re.I):  # a TIME counts ms; us and ns are LTIME's
        return None
    ns = time_ns(text)
    return None if ns is None else round(ns / 1_000_000)


def time_ns(text: str) -> int | None:
    """LT#1s5ns -> 1000000005 (LTIME in ns, docs/scl.md §3.3); None if it is no time literal."""
    body = text.split("#", 1)[1].replace("_", "")
    sign = -1 if body.startswith("-") else 1
    body = body.lstrip("+-")
    total, at = 0, 0
    for part in _TIME_PART.finditer(body):
        if part.start() != at:
            return None
        number, unit = part.group(1), TIME_UNITS[part.group(2).lower()]
        whole, _, fraction = number.partition(".")
        # exact in integers: LT#1.5us is 1500 ns, no float rounding at 64 bits
        total += int(whole) * unit + int(fraction or "0") * unit // 10 ** len(fraction)
        at = part.end()
    if at != len(body) or not body:
        return None
    return sign * total


# S7's $-escapes of a character string (TIA Portal's help "STRING", "CHAR": $$, $', $L line feed,
# $P form feed, $R carriage return, $T tabulator, $hh the character of code hh)
STRING_ESCAPES = {"$": 0x24, "'": 0x27, "L": 0x0A, "P": 0x0C, "R": 0x0D, "T": 0x09}


def characters(text: str, wide: bool) -> tuple[int, ...]:
    """The character codes of a string literal's body (between its quotes): 'a$'b' -> (97, 39,
    98). Raises ValueError naming what it does not take: $N (a new line, whose code TIA
    documents per target system), an unknown escape, a character outside the type's codes
    (a STRING's 0-255, a WSTRING's 0-65535)."""
    codes, i = [], 0
    while i < len(text):
        c = text[i]
        if c != "$":
            codes.append(ord(c))
            i += 1
            continue
        nxt = text[i + 1 : i + 2].upper()
        if nxt in STRING_ESCAPES:
            codes.append(STRING_ESCAPES[nxt])
            i += 2
        elif re.fullmatch(r"[0-9A-F]{2}", text[i + 1 : i + 3].upper()):
            codes.append(int(text[i + 1 : i + 3], 16))
            i += 3
        elif nxt == "N":
            raise ValueError("$N (a new line) is not supported: write $R$L or $L")
        else:
            raise ValueError(
                f"${text[i + 1 : i + 2]} is no escape of S7 ($$, $', $L, $P, $R, $T, $hh)"
            )
    top = 0xFFFF if wide else 0xFF
    for code in codes:
        if code > top:
            raise ValueError(
                f"the character {chr(code)!r} is beyond the codes of a "
                f"{'WSTRING' if wide else 'STRING'} (0 to {top})"
            )
    return tuple(codes)
