"""S7's conversions between character strings and integers (docs/scl.md §3.5 [S7-VAL-STRG],
[S7-STRG-VAL], [DEC-NUMBER-STRING], issue 30): VAL_STRG and STRG_VAL with FORMAT, P, SIZE and
PREC, <integer>_TO_STRING and STRING_TO_<integer>. The SCL is written here; every expected value
is worked out by hand from the rules of Siemens' S7-1200 system manual ("String and character":
VAL_STRG, STRG_VAL, their ENO conditions and tables of examples; several cases are the manual's
own examples, named so in the comments) or from our marked decisions. One FMU holds every case,
its results as STRING and integer outputs."""

from __future__ import annotations

import pytest

from tests.scl.driver import compile_text, run_cs
from tests.scl.test_strings import test_refused_at_its_place as refused_at

CASES = """
FUNCTION "Digits" : String
   VAR_INPUT
      v : DInt;
   END_VAR
   VAR_TEMP
      t : String;
   END_VAR
BEGIN
    // as a library's integer-to-text FC: SIZE 0, PREC 0, FORMAT 0, P 1 into an empty temp
    VAL_STRG(IN := #v, SIZE := 0, PREC := 0, FORMAT := 16#0000, P := 1, OUT => #t);
    #Digits := #t;
END_FUNCTION

FUNCTION_BLOCK "Numbers"
   VAR_INPUT
      value : DInt := 42;
      text : String := '  -1,234xyz';
   END_VAR
   VAR_OUTPUT
      plain : String;
      negative : String;
      padded : String;
      signed : String;
      signedZero : String;
      point : String;
      comma : String;
      zero : String;
      exponentBit : String;
      placed : String;
      tooLong : String;
      sizeNotAbovePrec : String;
      illegalFormat : String;
      pZero : String;
      beyond : String;
      cut : String[6];
      noRoom : String[6];
      number : DInt;
      numberP : UInt;
      commaPoint : DInt;
      exponent : DInt;
      exponentFixed : DInt;
      exponentP : UInt;
      plus : Int;
      trailing : Int;
      small : SInt;
      smallP : UInt;
      unsignedNegative : USInt;
      letters : DInt;
      empty : DInt;
      twoSigns : DInt;
      pBeyond : DInt;
      fromP : Bool;
      wide : UDInt;
      fc : String;
      fcNegative : String;
      toText : String;
      toTextNegative : String;
      toTextZero : String;
      toTextUnsigned : String;
      fromText : Int;
      fromTextFraction : Int;
      fromTextOverflow : Int;
      fromTextInvalid : Int;
      joined : String;
      eachType : String;
      fromEach : Bool;
   END_VAR
   VAR
      p : UInt;
      s : String;
      u : UDInt;
   END_VAR
BEGIN
    // VAL_STRG: <sign><digits without leading zeros>, the point before the last PREC digits
    VAL_STRG(IN := #value, SIZE := 0, PREC := 0, FORMAT := 16#0000, P := 1, OUT => #plain);
    // '42'
    VAL_STRG(IN := -#value, SIZE := 0, PREC := 0, FORMAT := 16#0000, P := 1, OUT => #negative);
    // '-42'
    VAL_STRG(IN := #value, SIZE := 5, PREC := 0, FORMAT := 16#0000, P := 1, OUT => #padded);
    // '   42': right-justified in SIZE 5
    VAL_STRG(IN := #value, SIZE := 0, PREC := 0, FORMAT := 16#0004, P := 1, OUT => #signed);
    // '+42': the sign bit
    VAL_STRG(IN := 0, SIZE := 3, PREC := 0, FORMAT := 16#0004, P := 1, OUT => #signedZero);
    // ' +0'
    VAL_STRG(IN := -5, SIZE := 6, PREC := 2, FORMAT := 16#0000, P := 1, OUT => #point);
    // ' -0.05': the zeros up to the digit left of the point
    VAL_STRG(IN := 12345678, SIZE := 10, PREC := 3, FORMAT := 16#0001, P := 1, OUT => #comma);
    // ' 12345,678' (the manual's example, UDInt 12345678, PREC 3, FORMAT 0001)
    VAL_STRG(IN := 0, SIZE := 0, PREC := 2, FORMAT := 16#0000, P := 1, OUT => #zero);
    // '0.00' (the manual's example, UInt 0 with PREC 2)
    VAL_STRG(IN := 7, SIZE := 0, PREC := 0, FORMAT := 16#0002, P := 1, OUT => #exponentBit);
    // '7': an integer in fixed point whatever the notation bit [DEC-VAL-STRG]
    #placed := 'T = xxxx C';
    VAL_STRG(IN := 123, SIZE := 4, PREC := 0, FORMAT := 16#0000, P := 5, OUT => #placed);
    // 'T =  123 C': the characters from P replaced, those after them kept
    #tooLong := 'keep';
    VAL_STRG(IN := 12345, SIZE := 4, PREC := 0, FORMAT := 16#0000, P := 1, OUT => #tooLong);
    // 'keep': a text longer than SIZE leaves OUT unchanged
    #sizeNotAbovePrec := 'keep';
    VAL_STRG(IN := 5, SIZE := 2, PREC := 2, FORMAT := 16#0000, P := 1, OUT => #sizeNotAbovePrec);
    // 'keep': SIZE must be greater than PREC
    #illegalFormat := 'keep';
    VAL_STRG(IN := 5, SIZE := 0, PREC := 0, FORMAT := 16#0008, P := 1, OUT => #illegalFormat);
    // 'keep'
    #pZero := 'keep';
    VAL_STRG(IN := 5, SIZE := 0, PREC := 0, FORMAT := 16#0000, P := 0, OUT => #pZero);
    // 'keep'
    #beyond := 'ab';
    VAL_STRG(IN := 7, SIZE := 2, PREC := 0, FORMAT := 16#0000, P := 5, OUT => #beyond);
    // 'ab   7': spaces up to P = 5, then ' 7'
    #cut := 'abcd';
    VAL_STRG(IN := 123456, SIZE := 0, PREC := 0, FORMAT := 16#0000, P := 3, OUT => #cut);
    // 'ab1234': SIZE 0 ends at the maximum length 6 [DEC-VAL-STRG]
    #noRoom := 'abcd';
    VAL_STRG(IN := 12, SIZE := 3, PREC := 0, FORMAT := 16#0000, P := 5, OUT => #noRoom);
    // 'abcd': SIZE 3 from P 5 does not fit 6 characters
    // STRG_VAL: from P, spaces skipped, a sign, digits, the thousands separators ignored
    #p := 1;
    STRG_VAL(IN := #text, FORMAT := 16#0000, P := #p, OUT => #number);
    #numberP := #p;
    // -1234, P 9: the 'x' after the number
    STRG_VAL(IN := '12,345.67', FORMAT := 16#0001, P := 1, OUT => #commaPoint);
    // 12: ',' the point, the '.' after it ends the number (the manual's 12.345 as an integer)
    #p := 1;
    STRG_VAL(IN := '1.5E2kg', FORMAT := 16#0002, P := #p, OUT => #exponent);
    #exponentP := #p;
    // 150, P 6 ('k'): the exponent in exponential notation
    STRG_VAL(IN := '1.5E2', FORMAT := 16#0000, P := 1, OUT => #exponentFixed);
    // 1: 'E' ends the number in fixed point (the manual's '1.23E-4' is 1.23)
    STRG_VAL(IN := '+2345', FORMAT := 16#0000, P := 1, OUT => #plus);
    // 2345 (the manual's example)
    STRG_VAL(IN := '00123AB', FORMAT := 16#0000, P := 1, OUT => #trailing);
    // 123 (the manual's example)
    #p := 1;
    STRG_VAL(IN := '12345', FORMAT := 16#0000, P := #p, OUT => #small);
    #smallP := #p;
    // 0: beyond a SInt (the manual's example); P kept at 1 [DEC-STRG-VAL]
    STRG_VAL(IN := '-5', FORMAT := 16#0000, P := 1, OUT => #unsignedNegative);
    // 0: beyond a USInt
    STRG_VAL(IN := 'A123', FORMAT := 16#0000, P := 1, OUT => #letters);
    // 0 (the manual's example)
    STRG_VAL(IN := '', FORMAT := 16#0000, P := 1, OUT => #empty);
    // 0 (the manual's example: P beyond the empty string)
    STRG_VAL(IN := '+-123', FORMAT := 16#0000, P := 1, OUT => #twoSigns);
    // 0 (the manual's example)
    STRG_VAL(IN := '12', FORMAT := 16#0000, P := 3, OUT => #pBeyond);
    // 0: P beyond the current length
    STRG_VAL(IN := 'ID=4000000000;', FORMAT := 16#0000, P := 4, OUT => #u);
    #fromP := #u = 4000000000; // from P 4, a UDInt beyond the FMI Integer
    #s := '99999999999999999999999';
    STRG_VAL(IN := #s, FORMAT := 16#0000, P := 1, OUT => #wide);
    // 0: beyond 64 bits too
    #fc := "Digits"(v := 2024);
    // '2024'
    #fcNegative := "Digits"(v := -7);
    // '-7'
    // <integer>_TO_STRING: the sign and the digits [DEC-NUMBER-STRING]
    #toText := DINT_TO_STRING(#value);
    // '+42'
    #toTextNegative := INT_TO_STRING(-300);
    // '-300'
    #toTextZero := SINT_TO_STRING(0);
    // '+0'
    #toTextUnsigned := UDINT_TO_STRING(4294967295);
    // '+4294967295'
    #fromText := STRING_TO_INT(' -00456');
    // -456 (the manual's example, with a leading space)
    #fromTextFraction := STRING_TO_INT('123.45');
    // 123 (the manual's example)
    #fromTextOverflow := STRING_TO_INT('40000');
    // 0: beyond an Int
    #fromTextInvalid := STRING_TO_INT('x1');
    // 0
    #joined := CONCAT(IN1 := INT_TO_STRING(12), IN2 := 'h',
                      IN3 := DELETE(IN := INT_TO_STRING(5), L := 1, P := 1), IN4 := 'm');
    // '+12' 'h' '5' 'm': '+12h5m' [DEC-CONCAT-MORE]
    #eachType := CONCAT(IN1 := USINT_TO_STRING(255), IN2 := UINT_TO_STRING(65535));
    // '+255' '+65535': each type's largest value with its sign
    #fromEach := STRING_TO_SINT('-128') = -128 AND STRING_TO_USINT('-5') = 0
                 AND STRING_TO_UINT('65535') = 65535 AND STRING_TO_DINT('-2147483648') = -2147483648
                 AND STRING_TO_UDINT('+4294967295') = 4294967295;
    // TRUE: each type's limits read back, '-5' beyond a USInt 0 (the manual's example)
END_FUNCTION_BLOCK
"""

EXPECTED = {
    "plain": "42",
    "negative": "-42",
    "padded": "   42",
    "signed": "+42",
    "signedZero": " +0",
    "point": " -0.05",
    "comma": " 12345,678",
    "zero": "0.00",
    "exponentBit": "7",
    "placed": "T =  123 C",
    "tooLong": "keep",
    "sizeNotAbovePrec": "keep",
    "illegalFormat": "keep",
    "pZero": "keep",
    "beyond": "ab   7",
    "cut": "ab1234",
    "noRoom": "abcd",
    "number": -1234,
    "numberP": 9,
    "commaPoint": 12,
    "exponent": 150,
    "exponentFixed": 1,
    "exponentP": 6,
    "plus": 2345,
    "trailing": 123,
    "small": 0,
    "smallP": 1,
    "unsignedNegative": 0,
    "letters": 0,
    "empty": 0,
    "twoSigns": 0,
    "pBeyond": 0,
    "fromP": True,
    "wide": 0,
    "fc": "2024",
    "fcNegative": "-7",
    "toText": "+42",
    "toTextNegative": "-300",
    "toTextZero": "+0",
    "toTextUnsigned": "+4294967295",
    "fromText": -456,
    "fromTextFraction": 123,
    "fromTextOverflow": 0,
    "fromTextInvalid": 0,
    "joined": "+12h5m",
    "eachType": "+255+65535",
    "fromEach": True,
}


# docs/scl.md rules: [S7-VAL-STRG] [DEC-VAL-STRG] [S7-STRG-VAL] [DEC-STRG-VAL]
# [DEC-NUMBER-STRING] [DEC-CONCAT-MORE]
def test_conversions_give_the_results_of_siemens_rules(tmp_path):
    fmu = compile_text(tmp_path, CASES, "Numbers")
    first, second = run_cs(fmu, 100_000, {}, {}, [(100_000, {"value": -9, "text": "7,0"})])
    assert first == EXPECTED
    # the next call with -9 and '7,0': the outputs keep their characters from the first call
    # (VAR_OUTPUT is static) and VAL_STRG replaces those from P only: '+42' -> '-92',
    # '-42' -> '942'; ',' is a thousands separator left of the point: '7,0' is 70, P 4
    changed = {"plain": "-9", "negative": "942", "padded": "   -9", "signed": "-92"}
    changed |= {"number": 70, "numberP": 4, "toText": "-9"}
    assert {k: second[k] for k in changed} == changed


VAL = "SIZE := 0, PREC := 0, FORMAT := 16#0000, P := 1"


# docs/scl.md rules: [S7-VAL-STRG] [S7-STRG-VAL] [DEC-NUMBER-STRING]
@pytest.mark.parametrize(
    "declarations, statement, message",
    [
        ("r : Real;\n", f"VAL_STRG(IN := #r, {VAL}, OUT => #s);", "9:20: E002: VAL_STRG of REAL"),
        ("b : Bool;\n", f"VAL_STRG(IN := #b, {VAL}, OUT => #s);", "9:20: E008: VAL_STRG of BOOL"),
        ("", f"VAL_STRG(IN := #i, {VAL}, OUT => #i);", "8:80: E010: VAL_STRG's OUT is a STRING"),
        ("w : WString;\n", f"VAL_STRG(IN := 1, {VAL}, OUT => #w);", "9:79: E010: VAL_STRG's OUT"),
        ("", f"VAL_STRG(#i, {VAL}, OUT => #s);", "8:14: E010: VAL_STRG: name the parameters"),
        ("", f"VAL_STRG(IN := #i, {VAL}, Q => #s);", "8:73: E010: VAL_STRG has no output 'Q'"),
        ("", f"VAL_STRG(IN := #i, X := 1, {VAL}, OUT => #s);", "8:24: E010: VAL_STRG has no"),
        ("", f"VAL_STRG(IN := #i, IN := 1, {VAL}, OUT => #s);", "8:24: E010: VAL_STRG: 'IN' is"),
        ("", f"VAL_STRG(IN := #i, {VAL});", "8:5: E010: VAL_STRG needs OUT"),
        (
            "t : Array[1..2] of String;\n",
            f"VAL_STRG(IN := #i, {VAL}, OUT => #t[#i]);",
            "9:80: E010: VAL_STRG's OUT is a variable, a member or an element at a literal index",
        ),
        ("", "#i := VAL_STRG(IN := #i);", "8:11: E013: VAL_STRG has no value"),
        (
            "r : Real;\n",
            "STRG_VAL(IN := #s, FORMAT := 0, P := 1, OUT => #r);",
            "9:52: E002: STRG_VAL into REAL",
        ),
        ("", "STRG_VAL(IN := #s, FORMAT := 0, P := 1, OUT => #s);", "8:52: E010: STRG_VAL into"),
        ("", "STRG_VAL(IN := #s, FORMAT := 0, P := #i, OUT => #i);", "8:42: E010: STRG_VAL's P"),
        ("", "STRG_VAL(IN := #i, FORMAT := 0, P := 1, OUT => #i);", "8:20: E006: STRG_VAL's IN"),
        ("", "#s := INT_TO_STRING(#s);", "8:25: E006: INT_TO_STRING's IN: S7 converts no STRING"),
        ("", "#i := STRING_TO_INT(#i);", "8:25: E006: STRING_TO_INT's IN: S7 converts no INT"),
        ("", "#s := LINT_TO_STRING(1);", "8:11: E002: LINT_TO_STRING is not supported yet"),
        ("", "#s := CONCAT(IN1 := 'a', IN3 := 'b');", "8:30: E010: CONCAT has no input 'IN3'"),
        ("", "#s := CONCAT('a');", "8:11: E010: CONCAT needs IN2"),
    ],
)
def test_refused_at_its_place(tmp_path, declarations, statement, message):
    refused_at(tmp_path, declarations, statement, message)
