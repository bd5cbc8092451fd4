"""`lgf-fmus compile --check-folder` (docs/scl.md §7) on a folder of SCL written here: a line per
block (compiled and ran, refused at file:line:col, or failed), the FC through its wrapper FB, a
file of types shared by the others, and a loop that never ends stopped by the time limit."""

from __future__ import annotations

from pathlib import Path

import pytest

from lgf_fmus.scl.corpus import check_folder
from tests.scl.driver import compile_command

FILES = {
    "Types.scl": """
TYPE "Pair"
   STRUCT
      a : Int;
      b : Int;
   END_STRUCT;
END_TYPE
""",
    "Adder.scl": """
FUNCTION_BLOCK "Adder"
   VAR_INPUT
      step : Int := 2;
   END_VAR
   VAR_OUTPUT
      total : Int;
   END_VAR
   VAR
      pair : "Pair";
   END_VAR
BEGIN
    #pair.a := #pair.a + #step;
    #total := #pair.a;
END_FUNCTION_BLOCK
""",
    "Twice.scl": """
FUNCTION "Twice" : Int
   VAR_INPUT
      x : Int;
   END_VAR
   VAR_OUTPUT
      odd : Bool;
   END_VAR
BEGIN
    #odd := (#x MOD 2) <> 0;
    #Twice := #x * 2;
END_FUNCTION
""",
    "Wide.scl": """
FUNCTION "Wide" : LWord
   VAR_INPUT
      n : LInt;
   END_VAR
   VAR_IN_OUT
      table : Array[*] of LWord;
   END_VAR
BEGIN
    #table[LOWER_BOUND(ARR := #table, DIM := 1)] := LINT_TO_LWORD(#n);
    #Wide := LINT_TO_LWORD(#n + 1);
END_FUNCTION
""",
    "Broken.scl": """
FUNCTION_BLOCK "Broken"
BEGIN
    #x := ;
END_FUNCTION_BLOCK
""",
}


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    folder = tmp_path_factory.mktemp("corpus")
    for name, text in FILES.items():
        (folder / name).write_text(text)
    return folder


def test_a_line_per_block_and_the_totals(folder):
    lines = []
    results = check_folder(folder, steps=10, out=lines.append)
    outcomes = {r.block: r.outcome for r in results}
    # Wide's 64-bit parameters, which FMI 2.0 cannot carry, are statics of its wrapper
    assert outcomes == {"Adder": "ran", "Twice": "ran", "Wide": "ran", "Broken": "refused"}
    assert lines[:4] == [
        "Adder: compiled, ran 10 steps",
        f"Broken: refused: {folder / 'Broken.scl'}:4:11: " + lines[1].split(":4:11: ", 1)[1],
        "Twice: compiled, ran 10 steps",
        "Wide: compiled, ran 10 steps",
    ]
    assert lines[4] == "4 blocks: 3 compiled and ran 10 steps, 1 refused, 0 failed"


def test_a_loop_that_never_ends_is_stopped_by_the_watchdog(tmp_path):
    # docs/scl.md rules: [DEC-WATCHDOG]
    (tmp_path / "Forever.scl").write_text(
        'FUNCTION_BLOCK "Forever"\nVAR_OUTPUT\n  n : Int;\nEND_VAR\nBEGIN\n'
        "    REPEAT\n        #n := #n + 1;\n    UNTIL FALSE\n    END_REPEAT;\nEND_FUNCTION_BLOCK\n"
    )
    lines = []
    (result,) = check_folder(tmp_path, steps=10, timeout=5, out=lines.append)
    assert result.outcome == "failed"
    # the first call (t = 0) runs the REPEAT of line 6 out of its budget of 150 ms
    assert result.detail.startswith(
        "run: Forever: the PLC call at t = 0 s failed: time error: the loop at Forever.scl:6 "
        "ran out of the call's budget of 1500000 loop iterations"
    ), result.detail


def test_the_command_line(folder):
    run = compile_command("--check-folder", folder)
    assert run.returncode == 0, run.stderr
    assert (
        run.stdout.splitlines()[-1] == "4 blocks: 3 compiled and ran 100 steps, 1 refused, 0 failed"
    )
    wrong = compile_command("--check-folder", folder, "--block", "X")
    assert wrong.returncode == 2
    assert wrong.stderr == "error: --check-folder takes no SOURCE.scl, --block or --program\n"


USES = {
    # an FB that uses an FB and an FC of other files, which use a UDT of a third
    "Outer.scl": """
FUNCTION_BLOCK "Outer"
   VAR_OUTPUT
      n : Int;
   END_VAR
   VAR
      inner : "Inner";
   END_VAR
BEGIN
    #inner();
    #n := "Bump"(x := #inner.count);
END_FUNCTION_BLOCK
""",
    "Inner.scl": """
FUNCTION_BLOCK "Inner"
   VAR_OUTPUT
      count : Int;
   END_VAR
   VAR
      p : "Point";
   END_VAR
BEGIN
    #p.x := #p.x + 1;
    #count := #p.x;
END_FUNCTION_BLOCK
""",
    "Bump.scl": """
FUNCTION "Bump" : Int
   VAR_INPUT
      x : Int;
   END_VAR
BEGIN
    #Bump := #x + 1;
END_FUNCTION
""",
    "Point.scl": """
TYPE "Point"
   STRUCT
      x : Int;
   END_STRUCT;
END_TYPE
FUNCTION "Unused" : Void
BEGIN
END_FUNCTION
""",
    "Lacking.scl": """
FUNCTION_BLOCK "Lacking"
   VAR
      c : "Config";
   END_VAR
BEGIN
END_FUNCTION_BLOCK
""",
    # a type name written plain: no UDT (TIA quotes them), so not one the folder lacks
    "Plain.scl": """
FUNCTION_BLOCK "Plain"
   VAR
      m : doubleWord;
   END_VAR
BEGIN
END_FUNCTION_BLOCK
""",
    # a file that is not valid SCL, and an FB that calls its FC
    "Bad.scl": 'FUNCTION "Bad" : Int\nBEGIN\n    #Bad := ;\nEND_FUNCTION\n',
    "UsesBad.scl": """
FUNCTION_BLOCK "UsesBad"
   VAR_OUTPUT
      n : Int;
   END_VAR
BEGIN
    #n := "Bad"();
END_FUNCTION_BLOCK
""",
    # the same FB as Inner: never compiled with Outer
    "Inner_1.scl": """
FUNCTION_BLOCK "Inner"
BEGIN
END_FUNCTION_BLOCK
""",
}


def test_the_blocks_and_udts_of_other_files(tmp_path):
    """Outer is compiled with the files of the names it uses (Inner, Bump) and theirs (Point,
    a file of a UDT and an FC, so not one of types only); a UDT no file defines is named as
    one the folder lacks, an FC whose file is refused as that."""
    for name, text in USES.items():
        (tmp_path / name).write_text(text)
    results = {(r.block, Path(r.file).name): r for r in check_folder(tmp_path, steps=3, out=str)}
    assert results["Outer", "Outer.scl"].outcome == "ran"
    lacking = results["Lacking", "Lacking.scl"]
    assert lacking.outcome == "refused"
    assert lacking.detail.endswith(": a UDT or block the folder lacks (Config)")
    uses_bad = results["UsesBad", "UsesBad.scl"]
    assert uses_bad.detail.endswith(": the file Bad.scl is refused"), uses_bad.detail
    plain = results["Plain", "Plain.scl"]
    assert plain.outcome == "refused" and "folder lacks" not in plain.detail
