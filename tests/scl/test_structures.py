"""Whole STRUCTs assigned (docs/scl.md §3.8 [S7-STRUCT]): two anonymous STRUCTs of the same
members in the same order copy into each other, also as ARRAY elements and whole ARRAYs of
them; STRUCTs of other members, and an anonymous STRUCT and a UDT, are refused. Values by
hand."""

from __future__ import annotations

import pytest

from tests.scl.driver import compile_text, run_cs
from tests.scl.test_errors import refuses

CYCLE_US = 100_000

SOURCE = """
FUNCTION_BLOCK "Copies"
   VAR_INPUT
      id : Int;
      qty : Real;
   END_VAR
   VAR_OUTPUT
      firstId : Int;
      secondQty : Real;
      copiedId : Int;
   END_VAR
   VAR
      item : Struct
         id : Int;
         qty : Real;
      END_STRUCT;
      store : Array[1..2] of Struct
         ID : Int;
         Qty : Real;
      END_STRUCT;
      backup : Array[1..2] of Struct
         id : Int;
         qty : Real;
      END_STRUCT;
   END_VAR
BEGIN
   #item.id := #id;
   #item.qty := #qty;
   #store[2] := #store[1];
   #store[1] := #item;
   #backup := #store;
   #firstId := #store[1].ID;
   #secondQty := #store[2].Qty;
   #copiedId := #backup[2].id;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-STRUCT]
def test_anonymous_structs_of_the_same_members_copy_by_hand(tmp_path):
    """Each call moves store[1] into store[2], then the inputs' item into store[1] (member
    names in another case, as S7's names are), and copies the whole ARRAY into backup."""
    fmu = compile_text(tmp_path, SOURCE, "Copies")
    names = ["firstId", "secondQty", "copiedId"]
    per_call = [{"id": 3, "qty": 1.5}, {"id": 7, "qty": 2.5}, {"id": 9, "qty": 4.0}]
    steps = [(CYCLE_US, inputs) for inputs in per_call[1:]]
    rows = run_cs(fmu, CYCLE_US, {}, per_call[0], steps, names=names)
    assert [[row[n] for n in names] for row in rows] == [[3, 0.0, 0], [7, 1.5, 3], [9, 2.5, 7]]


UDT = 'TYPE "P"\n   STRUCT\n      x : Int;\n   END_STRUCT;\nEND_TYPE\n'
CASES = {
    "another member type": (
        "   VAR\n      a : Struct\n         x : Int;\n      END_STRUCT;\n"
        "      b : Struct\n         x : DInt;\n      END_STRUCT;\n   END_VAR\n",
        "    #a := #b;\n",
        "",
        "fb.scl:19:11: the assignment to 'a': S7 converts no STRUCT to STRUCT implicitly",
    ),
    "another member name": (
        "   VAR\n      a : Struct\n         x : Int;\n      END_STRUCT;\n"
        "      b : Struct\n         y : Int;\n      END_STRUCT;\n   END_VAR\n",
        "    #a := #b;\n",
        "",
        "fb.scl:19:11: the assignment to 'a': S7 converts no STRUCT to STRUCT implicitly",
    ),
    "a udt to a struct": (
        '   VAR\n      a : Struct\n         x : Int;\n      END_STRUCT;\n      b : "P";\n'
        "   END_VAR\n",
        "    #a := #b;\n",
        UDT,
        "fb.scl:17:11: the assignment to 'a': S7 converts no \"P\" to STRUCT implicitly",
    ),
}


# docs/scl.md rules: [S7-STRUCT]
@pytest.mark.parametrize("case", sorted(CASES))
def test_refusal_of_a_struct_of_another_shape(tmp_path, case):
    refuses(tmp_path, *CASES[case])
