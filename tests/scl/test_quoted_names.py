"""Quoted names of any character TIA takes (docs/scl.md §3.11 [DEC-NAME-C] [DEC-NAME-FMI],
issue 30): variables, constants, statics, members of STRUCTs and UDTs, blocks, UDTs and DBs named
`"Conveyor.Main"`, `"Ventil-1"`, `."ON/OFF"`, with umlauts and spaces. The C holds each as a
mangled identifier, the FMU's variables keep TIA's name (quoted as FMI's structured convention
quotes a name). The SCL is written here; the expected values are computed by hand in the
comments."""

from __future__ import annotations

import xml.etree.ElementTree as ET
import zipfile

import pytest
from fmpy.validation import validate_fmu

from lgf_fmus.scl.cnames import fmi_part, identifier
from tests.scl.driver import compile_text, run_cs
from tests.scl.test_tia_syntax import refused

QUOTED = """
TYPE "Ventil-Typ"
VERSION : 0.1
   STRUCT
      "ON/OFF" : Bool;
      "Größe" : Int := 3;
   END_STRUCT;
END_TYPE

DATA_BLOCK "Werte DB"
   VAR
      "Grenze & <Max>" : Int := 40;
   END_VAR
BEGIN
END_DATA_BLOCK

FUNCTION "Rechne.Doppelt" : Int
   VAR_INPUT
      "Wert x" : Int;
   END_VAR
BEGIN
   #"Rechne.Doppelt" := #"Wert x" * 2;
END_FUNCTION

FUNCTION_BLOCK "Zähler-FB"
   VAR_INPUT
      "+1" : Bool;
   END_VAR
   VAR_OUTPUT
      "Stand [n]" : Int;
   END_VAR
BEGIN
   IF #"+1" THEN
      #"Stand [n]" += 1;
   END_IF;
END_FUNCTION_BLOCK

FUNCTION_BLOCK "Conveyor.Main"
   VAR_INPUT
      "Ventil-1" : Bool;
      "Speed [m/s]" : Real;
   END_VAR
   VAR_OUTPUT
      "Zähler" : Int;
      "out 'q'" : Real;
      "a\\b" : Int;
   END_VAR
   VAR_IN_OUT
      "io.x" : Int;
   END_VAR
   VAR
      v : "Ventil-Typ";
      "n.ok" : Int;
      "Zähler 1" : "Zähler-FB";
   END_VAR
   VAR CONSTANT
      "- - - Application Error codes" : Word;
      "//- internal constants" : Int := 7;
   END_VAR
BEGIN
   #v."ON/OFF" := #"Ventil-1";
   IF #v."ON/OFF" THEN
      #"n.ok" := "Rechne.Doppelt"("Wert x" := #"n.ok" + 1);
   END_IF;
   #"Zähler 1"("+1" := #"Ventil-1");
   #"Zähler" := #"n.ok" + #v."Größe" + WORD_TO_INT(#"- - - Application Error codes");
   #"out 'q'" := #"Speed [m/s]" * 2.0;
   #"a\\b" := MIN(IN1 := #"Zähler 1"."Stand [n]" * #"//- internal constants",
                  IN2 := "Werte DB"."Grenze & <Max>");
   #"io.x" := #"io.x" + 1;
END_FUNCTION_BLOCK
"""

EXPECTED_NAMES = {
    "'Ventil-1'",
    "'Speed [m/s]'",
    "'Zähler'",
    "'out \\'q\\''",  # a ' in a quoted name escaped by \, as FMI's structured names write it
    "'a\\\\b'",  # and a \
    "'io.x'",
    "'io.x_out'",
    "v.'ON/OFF'",
    "v.'Größe'",
    "'n.ok'",
    "'Zähler 1'.'+1'",
    "'Zähler 1'.'Stand [n]'",
    "'Werte DB'.'Grenze & <Max>'",
}


def test_the_c_and_fmi_names_of_a_quoted_name():
    assert identifier("Motor") == "Motor"
    assert identifier("Conveyor.Main") == "q_Conveyor_2e_Main"
    assert identifier("Größe") == "q_Gr_f6__df_e"
    assert identifier("1st") == "q_1st"
    assert fmi_part("Motor") == "Motor"
    assert fmi_part("Conveyor.Main") == "'Conveyor.Main'"
    assert fmi_part("it's") == "'it\\'s'"


# docs/scl.md rules: [DEC-NAME-C] [DEC-NAME-FMI]
@pytest.mark.parametrize("fmi", [2, 3])
def test_quoted_names_compile_and_run(tmp_path, fmi):
    fmu = compile_text(tmp_path, QUOTED, "Conveyor.Main", fmi=fmi)
    assert fmu.name == f"Conveyor.Main_fmi{fmi}.fmu"
    z = zipfile.ZipFile(fmu)
    description = ET.fromstring(z.read("modelDescription.xml"))
    names = {v.get("name") for v in description.iter() if v.tag not in ("Category",)}
    assert EXPECTED_NAMES <= names
    # the modelIdentifier is the C name of the FB, its files of that name
    assert {e.get("modelIdentifier") for e in description} - {None} == {"q_Conveyor_2e_Main"}
    assert "sources/blocks/q_Conveyor_2e_Main/block.c" in z.namelist()
    assert validate_fmu(str(fmu)) == []
    inputs = {"'Ventil-1'": True, "'Speed [m/s]'": 1.5, "'io.x'": 10}
    outputs = ["'Zähler'", "'out \\'q\\''", "'a\\\\b'", "'io.x_out'", "'n.ok'", "v.'ON/OFF'"]
    steps = [(100_000, {}), (100_000, {"'Ventil-1'": False})]
    rows = run_cs(fmu, 100_000, {}, inputs, steps, outputs)
    # call 1 (initialization), Ventil-1 TRUE: n.ok := (0 + 1) * 2 = 2; Zähler 1 counts to 1;
    # Zähler := 2 + 3 (Größe's start) + 0 (the constant without value) = 5; out 'q' := 3.0;
    # a\b := MIN(1 * 7, 40) = 7; io.x := 10 + 1 = 11
    first = {outputs[0]: 5, outputs[1]: 3.0, outputs[2]: 7, outputs[3]: 11, "'n.ok'": 2}
    # call 2: n.ok := (2 + 1) * 2 = 6, Zähler 6 + 3 = 9, the count 2: MIN(14, 40) = 14; the
    # in/out keeps the block's 11 (no new set), 12
    second = {outputs[0]: 9, outputs[1]: 3.0, outputs[2]: 14, outputs[3]: 12, "'n.ok'": 6}
    # call 3, Ventil-1 FALSE: n.ok stays 6, Zähler 9, the count stays 2; io.x 13
    third = {**second, outputs[3]: 13, "v.'ON/OFF'": False}
    assert rows == [
        {**first, "v.'ON/OFF'": True},
        {**second, "v.'ON/OFF'": True},
        third,
    ]


# docs/scl.md rules: [DEC-NAME-C]
@pytest.mark.parametrize(
    "text, message",
    [
        (  # two variables
            'FUNCTION_BLOCK F\n   VAR\n      "a.b" : Int;\n      q_a_2e_b : Int;\n   END_VAR\n'
            "BEGIN\nEND_FUNCTION_BLOCK\n",
            't.scl:4:7: E018: "q_a_2e_b" and "a.b" are both q_a_2e_b in the C: rename one',
        ),
        (  # two members
            'FUNCTION_BLOCK F\n   VAR\n      s : STRUCT\n         "x y" : Int;\n'
            "         q_x_20_y : Int;\n      END_STRUCT;\n   END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n",
            't.scl:5:10: E018: "q_x_20_y" and "x y" are both q_x_20_y in the C: rename one',
        ),
        (  # two blocks
            'FUNCTION "f-1" : Int\nBEGIN\n   #"f-1" := 1;\nEND_FUNCTION\n'
            "FUNCTION q_f_2d_1 : Int\nBEGIN\n   #q_f_2d_1 := 2;\nEND_FUNCTION\n"
            "FUNCTION_BLOCK F\n   VAR_OUTPUT\n      o : Int;\n   END_VAR\nBEGIN\n"
            '   #o := "f-1"() + q_f_2d_1();\nEND_FUNCTION_BLOCK\n',
            't.scl:5:1: E018: "q_f_2d_1" and "f-1" are both scl_FC_q_f_2d_1 in the C: rename one',
        ),
        (  # a control character
            'FUNCTION_BLOCK F\n   VAR\n      "a\tb" : Int;\n   END_VAR\n'
            "BEGIN\nEND_FUNCTION_BLOCK\n",
            "t.scl:3:7: E018: 'a\\tb': a name holds no control character (line break, tab)",
        ),
    ],
)
def test_names_alike_in_the_c_are_refused(tmp_path, text, message):
    assert refused(tmp_path, text) == message
