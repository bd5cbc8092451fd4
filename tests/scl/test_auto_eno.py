"""TIA Portal's block property "Set ENO automatically" (docs/scl.md §3.4 [S7-ENO-AUTO]), as
`lgf-fmus compile --auto-eno` takes it: a REAL or LREAL sum, difference, product or quotient
whose result is no finite number sets ENO FALSE; without it ENO stays what the block writes.
The SCL is written here; the expected values follow from IEEE 754 by hand: 1e38 * 10 is beyond
the largest REAL (3.4e38), an infinite operand gives an infinite sum, 1e300 * 1e300 overflows
an LREAL."""

from __future__ import annotations

import math

import pytest

from tests.scl.driver import compile_text, run_cs

SOURCE = """
FUNCTION_BLOCK "Eno"
VAR_INPUT
   a : Real;
   b : Real;
   c : LReal;
END_VAR
VAR_OUTPUT
   y : Real;
   z : LReal;
   ok : Bool;
   okAfterCompare : Bool;
END_VAR
BEGIN
    #okAfterCompare := #a > #b; // a comparison is no arithmetic: ENO stays
    #okAfterCompare := ENO;
    #y := #a * #b;
    #z := #c * #c;
    #ok := ENO;
END_FUNCTION_BLOCK
"""

# (inputs, ok with the property on); off, ok is always TRUE
CASES = [
    ({"a": 1.5, "b": 2.0, "c": 3.0}, True),
    ({"a": 1e38, "b": 10.0, "c": 3.0}, False),  # 1e39: beyond the largest REAL
    ({"a": math.inf, "b": 1.0, "c": 3.0}, False),  # an infinite operand
    ({"a": 1.0, "b": 1.0, "c": 1e300}, False),  # 1e600: beyond the largest LREAL
    ({"a": 1.0, "b": 1.0, "c": -2.0}, True),  # ENO starts TRUE in every call
]


# docs/scl.md rules: [S7-ENO-AUTO] [DEC-ENO]
@pytest.mark.parametrize("auto_eno", [True, False], ids=["auto-eno", "default"])
def test_eno_goes_false_at_a_real_result_that_is_no_number(tmp_path, auto_eno):
    fmu = compile_text(tmp_path, SOURCE, "Eno", auto_eno=auto_eno)
    steps = [(100_000, inputs) for inputs, _ in CASES]
    rows = run_cs(fmu, 100_000, {}, {}, steps)[1:]
    assert [row["ok"] for row in rows] == [ok or not auto_eno for _, ok in CASES]
    assert all(row["okAfterCompare"] for row in rows)
    assert rows[1]["y"] == math.inf and rows[3]["z"] == math.inf  # the value is IEEE's
