"""The slices of S7-1200/1500 SCL (docs/scl.md §3.8, issue 30): `.%B<n>`, `.%W<n>`, `.%D<n>` of
a bit string or integer, read and written, byte 0 the least significant (bits 0 to 7), as TIA
Portal's help "Addressing areas of a tag with slice access" numbers them and LGF's own blocks
use them (LGF_MergeBytesToDWord writes byte3 into %B3, LGF_SplitDWordToBytes takes it from bits
24 to 31). The SCL is written here; every expected value is computed by hand in the comments."""

from __future__ import annotations

from tests.scl.driver import compile_text, run_cs

SLICES = """
FUNCTION_BLOCK "Slices"
   VAR_INPUT
      dw : DWord := 16#12345678;
      w : Word := 16#ABCD;
      k : Int := 1;
   END_VAR
   VAR_OUTPUT
      b0 : Byte;
      b3 : Byte;
      w1 : Word;
      high : Byte;
      merged : DWord;
      negative : Int;
      d : DInt;
      top : Byte;
      upper : DWord;
      nested : Bool;
      nestedZero : Bool;
      element : Word;
   END_VAR
   VAR
      lw : LWord;
      table : Array[0..1] of Word;
   END_VAR
BEGIN
    #b0 := #dw.%B0;
    #b3 := #dw.%B3;
    #w1 := #dw.%W1;
    #high := #w.%B1;
    #merged.%B3 := #w.%B0;
    #merged.%B2 := #w.%B1;
    #merged.%W0 := #dw.%W1;
    #negative := 0;
    #negative.%B1 := 16#80;
    #negative.%B0 := B#16#01;
    #d := 0;
    #d.%W1 := 16#FFFF;
    #lw.%D1 := #dw;
    #top := #lw.%B7;
    #upper := #lw.%D1;
    #nested := #dw.%W1.%B0.%X2;
    #nestedZero := #dw.%W1.%B1.%X0;
    #table[#k].%B1 := #w.%B0;
    #element := #table[1];
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-SLICE]
def test_slices_read_and_write_their_part(tmp_path):
    fmu = compile_text(tmp_path, SLICES, "Slices", fmi=3)  # a DWORD of 32 bits: FMI 3.0's UInt32
    rows = run_cs(fmu, 100_000, {}, {}, [(100_000, {"w": 0x0102, "k": 5})])
    first = {
        "b0": 0x78,  # 16#12345678: byte 0 the least significant
        "b3": 0x12,
        "w1": 0x1234,
        "high": 0xAB,  # 16#ABCD.%B1
        "merged": 0xCDAB1234,  # %B3 := 16#CD, %B2 := 16#AB, %W0 := 16#1234
        "negative": -32767,  # 16#8001: the sign bit is in byte 1
        "d": -65536,  # 16#FFFF0000
        "top": 0x12,  # lw = 16#12345678_00000000, its byte 7
        "upper": 0x12345678,
        "nested": True,  # 16#1234.%B0 = 16#34 = 2#0011_0100, bit 2 set
        "nestedZero": False,  # 16#1234.%B1 = 16#12 = 2#0001_0010, bit 0 clear
        "element": 0xCD00,  # table[1].%B1 := 16#CD
    }
    # w = 16#0102: %B3 := 16#02, %B2 := 16#01; k = 5 is outside the table: the write is
    # ignored (docs/scl.md §3.8: Decision) and table[1] keeps 16#CD00
    second = {**first, "high": 0x01, "merged": 0x02011234}
    assert rows == [first, second]


COUNTED = """
FUNCTION_BLOCK "Counted"
   VAR_OUTPUT
      x : DWord := 16#0000_00AA;
   END_VAR
   VAR
      counter : CTU_UINT;
      toggle : Bool;
   END_VAR
BEGIN
    #toggle := NOT #toggle;
    #counter(CU := #toggle, R := FALSE, PV := 1000, CV => #x.%W1);
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-SLICE] [S7-INST-CALL] [S7-CONV-IEC]
def test_an_instance_output_into_a_slice(tmp_path):
    """CV (a UINT, into a WORD without the IEC check) into the high word; the low word keeps
    its 16#00AA."""
    fmu = compile_text(tmp_path, COUNTED, "Counted", fmi=3)
    rows = run_cs(fmu, 100_000, {}, {}, [(100_000, {}), (100_000, {})])
    # CU is TRUE, FALSE, TRUE: a rising edge in the first and the third call, CV 1, 1, 2
    assert [row["x"] for row in rows] == [0x0001_00AA, 0x0001_00AA, 0x0002_00AA]
