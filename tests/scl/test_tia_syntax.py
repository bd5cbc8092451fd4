"""What TIA Portal writes in an export (docs/scl.md §2.1, issue 30 item 1): the text after
END_REGION, the description placeholder (/**/), VAR CONSTANT without a value, positional start
values of STRUCTs and UDTs, quoted names wherever a name stands, the S7 literals (B#16#, W#16#,
DW#16#, LW#16#, C#, LT#; the date and time ones refused by type), the smallest value of a type
as a negative literal, T# literals beyond the TIME range, a block's constants as CASE labels
and ARRAY bounds (the slices .%B0: test_slices.py). The SCL is written here, in the style of an
export; every expected value is computed by hand in the comments."""

from __future__ import annotations

import pytest

from lgf_fmus.scl import ast as A
from lgf_fmus.scl import parser
from tests.scl.driver import calls, compile_text, compiled, refusal

TIA = """
TYPE "Reading"
VERSION : 0.1
   STRUCT
      "time" : Time := T#2s;
      value : Int := 7;
      limits : Struct
         low : Int := -5;
         high : Int := 50;
      END_STRUCT;
      valid : Bool := TRUE;
   END_STRUCT;

END_TYPE

FUNCTION "Shift" : Int
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
   VAR_INPUT
      "date" : Int;
      step : Int;
   END_VAR
   VAR_OUTPUT
      "twice" : Int;
   END_VAR
BEGIN
    REGION Shift
      #"twice" := #"date" * 2;
      #Shift := #"date" + #step;
    END_REGION Shift
END_FUNCTION

FUNCTION_BLOCK "TiaStyle"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
   VAR_INPUT
      i : Int;
   END_VAR
   VAR_OUTPUT
      smallest : Int;
      smallestD : DInt;
      smallestReal : Real;
      spaced : Int;
      byteOut : Byte;
      wordOut : Word;
      dwordOut : DWord;
      lwordHigh : DWord;
      counter : Word;
      ltimeMs : LReal;
      timeLow : Time;
      zeroConst : Int;
      zeroTime : Time;
      plainTime : Time;
      plainValue : Int;
      plainLow : Int;
      plainHigh : Int;
      plainValid : Bool;
      indexedTime : Time;
      indexedValue : Int;
      indexedHigh : Int;
      shifted : Int;
      doubled : Int;
      quoted : Int;
      after : Int;
   END_VAR
   VAR
      plain : "Reading" := (T#3s, (), (-1, ()), FALSE);
      table : Array[0..2] of "Reading" := [("time" := T#1s, value := 4), (T#5s, 8, (), ()), ()];
      "myValue" : Int := 3;
      lw : LWord := LW#16#0123_4567_89AB_CDEF;
   END_VAR
   VAR CONSTANT
      NONE : Int;
      NO_TIME : Time;
      "SEPARATOR" : Word;
   END_VAR

BEGIN
    REGION BLOCK INFO HEADER
      // written for the tests, as TIA writes a library block's header
    END_REGION Block info header

    REGION DESCRIPTION
      (/**/)
    END_REGION DESCRIPTION

    REGION Literals
      #smallest := -32768;
      #smallestD := -2147483648;
      #smallestReal := -1.5;
      #spaced := - (* a comment *) 32768;
      #byteOut := B#16#A5;
      #wordOut := W#16#FFFF;
      #dwordOut := DW#16#0001_0002;
      #lwordHigh := LWORD_TO_DWORD(SHR(IN := #lw, N := 32));
      #counter := C#123;
      #ltimeMs := LINT_TO_LREAL(LTIME_TO_LINT(LT#1ms500us)) / 1000000.0;
      #timeLow := -T#24d20h31m23s648ms;
      #zeroConst := #NONE - 1;
      #zeroTime := #NO_TIME;
    END_REGION // literals

    REGION Start values
      (/* TIA keeps a formatted description here */)
      #plainTime := #plain."time";
      #plainValue := #plain.value;
      #plainLow := #plain.limits.low;
      #plainHigh := #plain."limits"."high";
      #plainValid := #plain.valid;
      #indexedTime := #table[#i]."time";
      #indexedValue := #table[#i].value;
      #indexedHigh := #table[#i].limits.high;
    END_REGION;

    REGION Quoted names
      #shifted := "Shift"("date" := #i, step := 10, "twice" => #doubled);
      #"myValue" += 1;
      #quoted := #"myValue";
    END_REGION Quoted names; #after := 5;
END_FUNCTION_BLOCK
"""


tia = compiled(TIA, "TiaStyle")


def test_literals_as_tia_writes_them(tia):
    out = calls(tia, [{"i": 0}])[0]
    assert out["smallest"] == -32768  # the smallest INT, a literal of its own
    assert out["smallestD"] == -2147483648  # the smallest DINT
    assert out["smallestReal"] == -1.5
    assert out["spaced"] == -32768  # blanks and comments between the sign and the number
    assert out["byteOut"] == 0xA5  # 165
    assert out["wordOut"] == 0xFFFF  # 65535
    assert out["dwordOut"] == 0x0001_0002  # 65538
    assert out["lwordHigh"] == 0x0123_4567  # the high 32 bits: 19088743
    assert out["counter"] == 0x0123  # C#123 is the BCD WORD 16#0123 = 291
    assert out["ltimeMs"] == 1.5  # 1 ms 500 us = 1500000 ns
    assert out["timeLow"] == -2147483.648  # -2^31 ms, the smallest TIME, in s
    assert out["zeroConst"] == -1  # NONE has INT's default 0
    assert out["zeroTime"] == 0.0  # NO_TIME has TIME's default T#0s


def test_positional_start_values(tia):
    out = calls(tia, [{"i": 0}])[0]
    # plain := (T#3s, (), (-1, ()), FALSE): time 3 s, value kept at 7, limits.low -1 and
    # limits.high kept at 50, valid FALSE
    assert out["plainTime"] == 3.0
    assert out["plainValue"] == 7
    assert (out["plainLow"], out["plainHigh"]) == (-1, 50)
    assert out["plainValid"] is False or out["plainValid"] == 0
    # table[0] by names: time 1 s, value 4, the rest the UDT's (high 50)
    assert (out["indexedTime"], out["indexedValue"], out["indexedHigh"]) == (1.0, 4, 50)
    # table[1] positional: time 5 s, value 8, () (); table[2] () all the UDT's: 2 s, 7, 50
    rows = calls(tia, [{"i": 1}, {"i": 2}])
    assert (rows[0]["indexedTime"], rows[0]["indexedValue"], rows[0]["indexedHigh"]) == (
        5.0,
        8,
        50,
    )
    assert (rows[1]["indexedTime"], rows[1]["indexedValue"], rows[1]["indexedHigh"]) == (
        2.0,
        7,
        50,
    )


def test_quoted_names_and_region_ends(tia):
    rows = calls(tia, [{"i": 4}, {"i": -3}])
    # "Shift"("date" := 4, step := 10, "twice" => doubled): 14 and 8; then -3: 7 and -6
    assert (rows[0]["shifted"], rows[0]["doubled"]) == (14, 8)
    assert (rows[1]["shifted"], rows[1]["doubled"]) == (7, -6)
    # #"myValue" starts at 3 and counts 1 a call: 4, 5
    assert (rows[0]["quoted"], rows[1]["quoted"]) == (4, 5)
    # the statement after "END_REGION Quoted names;" on the same line runs
    assert rows[0]["after"] == 5


def one(text: str, body=True):
    """The single block of a text; body: the statements wrapped into an FB."""
    if body:
        text = f'FUNCTION_BLOCK "F"\nBEGIN\n{text}\nEND_FUNCTION_BLOCK\n'
    return parser.parse(text, "t.scl")[0]


def test_the_region_end_text_and_the_placeholder_are_comments():
    block = one("REGION Work\n(/**/)\n#x := 1;\nEND_REGION Work (the title again)\n#y := 2;")
    region, after = block.body
    assert isinstance(region, A.Region) and region.title == "Work"
    assert [s.target.name for s in region.body] == ["x"]
    assert after.target.name == "y"
    # the placeholder may hold text, and stands where a statement stands
    assert one("IF TRUE THEN (/* formatted */) END_IF;").body[0].branches[0][1] == []


def test_a_sign_on_a_number_is_the_literal_s():
    def value(expr):
        return one(f"#x := {expr};").body[0].value

    assert value("-32768") == A.Literal(A.Loc("t.scl", 3, 7), "int", "-32768", -32768)
    assert value("-16#8000").value == -32768
    assert value("-T#1s").value == -1000
    assert value("-LT#1ns").value == -1
    assert value("-DINT#5").type_prefix == "DINT"
    negation = value("-(32768)")  # a parenthesis: the negation of 32768
    assert isinstance(negation, A.Unary) and negation.operand.value == 32768
    difference = value("#a -5")  # after an operand, - is the subtraction
    assert isinstance(difference, A.Binary) and difference.right.value == 5


@pytest.mark.parametrize(
    "literal, prefix, value",
    [
        ("B#16#A5", "BYTE", 0xA5),
        ("b#2#1010", "BYTE", 10),
        ("W#16#8000", "WORD", 0x8000),
        ("DW#16#FFFF_0000", "DWORD", 0xFFFF0000),
        ("LW#16#1", "LWORD", 1),
        ("C#0", "WORD", 0),
        ("C#999", "WORD", 0x999),
        ("LT#2us5ns", "LTIME", 2005),
        ("T#-24d20h31m23s648ms", "TIME", -(2**31)),
        ("T#24d20h31m23s647ms", "TIME", 2**31 - 1),
    ],
)
def test_s7_literals_have_their_type(literal, prefix, value):
    read = one(f"#x := {literal};").body[0].value
    assert (read.type_prefix, read.value) == (prefix, value)


def refused(tmp_path, text: str, block="F") -> str:
    first = refusal(tmp_path, text, block, name="t.scl").diagnostics[0]
    text = f"{first.loc}: {first.code.number}: {first.message}"
    return text.replace(str(tmp_path / "t.scl"), "t.scl")


def fb(declarations: str, statement: str) -> str:
    return (
        'FUNCTION_BLOCK "F"\n'  # line 1
        "   VAR_OUTPUT\n"  # 2
        "      o : Int;\n"  # 3
        "      t : Time;\n"  # 4
        "      u : UInt;\n"  # 5
        "   END_VAR\n"  # 6
        f"{declarations}"
        "BEGIN\n"
        f"   {statement}\n"
        "END_FUNCTION_BLOCK\n"
    )


@pytest.mark.parametrize(
    "statement, message",
    [
        ("#t := T#25d;", "t.scl:8:10: E007: T#25d is beyond the TIME range (T#-24d20h31m23s648ms"),
        ("#t := T#24d20h31m23s648ms;", "t.scl:8:10: E007: T#24d20h31m23s648ms is beyond the TIME"),
        ("#t := -T#25d;", "t.scl:8:10: E007: -T#25d is beyond the TIME range"),
        ("#o := -32769;", "t.scl:8:10: E007: the assignment to 'o': -32769 does not fit INT"),
        ("#o := 32768;", "t.scl:8:10: E007: the assignment to 'o': 32768 does not fit INT"),
        ("#u := -5;", "t.scl:8:10: E007: the assignment to 'u': -5 does not fit UINT (0 to 65535)"),
        ("#o := W#16#1_0000;", "t.scl:8:10: E007: W#16#1_0000 does not fit WORD (0 to 65535)"),
        ("#o := C#1000;", "t.scl:8:10: E007: C#1000: a count value is C#0 to C#999 (BCD)"),
        ("#o := C#-1;", "t.scl:8:10: E007: C#-1: a count value is C#0 to C#999 (BCD)"),
        ("#o := 'A';", "t.scl:8:10: E006: the assignment to 'o': a character string literal is"),
        ("#o := WSTRING#'$'';", "t.scl:8:10: E006: the assignment to 'o': S7 converts no WSTRING"),
        ("#o := D#2169-06-07;", "t.scl:8:10: E007: D#2169-06-07 is beyond the DATE range"),
        ("#o := D#2024-02-29;", "t.scl:8:10: E006: the assignment to 'o': S7 converts no DATE"),
        ("#o := DATE#2023-02-29;", "t.scl:8:10: E020: DATE#2023-02-29: not a DATE literal"),
        ("#o := TOD#23:59:59.999;", "t.scl:8:10: E006: the assignment to 'o': S7 converts no"),
        ("#o := TIME_OF_DAY#24:00:00;", "t.scl:8:10: E020: TIME_OF_DAY#24:00:00: not a TIME_OF"),
        ("#o := LTOD#10:20:30.400_365_215;", "t.scl:8:10: E002: LTOD#10:20:30.400_365_215: LTOD"),
        ("#o := DT#2024-01-31-10:20:30;", "t.scl:8:10: E002: DT#2024-01-31-10:20:30: DATE_AND_T"),
        ("#o := LDT#2024-01-31-10:20:30.5;", "t.scl:8:10: E002: LDT#2024-01-31-10:20:30.5: LDT"),
        ("#o := DTL#2024-01-31-10:20:30.25;", "t.scl:8:10: E006: the assignment to 'o': S7 conv"),
        ("#o := S5T#10s;", "t.scl:8:10: E002: S5T#10s: S5TIME is not supported yet"),
    ],
)
def test_refused_at_the_literal(tmp_path, statement, message):
    assert refused(tmp_path, fb("", statement)).startswith(message)


def test_ltime_range(tmp_path):
    text = fb("   VAR\n      lt : LTime := LT#106752d;\n   END_VAR\n", "")
    assert refused(tmp_path, text).startswith(
        "t.scl:8:21: E007: LT#106752d is beyond the LTIME range (LT#-106751d23h47m16s854ms775us"
    )


def test_positional_start_value_with_too_many_members(tmp_path):
    text = fb(
        "   VAR\n      s : Struct\n         a : Int;\n      END_STRUCT := (1, 2);\n   END_VAR\n", ""
    )
    assert refused(tmp_path, text) == (
        "t.scl:10:25: E015: the initial value of 's': 2 values for the 1 of STRUCT"
    )


STATES = """
FUNCTION_BLOCK "States"
VERSION : 0.1
   VAR_INPUT
      s : Int;
   END_VAR
   VAR_OUTPUT
      o : Int;
      low : DInt;
      high : DInt;
      gridLow : DInt;
   END_VAR
   VAR
      table : Array[#FIRST..#LAST] of Int;
      grid : Array[0..1, #FIRST .. #LAST] of Int;
   END_VAR
   VAR CONSTANT
      IDLE : Int;
      RUN : Int := 1;
      STOP_A : Int := 2;
      STOP_B : Int := 16#4;
      FIRST : DInt := -1;
      LAST : DInt := 2;
   END_VAR

BEGIN
    CASE #s OF
        #IDLE:
            #o (* a statement, not a label: *) := 10; (* next: RUN, 7 *)
        #RUN (* running *), 7:
            #o := 11;
        #STOP_A..#STOP_B: // 2 to 4
            #o := 12;
        ELSE
            #o := -1;
    END_CASE;
    #low := LOWER_BOUND(ARR := #table, DIM := 1);
    #high := UPPER_BOUND(ARR := #table, DIM := 1);
    #gridLow := LOWER_BOUND(ARR := #grid, DIM := 2);
END_FUNCTION_BLOCK
"""


def test_constants_as_case_labels_and_array_bounds(tmp_path):
    fmu = compile_text(tmp_path, STATES, "States")
    per_call = [{"s": s} for s in (0, 1, 7, 2, 3, 4, 5, -1)]
    rows = calls(fmu, per_call)
    # IDLE (0, no value) 10; RUN (1) and 7: 11; STOP_A..STOP_B (2..4): 12; else -1
    assert [row["o"] for row in rows] == [10, 11, 11, 12, 12, 12, -1, -1]
    # table: Array[-1..2], grid's second dimension the same
    assert (rows[0]["low"], rows[0]["high"], rows[0]["gridLow"]) == (-1, 2, -1)


@pytest.mark.parametrize(
    "declarations, statement, message",
    [
        (
            "",
            "CASE #o OF #NOPE: #o := 1; END_CASE;",
            "t.scl:8:15: E003: #NOPE: a CASE label is a literal or a constant of the block with an "
            "integer value (VAR CONSTANT)",
        ),
        (
            "   VAR\n      a : Array[0..#HALF] of Int;\n   END_VAR\n"
            "   VAR CONSTANT\n      HALF : Real := 0.5;\n   END_VAR\n",
            "",
            "t.scl:8:20: E008: #HALF: an ARRAY bound is a literal or a constant of the block",
        ),
    ],
)
def test_constants_refused(tmp_path, declarations, statement, message):
    assert refused(tmp_path, fb(declarations, statement)).startswith(message)


# CASE TypeOf(#v) OF Int: ... (LGF_SearchMinMax), of a VARIANT: read and refused by name
TYPE_LABELS = 'CASE #o OF Int: #o := 1; "Point" : #o := 2; END_CASE;'


def test_a_data_type_as_a_case_label_is_refused_by_name(tmp_path):
    error = refusal(tmp_path, fb("", TYPE_LABELS), "F")
    assert [f"{d.loc.column}: {d.code.number}: {d.message}" for d in error.diagnostics] == [
        f"{column}: E002: the data type {name} as a CASE label (CASE TypeOf(...) OF, of a VARIANT)"
        " is not supported (docs/scl.md §6): the subset has no VARIANT"
        for column, name in ((15, "Int"), (29, '"Point"'))
    ]
