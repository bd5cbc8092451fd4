"""ARRAYs of FB instances (docs/scl.md §3.7 [S7-FB-ARRAY]): statics of a user FB's or a system
FB's instances, each element called `#axes[#i](...)` and read `#axes[1].pos`, in the FMU state
and as FMI locals element by element; a call at an index outside the ARRAY is not made. Values
by hand; then the refusals."""

from __future__ import annotations

import pytest

from tests.scl.driver import compile_text, run_cs, unpacked
from tests.scl.test_errors import refuses

CYCLE_US = 100_000

SOURCE = """
FUNCTION_BLOCK "Axis"
   VAR_INPUT
      go : Bool;
   END_VAR
   VAR_OUTPUT
      pos : Int;
   END_VAR
BEGIN
   IF #go THEN
      #pos := #pos + 1;
   END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK "Axes"
   VAR_INPUT
      which : Int;
   END_VAR
   VAR_OUTPUT
      p1 : Int;
      p2 : Int;
      q : Bool;
   END_VAR
   VAR
      axes : Array[1..2] of "Axis";
      timers : Array[0..1] of TON;
   END_VAR
   VAR_TEMP
      i : Int;
   END_VAR
BEGIN
   FOR #i := 1 TO 2 DO
      #axes[#i](go := #i = #which);
   END_FOR;
   #axes[#which + 1](go := TRUE, pos => #p2);
   #p1 := #axes[1].pos;
   #timers[1](IN := #which = 1, PT := T#250ms);
   #q := #timers[1].Q;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-FB-ARRAY]
def test_an_array_of_instances_by_hand(tmp_path):
    """which 1, 1, 1, 1, 2: axes[1] runs with go in the loop and again as axes[which + 1] =
    axes[2] (go TRUE, whose pos goes to p2); at which 2, axes[3] lies outside: no call, p2
    keeps its last value. axes[1].pos counts 1, 2, 3, 4, 4; axes[2].pos 1, 2, 3, 4, then 5
    from the loop, not written to p2. timers[1] runs while which = 1: Q after 250 ms, at the
    fourth call (300 ms), and falls with IN."""
    fmu = compile_text(tmp_path, SOURCE, "Axes")
    names = ["p1", "p2", "q"]
    per_call = [{"which": 1}, {"which": 1}, {"which": 1}, {"which": 1}, {"which": 2}]
    steps = [(CYCLE_US, inputs) for inputs in per_call[1:]]
    rows = run_cs(fmu, CYCLE_US, {}, per_call[0], steps, names=names)
    assert [[row[n] for n in names] for row in rows] == [
        [1, 1, False],
        [2, 2, False],
        [3, 3, False],
        [4, 4, True],
        [4, 4, False],
    ]
    _, md = unpacked(fmu)
    local = {v.name for v in md.modelVariables if v.causality == "local"}
    assert {"axes[1].pos", "axes[2].go", "timers[0].Q", "timers[1].ET"} <= local


BLOCKS = (
    'FUNCTION_BLOCK "Ax"\n   VAR_OUTPUT\n      pos : Int;\n   END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n'
)
AXES = '   VAR\n      ax : Array[1..2] of "Ax";\n      v : Array[1..2] of Int;\n   END_VAR\n'

CASES = {
    "an element assigned": (
        AXES,
        "    #ax[1] := #ax[2];\n",
        BLOCKS,
        "fb.scl:15:5: 'ax[..]' is an FB instance: it is not assigned",
    ),
    "an output written": (
        AXES,
        "    #ax[1].pos := 1;\n",
        BLOCKS,
        "fb.scl:15:5: 'ax[..].pos' is an output of Ax: only the instance writes it",
    ),
    "no such member": (
        AXES,
        "    #o := #ax[1].speed;\n",
        BLOCKS,
        "fb.scl:15:11: Ax has no input or output 'speed'",
    ),
    "an index outside": (
        AXES,
        "    #ax[3]();\n",
        BLOCKS,
        "fb.scl:15:9: the index 3 is outside ax's 1..2",
    ),
    "an element of no instance": (
        AXES,
        "    #v[1]();\n",
        BLOCKS,
        "fb.scl:15:5: 'v[..]' is a INT, not an FB instance",
    ),
    "instances in a struct": (
        '   VAR\n      s : STRUCT\n         a : Array[1..2] of "Ax";\n      END_STRUCT;\n'
        "   END_VAR\n",
        "",
        BLOCKS,
        "fb.scl:12:14: 's.a': an FB instance in a STRUCT",
    ),
    "an array[*] of instances": (
        "",
        '    "Fc"(a := #o);\n',
        BLOCKS + 'FUNCTION "Fc" : Void\n   VAR_IN_OUT\n      a : Array[*] of "Ax";\n'
        "   END_VAR\nBEGIN\nEND_FUNCTION\n",
        "fb.scl:21:7: 'a': an ARRAY[*] of Ax instances",
    ),
}


# docs/scl.md rules: [S7-FB-ARRAY]
@pytest.mark.parametrize("case", sorted(CASES))
def test_refusal_of_an_array_of_instances(tmp_path, case):
    refuses(tmp_path, *CASES[case])
