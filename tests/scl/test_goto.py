"""GOTO and jump labels (docs/scl.md §3.4 [S7-GOTO], issue 30): a jump forward, a jump back (a
loop the cycle watchdog counts, [DEC-WATCHDOG]), out of a loop, into a REGION; the jumps S7 does
not allow refused at their place. The SCL is written here; the values are computed by hand in
the comments."""

from __future__ import annotations

import pytest

from tests.scl.driver import compile_text, run_cs
from tests.scl.test_tia_syntax import refused as tia_refused
from tests.scl.test_watchdog import run

JUMPS = """
FUNCTION_BLOCK "Jumps"
   VAR_INPUT
      n : Int := 3;
      limit : Int := 100;
   END_VAR
   VAR_OUTPUT
      sum : Int;
      skipped : Bool;
      found : Int;
      late : Bool;
   END_VAR
   VAR_TEMP
      i : Int;
   END_VAR
BEGIN
   #sum := 0;
   #i := 0;
again:
   #i := #i + 1;
   #sum := #sum + #i;
   IF #i < #n THEN
      GOTO again;
   END_IF;
   GOTO done;
   #skipped := TRUE;
done:
   #found := -1;
   FOR #i := 1 TO 10 DO
      IF #i * #i >= #limit THEN
         #found := #i;
         GOTO Found;
      END_IF;
   END_FOR;
   #found := 0;
FOUND:
   #late := FALSE;
   IF #found = 0 THEN
      GOTO inRegion;
   END_IF;
   REGION the label in a region
      RETURN;
   inRegion:
      #late := TRUE;
   END_REGION
unused:
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-GOTO]
@pytest.mark.parametrize("fmi", [2, 3])
def test_jumps_forward_back_and_out_of_a_loop(tmp_path, fmi):
    fmu = compile_text(tmp_path, JUMPS, "Jumps", fmi=fmi)
    steps = [(100_000, {"n": 1, "limit": 20}), (100_000, {"n": 5, "limit": 200})]
    rows = run_cs(fmu, 100_000, {}, {}, steps)
    # n = 3: i runs 1, 2, 3 (two jumps back), sum 6; the GOTO done skips `skipped`; limit 100:
    # 10 * 10 >= 100 first, found 10, out of the FOR to FOUND (labels are case-insensitive),
    # found <> 0: RETURN before inRegion, late FALSE
    assert rows[0] == {"sum": 6, "skipped": False, "found": 10, "late": False}
    # n = 1: no jump back, sum 1; limit 20: 5 * 5 >= 20, found 5
    assert rows[1] == {"sum": 1, "skipped": False, "found": 5, "late": False}
    # n = 5: sum 15; limit 200: no i up to 10 has i * i >= 200, found 0, into the REGION
    assert rows[2] == {"sum": 15, "skipped": False, "found": 0, "late": True}


FOREVER = """
FUNCTION_BLOCK "Forever"
   VAR_INPUT
      n : DInt := 1;
   END_VAR
   VAR_OUTPUT
      count : DInt;
   END_VAR
BEGIN
   #count := 0;
top:
   #count := #count + 1;
   IF #count < #n THEN
      GOTO top;
   END_IF;
END_FUNCTION_BLOCK
"""
GOTO_LINE = next(i for i, x in enumerate(FOREVER.splitlines(), 1) if "GOTO" in x)


# docs/scl.md rules: [S7-GOTO] [DEC-WATCHDOG]
@pytest.mark.parametrize("fmi", [2, 3])
def test_a_jump_back_counts_for_the_cycle_watchdog(tmp_path, fmi):
    fmu = compile_text(tmp_path, FOREVER, "Forever", fmi=fmi)
    # maxCycleTime 1 ms: 10000 jumps back a call. n = 10001: count 1 ... 10000 jump back,
    # 10000 jumps, count ends at 10001; n = 10002: the jump at count 10001 finds none left
    result, log = run(fmu, False, {"maxCycleTime": 0.001}, [{"n": 10001}, {"n": 10002}])
    assert result["rows"] == [["ok", 10001], ["error", 10001]]
    assert f"the loop at Forever.scl:{GOTO_LINE} ran out of the call's budget of 10000" in log


def refused_body(tmp_path, body: str) -> str:
    return tia_refused(
        tmp_path,
        "FUNCTION_BLOCK F\n   VAR_OUTPUT\n      o : Int;\n   END_VAR\nBEGIN\n"
        + body
        + "END_FUNCTION_BLOCK\n",
    )


# docs/scl.md rules: [S7-GOTO]
@pytest.mark.parametrize(
    "body, message",
    [
        (
            "   GOTO nowhere;\n",
            "t.scl:6:4: E003: GOTO nowhere: the block has no jump label 'nowhere'",
        ),
        (
            "   GOTO inner;\n   IF #o = 0 THEN\n   inner:\n      #o := 1;\n   END_IF;\n",
            "t.scl:6:4: E013: GOTO inner: a jump into an IF, CASE or loop (docs/scl.md §3.4 "
            "[S7-GOTO]); jump to a label of the GOTO's own statements or of those around them",
        ),
        (
            "   WHILE #o < 3 DO\n   step:\n      #o := #o + 1;\n   END_WHILE;\n   GOTO step;\n",
            "t.scl:10:4: E013: GOTO step: a jump into an IF, CASE or loop (docs/scl.md §3.4 "
            "[S7-GOTO]); jump to a label of the GOTO's own statements or of those around them",
        ),
        (
            "twice:\n   #o := 1;\nTWICE:\n   GOTO twice;\n",
            "t.scl:8:1: E004: the jump label 'TWICE' stands twice in the block",
        ),
    ],
)
def test_a_jump_s7_does_not_take_is_refused(tmp_path, body, message):
    assert refused_body(tmp_path, body) == message
