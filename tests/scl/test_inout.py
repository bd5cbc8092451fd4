"""The parameters a call passes by reference (docs/scl.md §3.7): the in/outs of FCs and of the
FBs the FMU's FB uses, elementary, UDT, fixed ARRAY and ARRAY[*] of one and of two dimensions,
and an FC's ARRAY[*] input; LOWER_BOUND/UPPER_BOUND of the argument. Values by hand; then the
refusals, each at its place."""

from __future__ import annotations

import pytest

from tests.scl.driver import compile_text, run_cs, unpacked
from tests.scl.test_corpus import FILES
from tests.scl.test_errors import refused

CYCLE_US = 100_000

PROGRAM = """
TYPE "Span"
   STRUCT
      lo : Int;   // the low end
      hi : Int;   // the high end
   END_STRUCT;
END_TYPE

FUNCTION "Fill" : Void
   VAR_IN_OUT
      m : Array[*, *] of Int;
      n : DInt;
   END_VAR
   VAR_TEMP
      i : DInt;
      j : DInt;
   END_VAR
BEGIN
   FOR #i := LOWER_BOUND(ARR := #m, DIM := 1) TO UPPER_BOUND(ARR := #m, DIM := 1) DO
      FOR #j := LOWER_BOUND(ARR := #m, DIM := 2) TO UPPER_BOUND(ARR := #m, DIM := 2) DO
         #m[#i, #j] := DINT_TO_INT(#i * 10 + #j);
         #n += 1;
      END_FOR;
   END_FOR;
END_FUNCTION

FUNCTION "Sum" : DInt
   VAR_INPUT
      v : Array[*] of Int;
   END_VAR
   VAR_TEMP
      i : DInt;
   END_VAR
BEGIN
   #Sum := 0;
   FOR #i := LOWER_BOUND(ARR := #v, DIM := 1) TO UPPER_BOUND(ARR := #v, DIM := 1) DO
      #Sum += #v[#i];
   END_FOR;
END_FUNCTION

FUNCTION "Widen" : Void
   VAR_INPUT
      by : Int;
   END_VAR
   VAR_IN_OUT
      s : "Span";
   END_VAR
BEGIN
   #s.lo := #s.lo - #by;
   #s.hi := #s.hi + #by;
END_FUNCTION

FUNCTION_BLOCK "Ring"
   VAR_INPUT
      x : Int;
   END_VAR
   VAR_OUTPUT
      total : DInt;
   END_VAR
   VAR_IN_OUT
      buf : Array[*] of Int;
   END_VAR
   VAR
      pos : DInt;
   END_VAR
BEGIN
   #buf[LOWER_BOUND(ARR := #buf, DIM := 1) + #pos] := #x;
   #pos := (#pos + 1) MOD (UPPER_BOUND(ARR := #buf, DIM := 1)
                           - LOWER_BOUND(ARR := #buf, DIM := 1) + 1);
   #total := "Sum"(v := #buf);
END_FUNCTION_BLOCK

FUNCTION_BLOCK "InOut"
   VAR_INPUT
      x : Int;
   END_VAR
   VAR_OUTPUT
      total : DInt;
      tableSum : DInt;
      count : DInt;
      m12 : Int;
      m31 : Int;
      lo : Int;
      hi : Int;
   END_VAR
   VAR_IN_OUT
      t : Array[*] of Int := [1, 2, 3];
   END_VAR
   VAR
      ring : "Ring";
      last : Array[-1..1] of Int;
      grid : Array[1..3, 1..2] of Int;
      span : "Span";
   END_VAR
BEGIN
   #ring(x := #x, buf := #last, total => #total);
   #tableSum := "Sum"(v := #t);
   "Fill"(m := #grid, n := #count);
   #m12 := #grid[1, 2];
   #m31 := #grid[3, 1];
   "Widen"(by := #x, s := #span);
   #lo := #span.lo;
   #hi := #span.hi;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-INOUT] [S7-ARRAY-STAR]
def test_in_outs_by_reference_by_hand(tmp_path):
    """Ring writes x into its in/out last[-1..1] at -1 + pos, pos counting 0, 1, 2, 0, and
    sums it through Sum's ARRAY[*] input: 5, 5 + 7, 5 + 7 + 1, then last[-1] := 2: 2 + 7 + 1.
    Sum of the table t (numberOfT = 3, its 3 start values) is 1 + 2 + 3. Fill writes
    i * 10 + j into grid[1..3, 1..2] (grid[1, 2] = 12, grid[3, 1] = 31) and counts its 6
    elements into count in every call; Widen moves span's ends by x: ±5, ±12, ±13, ±15."""
    fmu = compile_text(tmp_path, PROGRAM, "InOut")
    names = ["total", "tableSum", "count", "m12", "m31", "lo", "hi"]
    per_call = [{"x": 5}, {"x": 7}, {"x": 1}, {"x": 2}]
    steps = [(CYCLE_US, inputs) for inputs in per_call[1:]]
    rows = run_cs(fmu, CYCLE_US, {}, per_call[0], steps, names=names)
    assert [[row[n] for n in names] for row in rows] == [
        [5, 6, 6, 12, 31, -5, 5],
        [12, 6, 12, 12, 31, -12, 12],
        [13, 6, 18, 12, 31, -13, 13],
        [10, 6, 24, 12, 31, -15, 15],
    ]
    _, md = unpacked(fmu)
    local = {v.name for v in md.modelVariables if v.causality == "local"}
    # the instance's in/out is the caller's variable, no data of its own (no FMI local)
    assert "ring.pos" in local and not any(n.startswith("ring.buf") for n in local)


STRUCTURED = """
TYPE "Pt"
   STRUCT
      x : Int;
      y : Int;
   END_STRUCT;
END_TYPE

FUNCTION "Mirror" : Int
   VAR_INPUT
      p : "Pt";
      w : Array[0..2] of Int;
   END_VAR
   VAR_OUTPUT
      q : "Pt";
   END_VAR
BEGIN
   #q.x := #p.y;
   #Mirror := #w[0] + #w[2];
END_FUNCTION

FUNCTION_BLOCK "Structured"
   VAR_INPUT
      x : Int;
   END_VAR
   VAR_OUTPUT
      qx : Int;
      qy : Int;
      r : Int;
   END_VAR
   VAR
      a : "Pt" := (x := 1, y := 2);
      b : "Pt" := (y := 9);
      w : Array[0..2] of Int := [5, 6, 7];
   END_VAR
BEGIN
   #a.y := #x;
   #r := "Mirror"(p := #a, w := #w, q => #b);
   #qx := #b.x;
   #qy := #b.y;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-INOUT]
def test_structured_inputs_and_outputs_of_an_fc_by_hand(tmp_path):
    """Mirror's UDT and ARRAY inputs and its UDT output are the caller's variables: q.x takes
    p.y (the input x through a.y), r = w[0] + w[2] = 5 + 7, and q.y, which Mirror does not
    write, keeps b's 9."""
    fmu = compile_text(tmp_path, STRUCTURED, "Structured")
    names = ["qx", "qy", "r"]
    steps = [(CYCLE_US, {"x": 4})]
    rows = run_cs(fmu, CYCLE_US, {}, {"x": 3}, steps, names=names)
    assert [[row[n] for n in names] for row in rows] == [[3, 9, 12], [4, 9, 12]]


AT_AN_INDEX = """
FUNCTION "Inc" : Void
   VAR_IN_OUT
      x : Int;
      v : Array[*] of Int;
   END_VAR
BEGIN
   #x := #x + 1;
   #v[LOWER_BOUND(ARR := #v, DIM := 1)] := #x;
END_FUNCTION

FUNCTION_BLOCK "AtIndex"
   VAR_INPUT
      i : Int;
   END_VAR
   VAR_OUTPUT
      a1 : Int;
      a2 : Int;
      m : Int;
   END_VAR
   VAR
      a : Array[1..2] of Int;
      rows : Array[1..2] of Struct
         vals : Array[0..1] of Int;
      END_STRUCT;
   END_VAR
BEGIN
   "Inc"(x := #a[#i], v := #rows[#i].vals);
   #a1 := #a[1];
   #a2 := #a[2];
   #m := #rows[2].vals[0];
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-INOUT] [DEC-INDEX]
def test_elements_at_a_run_time_index_by_reference_by_hand(tmp_path):
    """i = 2: Inc counts a[2] up by 1 and writes it into rows[2].vals[0] (its ARRAY[*]'s low
    bound), 1, 2; then i = 5 lies outside both: Inc runs on zeros, nothing of the FB changes;
    then i = 2 again: 3."""
    fmu = compile_text(tmp_path, AT_AN_INDEX, "AtIndex")
    names = ["a1", "a2", "m"]
    steps = [(CYCLE_US, {"i": 2}), (CYCLE_US, {"i": 5}), (CYCLE_US, {"i": 2})]
    rows = run_cs(fmu, CYCLE_US, {}, {"i": 2}, steps, names=names)
    assert [[row[n] for n in names] for row in rows] == [[0, 1, 1], [0, 2, 2], [0, 2, 2], [0, 3, 3]]


FC_IO = 'FUNCTION "Io" : Void\n   VAR_IN_OUT\n      x : Int;\n   END_VAR\nBEGIN\nEND_FUNCTION\n'
FC_STAR = (
    'FUNCTION "Star" : Void\n   VAR_IN_OUT\n      a : Array[*] of Int;\n   END_VAR\n'
    "BEGIN\nEND_FUNCTION\n"
)
FB_SUB = (
    'FUNCTION_BLOCK "Sub"\n   VAR_IN_OUT\n      x : Int;\n   END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n'
)
FB_DECLS = (
    '   VAR\n      s : "Sub";\n      w : Word;\n      a : Array[1..2] of Int;\n'
    "      r2 : Array[1..2] of Real;\n      m : Array[1..2, 1..2] of Int;\n   END_VAR\n"
)

# (declarations, body, blocks after the FB, the message's start)
CASES = {
    "a value to an in/out": (
        "",
        '    "Io"(x := #o + 1);\n',
        FC_IO,
        'fb.scl:11:15: "Io"\'s VAR_IN_OUT x is passed by reference: it takes a variable, '
        "not a value",
    ),
    "another type to an in/out": (
        "   VAR\n      n : DInt;\n   END_VAR\n",
        '    "Io"(x := #n);\n',
        FC_IO,
        "fb.scl:14:15: \"Io\"'s VAR_IN_OUT x is a INT; 'n' is a DINT",
    ),
    "an in/out left out": (
        "",
        '    "Io"();\n',
        FC_IO,
        'fb.scl:11:5: "Io" needs x: S7 passes them by reference, so every call gives them',
    ),
    "an instance's in/out left out": (
        FB_DECLS,
        "    #s();\n",
        FB_SUB,
        "fb.scl:18:5: Sub 's' needs x: its in/outs are passed by reference in every call",
    ),
    "a bit to an in/out": (
        FB_DECLS,
        "    #s(x := #w.%X1);\n",
        FB_SUB,
        "fb.scl:18:13: Sub's VAR_IN_OUT x is passed by reference: it takes no bit (.%X)",
    ),
    "an instance's member to an in/out": (
        "   VAR\n      tn : TON;\n   END_VAR\n",
        '    "Bo"(x := #tn.IN);\n',
        'FUNCTION "Bo" : Void\n   VAR_IN_OUT\n      x : Bool;\n   END_VAR\nBEGIN\nEND_FUNCTION\n',
        'fb.scl:14:15: "Bo"\'s VAR_IN_OUT x is passed by reference: it takes a variable, member '
        "or element, not an instance's or a DTL's member",
    ),
    "an input to an in/out": (
        FB_DECLS,
        "    #s(x := #i);\n",
        FB_SUB,
        "fb.scl:18:13: 'i' is an input, set by the importer at every call",
    ),
    "an array of another element": (
        FB_DECLS,
        '    "Star"(a := #r2);\n',
        FB_SUB + FC_STAR,
        "fb.scl:18:17: \"Star\"'s VAR_IN_OUT a is a ARRAY[*] OF INT; 'r2' is a ARRAY[1..2] OF REAL",
    ),
    "an array of other dimensions": (
        FB_DECLS,
        '    "Star"(a := #m);\n',
        FB_SUB + FC_STAR,
        "fb.scl:18:17: \"Star\"'s VAR_IN_OUT a is a ARRAY[*] OF INT; 'm' is a ARRAY[1..2, 1..2]",
    ),
    "an array[*] assigned whole": (
        FB_DECLS,
        '    "Cp"(a := #a, b := #a);\n',
        FB_SUB + 'FUNCTION "Cp" : Void\n   VAR_IN_OUT\n      a : Array[*] of Int;\n'
        "      b : Array[*] of Int;\n   END_VAR\nBEGIN\n    #a := #b;\nEND_FUNCTION\n",
        "fb.scl:32:5: 'a' is an ARRAY[*] OF INT: an ARRAY[*] is assigned element by element",
    ),
    "an array[*] static": (
        "   VAR\n      a : ARRAY[*] OF Int;\n   END_VAR\n",
        "",
        "",
        "fb.scl:11:11: 'a': ARRAY[*] is only the type of a VAR_IN_OUT or of an FC's VAR_INPUT "
        "or VAR_OUTPUT (S7)",
    ),
    "an array[*] with bounds": (
        "   VAR_IN_OUT\n      a : ARRAY[*, 1..2] OF Int;\n   END_VAR\n",
        "",
        "",
        "fb.scl:11:11: 'a': ARRAY[*] has * in every dimension, no bounds",
    ),
    "a table of two dimensions": (
        "   VAR_IN_OUT\n      t : ARRAY[*, *] OF Int;\n   END_VAR\n",
        "",
        "",
        "fb.scl:11:11: 't': an ARRAY[*, *] OF INT in/out of the FB compiled into the FMU",
    ),
}


def fb(declarations: str, body: str) -> str:
    from tests.scl.test_errors import fb as error_fb

    return error_fb(declarations, body)


# docs/scl.md rules: [S7-INOUT] [S7-ARRAY-STAR]
@pytest.mark.parametrize("case", sorted(CASES))
def test_refusal_of_an_argument_by_reference(tmp_path, case):
    declarations, body, after, expected = CASES[case]
    message = refused(tmp_path, fb(declarations, body) + after)
    assert message.startswith(expected), message


WIDE = (
    FILES["Wide.scl"]
    + """
FUNCTION_BLOCK "UsesWide"
   VAR_OUTPUT
      low : DWord;
      high : DWord;
      returnedLow : DWord;
   END_VAR
   VAR
      t : Array[3..4] of LWord;
      r : LWord;
   END_VAR
BEGIN
    #r := "Wide"(n := LINT#4294967297, table := #t); // 2^32 + 1
    #low := LWORD_TO_DWORD(#t[3]);
    #high := LWORD_TO_DWORD(SHR(IN := #t[3], N := 32));
    #returnedLow := LWORD_TO_DWORD(#r);
END_FUNCTION_BLOCK
"""
)


# docs/scl.md rules: [DEC-TYPE-64] [S7-INOUT]
def test_an_fc_takes_and_returns_64_bit_values(tmp_path):
    """2^32 + 1 into the table's first element (index 3): its halves 1 and 1; the return value
    2^32 + 2: its low half 2."""
    fmu = compile_text(tmp_path, WIDE, "UsesWide")
    out = run_cs(fmu, 100_000, {}, {}, [(100_000, {})])[-1]
    assert (out["low"], out["high"], out["returnedLow"]) == (1, 1, 2)
