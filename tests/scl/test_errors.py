"""What the compiler refuses (docs/scl.md §5): each refusal `file:line:col: message` names the
construct (with the S7 rule where one applies), before any C is generated. How the errors are
reported together (codes, source lines, notes, the command line) is test_diagnostics.py's."""

from __future__ import annotations

import pytest

from tests.scl.driver import refusal


def fb(declarations: str, body: str) -> str:
    return (
        'FUNCTION_BLOCK "Fb"\n'  # line 1
        "   VAR_INPUT\n"  # 2
        "      i : Int;\n"  # 3
        "      d : DInt;\n"  # 4
        "      r : Real;\n"  # 5
        "   END_VAR\n"  # 6
        "   VAR_OUTPUT\n"  # 7
        "      o : Int;\n"  # 8
        "   END_VAR\n"  # 9
        f"{declarations}"
        "BEGIN\n"
        f"{body}"
        "END_FUNCTION_BLOCK\n"
    )


def refused(tmp_path, text: str, block="Fb") -> str:
    """The first error of the source, as `fb.scl:line:col: message`."""
    first = refusal(tmp_path, text, block).diagnostics[0]
    where = f"{first.loc}: " if first.loc is not None else ""
    return (where + first.message).replace(str(tmp_path / "fb.scl"), "fb.scl")


def refuses(tmp_path, declarations: str, body: str, after: str, expected: str) -> None:
    """fb(declarations, body) and the sources after it: the first error starts with expected."""
    message = refused(tmp_path, fb(declarations, body) + after)
    assert message.startswith(expected), message


# (declarations, body, the message's start: file:line:col and the words it must hold)
CASES = {
    "syntax": ("", "    #o := ;\n", "fb.scl:11:11: unexpected ';'"),
    # docs/scl.md §6: source that is not valid SCL, said so
    "comparison as a statement": (
        "",
        "    #o = 1;\n",
        "fb.scl:11:8: '=' compares and assigns nothing, an assignment is ':=': the source is not "
        "valid SCL (docs/scl.md §6)",
    ),
    "member with #": (
        "   VAR\n      s : STRUCT x : Int; END_STRUCT;\n   END_VAR\n",
        "    #o := #s.#x;\n",
        "fb.scl:14:14: a member is named without #, .x and not .#x: the source is not valid SCL",
    ),
    "end_if of nothing": (
        "",
        "    REGION a\n        #o := 1;\n        END_IF;\n    END_REGION\n",
        "fb.scl:13:9: END_IF without its IF: the source is not valid SCL (docs/scl.md §6)",
    ),
    # docs/scl.md rules: [S7-INPUT-RO]
    "writing the calling ob": (
        "   VAR_INPUT\n      callOB : OB_CYCLIC;\n   END_VAR\n",
        "    #callOB := 5;\n",
        "fb.scl:14:5: 'callOB' is an input, set by the importer at every call",
    ),
    # docs/scl.md rules: [DEC-ENO]
    "declaring eno": (
        "   VAR_OUTPUT\n      ENO : Bool;\n   END_VAR\n",
        "",
        "fb.scl:11:7: 'ENO': S7 gives every block its enable output ENO; name it otherwise",
    ),
    "undeclared": ("", "    #o := #nothing;\n", "fb.scl:11:11: 'nothing' is not declared in Fb"),
    "name too long": (
        "   VAR\n      " + "a" * 129 + " : Int;\n   END_VAR\n",
        "",
        'fb.scl:11:7: "aaaaaaaaaaaaaaaaaaaa...": a name of 129 characters (TIA: 128 at most)',
    ),
    # docs/scl.md rules: [S7-CONV-1]
    "narrowing": (
        "",
        "    #o := #r;\n",
        "fb.scl:11:11: the assignment to 'o': S7 converts no REAL to INT implicitly; "
        "write REAL_TO_INT(...)",
    ),
    # docs/scl.md rules: [S7-CONV-3]
    "real to int": (
        "",
        "    #o := #r;\n",
        "fb.scl:11:11: the assignment to 'o': S7 converts no REAL",
    ),
    # docs/scl.md rules: [S7-LIT-1]
    "literal too big": (
        "",
        "    #o := 40000;\n",
        "fb.scl:11:11: the assignment to 'o': 40000 does not fit INT (-32768 to 32767)",
    ),
    "real too big": (
        "   VAR\n      x : Real;\n   END_VAR\n",
        "    #x := 1e39;\n",
        "fb.scl:14:11: the assignment to 'x': 1e39 is beyond the largest REAL",
    ),
    # docs/scl.md rules: [S7-FLOW-LOOP]
    "exit": ("", "    EXIT;\n", "fb.scl:11:5: EXIT outside FOR, WHILE or REPEAT"),
    "unknown type": (
        "   VAR\n      s : Strung;\n   END_VAR\n",
        "",
        "fb.scl:11:11: unknown or unsupported data type 'Strung' of 's'",
    ),
    # docs/scl.md rules: [S7-STRING]
    "string": (
        "   VAR_INPUT\n      s : String := '$07';\n   END_VAR\n",
        "",
        "fb.scl:11:21: the start value of 's' holds the character $07",
    ),
    "sized string": (
        "   VAR\n      s : String[255];\n   END_VAR\n",
        "",
        "fb.scl:11:11: 's': STRING[255]: a STRING holds 1 to 254 characters",
    ),
    "unknown function": (
        "",
        "    #o := FOO(#i);\n",
        "fb.scl:11:11: unknown or unsupported function 'FOO'",
    ),
    # docs/scl.md rules: [S7-INPUT-RO]
    "input written": ("", "    #i := 1;\n", "fb.scl:11:5: 'i' is an input"),
    # docs/scl.md rules: [S7-TIME-1]
    "time plus int": (
        "   VAR\n      t : Time;\n   END_VAR\n",
        "    #t := #t + 5;\n",
        "fb.scl:14:11: TIME + an integer literal: TIME takes + and - of TIME",
    ),
    # docs/scl.md rules: [S7-CONV-3]
    "condition": (
        "",
        "    IF #i THEN #o := 1; END_IF;\n",
        "fb.scl:11:8: the IF condition: S7 converts no INT to BOOL implicitly",
    ),
    # docs/scl.md rules: [S7-INST-CALL]
    "timer argument": (
        "   VAR\n      t : TON;\n   END_VAR\n",
        "    #t(IN := TRUE, PX := T#1s);\n",
        "fb.scl:14:20: TON has no input 'PX' (IN, PT)",
    ),
    # docs/scl.md rules: [S7-INST-CALL]
    "timer output": (
        "   VAR\n      t : TON;\n   END_VAR\n",
        "    #t.Q := TRUE;\n",
        "fb.scl:14:5: 't.Q' is an output of TON",
    ),
    "timer as value": (
        "   VAR\n      t : TON;\n   END_VAR\n",
        "    #o := #t;\n",
        "fb.scl:14:11: the TON instance 't' is not a value",
    ),
    "duplicate": (
        "   VAR\n      I : Bool;\n   END_VAR\n",
        "",
        "fb.scl:11:7: 'I' is declared twice",
    ),
    "in_out of instances": (
        "   VAR_IN_OUT\n      io : ARRAY[0..1] OF TON;\n   END_VAR\n",
        "",
        "fb.scl:11:7: the TON instance 'io' must be a static (VAR)",
    ),
    "in_out output name": (
        "   VAR_IN_OUT\n      io : Int;\n   END_VAR\n   VAR\n      io_out : Int;\n   END_VAR\n",
        "",
        "fb.scl:11:7: VAR_IN_OUT 'io': its output 'io_out' is declared as well",
    ),
    "table size name": (
        "   VAR_IN_OUT\n      t : ARRAY[*] OF Int;\n   END_VAR\n   VAR\n      numberOfT : Int;\n"
        "   END_VAR\n",
        "",
        "fb.scl:11:7: VAR_IN_OUT 't': 'numberOfT', the size of its table, is declared as well",
    ),
    # docs/scl.md rules: [S7-ARRAY-STAR]
    "array star outside in_out": (
        "   VAR\n      a : ARRAY[*] OF Int;\n   END_VAR\n",
        "",
        "fb.scl:11:11: 'a': ARRAY[*] is only the type of a VAR_IN_OUT or of an FC's VAR_INPUT",
    ),
    "array bounds": (
        "   VAR\n      a : ARRAY[3..1] OF Int;\n   END_VAR\n",
        "",
        "fb.scl:11:11: 'a': ARRAY[3..1]: the low bound is above the high",
    ),
    # docs/scl.md rules: [S7-ARRAY]
    "constant index outside": (
        "   VAR\n      a : ARRAY[1..3] OF Int;\n   END_VAR\n",
        "    #o := #a[4];\n",
        "fb.scl:14:14: the index 4 is outside a's 1..3",
    ),
    "index type": (
        "   VAR\n      a : ARRAY[1..3] OF Int;\n   END_VAR\n",
        "    #o := #a[#r];\n",
        "fb.scl:14:14: the index of 'a' must be an integer of up to 32 bits, not REAL",
    ),
    "index count": (
        "   VAR\n      a : ARRAY[1..3, 0..1] OF Int;\n   END_VAR\n",
        "    #o := #a[1];\n",
        "fb.scl:14:13: 'a' is an ARRAY[1..3, 0..1] OF INT: it takes 2 index(es), not 1",
    ),
    "index of a scalar": (
        "",
        "    #o := #i[1];\n",
        "fb.scl:11:13: 'i' is a INT, not an ARRAY: it takes no index",
    ),
    "array init too long": (
        "   VAR\n      a : ARRAY[0..1] OF Int := [1, 2, 3];\n   END_VAR\n",
        "",
        "fb.scl:11:33: the initial value of 'a': 3 values for the 2 of ARRAY[0..1] OF INT",
    ),
    # docs/scl.md rules: [S7-STRUCT]
    "struct member": (
        "   VAR\n      s : STRUCT x : Int; END_STRUCT;\n   END_VAR\n",
        "    #o := #s.y;\n",
        "fb.scl:14:11: 's' is a STRUCT: it has no member 'y'",
    ),
    "struct as number": (
        "   VAR\n      s : STRUCT x : Int; END_STRUCT;\n   END_VAR\n",
        "    #o := #s + 1;\n",
        "fb.scl:14:16: the + operand: an integer literal is no STRUCT",
    ),
    "unknown udt": (
        '   VAR\n      u : "Point";\n   END_VAR\n',
        "",
        "fb.scl:11:11: unknown or unsupported data type 'Point' of 'u'",
    ),
    # docs/scl.md rules: [S7-BIT]
    "bit number": (
        "   VAR\n      q : Bool;\n   END_VAR\n",
        "    #q := #i.%X16;\n",
        "fb.scl:14:13: 'i' is a INT: its bits are %X0 to %X15",
    ),
    "bit of a real": (
        "   VAR\n      q : Bool;\n   END_VAR\n",
        "    #q := #r.%X0;\n",
        "fb.scl:14:13: 'r' is a REAL: bit access .%X is on a bit string or integer",
    ),
    # docs/scl.md rules: [S7-SLICE]
    "slice number": (
        "   VAR\n      b : Byte;\n   END_VAR\n",
        "    #b := #i.%B2;\n",
        "fb.scl:14:13: 'i' is a INT: its bytes are %B0 to %B1",
    ),
    "slice of a real": (
        "   VAR\n      w : Word;\n   END_VAR\n",
        "    #w := #r.%W0;\n",
        "fb.scl:14:13: 'r' is a REAL: the slice .%W is on a bit string or integer",
    ),
    "slice as wide as its variable": (
        "   VAR\n      w : Word;\n   END_VAR\n",
        "    #w := #i.%W0;\n",
        "fb.scl:14:13: 'i' is a INT: the slice .%W is of a variable wider than a WORD",
    ),
    # docs/scl.md rules: [DEC-TYPE-64]
    "64-bit interface": (
        "   VAR_OUTPUT\n      big : LInt;\n   END_VAR\n",
        "",
        "fb.scl:11:13: LINT VAR_OUTPUT 'big': FMI 2.0 and the core have no 64-bit integer",
    ),
    "array of arrays": (
        "   VAR\n      a : ARRAY[0..1] OF ARRAY[0..1] OF Int;\n   END_VAR\n",
        "",
        "fb.scl:11:11: 'a': an ARRAY of ARRAYs; write ARRAY[a..b, c..d] OF ...",
    ),
    # docs/scl.md rules: [S7-ARRAY]
    "array too large": (
        "   VAR\n      a : ARRAY[0..70000] OF Bool;\n   END_VAR\n",
        "",
        "fb.scl:11:11: 'a': ARRAY[0..70000] OF BOOL has more than 65536 elements",
    ),
    "instance in a struct": (
        "   VAR\n      s : STRUCT t : TON; END_STRUCT;\n   END_VAR\n",
        "",
        "fb.scl:11:22: 's.t': an FB instance in a STRUCT",
    ),
    "struct initial value": (
        "   VAR\n      s : STRUCT x : Int; END_STRUCT := 5;\n   END_VAR\n",
        "",
        "fb.scl:11:41: the initial value of 's': a STRUCT takes (member := value, ...)",
    ),
    "struct initial member": (
        "   VAR\n      a : ARRAY[0..0] OF STRUCT x : Int; END_STRUCT := [(y := 1)];\n   END_VAR\n",
        "",
        "fb.scl:11:58: the initial value of 'a': STRUCT has no member 'y'",
    ),
    "repetition count": (
        "   VAR\n      a : ARRAY[0..1] OF Int := [0(1)];\n   END_VAR\n",
        "",
        "fb.scl:11:33: the initial value of 'a': a repetition count must be 1 or more",
    ),
    "table too long": (
        "   VAR_IN_OUT\n      t : ARRAY[*] OF Int := [65(1)];\n   END_VAR\n",
        "",
        "fb.scl:11:30: the initial value of 't': 65 values, the table holds 64",
    ),
    "table of two dimensions": (
        "   VAR_IN_OUT\n      t : ARRAY[*, *] OF Int;\n   END_VAR\n",
        "",
        "fb.scl:11:11: 't': an ARRAY[*, *] OF INT in/out of the FB compiled into the FMU",
    ),
    "bound of a scalar": (
        "",
        "    #o := DINT_TO_INT(UPPER_BOUND(ARR := #i, DIM := 1));\n",
        "fb.scl:11:42: UPPER_BOUND's ARR must be an ARRAY, not INT",
    ),
    "bound dimension": (
        "   VAR\n      a : ARRAY[0..1] OF Int;\n   END_VAR\n",
        "    #o := DINT_TO_INT(UPPER_BOUND(ARR := #a, DIM := 2));\n",
        "fb.scl:14:53: UPPER_BOUND's DIM must be a literal or a constant of the block from 1 to 1",
    ),
    "for over an element": (
        "   VAR\n      a : ARRAY[0..1] OF Int;\n   END_VAR\n",
        "    FOR #a[0] := 1 TO 2 DO END_FOR;\n",
        "fb.scl:14:9: the FOR variable must be a plain variable",
    ),
    # docs/scl.md rules: [S7-QRY-CINT]
    "qry_cint into an element": (
        "   VAR\n      a : ARRAY[0..1] OF UDInt;\n   END_VAR\n",
        "    #o := QRY_CINT(OB_NR := 30, CYCLE => #a[0]);\n",
        "fb.scl:14:33: QRY_CINT's CYCLE goes to a variable or member, not to an element",
    ),
    # docs/scl.md rules: [S7-OP-BITS]
    "struct as a bool": (
        "   VAR\n      s : STRUCT x : Int; END_STRUCT;\n   END_VAR\n",
        "    IF NOT #s THEN #o := 1; END_IF;\n",
        "fb.scl:14:8: NOT needs a BOOL or a bit string, not STRUCT",
    ),
    "array as a number": (
        "   VAR\n      a : ARRAY[0..2] OF Int;\n   END_VAR\n",
        "    #o := ABS(#a);\n",
        "fb.scl:14:15: ABS's argument: S7 converts no ARRAY[0..2] OF INT to DINT implicitly",
    ),
    # docs/scl.md rules: [S7-TIME-L]
    "ltime plus int": (
        "   VAR\n      lt : LTime;\n   END_VAR\n",
        "    #lt := #lt + 5;\n",
        "fb.scl:14:12: LTIME + an integer literal: LTIME takes + and - of LTIME",
    ),
    # docs/scl.md rules: [S7-FLOW-1]
    "case label": (
        "",
        "    CASE #i OF 1..3: #o := 1; 2: #o := 2; END_CASE;\n",
        "fb.scl:11:5: the CASE label 2..2 overlaps 1..3",
    ),
    # docs/scl.md rules: [S7-LIT-2]
    "bad time": ("", "    #o := TIME_TO_INT(T#1x);\n", "fb.scl:11:23: T#1x: not a TIME literal"),
    # docs/scl.md rules: [S7-TIME-1]
    "time in us": (
        "",
        "    #o := TIME_TO_INT(T#5us);\n",
        "fb.scl:11:23: T#5us: not a TIME literal",
    ),
    "bad ltime": ("", "    #o := 1;\n    #o := 2 + LT#5x;\n", "fb.scl:12:15: LT#5x: not an LTIME"),
    # docs/scl.md rules: [S7-SCALE]
    "scale_x to an integer": (
        "",
        "    #o := SCALE_X(MIN := 0, VALUE := 0.5, MAX := #i);\n",
        "fb.scl:11:11: SCALE_X to INT is not supported yet: Siemens' description leaves",
    ),
    "scale_x of booleans": (
        "",
        "    #o := SCALE_X(MIN := FALSE, VALUE := 0.5, MAX := TRUE);\n",
        "fb.scl:11:11: SCALE_X's MIN and MAX are numbers, not BOOL",
    ),
    "scale_x of an integer value": (
        "",
        "    #o := SCALE_X(MIN := #r, VALUE := #i, MAX := #r);\n",
        "fb.scl:11:39: SCALE_X's VALUE is a REAL or LREAL, not INT",
    ),
    "norm_x into an integer": (
        "",
        "    #o := NORM_X(MIN := 0, VALUE := #i, MAX := 10);\n",
        "fb.scl:11:11: the assignment to 'o': a real literal is no INT",
    ),
    # docs/scl.md rules: [S7-CONV-NONE]
    "conversion": (
        "",
        "    #o := REAL_TO_TIME(#r);\n",
        "fb.scl:11:11: REAL_TO_TIME: S7 has no conversion between REAL and TIME",
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_refusal_names_the_construct_at_its_place(tmp_path, case):
    declarations, body, expected = CASES[case]
    refuses(tmp_path, declarations, body, "", expected)


# docs/scl.md rules: [S7-STRUCT]
def test_a_udt_that_contains_itself(tmp_path):
    text = 'TYPE "Loop"\n   STRUCT\n      next : "Loop";\n   END_STRUCT;\nEND_TYPE\n' + fb(
        '   VAR\n      l : "Loop";\n   END_VAR\n', ""
    )
    message = refused(tmp_path, text)
    assert message == 'fb.scl:3:14: the UDT "Loop" contains itself'


# blocks after the FB of fb(): an FC of two inputs and an output, a VOID FC, an FB
BLOCKS = """FUNCTION "Two" : Int
   VAR_INPUT
      x : Int;
      y : Int;
   END_VAR
   VAR_OUTPUT
      z : Int;
   END_VAR
BEGIN
END_FUNCTION
FUNCTION "Nothing" : Void
BEGIN
END_FUNCTION
FUNCTION_BLOCK "Motor"
   VAR_INPUT
      start : Bool;
   END_VAR
   VAR
      calls : Int;
   END_VAR
BEGIN
END_FUNCTION_BLOCK
"""
STATIC_M = '   VAR\n      m : "Motor";\n   END_VAR\n'

# (declarations, body, blocks after the FB, the message's start) for calls and functions
CALL_CASES = {
    # docs/scl.md rules: [S7-RECURSION]
    "fc recursion": (
        "",
        '    #o := "Rec"(#i);\n',
        'FUNCTION "Rec" : Int\n   VAR_INPUT\n      x : Int;\n   END_VAR\nBEGIN\n'
        '    #Rec := "Rec"(#x);\nEND_FUNCTION\n',
        "fb.scl:18:13: Rec calls itself (Rec -> Rec): S7 has no recursion",
    ),
    # docs/scl.md rules: [S7-RECURSION]
    "fb recursion": (
        '   VAR\n      m : "Inner";\n   END_VAR\n',
        "",
        'FUNCTION_BLOCK "Inner"\n   VAR\n      f : "Fb";\n   END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n',
        "fb.scl:17:11: Fb calls itself (Fb -> Inner -> Fb): S7 has no recursion",
    ),
    # docs/scl.md rules: [S7-FC]
    "fc input missing": (
        "",
        '    #o := "Two"(x := 1);\n',
        BLOCKS,
        'fb.scl:11:11: "Two" needs y: an FC has no instance data',
    ),
    "fc positional count": (
        "",
        '    #o := "Two"(1);\n',
        BLOCKS,
        'fb.scl:11:11: "Two" takes 2 inputs (x, y), not 1',
    ),
    "fc output type": (
        "   VAR\n      s : DInt;\n   END_VAR\n",
        '    #o := "Two"(x := 1, y := 2, z => #s);\n',
        BLOCKS,
        "fb.scl:14:38: \"Two\"'s output z is a INT; 's' is a DINT",
    ),
    # docs/scl.md rules: [S7-FC]
    "void as value": (
        "",
        '    #o := "Nothing"();\n',
        BLOCKS,
        'fb.scl:11:11: "Nothing" is a FUNCTION : Void, it has no value',
    ),
    # docs/scl.md rules: [S7-NAMES]
    "fb called as a function": (
        "",
        '    #o := "Motor"(start := TRUE);\n',
        BLOCKS,
        "fb.scl:11:11: Motor is a FUNCTION_BLOCK: declare an instance of it",
    ),
    "fc as an instance": (
        '   VAR\n      f : "Two";\n   END_VAR\n',
        "",
        BLOCKS,
        "fb.scl:11:11: Two is a FUNCTION: it has no instance",
    ),
    "instance as a value": (
        STATIC_M,
        "    #o := #m;\n",
        BLOCKS,
        "fb.scl:14:11: the Motor instance 'm' is not a value: use #m.<output>",
    ),
    # docs/scl.md rules: [S7-FB]
    "static of an instance": (
        STATIC_M,
        "    #o := #m.calls;\n",
        BLOCKS,
        "fb.scl:14:11: Motor has no input or output 'calls'",
    ),
    "statics in an fc": (
        "",
        '    #o := "Stat"(1);\n',
        'FUNCTION "Stat" : Int\n   VAR\n      s : Int;\n   END_VAR\n'
        "   VAR_INPUT\n      x : Int;\n   END_VAR\nBEGIN\nEND_FUNCTION\n",
        "fb.scl:15:7: the FUNCTION Stat has no instance data, so no statics",
    ),
    # docs/scl.md rules: [S7-MUX]
    "mux selector": (
        "",
        "    #o := MUX(K := #r, IN0 := 1, IN1 := 2);\n",
        "",
        "fb.scl:11:20: MUX's K must be an integer, not REAL",
    ),
    # docs/scl.md rules: [S7-SHIFT]
    "shift of a literal": (
        "",
        "    #o := SHL(IN := 5, N := 1);\n",
        "",
        "fb.scl:11:11: SHL of an untyped literal: give it its type",
    ),
    # docs/scl.md rules: [S7-FN-REAL]
    "power of an integer": (
        "",
        "    #o := #i ** 2;\n",
        "",
        "fb.scl:11:11: ** needs a REAL or LREAL base, not INT",
    ),
    "sqr of an integer": (
        "",
        "    #o := REAL_TO_INT(SQR(#i));\n",
        "",
        "fb.scl:11:23: SQR needs a REAL or LREAL, not INT",
    ),
    # docs/scl.md rules: [S7-FN-REAL]
    "exp of an integer": (
        "",
        "    #o := REAL_TO_INT(EXP(#i));\n",
        "",
        "fb.scl:11:23: EXP needs a REAL or LREAL, not INT",
    ),
    "rd_sys_t target": (
        "",
        "    #o := RD_SYS_T(OUT => #i);\n",
        "",
        "fb.scl:11:20: RD_SYS_T's OUT is a DTL variable or member; 'i' is not",
    ),
    "runtime memory": (
        "   VAR\n      m : Real;\n   END_VAR\n",
        "    #o := LREAL_TO_INT(RUNTIME(#m));\n",
        "",
        "fb.scl:14:32: RUNTIME's MEM is an LREAL; 'm' is a REAL",
    ),
    "clock parameter name": (
        "   VAR\n      now : DTL;\n      startDateAndTime : LReal;\n   END_VAR\n",
        "    RD_SYS_T(OUT => #now);\n",
        "",
        "fb.scl:12:7: 'startDateAndTime' is the FMU's own parameter of RD_SYS_T/RD_LOC_T",
    ),
    "counter parameter": (
        "   VAR\n      c : CTU;\n   END_VAR\n",
        "    #c(CU := TRUE, PV := 3, LD := TRUE);\n",
        "",
        "fb.scl:14:29: CTU_INT has no input 'LD' (CU, R, PV)",
    ),
}


DATA = 'DATA_BLOCK "Data"\nVAR\n   v : Int;\nEND_VAR\nBEGIN\n'
# (declarations, body, the sources after the FB, the message's start) of DBs (docs/scl.md §3.9)
DB_CASES = {
    # docs/scl.md rules: [S7-DB-INST]
    "two timers on one db": (
        "",
        '    "T_DB".TON(IN := TRUE, PT := T#1s);\n    "T_DB".TOF(IN := TRUE, PT := T#1s);\n',
        "",
        'fb.scl:11:5: the IEC_TIMER DB "T_DB" must run one timer, "T_DB".TON/TOF/TP(...), '
        "not TOF, TON",
    ),
    "a timer db called as an fb": (
        "",
        '    "T_DB".TP(IN := TRUE, PT := T#1s);\n    "T_DB"(IN := TRUE);\n',
        "",
        'fb.scl:12:5: "T_DB" is an IEC_TIMER DB: call it as "T_DB".TP(...)',
    ),
    "a timer on an fb's db": (
        "",
        '    "C_DB".TON(IN := TRUE, PT := T#1s);\n',
        'DATA_BLOCK "C_DB"\n"Inner"\nBEGIN\nEND_DATA_BLOCK\n'
        'FUNCTION_BLOCK "Inner"\nBEGIN\nEND_FUNCTION_BLOCK\n',
        'fb.scl:11:5: "C_DB".TON(...): "C_DB" is the DB of Inner',
    ),
    "the db of no fb": (
        "",
        '    "C_DB"();\n',
        'DATA_BLOCK "C_DB"\n"Nothing"\nBEGIN\nEND_DATA_BLOCK\n',
        'fb.scl:13:1: the DB "C_DB" is an instance of Nothing, which is no FB of the sources',
    ),
    # docs/scl.md rules: [S7-DB-GLOBAL]
    "a start value of no member": (
        "",
        '    #o := "Data".v;\n',
        DATA + "   w := 1;\nEND_DATA_BLOCK\n",
        "fb.scl:18:4: the DB \"Data\" has no member 'w'",
    ),
    "a quoted name of no db": (
        "",
        '    #o := "Nowhere".v;\n',
        "",
        "fb.scl:11:11: 'Nowhere' is not",
    ),
}


def test_a_missing_block_names_the_blocks_there_are(tmp_path):
    message = refused(tmp_path, fb("", ""), block="Motor")
    assert message == "no block 'Motor' in the sources (they define: Fb)"


TWICE = 'FUNCTION "Twice" : Int\n   VAR_INPUT\n      x : Int;\n   END_VAR\nBEGIN\nEND_FUNCTION\n'


def test_a_function_is_not_an_fmu(tmp_path):
    text = TWICE
    message = refused(tmp_path, text, block="Twice")
    assert message == "fb.scl:1:1: Twice: only a FUNCTION_BLOCK becomes an FMU"


STRUCT_M = '   VAR\n      s : STRUCT\n         m : "Motor";\n      END_STRUCT;\n   END_VAR\n'

# (declarations, body, blocks after the FB, the message's start) where calls meet data structures
MEET_CASES = {
    "instance in a struct": (
        STRUCT_M,
        "",
        BLOCKS,
        "fb.scl:12:14: 's.m': an FB instance in a STRUCT",
    ),
    "struct input of a used fb": (
        '   VAR\n      sp : "Sp";\n   END_VAR\n',
        "",
        'FUNCTION_BLOCK "Sp"\n   VAR_INPUT\n      p : STRUCT\n         x : Int;\n'
        "      END_STRUCT;\n   END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n",
        "fb.scl:17:11: the STRUCT VAR_INPUT 'p' of Sp: the inputs and outputs of an FB's "
        "instance are elementary",
    ),
    "array return type": (
        "",
        '    #o := "Arr"();\n',
        'FUNCTION "Arr" : Array[1..2] of Int\nBEGIN\nEND_FUNCTION\n',
        "fb.scl:13:1: the FUNCTION Arr : ARRAY: unsupported return type",
    ),
    # docs/scl.md rules: [S7-FC-DATA]
    "fc output to a bit": (
        "   VAR\n      w : Word;\n   END_VAR\n",
        '    "Two"(x := 1, y := 2, z => #w.%X1);\n',
        BLOCKS,
        'fb.scl:14:32: "Two"\'s output z goes to a variable, member or element, not to a bit',
    ),
    "runtime memory at a run-time index": (
        "   VAR\n      mems : Array[1..2] of LReal;\n   END_VAR\n",
        "    #o := LREAL_TO_INT(RUNTIME(#mems[#i]));\n",
        "",
        "fb.scl:14:32: RUNTIME's MEM is a variable, a member or an element at a literal index",
    ),
}


def var(section: str, *lines: str) -> str:
    """A section of declarations for fb(): its header at line 10, the first declaration at line
    11, one a line."""
    return f"   {section}\n" + "".join(f"      {x}\n" for x in lines) + "   END_VAR\n"


TON_T = var("VAR", "t : TON;")  # t at line 11, the body from line 14
NOW = var("VAR", "now : DTL;")
UINT_U = var("VAR", "u : UInt;")

# (declarations, body, blocks after the FB, the message's start): a refusal of every other check
# of the compiler (tests/scl/test_refusals.py requires every refusal site to be reached)
MORE_CASES = {
    # built-ins: conversions, shifts, MUX (docs/scl.md §3.3, §3.5)
    "conversion to itself": (
        "",
        "    #o := INT_TO_INT(#i);\n",
        "",
        "fb.scl:11:11: unknown conversion",
    ),
    "bool to time": (
        "",
        "    #o := TIME_TO_INT(BOOL_TO_TIME(TRUE));\n",
        "",
        "fb.scl:11:23: BOOL_TO_TIME: S7 has no conversion between BOOL and TIME",
    ),
    "shift of a real": (
        "",
        "    #o := REAL_TO_INT(SHL(IN := #r, N := 1));\n",
        "",
        "fb.scl:11:23: SHL needs a bit string or an integer, not REAL",
    ),
    # docs/scl.md rules: [S7-SWAP]
    "swap of an int": (
        "",
        "    #o := SWAP(#i);\n",
        "",
        "fb.scl:11:11: SWAP needs a WORD, DWORD or LWORD, not INT",
    ),
    "mux output": (
        "",
        "    #o := MUX(K := 0, IN0 := 1, IN1 => #o);\n",
        "",
        "fb.scl:11:11: MUX has no outputs: its value is the input selected",
    ),
    "mux mixed": (
        "",
        "    #o := MUX(0, IN0 := 1);\n",
        "",
        "fb.scl:11:11: MUX: name every parameter (K := ..., IN0 := ...) or none",
    ),
    "mux twice": (
        "",
        "    #o := MUX(K := 0, IN0 := 1, IN0 := 2);\n",
        "",
        "fb.scl:11:33: MUX: 'IN0' is given twice",
    ),
    "mux unknown input": (
        "",
        "    #o := MUX(K := 0, IN0 := 1, X := 2);\n",
        "",
        "fb.scl:11:33: MUX has no input 'X' (K, IN0, IN1, ..., INELSE)",
    ),
    "mux gap": (
        "",
        "    #o := MUX(K := 0, IN0 := 1, IN2 := 2);\n",
        "",
        "fb.scl:11:11: MUX needs K and IN0, IN1, ... without a gap",
    ),
    "mux of one": (
        "",
        "    #o := MUX(K := 0, IN0 := 1);\n",
        "",
        "fb.scl:11:11: MUX needs two inputs or more (IN0, IN1, ...)",
    ),
    # built-ins: numbers (§3.5)
    "max of bools": (
        "",
        "    #o := BOOL_TO_INT(MAX(TRUE, FALSE));\n",
        "",
        "fb.scl:11:23: MAX needs numbers, not BOOL",
    ),
    "abs of an unsigned": (
        UINT_U,
        "    #u := ABS(#u);\n",
        "",
        "fb.scl:14:11: ABS of an unsigned UINT",
    ),
    "max without a common type": (
        "",
        "    #o := MAX(TRUE, #i);\n",
        "",
        "fb.scl:11:11: MAX: BOOL and INT have no common type; convert with *_TO_*",
    ),
    "builtin output": (
        "",
        "    #o := ABS(IN => #i);\n",
        "",
        "fb.scl:11:15: ABS has no output 'IN'",
    ),
    "builtin positional after named": (
        "",
        "    #o := LIMIT(MN := 0, #i, 5);\n",
        "",
        "fb.scl:11:26: LIMIT: name the arguments (MN, IN, MX := ...)",
    ),
    "builtin unknown input": (
        "",
        "    #o := ABS(X := #i);\n",
        "",
        "fb.scl:11:15: ABS has no input 'X' (it takes IN)",
    ),
    "builtin input twice": (
        "",
        "    #o := LIMIT(MN := 0, MN := 1, IN := #i, MX := 5);\n",
        "",
        "fb.scl:11:26: LIMIT: 'MN' is given twice",
    ),
    "builtin input missing": (
        "",
        "    #o := LIMIT(MN := 0, IN := #i);\n",
        "",
        "fb.scl:11:11: LIMIT needs MX",
    ),
    # built-ins of arrays and the CPU (§3.6, §3.8)
    "bound of a literal": (
        "",
        "    #o := DINT_TO_INT(UPPER_BOUND(ARR := 5, DIM := 1));\n",
        "",
        "fb.scl:11:42: UPPER_BOUND's ARR must be an ARRAY variable",
    ),
    "rd_sys_t without out": (
        "",
        "    #o := RD_SYS_T();\n",
        "",
        "fb.scl:11:11: RD_SYS_T needs OUT => #dtl (a DTL)",
    ),
    "rd_sys_t input": (
        "",
        "    #o := RD_SYS_T(OUT := #i);\n",
        "",
        "fb.scl:11:20: RD_SYS_T takes OUT => #dtl (a DTL) only",
    ),
    "runtime of two": (
        "",
        "    #o := LREAL_TO_INT(RUNTIME(#r, #r));\n",
        "",
        "fb.scl:11:24: RUNTIME takes one LREAL variable",
    ),
    "runtime of a literal": (
        "",
        "    #o := LREAL_TO_INT(RUNTIME(1.5));\n",
        "",
        "fb.scl:11:32: RUNTIME's MEM must be a variable",
    ),
    "qry_cint output": (
        "",
        "    #o := QRY_CINT(OB_NR := 30, X => #d);\n",
        "",
        "fb.scl:11:33: QRY_CINT has no output 'X' (CYCLE, PHASE, STATUS)",
    ),
    "qry_cint output type": (
        var("VAR", "dd : DInt;"),
        "    #o := QRY_CINT(OB_NR := 30, CYCLE => #dd);\n",
        "",
        "fb.scl:14:33: QRY_CINT's CYCLE is a UDINT; 'dd' is a DINT",
    ),
    "qry_cint ob number": (
        "",
        "    #o := QRY_CINT(OB_NR := #r);\n",
        "",
        "fb.scl:11:20: QRY_CINT's OB_NR is a number, not REAL",
    ),
    "qry_cint input": (
        "",
        "    #o := QRY_CINT(X := 1);\n",
        "",
        "fb.scl:11:20: QRY_CINT takes OB_NR := and CYCLE =>, PHASE =>, STATUS =>",
    ),
    # expressions (§3.2-§3.4)
    "constant written": (
        var("VAR CONSTANT", "k : Int := 1;"),
        "    #k := 2;\n",
        "",
        "fb.scl:14:5: 'k' is a constant",
    ),
    "literal of no type": (
        "",
        "    #o := FOO#5;\n",
        "",
        "fb.scl:11:11: FOO#5: unknown literal type FOO",
    ),
    "real int literal": (
        "",
        "    #o := INT#1.5;\n",
        "",
        "fb.scl:11:11: INT#1.5: a INT literal must be a whole number",
    ),
    "typed literal too big": (
        "",
        "    #o := INT#40000;\n",
        "",
        "fb.scl:11:11: INT#40000 does not fit INT (-32768 to 32767)",
    ),
    "typed real too big": (
        "",
        "    #o := REAL_TO_INT(REAL#1e39);\n",
        "",
        "fb.scl:11:23: REAL#1e39 is beyond the largest REAL",
    ),
    "real and bool": (
        "",
        "    #o := BOOL_TO_INT(#r = TRUE);\n",
        "",
        "fb.scl:11:23: REAL = BOOL: S7 converts neither operand to the other's type implicitly",
    ),
    "integer literal as bool": (
        var("VAR", "b : Bool;"),
        "    #b := 1;\n",
        "",
        "fb.scl:14:11: the assignment to 'b': an integer literal is no BOOL",
    ),
    "minus of an unsigned": (
        UINT_U,
        "    #u := -#u;\n",
        "",
        "fb.scl:14:11: unary minus needs a signed number or TIME, not UINT",
    ),
    "and of literals": (
        "",
        "    #o := BOOL_TO_INT(1 AND 2);\n",
        "",
        "fb.scl:11:23: AND of two untyped literals: give one a type (INT#..)",
    ),
    "sum of bools": (
        "",
        "    #o := BOOL_TO_INT(TRUE + FALSE);\n",
        "",
        "fb.scl:11:23: + needs numbers, not BOOL",
    ),
    "mod of reals": (
        var("VAR", "x : Real;"),
        "    #x := #r MOD #r;\n",
        "",
        "fb.scl:14:11: MOD needs integers, not REAL",
    ),
    "bools ordered": (
        "",
        "    #o := BOOL_TO_INT(TRUE < FALSE);\n",
        "",
        "fb.scl:11:23: BOOL values compare with = and <> only, not <",
    ),
    "and of integers": (
        "",
        "    #o := #i AND #i;\n",
        "",
        "fb.scl:11:11: AND needs BOOL or bit strings, not INT",
    ),
    "bool exponent": (
        "",
        "    #o := REAL_TO_INT(#r ** TRUE);\n",
        "",
        "fb.scl:11:23: the exponent of ** must be a number, not BOOL",
    ),
    "instance call as a value": (
        TON_T,
        "    #o := BOOL_TO_INT(#t(IN := TRUE, PT := T#1s));\n",
        "",
        "fb.scl:14:23: the instance call #t(...) is a statement, not a value",
    ),
    "member of a member of an instance": (
        TON_T,
        "    #o := BOOL_TO_INT(#t.Q.x);\n",
        "",
        "fb.scl:14:23: 't': TON has members .Q, .IN, ... only",
    ),
    "member of no system fb": (
        TON_T,
        "    #o := BOOL_TO_INT(#t.XYZ);\n",
        "",
        "fb.scl:14:23: TON has no member 'XYZ'",
    ),
    # docs/scl.md rules: [S7-TYPE-DTL]
    "dtl into an int": (
        NOW,
        "    #o := #now;\n",
        "",
        "fb.scl:14:11: the assignment to 'o': S7 converts no DTL to INT implicitly",
    ),
    # docs/scl.md rules: [S7-DTL-OP] [S7-T-ADD] [S7-DTL-CONV]
    "dtl plus an integer": (
        NOW,
        "    #now := #now + 1;\n",
        "",
        "fb.scl:14:13: DTL + an integer literal: a DTL compares with a DTL, takes + and -",
    ),
    "t_add of an integer": (
        NOW,
        "    #now := T_ADD(IN1 := #i, IN2 := T#1s);\n",
        "",
        "fb.scl:14:26: T_ADD's IN1 is a DTL or a TIME, not INT",
    ),
    "t_diff of a time": (
        NOW,
        "    #o := TIME_TO_INT(T_DIFF(IN1 := #now, IN2 := T#1s));\n",
        "",
        "fb.scl:14:50: T_DIFF's IN2 is a DTL, not TIME",
    ),
    "dtl_to_date of two": (
        NOW,
        "    #o := DATE_TO_INT(DTL_TO_DATE(#now, #now));\n",
        "",
        "fb.scl:14:23: DTL_TO_DATE takes one DTL: DTL_TO_DATE(IN := ...)",
    ),
    "date_to_dtl of an int": (
        NOW,
        "    #now := DATE_TO_DTL(#i);\n",
        "",
        "fb.scl:14:25: DATE_TO_DTL's argument: S7 converts no INT to DATE implicitly",
    ),
    "dint_to_tod": (
        "",
        "    #o := TOD_TO_INT(DINT_TO_TOD(#d));\n",
        "",
        "fb.scl:11:11: TOD_TO_INT: TIME_OF_DAY to INT is not in the subset",
    ),
    "dtl member": (
        NOW,
        "    #o := USINT_TO_INT(#now.CENTURY);\n",
        "",
        "fb.scl:14:24: 'now' is a DTL: it has no member 'CENTURY'",
    ),
    # statements (§3.4, §3.6)
    "case of a real": (
        "",
        "    CASE #r OF 1: #o := 1; END_CASE;\n",
        "",
        "fb.scl:11:10: the CASE selector must be an integer or bit string, not REAL",
    ),
    "case label beyond the type": (
        var("VAR", "s : SInt;"),
        "    CASE #s OF 200: #o := 1; END_CASE;\n",
        "",
        "fb.scl:14:5: the CASE label 200..200 is not a range of SINT",
    ),
    "for over a real": (
        var("VAR", "x : Real;"),
        "    FOR #x := 1 TO 2 DO END_FOR;\n",
        "",
        "fb.scl:14:9: the FOR variable must be a SINT, INT or DINT, not REAL",
    ),
    "call of an integer": ("", "    #i();\n", "", "fb.scl:11:5: 'i' is a INT, not an FB instance"),
    "call of nothing": (
        "",
        "    #nothing();\n",
        "",
        "fb.scl:11:5: 'nothing' is not declared in Fb",
    ),
    "instance positional": (
        TON_T,
        "    #t(TRUE);\n",
        "",
        "fb.scl:14:8: TON 't': name the parameters (IN := ...)",
    ),
    "instance input twice": (
        TON_T,
        "    #t(IN := TRUE, IN := FALSE);\n",
        "",
        "fb.scl:14:20: 'IN' is given twice",
    ),
    "instance output": (
        TON_T,
        "    #t(IN := TRUE, X => #o);\n",
        "",
        "fb.scl:14:20: TON has no output 'X' (Q, ET)",
    ),
    "instance output type": (
        TON_T,
        "    #t(IN := TRUE, ET => #o);\n",
        "",
        "fb.scl:14:20: TON's ET is a TIME, 'o' a INT",
    ),
    "reset_timer of two": (
        TON_T,
        "    RESET_TIMER(#t, #t);\n",
        "",
        "fb.scl:14:5: RESET_TIMER takes one timer: RESET_TIMER(#inst)",
    ),
    "reset_timer of an integer": (
        "",
        "    RESET_TIMER(#i);\n",
        "",
        "fb.scl:11:17: RESET_TIMER's TIMER must be a TON, TOF or TP instance",
    ),
    "reset_timer as a value": (
        TON_T,
        "    #o := BOOL_TO_INT(RESET_TIMER(#t));\n",
        "",
        "fb.scl:14:23: RESET_TIMER has no value: call it as a statement",
    ),
    "a timer run on an integer": (
        "",
        "    #i.TON(IN := TRUE, PT := T#1s);\n",
        "",
        "fb.scl:11:5: #i.TON(...): 'i' is no IEC_TIMER",
    ),
    "an iec_timer static of two timers": (
        var("VAR", "x : IEC_TIMER;"),
        "    #x.TON(IN := TRUE, PT := T#1s);\n    #x.TOF(IN := TRUE, PT := T#1s);\n",
        "",
        "fb.scl:11:7: the IEC_TIMER 'x' must run one timer, #x.TON/TOF/TP(...), not TOF, TON",
    ),
    # FC calls (§3.7)
    "fc mixed": (
        "",
        '    #o := "Two"(1, y := 2);\n',
        BLOCKS,
        'fb.scl:11:11: "Two": name every parameter',
    ),
    "fc input twice": (
        "",
        '    #o := "Two"(x := 1, x := 2, y := 3);\n',
        BLOCKS,
        "fb.scl:11:25: \"Two\": 'x' is given twice",
    ),
    "fc unknown input": (
        "",
        '    #o := "Two"(x := 1, y := 2, w := 3);\n',
        BLOCKS,
        "fb.scl:11:33: \"Two\" has no input 'w' (inputs: x, y)",
    ),
    "fc unknown output": (
        "",
        '    #o := "Two"(x := 1, y := 2, v => #o);\n',
        BLOCKS,
        "fb.scl:11:33: \"Two\" has no output 'v' (outputs: z)",
    ),
    "fc return name": (
        "",
        '    #o := "Same"(1);\n',
        'FUNCTION "Same" : Int\n   VAR_INPUT\n      same : Int;\n   END_VAR\nBEGIN\nEND_FUNCTION\n',
        "fb.scl:15:7: 'same' is the name of its FUNCTION",
    ),
    # declarations and types (§2, §3.1, §3.8, §3.9)
    "name with a control character": (  # [DEC-NAME-C]
        var("VAR", '"a\tb" : Int;'),
        "",
        "",
        "fb.scl:11:7: 'a\\tb': a name holds no control character (line break, tab)",
    ),
    "cycle time declared": (
        var("VAR", "cycleTime : Real;"),
        "",
        "",
        "fb.scl:11:7: 'cycleTime' is the FMU's own parameter",
    ),
    "max cycle time declared": (  # [DEC-WATCHDOG]
        var("VAR_INPUT", "maxCycleTime : Time;"),
        "",
        "",
        "fb.scl:11:7: 'maxCycleTime' is the FMU's own parameter of the cycle watchdog",
    ),
    "instance db start value of no member": (  # [S7-DB-START]
        "",
        '    "M_DB"(start := TRUE);\n',
        'DATA_BLOCK "M_DB"\n"Motor"\nBEGIN\n   stop := TRUE;\nEND_DATA_BLOCK\n' + BLOCKS,
        "fb.scl:16:4: the FB Motor of \"M_DB\" has no input, output or static 'stop'",
    ),
    "instance db start value of an instance": (  # [S7-DB-START]
        "",
        '    "D_DB"();\n',
        'DATA_BLOCK "D_DB"\n"Delay"\nBEGIN\n   t := 1;\nEND_DATA_BLOCK\n'
        'FUNCTION_BLOCK "Delay"\n   VAR\n      t : TON;\n   END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n',
        "fb.scl:16:4: the instance DB \"D_DB\": a start value of 't', a TON: only of an "
        "elementary member",
    ),
    "instance db start value of a wrong type": (  # [S7-DB-START]
        "",
        '    "M_DB"(start := TRUE);\n',
        'DATA_BLOCK "M_DB"\n"Motor"\nBEGIN\n   calls := 1.5;\nEND_DATA_BLOCK\n' + BLOCKS,
        "fb.scl:16:13: the start value of M_DB.calls",
    ),
    "array as an int's value": (
        var("VAR", "x : Int := [1, 2];"),
        "",
        "",
        "fb.scl:11:18: the initial value of 'x': INT takes a literal",
    ),
    "initial value of a variable": (
        var("VAR", "x : Int := #i;"),
        "",
        "",
        "fb.scl:11:18: the initial value of 'x' must be a literal or a constant of the block",
    ),
    "instance as a temporary": (
        var("VAR_TEMP", "t : TON;"),
        "",
        "",
        "fb.scl:11:7: the TON instance 't' must be a static (VAR)",
    ),
    "instance initial value": (
        var("VAR", "t : TON := 1;"),
        "",
        "",
        "fb.scl:11:18: the TON instance 't' takes no initial value",
    ),
    "dtl initial value": (
        var("VAR", "now : DTL := 1;"),
        "",
        "",
        "fb.scl:11:20: the initial value of 'now': a DTL takes DTL#... or (member := value, ...)",
    ),
    "struct member twice": (
        var("VAR", "s : STRUCT x : Int; x : Int; END_STRUCT;"),
        "",
        "",
        "fb.scl:11:27: 's' has two members 'x'",
    ),
    "table in a struct": (
        var("VAR", "s : STRUCT a : ARRAY[*] OF Int; END_STRUCT;"),
        "",
        "",
        "fb.scl:11:22: 's.a': ARRAY[*] in a STRUCT",
    ),
    "array from a literal": (
        var("VAR", "a : ARRAY[0..1] OF Int := 5;"),
        "",
        "",
        "fb.scl:11:33: the initial value of 'a': an ARRAY takes [value, count(value), ...]",
    ),
    "array bounds beyond dint": (
        var("VAR", "a : ARRAY[0..3000000000] OF Bool;"),
        "",
        "",
        "fb.scl:11:11: 'a': ARRAY bounds are DINTs",
    ),
    "struct initial member twice": (
        var("VAR", "s : STRUCT x : Int; END_STRUCT := (x := 1, x := 2);"),
        "",
        "",
        "fb.scl:11:50: the initial value of 's': 'x' is given twice",
    ),
}


# every case of (declarations, body, the sources after the FB, the message's start)
AFTER_CASES = {**CALL_CASES, **DB_CASES, **MEET_CASES, **MORE_CASES}


@pytest.mark.parametrize("case", sorted(AFTER_CASES))
def test_refusal_with_the_sources_after_names_it_at_its_place(tmp_path, case):
    """Calls, DBs (docs/scl.md §3.9), calls where they meet data structures, every other check."""
    refuses(tmp_path, *AFTER_CASES[case])


def test_the_end_of_the_file(tmp_path):
    message = refused(tmp_path, 'FUNCTION_BLOCK "Fb"\nBEGIN\n')
    assert message.startswith("fb.scl:3:1: unexpected end of file; expected ")


def test_a_block_defined_twice(tmp_path):
    message = refused(tmp_path, fb("", "") + fb("", ""))
    assert message == "fb.scl:12:1: Fb is defined twice"  # fb() is 11 lines without a body


def test_text_before_the_first_block_is_not_scl(tmp_path):
    """A source of blocks with a character before them (a file edited after its export)."""
    assert refused(tmp_path, "1" + fb("", "")) == (
        "fb.scl:1:1: '1' before the first block (an SCL source holds blocks only): the source is "
        "not valid SCL (docs/scl.md §6)"
    )


def test_a_variable_as_a_data_type_is_not_scl(tmp_path):
    """A variable's name where a data type stands (a file edited after its export)."""
    text = fb("   VAR CONSTANT\n      MASK : d := 1;\n   END_VAR\n", "")
    assert refused(tmp_path, text) == (
        "fb.scl:11:14: 'd', the data type of 'MASK', is a variable of the block, not a data "
        "type: the source is not valid SCL (docs/scl.md §6)"
    )
