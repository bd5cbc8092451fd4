"""LGF_CountBooleanEdges against the rules of docs/behaviour.md §12, with hand-computed
expectations (each trace is worked out from the block's original SCL, as §12.2 states it, in the
comments, never taken from the FMU). The TP is executed only at an edge (IN TRUE) and when the
count is cleared (IN FALSE); between, its Q is read with the S7 update on read (§1.12).

Call k happens at k·cycle; the trigger value of call k is set before the step that ends there
(call 0: in initialization)."""

import math

import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of

BLOCK = "LGF_CountBooleanEdges"
F, T = False, True
FLAGS = ("single", "double", "long", "severalEdges")


def run(triggers, monitor, cycle=0.1, changes=None):
    """The outputs of every call: call k sees triggers[k] (and changes[k], if any)."""
    changes = changes or {}
    s = Slave(
        BLOCK,
        {"cycleTime": cycle},
        {"trigger": triggers[0], "monitorTime": monitor, **changes.get(0, {})},
    )
    rows = [s.outputs()]
    for k in range(1, len(triggers)):
        s.set({"trigger": triggers[k], **changes.get(k, {})})
        rows.append(s.step(cycle))
    s.free()
    return rows


def shown(rows):
    """Per call: the TRUE flag's name (or '-') and noOfEdges."""
    out = []
    for r in rows:
        flags = [name for name in FLAGS if r[name]]
        assert len(flags) <= 1, r  # §12.2 step 4: at most one case applies
        out.append((flags[0] if flags else "-", r["noOfEdges"]))
    return out


def pulses(length, *true_calls):
    return [k in true_calls for k in range(length)]


def test_worked_example():
    # docs/behaviour.md §12.3: cycle 0.1 s, monitorTime 0.5 s.
    # call 0 rises: pulse from 0.0 s, edges 1; call 2 rises: edges 2 (the TP, executed again
    # with IN TRUE, runs on); call 5 (0.5 s) is the first at or after 0.0 + 0.5: Q read FALSE,
    # trigger FALSE, nothing shown yet -> double, 2. Call 6: trigger FALSE, a result was shown:
    # cleared, edges 0, the TP gets IN FALSE. Call 8 rises: pulse 0.8 ... 1.3 s, held to call
    # 14; call 13: long, 1; call 14 (trigger still TRUE): long, 1; call 15 (FALSE): cleared.
    triggers = [T, F, T, F, F, F, F, F, T, T, T, T, T, T, T, F, F, F]
    expected = (
        [("-", 0)] * 5 + [("double", 2)] + [("-", 0)] * 7 + [("long", 1)] * 2 + [("-", 0)] * 3
    )
    assert shown(run(triggers, 0.5)) == expected


def test_single_lasts_exactly_one_call():
    # call 2 rises (pulse 0.2 ... 0.7 s), FALSE from call 3. The TP is not executed again; Q
    # read in calls 3 ... 6 is TRUE, in call 7 (0.7 s) FALSE (update on read): single, 1. Call
    # 8: trigger FALSE after a result: cleared; then nothing
    rows = shown(run(pulses(12, 2), 0.5))
    assert rows == [("-", 0)] * 7 + [("single", 1)] + [("-", 0)] * 4


def test_long_then_release_clears_without_a_single():
    # rises at call 1, held to call 9: pulse 0.1 ... 0.4 s; long from call 4 (0.4 s) to call 9;
    # call 10 FALSE: Q FALSE, trigger FALSE, a result was shown: cleared (no single), edges 0
    triggers = [F] + [T] * 9 + [F] * 4
    expected = [("-", 0)] * 4 + [("long", 1)] * 6 + [("-", 0)] * 4
    assert shown(run(triggers, 0.3)) == expected


def test_several_edges_and_double_held():
    # three edges (calls 0, 2, 4), window 0.0 ... 1.0 s: severalEdges, 3 at call 10, one call
    assert shown(run(pulses(13, 0, 2, 4), 1.0))[9:12] == [("-", 0), ("severalEdges", 3), ("-", 0)]
    # ten edges (calls 0, 2, ..., 18) in a window of 2 s: severalEdges, 10 at call 20
    assert shown(run(pulses(22, *range(0, 20, 2)), 2.0))[19:22] == [
        ("-", 0),
        ("severalEdges", 10),
        ("-", 0),
    ]
    # two edges, the second held (calls 0 and 2..7): double from call 5 while TRUE (5, 6, 7)
    triggers = [T, F, T, T, T, T, T, T, F, F]
    assert shown(run(triggers, 0.5)) == [("-", 0)] * 5 + [("double", 2)] * 3 + [("-", 0)] * 2


def test_the_window_ends_at_the_first_call_at_or_after_start_plus_pt_in_whole_ms():
    # cycle 0.05 s; 0.2504 s -> 250 ms: call 0 + 0.25 s = call 5; 0.2506 s -> 251 ms: call 6
    assert [r[0] for r in shown(run(pulses(8, 0), 0.2504, cycle=0.05))].index("single") == 5
    assert [r[0] for r in shown(run(pulses(8, 0), 0.2506, cycle=0.05))].index("single") == 6
    # a PT that is not a multiple of the cycle: 0.25 s at cycle 0.1 s ends at call 3 (0.3 s)
    assert [r[0] for r in shown(run(pulses(6, 0), 0.25))].index("single") == 3


def test_a_new_monitor_time_waits_for_the_next_start():
    # PT 1.0 s taken at call 0; 0.2 s from call 2 on: the window still ends at call 10; the
    # next one, started at call 12, takes 0.2 s and ends at call 14
    triggers = pulses(17, 0, 12)
    rows = shown(run(triggers, 1.0, changes={2: {"monitorTime": 0.2}}))
    assert [k for k, r in enumerate(rows) if r != ("-", 0)] == [10, 14]
    assert rows[10] == rows[14] == ("single", 1)


def test_an_edge_in_the_call_the_time_ends_counts_into_that_window():
    # call 0 rises: TP executed with IN TRUE, pulse 0 ... 0.5 s, edges 1. Calls 1 ... 4: no
    # edge, the TP is not executed; its Q read (update on read, §1.12) is TRUE. Call 5 (0.5 s)
    # rises again: the TP is executed with IN TRUE, but its IN was TRUE at its last execution,
    # so no edge for the timer and no restart; edges 2. Q read: FALSE (0.5 s elapsed), trigger
    # TRUE, no result shown yet -> double, 2. Call 6: trigger FALSE, a result was shown ->
    # cleared (the TP gets IN FALSE), all FALSE.
    rows = shown(run(pulses(12, 0, 5), 0.5))
    assert rows == [("-", 0)] * 5 + [("double", 2)] + [("-", 0)] * 6
    # the same with edges at calls 0 and 2 before: the third edge, at call 5, makes it several
    rows = shown(run(pulses(8, 0, 2, 5), 0.5))
    assert rows == [("-", 0)] * 5 + [("severalEdges", 3)] + [("-", 0)] * 2


def test_an_edge_right_after_a_result_counts_into_the_old_window():
    # call 0 rises (TP from 0.0 s, PT 0.5 s, edges 1), FALSE from call 1. Call 5: Q FALSE,
    # trigger FALSE, nothing shown yet -> single, 1 (a result is now shown). Call 6 rises
    # before any call with trigger FALSE has cleared it: the TP's IN is still TRUE from call 0,
    # so it does not restart; edges 2; Q FALSE, trigger TRUE -> double, 2; call 7 (held):
    # double, 2. Call 8 FALSE: cleared, the TP gets IN FALSE. Call 9: nothing to show. Call 10
    # rises: the TP's IN goes FALSE -> TRUE, a new pulse 1.0 ... 1.5 s, edges 1; call 15
    # (1.5 s, trigger FALSE): single, 1; call 16: cleared.
    triggers = pulses(17, 0, 6, 7, 10)
    expected = (
        [("-", 0)] * 5
        + [("single", 1)]
        + [("double", 2)] * 2
        + [("-", 0)] * 7
        + [("single", 1)]
        + [("-", 0)]
    )
    assert shown(run(triggers, 0.5)) == expected


def test_a_long_result_held_then_released_and_risen_again():
    # call 0 rises and is held: long from call 5 (0.5 s) while TRUE (5, 6). Call 7 FALSE:
    # cleared (TP IN FALSE). Call 8 rises: a new pulse 0.8 ... 1.3 s; FALSE from call 9; call 13
    # (1.3 s): single, 1.
    triggers = [True] * 7 + [False, True] + [False] * 6
    expected = [("-", 0)] * 5 + [("long", 1)] * 2 + [("-", 0)] * 6 + [("single", 1), ("-", 0)]
    assert shown(run(triggers, 0.5)) == expected


@pytest.mark.parametrize("monitor", [0.0, -0.3])
def test_no_monitoring_time_shows_each_edge_at_once(monitor):
    # q is never TRUE: call 1 rises (edges 1, trigger TRUE -> long, 1), call 2 FALSE (cleared);
    # calls 4..6 TRUE: long, 1 in each; call 7 FALSE: nothing
    triggers = [F, T, F, F, T, T, T, F]
    assert shown(run(triggers, monitor)) == [
        ("-", 0),
        ("long", 1),
        ("-", 0),
        ("-", 0),
        ("long", 1),
        ("long", 1),
        ("long", 1),
        ("-", 0),
    ]


def test_the_edge_counter_is_a_usint():
    # cycle 1 ms, window 1 s (calls 0 ... 999, result at call 1000). 256 edges (calls 0, 2, ...,
    # 510) wrap the count to 0: nothing shown. 257 edges (to call 512): count 1, trigger FALSE:
    # single, 1. 300 edges: 300 - 256 = 44: severalEdges, 44.
    for edges, expected in [(256, ("-", 0)), (257, ("single", 1)), (300, ("severalEdges", 44))]:
        triggers = pulses(1002, *range(0, 2 * edges, 2))
        rows = shown(run(triggers, 1.0, cycle=0.001))
        assert rows[1000] == expected, edges
        assert set(rows[:1000]) == {("-", 0)}  # nothing while the time runs


def test_a_window_whose_count_wrapped_to_zero_is_never_cleared():
    # 256 edges as above: at call 1000 the count is 0, so no result is shown and nothing is
    # ever cleared: the TP is not executed with IN FALSE and keeps IN TRUE. The edge at call
    # 1100 therefore starts no pulse (no IN edge for the timer): count 1, Q FALSE, trigger
    # TRUE -> long, 1 at once. Call 1101 FALSE: cleared, the TP gets IN FALSE. The edge at call
    # 1110 starts a pulse again (1.11 ... 2.11 s): single, 1 at call 2110 (trigger FALSE).
    triggers = pulses(2112, *range(0, 512, 2), 1100, 1110)
    rows = shown(run(triggers, 1.0, cycle=0.001))
    assert [(k, r) for k, r in enumerate(rows) if r != ("-", 0)] == [
        (1100, ("long", 1)),
        (2110, ("single", 1)),
    ]


def test_the_start_values_show_long_after_seven_tenths_of_a_second():
    # trigger TRUE and monitorTime 0.7 s (docs/behaviour.md §12.1): call 0 rises, long from call
    # 7 (0.7 s) on, single stays FALSE
    s = Slave(BLOCK)
    rows = [s.outputs()] + [s.step(0.1) for _ in range(20)]
    assert [r["long"] for r in rows] == [F] * 7 + [T] * 14
    assert not any(r["single"] for r in rows)
    assert rows[-1]["noOfEdges"] == 1
    s.free()


def test_every_call_of_a_step_sees_the_same_trigger():
    # one step of 0.3 s with trigger TRUE is calls 1, 2, 3 with TRUE: one edge (call 1); then a
    # step of 0.2 s FALSE (calls 4, 5), a step of 0.1 s TRUE (call 6, second edge); window 0.1
    # ... 0.8 s ends at call 8: double, 2
    s = Slave(BLOCK, {"cycleTime": 0.1}, {"trigger": F, "monitorTime": 0.7})
    s.set({"trigger": T})
    s.step(0.3)
    s.set({"trigger": F})
    s.step(0.2)
    s.set({"trigger": T})
    s.step(0.1)
    s.set({"trigger": F})
    assert s.step(0.1)["double"] == F  # call 7
    r = s.step(0.1)  # call 8
    assert (r["double"], r["noOfEdges"]) == (T, 2)
    s.free()


@pytest.mark.parametrize("value", [math.nan, 2147483.648, -2147484.0, math.inf])
def test_monitor_time_outside_time_is_refused(value):
    s = Slave(BLOCK, {"cycleTime": 0.1}, {"trigger": F, "monitorTime": 0.5})
    before = s.outputs()
    assert status_of(s.fmu.setReal, [s.vr("monitorTime")], [value]) == fmi2Error
    assert s.get(["monitorTime"])["monitorTime"] == 0.5
    assert s.outputs() == before
    s.free()


def test_outputs_are_not_settable():
    s = Slave(BLOCK)
    assert status_of(s.fmu.setInteger, [s.vr("noOfEdges")], [3]) == fmi2Error
    assert status_of(s.fmu.setBoolean, [s.vr("long")], [True]) == fmi2Error
    s.free()
