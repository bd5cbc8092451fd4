"""FRAC, FRAC_REAL and FRAC_LREAL (docs/scl.md §3.5 [DEC-FRAC], issue 30: LGF_Boxplot_*,
LGF_GpsDDToGps): the places after the decimal point, IN - TRUNC(IN), of IN's sign. The SCL is
written here; Siemens documents FRAC(2.5) = 0.5, the other values are computed by hand in the
comments."""

from __future__ import annotations

import pytest

from tests.scl.driver import compile_text, run_cs

FRACTIONS = """
FUNCTION_BLOCK "Fractions"
   VAR_INPUT
      r : Real := 2.5;
      l : LReal := -2.5;
   END_VAR
   VAR_OUTPUT
      ofReal : Real;
      ofLReal : LReal;
      typedReal : Real;
      typedLReal : LReal;
      widened : LReal;
      literal : LReal;
      whole : Real;
      inExpression : LReal;
   END_VAR
BEGIN
    #ofReal := FRAC(#r);
    #ofLReal := FRAC(IN := #l);
    #typedReal := FRAC_REAL(#r * 0.5);
    #typedLReal := FRAC_LREAL(#l * 0.25);
    #widened := FRAC_LREAL(#r);
    #literal := FRAC(1.1);
    #whole := FRAC(#r * 2.0);
    #inExpression := 10.0 + FRAC_LREAL(#l) * 4.0;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [DEC-FRAC] [S7-FN-1]
@pytest.mark.parametrize("fmi", [2, 3])
def test_frac_keeps_the_sign_of_in(tmp_path, fmi):
    fmu = compile_text(tmp_path, FRACTIONS, "Fractions", fmi=fmi)
    rows = run_cs(fmu, 100_000, {}, {}, [(100_000, {"r": -7.75, "l": 3.0})])
    assert rows[0] == {
        "ofReal": 0.5,  # Siemens' example: FRAC(2.5) = 0.5
        "ofLReal": -0.5,  # -2.5 - TRUNC(-2.5) = -2.5 - (-2.0)
        "typedReal": 0.25,  # 1.25 - 1.0
        "typedLReal": -0.625,  # -0.625 - TRUNC(-0.625) = -0.625 - 0
        "widened": 0.5,  # the REAL 2.5 as an LREAL
        "literal": 0.10000000000000009,  # the double nearest 1.1 minus 1, exact
        "whole": 0.0,  # 5.0 - 5.0
        "inExpression": 8.0,  # 10 + (-0.5) * 4
    }
    assert rows[1] == {
        "ofReal": -0.75,  # -7.75 - (-7.0)
        "ofLReal": 0.0,  # 3.0 - 3.0
        "typedReal": -0.875,  # -3.875 - (-3.0)
        "typedLReal": 0.75,  # 0.75 - 0
        "widened": -0.75,
        "literal": 0.10000000000000009,
        "whole": -0.5,  # -15.5 - (-15.0)
        "inExpression": 10.0,
    }
