"""What the compiler refuses (docs/scl.md §5): each refusal `file:line:col: message` names the
construct (with the S7 rule where one applies), before any C is generated. How the errors are
reported together (codes, source lines, notes, the command line) is test_diagnostics.py's."""

from __future__ import annotations

import pytest

from lgf_fmus import scl
from lgf_fmus.scl import SclError


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
    source = tmp_path / "fb.scl"
    source.write_text(text, encoding="utf-8")
    with pytest.raises(SclError) as caught:
        scl.generate_c([source], block=block)
    first = caught.value.diagnostics[0]
    where = f"{first.loc}: " if first.loc is not None else ""
    return (where + first.message).replace(str(source), "fb.scl")


# (declarations, body, the message's start: file:line:col and the words it must hold)
CASES = {
    "syntax": ("", "    #o := ;\n", "fb.scl:11:11: unexpected ';'"),
    "writing the calling ob": (
        "   VAR_INPUT\n      callOB : OB_CYCLIC;\n   END_VAR\n",
        "    #callOB := 5;\n",
        "fb.scl:14:5: 'callOB' is an input, set by the importer at every call",
    ),
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
    "narrowing": (
        "",
        "    #o := #d;\n",
        "fb.scl:11:11: the assignment to 'o': S7 converts no DINT to INT implicitly; "
        "write DINT_TO_INT(...)",
    ),
    "real to int": (
        "",
        "    #o := #r;\n",
        "fb.scl:11:11: the assignment to 'o': S7 converts no REAL",
    ),
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
    "exit": ("", "    EXIT;\n", "fb.scl:11:5: EXIT outside FOR, WHILE or REPEAT"),
    "unknown type": (
        "   VAR\n      s : Strung;\n   END_VAR\n",
        "",
        "fb.scl:11:11: unknown or unsupported data type 'Strung' of 's'",
    ),
    "string": (
        "   VAR\n      s : String;\n   END_VAR\n",
        "",
        "fb.scl:11:11: STRING is not supported yet (docs/scl.md §6)",
    ),
    "sized string": (
        "   VAR\n      s : WString[20];\n   END_VAR\n",
        "",
        "fb.scl:11:11: WSTRING is not supported yet (docs/scl.md §6)",
    ),
    "unknown function": (
        "",
        "    #o := FOO(#i);\n",
        "fb.scl:11:11: unknown or unsupported function 'FOO'",
    ),
    "input written": ("", "    #i := 1;\n", "fb.scl:11:5: 'i' is an input"),
    "time plus int": (
        "   VAR\n      t : Time;\n   END_VAR\n",
        "    #t := #t + 5;\n",
        "fb.scl:14:11: TIME + an integer literal: TIME takes + and - of TIME",
    ),
    "condition": (
        "",
        "    IF #i THEN #o := 1; END_IF;\n",
        "fb.scl:11:8: the IF condition: S7 converts no INT to BOOL implicitly",
    ),
    "timer argument": (
        "   VAR\n      t : TON;\n   END_VAR\n",
        "    #t(IN := TRUE, PX := T#1s);\n",
        "fb.scl:14:20: TON has no input 'PX' (IN, PT)",
    ),
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
        "fb.scl:11:12: 'io': an ARRAY or STRUCT of TON instances",
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
    "array star outside in_out": (
        "   VAR\n      a : ARRAY[*] OF Int;\n   END_VAR\n",
        "",
        "fb.scl:11:11: 'a': ARRAY[*] is only a VAR_IN_OUT's type",
    ),
    "array bounds": (
        "   VAR\n      a : ARRAY[3..1] OF Int;\n   END_VAR\n",
        "",
        "fb.scl:11:11: 'a': ARRAY[3..1]: the low bound is above the high",
    ),
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
    "array of instances": (
        "   VAR\n      a : ARRAY[0..1] OF TON;\n   END_VAR\n",
        "",
        "fb.scl:11:11: 'a': an ARRAY or STRUCT of TON instances",
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
        "fb.scl:11:11: 't': ARRAY[*] of one dimension only is supported",
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
    "qry_cint into an element": (
        "   VAR\n      a : ARRAY[0..1] OF UDInt;\n   END_VAR\n",
        "    #o := QRY_CINT(OB_NR := 30, CYCLE => #a[0]);\n",
        "fb.scl:14:33: QRY_CINT's CYCLE goes to a variable or member, not to an element",
    ),
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
    "ltime plus int": (
        "   VAR\n      lt : LTime;\n   END_VAR\n",
        "    #lt := #lt + 5;\n",
        "fb.scl:14:12: LTIME + an integer literal: LTIME takes + and - of LTIME",
    ),
    "case label": (
        "",
        "    CASE #i OF 1..3: #o := 1; 2: #o := 2; END_CASE;\n",
        "fb.scl:11:5: the CASE label 2..2 overlaps 1..3",
    ),
    "bad time": ("", "    #o := TIME_TO_INT(T#1x);\n", "fb.scl:11:23: T#1x: not a TIME literal"),
    "time in us": (
        "",
        "    #o := TIME_TO_INT(T#5us);\n",
        "fb.scl:11:23: T#5us: not a TIME literal",
    ),
    "bad ltime": ("", "    #o := 1;\n    #o := 2 + LT#5x;\n", "fb.scl:12:15: LT#5x: not an LTIME"),
    "conversion": (
        "",
        "    #o := REAL_TO_TIME(#r);\n",
        "fb.scl:11:11: REAL_TO_TIME: S7 has no conversion between REAL and TIME",
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_refusal_names_the_construct_at_its_place(tmp_path, case):
    declarations, body, expected = CASES[case]
    message = refused(tmp_path, fb(declarations, body))
    assert message.startswith(expected), message


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
    "fc recursion": (
        "",
        '    #o := "Rec"(#i);\n',
        'FUNCTION "Rec" : Int\n   VAR_INPUT\n      x : Int;\n   END_VAR\nBEGIN\n'
        '    #Rec := "Rec"(#x);\nEND_FUNCTION\n',
        "fb.scl:18:13: Rec calls itself (Rec -> Rec): S7 has no recursion",
    ),
    "fb recursion": (
        '   VAR\n      m : "Inner";\n   END_VAR\n',
        "",
        'FUNCTION_BLOCK "Inner"\n   VAR\n      f : "Fb";\n   END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n',
        "fb.scl:17:11: Fb calls itself (Fb -> Inner -> Fb): S7 has no recursion",
    ),
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
    "void as value": (
        "",
        '    #o := "Nothing"();\n',
        BLOCKS,
        'fb.scl:11:11: "Nothing" is a FUNCTION : Void, it has no value',
    ),
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
    "mux selector": (
        "",
        "    #o := MUX(K := #r, IN0 := 1, IN1 := 2);\n",
        "",
        "fb.scl:11:20: MUX's K must be an integer, not REAL",
    ),
    "shift of a literal": (
        "",
        "    #o := SHL(IN := 5, N := 1);\n",
        "",
        "fb.scl:11:11: SHL of an untyped literal: give it its type",
    ),
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
        "fb.scl:11:20: RD_SYS_T's OUT is a DTL; 'i' is not",
    ),
    "runtime memory": (
        "   VAR\n      m : Real;\n   END_VAR\n",
        "    #o := LREAL_TO_INT(RUNTIME(#m));\n",
        "",
        "fb.scl:14:32: RUNTIME's MEM is an LREAL; 'm' is a REAL",
    ),
    "dtl output": (
        "   VAR_OUTPUT\n      t : DTL;\n   END_VAR\n",
        "",
        "",
        "fb.scl:11:7: the DTL 't': only a static or a VAR_TEMP can be a DTL",
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


@pytest.mark.parametrize("case", sorted(CALL_CASES) + sorted(DB_CASES))
def test_refusal_of_a_call_names_it_at_its_place(tmp_path, case):
    """Calls, and DBs (docs/scl.md §3.9)."""
    declarations, body, after, expected = {**CALL_CASES, **DB_CASES}[case]
    message = refused(tmp_path, fb(declarations, body) + after)
    assert message.startswith(expected), message


def test_a_missing_block_names_the_blocks_there_are(tmp_path):
    message = refused(tmp_path, fb("", ""), block="Motor")
    assert message == "no block 'Motor' in the sources (they define: Fb)"


def test_a_function_is_not_an_fmu(tmp_path):
    text = 'FUNCTION "Twice" : Int\n   VAR_INPUT\n      x : Int;\n   END_VAR\nBEGIN\nEND_FUNCTION\n'
    message = refused(tmp_path, text, block="Twice")
    assert message == "fb.scl:1:1: Twice: only a FUNCTION_BLOCK becomes an FMU"


STRUCT_M = '   VAR\n      s : STRUCT\n         m : "Motor";\n      END_STRUCT;\n   END_VAR\n'
SUB_IN_OUT = (
    'FUNCTION_BLOCK "Sub"\n   VAR_IN_OUT\n      x : Int;\n   END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n'
)

# (declarations, body, blocks after the FB, the message's start) where calls meet data structures
MEET_CASES = {
    "instance in a struct": (
        STRUCT_M,
        "",
        BLOCKS,
        "fb.scl:12:14: 's.m': an FB instance in a STRUCT",
    ),
    "array of instances": (
        '   VAR\n      ms : Array[1..2] of "Motor";\n   END_VAR\n',
        "",
        BLOCKS,
        "fb.scl:11:12: 'ms': an ARRAY or STRUCT of Motor instances",
    ),
    "in/out of an fc": (
        "",
        '    #o := "Io"();\n',
        'FUNCTION "Io" : Int\n   VAR_IN_OUT\n      x : Int;\n   END_VAR\nBEGIN\nEND_FUNCTION\n',
        "fb.scl:15:7: VAR_IN_OUT 'x' of Io: only the FB compiled into the FMU has in/outs",
    ),
    "in/out of a used fb": (
        '   VAR\n      s : "Sub";\n   END_VAR\n',
        "",
        SUB_IN_OUT,
        "fb.scl:17:7: VAR_IN_OUT 'x' of Sub: only the FB compiled into the FMU has in/outs",
    ),
    "struct input of an fc": (
        "",
        '    #o := "Sp"(p := #o);\n',
        'FUNCTION "Sp" : Int\n   VAR_INPUT\n      p : STRUCT\n         x : Int;\n'
        "      END_STRUCT;\n   END_VAR\nBEGIN\nEND_FUNCTION\n",
        "fb.scl:15:11: the STRUCT VAR_INPUT 'p' of Sp: the inputs and outputs of an FC or of an "
        "FB's instance are elementary",
    ),
    "array return type": (
        "",
        '    #o := "Arr"();\n',
        'FUNCTION "Arr" : Array[1..2] of Int\nBEGIN\nEND_FUNCTION\n',
        "fb.scl:13:1: the FUNCTION Arr : ARRAY: unsupported return type",
    ),
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
    "dtl in a struct": (
        "   VAR\n      s : STRUCT\n         t : DTL;\n      END_STRUCT;\n   END_VAR\n",
        "",
        "",
        "fb.scl:12:14: 's.t': a DTL in a STRUCT is not supported",
    ),
}


@pytest.mark.parametrize("case", sorted(MEET_CASES))
def test_refusal_where_calls_meet_data_structures(tmp_path, case):
    declarations, body, after, expected = MEET_CASES[case]
    message = refused(tmp_path, fb(declarations, body) + after)
    assert message.startswith(expected), message
