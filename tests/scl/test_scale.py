"""NORM_X and SCALE_X (docs/scl.md §3.5 [S7-SCALE] [DEC-SCALE]): Siemens' formulas (S7-1200
System Manual, "SCALE_X and NORM_X": OUT = (VALUE - MIN) / (MAX - MIN) and OUT = VALUE (MAX -
MIN) + MIN); the expected values by hand, each quotient the nearest REAL or LREAL of the exact
one."""

from __future__ import annotations

import math

import numpy as np

from tests.scl.driver import compiled, run_cs

SOURCE = """
FUNCTION_BLOCK "Scale"
   VAR_INPUT
      raw : Int;
      lo : Real := 0.0;
      hi : Real := 100.0;
      v : LReal;
   END_VAR
   VAR_OUTPUT
      normReal : Real;
      normLReal : LReal;
      third : LReal;
      thirdReal : Real;
      scaled : Real;
      scaledLReal : LReal;
      chained : Real;
      flat : Real;
      same : LReal;
      literals : Real;
   END_VAR
BEGIN
    #normReal := NORM_X(MIN := 0, VALUE := #raw, MAX := 27648);
    #normLReal := NORM_X(MIN := 0, VALUE := #raw, MAX := 27648);
    #third := NORM_X(MIN := 0, VALUE := 1, MAX := 3);
    #thirdReal := NORM_X(MIN := 0, VALUE := 1, MAX := 3);
    #scaled := SCALE_X(MIN := #lo, VALUE := #v, MAX := #hi);
    #scaledLReal := SCALE_X(MIN := -10.0, VALUE := #v, MAX := 10.0);
    #chained := SCALE_X(MIN := #lo, VALUE := NORM_X(MIN := 0, VALUE := #raw, MAX := 27648),
                        MAX := #hi);
    #flat := NORM_X(MIN := 2, VALUE := 3, MAX := 2);
    #same := SCALE_X(MIN := 5.0, VALUE := #v, MAX := 5.0);
    #literals := SCALE_X(MIN := 0, VALUE := 0.5, MAX := 100);
END_FUNCTION_BLOCK
"""


scale = compiled(SOURCE, "Scale")


def outputs(fmu, **inputs):
    return run_cs(fmu, 100_000, {}, inputs, [])[0]


def test_norm_x(scale):
    # docs/scl.md rules: [S7-SCALE]
    got = outputs(scale, raw=13824, v=0.0)
    assert (got["normReal"], got["normLReal"]) == (0.5, 0.5)  # 13824 / 27648
    assert got["third"] == 1 / 3  # the LREAL nearest 1/3: the context gives the type
    assert got["thirdReal"] == float(np.float32(1 / 3))
    # above MAX: above 1.0, as the formula (the CPU's ENO stays TRUE)
    got = outputs(scale, raw=30000, v=0.0)
    assert got["normReal"] == float(np.float32(30000 / 27648))
    assert got["normLReal"] == 30000 / 27648


def test_scale_x(scale):
    # docs/scl.md rules: [S7-SCALE]
    got = outputs(scale, raw=6912, v=0.25)
    assert got["scaled"] == 25.0  # 0.25 * (100 - 0) + 0
    assert got["scaledLReal"] == -5.0  # 0.25 * (10 - -10) + -10
    assert got["chained"] == 25.0  # NORM_X 6912 / 27648 = 0.25, scaled to 0 ... 100
    assert got["literals"] == 50.0  # of literals: a REAL, as its target
    got = outputs(scale, raw=0, v=1.5, lo=-50.0, hi=50.0)
    assert (got["scaled"], got["scaledLReal"]) == (100.0, 20.0)  # beyond 1.0: beyond MAX


def test_max_not_above_min(scale):
    # docs/scl.md rules: [DEC-SCALE]
    got = outputs(scale, raw=0, v=0.5)
    assert got["flat"] == math.inf  # (3 - 2) / (2 - 2)
    assert got["same"] == 5.0  # 0.5 * 0 + 5
