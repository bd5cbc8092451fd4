"""A compiled program reads an IEC timer's Q and ET as the S7 does: the timer is updated when
the program reads them, with the time of the read, not only when it runs (S7-1200 System
Manual V4.2 §8.2; docs/behaviour.md §1.12, docs/scl.md §3.6). Hand traces, cycle 100 ms."""

from __future__ import annotations

import pytest

from lgf_fmus import scl
from tests.scl.driver import compile_text, run_cs

SOURCE = """
FUNCTION_BLOCK "ReadTimers"
   VAR_INPUT
      in : Bool;
   END_VAR
   VAR_OUTPUT
      tonBefore : Bool;
      etBefore : Time;
      tonAfter : Bool;
      tofBefore : Bool;
      tpBefore : Bool;
   END_VAR
   VAR
      onDelay : TON;
      offDelay : TOF;
      pulse : TP;
   END_VAR
BEGIN
    // read before the instance runs in this call
    #tonBefore := #onDelay.Q;
    #etBefore := #onDelay.ET;
    #tofBefore := #offDelay.Q;
    #tpBefore := #pulse.Q;
    #onDelay(IN := #in, PT := T#300ms);
    #offDelay(IN := #in, PT := T#200ms);
    #pulse(IN := #in, PT := T#200ms);
    #tonAfter := #onDelay.Q;
END_FUNCTION_BLOCK
"""


@pytest.fixture(scope="module", params=[2, 3])
def fmu(request, tmp_path_factory):
    return compile_text(tmp_path_factory.mktemp("reads"), SOURCE, "ReadTimers", request.param)


# docs/scl.md rules: [S7-TIMER-READ]
def test_reads_before_the_call_see_the_time_of_the_read(fmu):
    # IN TRUE in calls 0-4 (TON from 0 ms, PT 300 ms; TP pulse 0-200 ms), FALSE from call 5
    # (TOF from 500 ms, PT 200 ms).
    ins = [True] * 5 + [False] * 4
    rows = run_cs(fmu, 100_000, {}, {"in": ins[0]}, [(100_000, {"in": x}) for x in ins[1:]])
    col = lambda name: [r[name] for r in rows]  # noqa: E731
    F, T = False, True
    # call 3 at 300 ms: the read before the TON runs already sees it elapsed (with the value
    # the last call left, it would be FALSE and 200 ms)
    assert col("tonBefore") == [F, F, F, T, T, T, F, F, F]
    assert col("etBefore") == [0, 0.1, 0.2, 0.3, 0.3, 0.3, 0, 0, 0]
    assert col("tonAfter") == [F, F, F, T, T, F, F, F, F]
    # TOF: IN fell in call 5 (500 ms): the read in call 7 (700 ms) sees its 200 ms passed
    assert col("tofBefore") == [F, T, T, T, T, T, T, F, F]
    # TP: the pulse of 0-200 ms ends for the read in call 2 (200 ms)
    assert col("tpBefore") == [F, T, F, F, F, F, F, F, F]


IEC_TIMERS = """
FUNCTION_BLOCK "OnOff"
   VAR_INPUT
      in : Bool;
   END_VAR
   VAR_OUTPUT
      out : Bool;
   END_VAR
   VAR
      instOn {InstructionName := 'IEC_TIMER'; LibVersion := '1.0'} : IEC_TIMER;
      instOff : IEC_TIMER;
   END_VAR
BEGIN
    #instOn.TON(IN := #in, PT := T#200ms);
    #instOff.TOF(IN := #instOn.Q, PT := T#300ms);
    #out := #instOff.Q;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-TIMER]
def test_iec_timer_multi_instances_as_tia_writes_them(tmp_path):
    """`inst : IEC_TIMER` run as `#inst.TON(...)` (LGF_IecTimerOnOff's form): the timer the
    block runs on it. in TRUE in calls 0-4: the TON's Q from 200 ms, the TOF's until 300 ms
    after it falls (in call 5, at 500 ms)."""
    fmu = compile_text(tmp_path, IEC_TIMERS, "OnOff")
    ins = [True] * 5 + [False] * 5
    rows = run_cs(fmu, 100_000, {}, {"in": ins[0]}, [(100_000, {"in": x}) for x in ins[1:]])
    F, T = False, True
    assert [r["out"] for r in rows] == [F, F, T, T, T, T, T, T, F, F]


def test_an_iec_timer_must_run_one_timer(tmp_path):
    two = IEC_TIMERS.replace("#instOff.TOF(", "#instOn.TOF(")
    with pytest.raises(scl.SclError) as refused:
        compile_text(tmp_path, two, "OnOff")
    assert "the IEC_TIMER 'instOn' must run one timer, #instOn.TON/TOF/TP(...), not TOF, TON" in (
        str(refused.value)
    )


RESET = """
FUNCTION_BLOCK "Reset"
   VAR_INPUT
      reset : Bool;
   END_VAR
   VAR_OUTPUT
      q : Bool;
   END_VAR
   VAR
      t : TON;
   END_VAR
BEGIN
    IF #reset THEN
        RESET_TIMER(#t);
    END_IF;
    #t(IN := TRUE, PT := T#300ms);
    #q := #t.Q;
END_FUNCTION_BLOCK
"""


# docs/scl.md rules: [S7-RESET-TIMER]
def test_reset_timer_starts_the_timer_anew(tmp_path):
    """LGF_Frequency resets its timers on new settings: RESET_TIMER sets the timer back to
    before its first run, so IN TRUE is a rising edge again. TON 300 ms from 0 ms: Q at
    300 ms; reset in call 4 (400 ms): it starts again, Q at 700 ms."""
    fmu = compile_text(tmp_path, RESET, "Reset")
    resets = [k == 4 for k in range(8)]
    rows = run_cs(fmu, 100_000, {}, {"reset": False}, [(100_000, {"reset": r}) for r in resets[1:]])
    F, T = False, True
    assert [r["q"] for r in rows] == [F, F, F, T, F, F, F, T]


def test_reset_timer_is_a_statement(tmp_path):
    value = RESET.replace("RESET_TIMER(#t);", "#q := RESET_TIMER(#t);")
    with pytest.raises(scl.SclError) as refused:
        compile_text(tmp_path, value, "Reset")
    assert "RESET_TIMER has no value: call it as a statement" in str(refused.value)
