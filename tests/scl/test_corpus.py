"""`lgf-fmus compile --check-folder` (docs/scl.md §7) on a folder of SCL written here: a line per
block (compiled and ran, refused at file:line:col, or failed), the FC through its wrapper FB, a
file of types shared by the others, and a loop that never ends stopped by the time limit."""

from __future__ import annotations

import subprocess
import sys

import pytest

from lgf_fmus.scl.corpus import check_folder

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
    assert outcomes == {"Adder": "ran", "Twice": "ran", "Broken": "refused"}
    assert lines[:3] == [
        "Adder: compiled, ran 10 steps",
        f"Broken: refused: {folder / 'Broken.scl'}:4:11: " + lines[1].split(":4:11: ", 1)[1],
        "Twice: compiled, ran 10 steps",
    ]
    assert lines[3] == "3 blocks: 2 compiled and ran 10 steps, 1 refused, 0 failed"


def test_a_loop_that_never_ends_is_stopped(tmp_path):
    (tmp_path / "Forever.scl").write_text(
        'FUNCTION_BLOCK "Forever"\nVAR_OUTPUT\n  n : Int;\nEND_VAR\nBEGIN\n'
        "    REPEAT\n        #n := #n + 1;\n    UNTIL FALSE\n    END_REPEAT;\nEND_FUNCTION_BLOCK\n"
    )
    lines = []
    (result,) = check_folder(tmp_path, steps=10, timeout=5, out=lines.append)
    assert result.outcome == "failed"
    assert "ran past 5 s" in result.detail


def test_the_command_line(folder):
    run = subprocess.run(
        [sys.executable, "-m", "lgf_fmus", "compile", "--check-folder", str(folder)],
        capture_output=True, text=True,
    )  # fmt: skip
    assert run.returncode == 0, run.stderr
    assert (
        run.stdout.splitlines()[-1] == "3 blocks: 2 compiled and ran 100 steps, 1 refused, 0 failed"
    )
    command = [sys.executable, "-m", "lgf_fmus", "compile", "--check-folder", str(folder)]
    wrong = subprocess.run([*command, "--block", "X"], capture_output=True, text=True)
    assert wrong.returncode == 2
    assert wrong.stderr == "error: --check-folder takes no SOURCE.scl and no --block\n"
