"""The refusals of a program (docs/scl.md §3.10): of its program file, each at the key it names,
and of its OBs, each at its place; and the defaults a program file leaves to TIA's."""

from __future__ import annotations

import pytest

from lgf_fmus import scl
from lgf_fmus.scl import program as P

OBS = """
ORGANIZATION_BLOCK "Main"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
   VAR_INPUT
      Initial_Call : Bool;
      Remanence : Bool;
   END_VAR
BEGIN
    ;
END_ORGANIZATION_BLOCK
"""
MAIN = "[ob.Main]\nnumber = 1\n"

# program file -> the refusal's text
FILE_CASES = {
    "unknown key": ("cycle = 1\n" + MAIN, "unknown key 'cycle'"),
    "name of other characters": ('name = "A line"\n' + MAIN, "letters, digits and _"),
    "no OB": ('name = "Line"\n', "no OB: give each OB a table"),
    "an OB no table": ("ob = { Main = 1 }\n", "[ob.Main] is no table"),
    "unknown OB key": (MAIN + "interval = 5\n", "[ob.Main]: unknown key 'interval'"),
    "no number": ("[ob.Main]\npriority = 1\n", "[ob.Main]: number is missing"),
    "number no integer": ('[ob.Main]\nnumber = "1"\n', "number = '1' is not a whole number"),
    "number twice": (MAIN + "[ob.Other]\nnumber = 1\n", "OB1 is also [ob.Main]"),
    "no such class": (MAIN + 'class = "free"\n', "class = 'free' is none of"),
    "class of no OB": ("[ob.Main]\nnumber = 200\n", "OB200 needs its class"),
    "an event not supported": ("[ob.Main]\nnumber = 40\n", "OB40 is no startup"),
    "class against number": (MAIN + 'class = "startup"\n', "OB1 is a program cycle OB"),
    "a cycle of OB1": (MAIN + "cycle_us = 5000\n", "has no cycle_us (its cycle: min_cycle_us"),
    "a phase of OB100": (
        "[ob.S]\nnumber = 100\nphase_us = 5\n",
        "has no phase_us (its cycle: none",
    ),
    "priority of OB1": (MAIN + "priority = 2\n", "priority = 2 is not a whole number from 1 to 1"),
    "phase beyond cycle": (
        "[ob.C]\nnumber = 38\nphase_us = 10000\n",
        "phase_us = 10000 is not a whole number from 0 to 9999",
    ),
    "cycle beyond 60 s": ("[ob.C]\nnumber = 30\ncycle_us = 60000001\n", "cycle_us = 60000001"),
    "cyclic from 123 without cycle": (
        '[ob.C]\nnumber = 123\nclass = "cyclic interrupt"\npriority = 9\n',
        "[ob.C]: cycle_us is missing",
    ),
    "minimum cycle 0": ("min_cycle_us = 0\n" + MAIN, "min_cycle_us = 0 is not a whole number"),
}


# docs/scl.md rules: [S7-OB-CLASS] [S7-PROG-DEFAULTS]
@pytest.mark.parametrize("case", FILE_CASES)
def test_a_program_file_refused(tmp_path, case):
    text, expected = FILE_CASES[case]
    (tmp_path / "program.toml").write_text(text, encoding="utf-8")
    with pytest.raises(scl.SclError) as caught:
        P.load(tmp_path / "program.toml")
    assert expected in str(caught.value)
    assert "program.toml" in str(caught.value)


def test_a_file_that_is_no_toml_or_none(tmp_path):
    (tmp_path / "program.toml").write_text("[ob.Main\n", encoding="utf-8")
    with pytest.raises(scl.SclError, match="not a TOML file"):
        P.load(tmp_path / "program.toml")
    with pytest.raises(scl.SclError, match="cannot read it"):
        P.load(tmp_path / "missing.toml")


# docs/scl.md rules: [S7-PROG-DEFAULTS] [DEC-PROG-OB1]
def test_the_defaults_are_tias():
    """OB30 ... OB38 with Siemens' default intervals and priorities, OB1 every 10 ms."""
    obs = "\n".join(f"[ob.C{n}]\nnumber = {n}" for n in range(30, 39))
    schedule = P.from_dict(P.tomllib.loads(MAIN + obs))
    got = {ob.number: (ob.cycle_us, ob.phase_us, ob.priority) for ob in schedule.obs}
    ms = [5000, 2000, 1000, 500, 200, 100, 50, 20, 10]
    assert got == {
        1: (0, 0, 1),
        **{30 + i: (ms[i] * 1000, 0, 7 + i) for i in range(9)},
    }
    assert schedule.min_cycle_us == 10_000 and schedule.name == "Program"
    assert schedule.tick_us == 10_000  # the gcd of 10 ms ... 5 s
    assert [ob.number for ob in schedule.cyclic] == [38, 37, 36, 35, 34, 33, 32, 31, 30, 1]


# program file, extra SCL -> the refusal's text
SOURCE_CASES = {
    "an OB without table": (
        MAIN,
        'ORGANIZATION_BLOCK "Other"\nBEGIN\nEND_ORGANIZATION_BLOCK\n',
        'the ORGANIZATION_BLOCK "Other" has no table [ob.Other]',
    ),
    "a table without OB": (
        MAIN + "[ob.Cyc]\nnumber = 35\n",
        "",
        "[ob.Cyc]: no ORGANIZATION_BLOCK of that name in the sources (they define: Main)",
    ),
    "the program's name a block's": (
        'name = "Main"\n' + MAIN,
        "",
        "the program's name 'Main' is a block's of the sources",
    ),
    "start information of another class": (
        MAIN + "[ob.Cyc]\nnumber = 35\n",
        'ORGANIZATION_BLOCK "Cyc"\nVAR_INPUT\n Remanence : Bool;\nEND_VAR\nBEGIN\n'
        "END_ORGANIZATION_BLOCK\n",
        "'Remanence': the VAR_INPUT of a cyclic interrupt OB is its start information "
        "(Initial_Call : Bool, Event_Count : Int)",
    ),
    "start information of another type": (
        MAIN + "[ob.Cyc]\nnumber = 35\n",
        'ORGANIZATION_BLOCK "Cyc"\nVAR_INPUT\n Event_Count : DInt;\nEND_VAR\nBEGIN\n'
        "END_ORGANIZATION_BLOCK\n",
        "'Event_Count': the VAR_INPUT of a cyclic interrupt OB",
    ),
    "a static of an OB": (
        MAIN + "[ob.Cyc]\nnumber = 35\n",
        'ORGANIZATION_BLOCK "Cyc"\nVAR\n n : Int;\nEND_VAR\nBEGIN\nEND_ORGANIZATION_BLOCK\n',
        "the ORGANIZATION_BLOCK Cyc has no instance data and no parameters: only its start "
        "information (VAR_INPUT), VAR_TEMP and VAR CONSTANT, not VAR 'n'",
    ),
    "an output of an OB": (
        MAIN + "[ob.Cyc]\nnumber = 35\n",
        'ORGANIZATION_BLOCK "Cyc"\nVAR_OUTPUT\n n : Int;\nEND_VAR\nBEGIN\nEND_ORGANIZATION_BLOCK\n',
        "not VAR_OUTPUT 'n'",
    ),
    "an OB's C name another block's": (
        MAIN + '[ob."Cyc 1"]\nnumber = 35\n',
        'ORGANIZATION_BLOCK "Cyc 1"\nBEGIN\nEND_ORGANIZATION_BLOCK\n'
        'FUNCTION "Cyc_1" : Void\nBEGIN\nEND_FUNCTION\n',
        'the OB "Cyc 1" is Cyc_1 in the C, as is another block or the program',
    ),
    "an OB called": (
        MAIN + "[ob.Cyc]\nnumber = 35\n",
        'ORGANIZATION_BLOCK "Cyc"\nBEGIN\n "Main"(Initial_Call := TRUE, Remanence := FALSE);\n'
        "END_ORGANIZATION_BLOCK\n",
        "Main is an ORGANIZATION_BLOCK: only the CPU calls an OB",
    ),
}


# docs/scl.md rules: [S7-OB-SOURCE] [S7-OB-START]
@pytest.mark.parametrize("case", SOURCE_CASES)
def test_a_program_refused(tmp_path, case):
    text, extra, expected = SOURCE_CASES[case]
    (tmp_path / "program.toml").write_text(text, encoding="utf-8")
    (tmp_path / "obs.scl").write_text(OBS + extra, encoding="utf-8")
    schedule = P.load(tmp_path / "program.toml", "Line")
    with pytest.raises(scl.SclError) as caught:
        scl.generate_c([tmp_path / "obs.scl"], None, schedule)
    assert expected in str(caught.value)


def test_an_ob_as_the_block_and_the_arguments_of_compile(tmp_path):
    (tmp_path / "obs.scl").write_text(OBS, encoding="utf-8")
    (tmp_path / "program.toml").write_text(MAIN, encoding="utf-8")
    with pytest.raises(scl.SclError, match="compile the program with --program"):
        scl.generate_c([tmp_path / "obs.scl"], "Main")
    with pytest.raises(scl.SclError, match="give a block or a program, not both"):
        scl.compile([tmp_path / "obs.scl"], "Main", program=tmp_path / "program.toml")
    with pytest.raises(scl.SclError, match="the block to compile, or a program"):
        scl.compile([tmp_path / "obs.scl"])
