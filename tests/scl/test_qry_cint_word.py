"""QRY_CINT's STATUS into a WORD, as every LGF CI block writes it: TIA Portal compiles with "IEC
check" off by default, which converts the DWORD into a WORD implicitly, keeping its low word
(docs/scl.md §3.6). The STATUS of the FMU's cyclic interrupt is 16#0014 (OB loaded, interrupt
active), so the LGF test for a missing OB (STATUS = 0) does not fire."""

from __future__ import annotations

from tests.scl.driver import compile_text, run_cs

SOURCE = """
FUNCTION_BLOCK "CiStatus"
   VAR_INPUT
      callOB : OB_CYCLIC;
   END_VAR
   VAR_OUTPUT
      status : Word;
      cycle : UDInt;
      missing : Bool;
      ret : Int;
   END_VAR
   VAR_TEMP
      tempStatus : Word;
   END_VAR
BEGIN
    #ret := QRY_CINT(OB_NR := #callOB, CYCLE => #cycle, STATUS => #tempStatus);
    #missing := #tempStatus = 16#0000;
    #status := #tempStatus;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-QRY-CINT]
def test_status_into_a_word_is_its_low_word(tmp_path):
    fmu = compile_text(tmp_path, SOURCE, "CiStatus")
    rows = run_cs(fmu, 20_000, {}, {}, [(20_000, {})])
    assert rows == [{"status": 0x0014, "cycle": 20_000, "missing": False, "ret": 0}] * 2


BOUNDS = """
FUNCTION_BLOCK "Bounds"
   VAR_OUTPUT
      low : DInt;
      high : DInt;
   END_VAR
   VAR
      table : Array[2..7] of Int;
   END_VAR
   VAR CONSTANT
      DIMENSION_ONE : UDInt := 1;
   END_VAR
BEGIN
    #low := LOWER_BOUND(ARR := #table, DIM := #DIMENSION_ONE);
    #high := UPPER_BOUND(ARR := #table, DIM := #DIMENSION_ONE);
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-ARRAY]
def test_a_constant_of_the_block_as_dim(tmp_path):
    """LGF_RampCI passes `DIM := #DIMENSION_ONE`, a VAR CONSTANT: TIA takes a constant there."""
    fmu = compile_text(tmp_path, BOUNDS, "Bounds")
    assert run_cs(fmu, 100_000, {}, {}, []) == [{"low": 2, "high": 7}]


CONSTANT_STARTS = """
FUNCTION_BLOCK "ConstantStarts"
   VAR_OUTPUT
      low : LReal;
      status : Word := #STATUS_IDLE;
   END_VAR
   VAR
      statMin : LReal := #LREAL_MAX;
   END_VAR
   VAR CONSTANT
      LREAL_MAX : LReal := 1.7976931348623157e+308;
      STATUS_IDLE : Word := 16#7000;
   END_VAR
BEGIN
    #low := #statMin;
END_FUNCTION_BLOCK
"""


def test_a_constant_of_the_block_as_a_start_value(tmp_path):
    """docs/scl.md §2: LGF_StoreMinMax starts its minimum at := #LREAL_MAX, a VAR CONSTANT:
    TIA takes a constant of the block as a start value; it is the constant's literal."""
    fmu = compile_text(tmp_path, CONSTANT_STARTS, "ConstantStarts")
    assert run_cs(fmu, 100_000, {}, {}, []) == [{"low": 1.7976931348623157e308, "status": 0x7000}]


CHAINED = """
FUNCTION_BLOCK "Chained"
   VAR_INPUT
      x : Int;
   END_VAR
   VAR_OUTPUT
      a : DInt;
      b : Int;
      c : Bool;
      d : Bool;
   END_VAR
BEGIN
    #a := #b := #x + 1;
    #c := #d := TRUE;
END_FUNCTION_BLOCK
"""


def test_a_chained_assignment(tmp_path):
    """docs/scl.md §2.1: `#a := #b := e` (LGF_CountBooleanEdges writes it) assigns e to #b,
    then #b to #a, each by the rules of its assignment (the INT #b widened into the DINT #a)."""
    fmu = compile_text(tmp_path, CHAINED, "Chained")
    assert run_cs(fmu, 100_000, {}, {"x": 41}, []) == [{"a": 42, "b": 42, "c": True, "d": True}]
