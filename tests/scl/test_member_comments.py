"""The description of an FMI variable of a STRUCT's or UDT's member (docs/scl.md §2, §4): the
member's // comment in its STRUCT or UDT, else the declaration's, else its type and role
(issue 28: config.rampUpRate was "REAL input of the SCL block")."""

from __future__ import annotations

from tests.scl.driver import compile_text, unpacked

SOURCE = """
TYPE "Cfg"
   STRUCT
      rate : Real := 1.0;   // Ramp up rate in units per second
      limit : Int;
   END_STRUCT;
END_TYPE

FUNCTION_BLOCK "Described"
   VAR_INPUT
      config : "Cfg";   // The configuration
      plain : "Cfg";
   END_VAR
   VAR_OUTPUT
      y : Real;
   END_VAR
   VAR
      s : STRUCT
         a : Int;   // Counts the calls
      END_STRUCT;
   END_VAR
BEGIN
   #s.a := #s.a + 1;
   #y := #config.rate + #plain.rate;
END_FUNCTION_BLOCK
"""


def test_a_members_comment_describes_its_variables(tmp_path):
    fmu = compile_text(tmp_path, SOURCE, "Described")
    _, md = unpacked(fmu)
    described = {v.name: v.description for v in md.modelVariables}
    assert described["config.rate"] == "REAL: Ramp up rate in units per second"
    assert described["config.limit"] == "INT: The configuration"
    assert described["plain.rate"] == "REAL: Ramp up rate in units per second"
    assert described["plain.limit"] == "INT input of the SCL block Described"
    assert described["s.a"] == "Counts the calls"
