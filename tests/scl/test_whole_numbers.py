"""ROUND, CEIL and FLOOR (docs/scl.md §3.5 [S7-ROUND]): a REAL or LREAL to a DINT, SCL's type of
their value. The expected values are by hand from Siemens' description (S7-1200 System Manual,
"ROUND and TRUNC": to the nearest, exactly halfway to the even integer, ROUND(10.5) = 10,
ROUND(11.5) = 12; "CEIL and FLOOR": the smallest integer not below IN, the largest not above it)
and from the limits of docs/scl.md §3.3 (NaN 0, a value beyond the DINT range its limit)."""

from __future__ import annotations

import math

import pytest

from tests.scl.driver import compiled, run_cs

SOURCE = """
FUNCTION_BLOCK "Whole"
   VAR_INPUT
      r : Real;
      l : LReal;
   END_VAR
   VAR_OUTPUT
      roundReal : DInt;
      ceilReal : DInt;
      floorReal : DInt;
      roundLReal : DInt;
      ceilLReal : DInt;
      floorLReal : DInt;
      named : DInt;
      literal : DInt;
      asReal : Real;
      ofNaN : DInt;
   END_VAR
BEGIN
    #roundReal := ROUND(#r);
    #ceilReal := CEIL(#r);
    #floorReal := FLOOR(#r);
    #roundLReal := ROUND(#l);
    #ceilLReal := CEIL(IN := #l);
    #floorLReal := FLOOR(#l);
    #named := ROUND(IN := 2.5);
    #literal := CEIL(-0.5) + FLOOR(-0.5);
    // the LGF's use: a whole number of quadrants as a REAL again
    #asReal := DINT_TO_REAL(FLOOR(#r / 90.0)) * 90.0;
    // NaN (an importer cannot set one): 0 each
    #ofNaN := ROUND(SQRT(-1.0)) + CEIL(SQRT(REAL#-1.0)) + FLOOR(SQRT(#l - 5.0)) + 7;
END_FUNCTION_BLOCK
"""
NAMES = ["roundReal", "ceilReal", "floorReal", "roundLReal", "ceilLReal", "floorLReal"]


whole = compiled(SOURCE, "Whole")


def outputs(fmu, r, lreal):
    return run_cs(fmu, 100_000, {}, {"r": r, "l": lreal}, [])[0]


@pytest.mark.parametrize(
    "value, expected",
    [
        # (round, ceil, floor) of the value, by hand
        (10.5, (10, 11, 10)),  # halfway: to the even integer (Siemens' example)
        (11.5, (12, 12, 11)),  # Siemens' other example
        (-2.5, (-2, -2, -3)),
        (-3.5, (-4, -3, -4)),
        (2.4, (2, 3, 2)),
        (-0.7, (-1, 0, -1)),
        (7.0, (7, 7, 7)),
        (-1e12, (-2147483648, -2147483648, -2147483648)),  # beyond the range: its limit
        (1e12, (2147483647, 2147483647, 2147483647)),
        (math.inf, (2147483647, 2147483647, 2147483647)),
    ],
)
def test_round_ceil_floor(whole, value, expected):
    # docs/scl.md rules: [S7-ROUND] [DEC-CONV-LIMIT]
    got = outputs(whole, value, value)
    assert tuple(got[n] for n in NAMES[:3]) == expected  # of a REAL
    assert tuple(got[n] for n in NAMES[3:]) == expected  # of an LREAL


def test_the_real_the_fmu_stores_is_rounded(whole):
    # docs/scl.md rules: [S7-ROUND]
    # 16777217 is no REAL: the importer's value is stored as the nearest, halfway to the even
    # 16777216 (docs/behaviour.md §1.4), which ROUND keeps; as an LREAL 16777216.5 is halfway
    # between two integers and rounds to the even 16777216, CEIL 16777217, FLOOR 16777216
    got = outputs(whole, 16777217.0, 16777216.5)
    assert got["roundReal"] == 16777216
    assert (got["roundLReal"], got["ceilLReal"], got["floorLReal"]) == (
        16777216,
        16777217,
        16777216,
    )


def test_literals_and_the_value_as_a_real(whole):
    # docs/scl.md rules: [S7-ROUND]
    got = outputs(whole, -100.0, 0.0)
    assert got["named"] == 2  # 2.5 halfway: to the even 2
    assert got["literal"] == 0 + -1  # CEIL(-0.5) = 0 (as -0 in IEEE), FLOOR(-0.5) = -1
    assert got["asReal"] == -180.0  # FLOOR(-100 / 90) = FLOOR(-1.11) = -2, times 90
    # docs/scl.md rules: [DEC-CONV-LIMIT]
    assert got["ofNaN"] == 7  # ROUND, CEIL and FLOOR of NaN (SQRT of -1, -5) give 0
