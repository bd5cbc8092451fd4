"""S7's character strings (docs/scl.md §3.1 [S7-STRING], §3.5 [S7-STRING-FN], issue 30):
STRING[n], WSTRING, CHAR and WCHAR; literals with their $-escapes; an assignment cut at the
target's maximum length; S7's comparison; the characters #s[i]; CHAR conversions; LEN, CONCAT,
LEFT, RIGHT, MID, FIND, INSERT, DELETE and REPLACE with the results of their edge cases as
Siemens' S7-1200 system manual ("String and character" instructions: LEFT, RIGHT and MID;
DELETE; INSERT; REPLACE; FIND; CONCAT) documents them. The SCL is written here; every expected
value is worked out by hand in the comments. The FMU shows each result as a BOOL (the string
equals the value worked out by hand) or an INT, CHAR or WCHAR (FMI Integers)."""

from __future__ import annotations

import pytest

from lgf_fmus.scl import SclError
from tests.scl.driver import Instance, compile_text, run_cs

FUNCTIONS = """
FUNCTION_BLOCK "Strings"
   VAR_INPUT
      p : Int := 2;
   END_VAR
   VAR_OUTPUT
      len : Int;
      cut : Bool;
      cutLen : Int;
      escapes : Bool;
      escapesLen : Int;
      first : Char;
      last : Char;
      concat : Bool;
      left : Bool;
      leftAll : Bool;
      leftNone : Bool;
      right : Bool;
      mid : Bool;
      midEnd : Bool;
      midBeyond : Bool;
      midZero : Bool;
      find : Int;
      findNone : Int;
      findEmpty : Int;
      insert : Bool;
      insertFront : Bool;
      insertEnd : Bool;
      insertNegative : Bool;
      delete : Bool;
      deleteEnd : Bool;
      deleteBeyond : Bool;
      deleteZeroP : Bool;
      replace : Bool;
      replaceInsert : Bool;
      replaceEnd : Bool;
      replaceBeyond : Bool;
      replaceNegative : Bool;
      upper : Char;
      code : Int;
      wide : Bool;
      wideChar : WChar;
      maxLen : DInt;
   END_VAR
   VAR
      short : String[4];
      text : String := 'Hello';
      s : String;
      w : WString[10] := WSTRING#'ab';
   END_VAR
BEGIN
    #len := LEN(#text); // 5
    #short := #text; // cut at 4: 'Hell'
    #cut := #short = 'Hell';
    #cutLen := LEN(#short);
    #s := 'a$$b$'c$L$R$T$P$41'; // a $ b ' c LF CR TAB FF A: 10 characters
    #escapes := #s = CONCAT(IN1 := 'a$$b', IN2 := '$27c$0A$0D$09$0CA');
    #escapesLen := LEN(#s);
    #first := #text[1]; // 'H' = 72
    #last := #text[#p + 3]; // #text[5] = 'o' = 111
    #concat := CONCAT(IN1 := #short, IN2 := 'o!') = 'Hello!';
    #left := LEFT(IN := #text, L := #p) = 'He';
    #leftAll := LEFT(IN := #text, L := 9) = 'Hello'; // L beyond the length: all
    #leftNone := LEFT(IN := #text, L := -1) = ''; // L <= 0: empty
    #right := RIGHT(IN := #text, L := 3) = 'llo';
    #mid := MID(IN := #text, L := 3, P := #p) = 'ell';
    #midEnd := MID(IN := #text, L := 9, P := 4) = 'lo'; // to the end
    #midBeyond := MID(IN := #text, L := 1, P := 6) = ''; // P beyond the length
    #midZero := MID(IN := #text, L := 2, P := 0) = ''; // P <= 0
    #find := FIND(IN1 := #text, IN2 := 'l'); // the first 'l': 3
    #findNone := FIND(IN1 := #text, IN2 := 'lx'); // 0
    #findEmpty := FIND(IN1 := #text, IN2 := ''); // 0 (docs/scl.md [DEC-STRING-FIND])
    #insert := INSERT(IN1 := #text, IN2 := '-', P := #p) = 'He-llo'; // after the P-th
    #insertFront := INSERT(IN1 := #text, IN2 := '>', P := 0) = '>Hello';
    #insertEnd := INSERT(IN1 := #text, IN2 := '!', P := 7) = 'Hello!'; // P beyond: appended
    #insertNegative := INSERT(IN1 := #text, IN2 := '!', P := -1) = '';
    #delete := DELETE(IN := #text, L := 2, P := #p) = 'Hlo'; // 'el' deleted
    #deleteEnd := DELETE(IN := #text, L := 9, P := 3) = 'He'; // to the end
    #deleteBeyond := DELETE(IN := #text, L := 1, P := 6) = 'Hello'; // P beyond: unchanged
    #deleteZeroP := DELETE(IN := #text, L := 1, P := 0) = ''; // P <= 0: empty
    #replace := REPLACE(IN1 := #text, IN2 := 'ipp', L := 4, P := #p) = 'Hipp';
    #replaceInsert := REPLACE(IN1 := #text, IN2 := 'XY', L := 0, P := #p) = 'HXYello';
    #replaceEnd := REPLACE(IN1 := #text, IN2 := 'p!', L := 9, P := 4) = 'Help!';
    #replaceBeyond := REPLACE(IN1 := #text, IN2 := '!', L := 1, P := 8) = 'Hello!';
    #replaceNegative := REPLACE(IN1 := #text, IN2 := '!', L := -1, P := 1) = '';
    #upper := USINT_TO_CHAR(CHAR_TO_USINT(#text[2]) - 32); // 'e' 101 -> 'E' 69
    #code := CHAR_TO_INT('$FF'); // 255
    #w := CONCAT(IN1 := #w, IN2 := WCHAR#'c');
    #wide := #w = WSTRING#'abc';
    #wideChar := #w[3]; // 'c' = 99
    #maxLen := MAX_LEN(#short) + MAX_LEN(#w) + MAX_LEN(IN := #s); // 4 + 10 + 254
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-STRING] [S7-STRING-LIT] [S7-STRING-ASSIGN] [S7-STRING-CHAR]
# [S7-STRING-FN] [DEC-STRING-FIND] [S7-CHAR-CONV] [DEC-CHAR-FMI]
def test_string_functions_give_siemens_results(tmp_path):
    fmu = compile_text(tmp_path, FUNCTIONS, "Strings")
    (row,) = run_cs(fmu, 100_000, {}, {}, [])
    counts = {"len": 5, "cutLen": 4, "escapesLen": 10, "find": 3, "findNone": 0, "findEmpty": 0}
    chars = {"first": 72, "last": 111, "upper": 69, "code": 255, "wideChar": 99, "maxLen": 268}
    expected = {**counts, **chars}
    assert {k: row[k] for k in expected} == expected
    assert [k for k, v in row.items() if k not in expected and v is not True] == []


PROGRAM = """
FUNCTION "Upper" : String
   VAR_INPUT
      s : String[8];
   END_VAR
   VAR_TEMP
      i : Int;
      c : Char;
      r : String;
   END_VAR
BEGIN
    #r := '';
    FOR #i := 1 TO LEN(#s) DO
        #c := #s[#i];
        IF 'a' <= #c AND #c <= 'z' THEN
            #c := USINT_TO_CHAR(CHAR_TO_USINT(#c) - 32);
        END_IF;
        #r := CONCAT(IN1 := #r, IN2 := #c);
    END_FOR;
    #Upper := #r;
END_FUNCTION

FUNCTION_BLOCK "Grow"
   VAR_OUTPUT
      n : Int;
      upper : Bool;
      cutInput : Bool;
      less : Bool;
      prefixLess : Bool;
      greater : Bool;
      equal : Bool;
      longer : Bool;
      unsetIsEmpty : Bool;
   END_VAR
   VAR
      unset : Char;
      letter : Char := 'x';
      grown : String[3];
      table : Array[1..2] of String[4] := ['ab', 'abc'];
   END_VAR
BEGIN
    #grown := CONCAT(IN1 := #grown, IN2 := 'x'); // one more x each cycle, cut at 3
    #n := LEN(#grown);
    #upper := "Upper"(s := 'aZ-b') = 'AZ-B';
    #cutInput := "Upper"(s := 'abcdefghij') = 'ABCDEFGH'; // the input cut at its 8
    #less := 'abc' < 'abd'; // the first character that differs decides
    #prefixLess := #table[1] < #table[2]; // 'ab' is the start of 'abc': the shorter is less
    #greater := 'b' > #table[2]; // 'b' > 'a'
    #equal := #table[2] = 'abc' AND NOT (#table[2] <> 'abc');
    #longer := #table[2] >= 'ab' AND 'ab' <= #table[1];
    #unsetIsEmpty := #unset = '' AND NOT ('' <> #unset) AND #letter <> ''; // '' as a CHAR: $00
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-STRING-CMP] [S7-STRING-ASSIGN] [S7-STRING-CHAR] [DEC-CHAR-EMPTY]
def test_a_string_static_an_fc_of_strings_and_the_comparison(tmp_path):
    fmu = compile_text(tmp_path, PROGRAM, "Grow")
    rows = run_cs(fmu, 100_000, {}, {}, [(100_000, {})] * 3)
    assert [row.pop("n") for row in rows] == [1, 2, 3, 3]  # 'x', 'xx', 'xxx', then cut at 3
    assert all(all(row.values()) for row in rows)


def fb(declarations: str, statement: str) -> str:
    return (
        'FUNCTION_BLOCK "F"\n   VAR\n      s : String;\n      c : Char;\n      i : Int;\n'
        f"{declarations}   END_VAR\nBEGIN\n    {statement}\nEND_FUNCTION_BLOCK\n"
    )


# docs/scl.md rules: [S7-STRING] [S7-STRING-LIT] [S7-STRING-CMP] [S7-STRING-CHAR]
@pytest.mark.parametrize(
    "declarations, statement, message",
    [
        ("", "#s := 'a$Nb';", "8:11: E020: 'a$Nb': $N (a new line) is not supported: write $R$L"),
        ("", "#s := '$Q';", "8:11: E020: '$Q': $Q is no escape of S7"),
        ("", "#s := 'Ω';", "8:11: E020: 'Ω': the character 'Ω' is beyond the codes of a STRING"),
        ("", "#c := CHAR#'ab';", "8:11: E020: CHAR#'ab': a CHAR literal is one character"),
        ("", "#c := 'ab';", "8:11: E006: the assignment to 'c': a character string literal is no"),
        ("", "#s := #s + 'a';", "8:11: E008: + needs numbers or bit strings, not STRING and"),
        ("", "#i := #s;", "8:11: E006: the assignment to 'i': S7 converts no STRING to INT"),
        (
            "w : WString;\n",
            "#i := LEN(#w) + FIND(IN1 := #s, IN2 := #w);",
            "9:44: E006: FIND's IN2: S7 converts",
        ),
        ("w : WString;\n", "#c := #s[0];", "9:14: E007: the index 0 is outside s's 1..254"),
        ("w : WString;\n", "#c := #w[1];", "9:11: E006: the assignment to 'c': S7 converts no"),
        ("", "#c := #s[1, 2];", "8:13: E009: 's' is a STRING: it takes one index"),
        ("", "#c := #s[#c];", "8:14: E008: the index of 's' must be an integer of up to 32 bits"),
        ("", "#i := LEFT(IN := #s, L := 1.5);", "8:31: E006: LEFT's L: a real literal is no INT"),
        ("", "#i := DINT_TO_INT(MAX_LEN('ab'));", "8:31: E008: MAX_LEN needs a STRING or WSTRING"),
        ("", "#c := 5;", "8:11: E006: the assignment to 'c': an integer literal is no CHAR"),
        ("", "#s := -#s;", "8:11: E008: unary minus needs a signed number or TIME, not STRING"),
        ("", "#s := SEL(G := TRUE, IN0 := #s, IN1 := 'a');", "8:11: E002: SEL of character"),
        ("", "#s := REAL_TO_STRING(1.0);", "8:11: E002: REAL_TO_STRING is not supported yet"),
        ("", "#c := REAL_TO_CHAR(1.0);", "8:11: E006: REAL_TO_CHAR: S7 has no conversion"),
        ("w : WString;\n", "IF #s = #w THEN #i := 1; END_IF;", "9:8: E006: STRING = WSTRING"),
        ("t : Int[5];\n", "", "6:5: E003: unknown or unsupported data type 'Int[5]' of 't'"),
        ("t : String[#i];\n", "", "6:5: E002: 't': the length of STRING[#i] is an integer or a"),
        ("t : WString[0];\n", "", "6:5: E007: 't': WSTRING[0]: a WSTRING holds 1 to 16382"),
    ],
)
def test_refused_at_its_place(tmp_path, declarations, statement, message):
    with pytest.raises(SclError) as error:
        compile_text(tmp_path, fb(declarations, statement), "F")
    first = str(error.value).splitlines()[0].split("F.scl:", 1)[1].replace("error ", "")
    assert first.startswith(message), first


INTERFACE = """
FUNCTION_BLOCK "Greet"
   VAR_INPUT
      name : String[5] := 'Ann';
      wide : WString[4] := WSTRING#'Ωx';
      letter : Char := 'a';
   END_VAR
   VAR_OUTPUT
      greeting : String;
      count : Int;
      wideOut : WString;
      next : Char;
   END_VAR
   VAR
      last : String[4];
   END_VAR
BEGIN
    #greeting := CONCAT(IN1 := 'Hi ', IN2 := #name);
    #count := LEN(#name);
    #last := #greeting; // cut at 4: 'Hi A'
    #wideOut := CONCAT(IN1 := #wide, IN2 := WSTRING#'é');
    #next := USINT_TO_CHAR(CHAR_TO_USINT(#letter) + 1);
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-STRING-FMI] [DEC-CHAR-FMI] [S7-STRING-ASSIGN]
@pytest.mark.parametrize("fmi", [2, 3])
def test_strings_of_the_interface_are_fmi_strings(tmp_path, fmi):
    fmu = compile_text(tmp_path, INTERFACE, "Greet", fmi=fmi)
    rows = run_cs(fmu, 100_000, {}, {}, [(100_000, {"name": "Zoë", "letter": ord("y")})])
    assert rows == [
        # at the start (initialization: the first call's outputs): 'Hi ' + 'Ann'
        {"greeting": "Hi Ann", "count": 3, "wideOut": "Ωxé", "next": ord("b")},
        {"greeting": "Hi Zoë", "count": 3, "wideOut": "Ωxé", "next": ord("z")},
    ]


# docs/scl.md rules: [S7-STRING-FMI]
@pytest.mark.parametrize("fmi", [2, 3])
def test_a_string_set_is_refused_beyond_the_length_and_the_instance_unchanged(tmp_path, fmi):
    fmu = compile_text(tmp_path, INTERFACE, "Greet", fmi=fmi)
    s = Instance(fmu, {"cycleTime": 0.1}, {})
    for name, value in [("name", "Maxima"), ("name", "Ωmega"), ("wide", "abcde")]:
        with pytest.raises(Exception):
            s.set({name: value})
    log = "\n".join(s.log)
    function = "fmi2SetString" if fmi == 2 else "fmi3SetString"
    assert (
        f'{function}: name = "Maxima" is refused: it has 6 characters, more than its STRING[5]'
        in log
    )
    assert "its character U+03A9 is beyond a STRING's (U+0000 to U+00FF)" in log
    assert 'wide = "abcde" is refused: it has 5 characters, more than its WSTRING[4] holds' in log
    # unchanged: the start values, and last of the call at the end of initialization
    assert s.get(["name", "wide", "last"]) == {"name": "Ann", "wide": "Ωx", "last": "Hi A"}
    s.set({"name": "Björn"})  # five characters: a STRING's ö is U+00F6
    s.fmu.doStep(currentCommunicationPoint=0.0, communicationStepSize=0.1)
    assert s.get(["greeting", "last"]) == {"greeting": "Hi Björn", "last": "Hi B"}
    s.free()


# docs/scl.md rules: [S7-STRING-FMI]
def test_a_string_start_value_xml_cannot_carry_is_refused(tmp_path):
    text = INTERFACE.replace("'Ann'", "'A$01'")
    with pytest.raises(SclError) as error:
        compile_text(tmp_path, text, "Greet")
    assert "the start value of 'name' holds the character $01" in str(error.value)


INSTANCE = """
FUNCTION_BLOCK "Tag"
   VAR_INPUT
      text : String[3];
   END_VAR
   VAR_OUTPUT
      tagged : String;
   END_VAR
BEGIN
    #tagged := CONCAT(IN1 := #text, IN2 := '!');
END_FUNCTION_BLOCK

FUNCTION_BLOCK "Main"
   VAR_OUTPUT
      out : String[3];
      member : String;
   END_VAR
   VAR
      t : "Tag";
   END_VAR
BEGIN
    #t(text := 'abcdef', tagged => #out); // the input cut at 3: 'abc!', the output at 3: 'abc'
    #member := #t.tagged;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-STRING-ASSIGN] [S7-STRING-FMI]
def test_the_string_input_and_output_of_an_instance(tmp_path):
    fmu = compile_text(tmp_path, INSTANCE, "Main")
    assert run_cs(fmu, 100_000, {}, {}, []) == [{"out": "abc", "member": "abc!"}]
