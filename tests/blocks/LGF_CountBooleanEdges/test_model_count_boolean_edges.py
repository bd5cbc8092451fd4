"""Hand traces of the CountBooleanEdges model against the original block's program (no FMU): call
k at k · cycle. The original executes its TP only at an edge (IN TRUE) and when it clears a
result (IN FALSE), and otherwise reads its Q, which the S7 update on read (docs/behaviour.md
§1.12) shows at the reading call's time."""

import pytest

from .model import CountBooleanEdges

F, T = False, True


def run(trigger, monitor, cycle_us=100_000):
    """Per call the shown result as (name or None, noOfEdges) and the edge counter after it."""
    n = len(trigger)
    monitor = monitor if isinstance(monitor, list) else [monitor] * n
    m = CountBooleanEdges(cycle_us)
    out = []
    for k in range(n):
        o = m.call(k * cycle_us, {"trigger": trigger[k], "monitorTime": monitor[k]})
        names = [x for x in ("single", "double", "long", "severalEdges") if o[x]]
        assert len(names) <= 1
        out.append((names[0] if names else None, o["noOfEdges"], m.edges))
    return out


def shown(out):
    return [(name, n) for name, n, _ in out]


def counts(out):
    return [e for _, _, e in out]


NONE = (None, 0)


def test_two_edges_then_a_held_one():
    # monitorTime 0.5 s. Call 0: edge, the TP starts at 0 s, counter 1, Q TRUE. Call 2: edge, the
    # TP's IN was TRUE already: no restart, counter 2. Call 5 (0.5 s): Q read FALSE, trigger
    # FALSE but no result yet: double, 2, flag set. Call 6: trigger FALSE and flag: cleared, the
    # TP gets IN FALSE. Call 8: edge, the TP starts at 0.8 s; call 13 (1.3 s): long, 1, while
    # held (call 14); call 15: cleared.
    trigger = [T, F, T, F, F, F, F, F, T, T, T, T, T, T, T, F, F, F]
    out = run(trigger, 0.5)
    assert counts(out) == [1, 1, 2, 2, 2, 2, 0, 0, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0]
    expected = [NONE] * 5 + [("double", 2)] + [NONE] * 7 + [("long", 1)] * 2 + [NONE] * 3
    assert shown(out) == expected


def test_single_lasts_one_call():
    # one edge, trigger FALSE when the time (0.3 s) ends in call 3: single, 1; call 4 clears.
    out = run([T, F, F, F, F, F], 0.3)
    assert shown(out) == [NONE] * 3 + [("single", 1)] + [NONE] * 2
    assert counts(out) == [1, 1, 1, 1, 0, 0]


def test_several_edges():
    # edges in calls 0, 2, 4 in 0.5 s, trigger FALSE in call 5: severalEdges, 3; call 6 clears.
    out = run([T, F, T, F, T, F, F], 0.5)
    assert shown(out)[5:] == [("severalEdges", 3), NONE]
    # two edges, trigger held at the end: double while held, cleared when it falls.
    out = run([T, F, T, T, T, T, T, F, F], 0.5)
    assert shown(out)[5:] == [("double", 2), ("double", 2), NONE, NONE]
    assert counts(out)[5:] == [2, 2, 0, 0]


def test_an_edge_in_the_call_the_window_ends_counts_into_it():
    # Window 0 .. 0.5 s; the edge of call 5 (0.5 s) runs the TP with IN TRUE, whose IN is TRUE
    # already: no restart; counter 2, Q read FALSE: double, 2, in call 5 itself; held: double;
    # call 7 with trigger FALSE clears.
    out = run([T, F, F, F, F, T, T, F, F], 0.5)
    assert shown(out) == [NONE] * 5 + [("double", 2)] * 2 + [NONE] * 2
    assert counts(out) == [1, 1, 1, 1, 1, 2, 2, 0, 0]


def test_an_edge_right_after_a_result_counts_into_the_old_window():
    # single in call 5 (window 0 .. 0.5 s, trigger FALSE); the edge of call 6 comes before a
    # call with trigger FALSE cleared the result: no new window, counter 2: double, 2, in call 6
    # and while held (call 7); call 8 clears; the edge of call 9 starts a new window (0.9 s ..
    # 1.4 s): nothing until call 14 (long, held).
    trigger = [T, F, F, F, F, F, T, T, F, T, T, T, T, T, T]
    out = run(trigger, 0.5)
    assert shown(out) == [NONE] * 5 + [("single", 1)] + [("double", 2)] * 2 + [NONE] * 6 + [
        ("long", 1)
    ]
    assert counts(out)[5:10] == [1, 2, 2, 0, 1]


def test_the_window_ends_in_a_call_that_does_not_run_the_tp():
    # Held TRUE from call 0: the TP runs only in call 0; calls 1 … 9 only read its Q, which turns
    # FALSE at 1.0 s (call 10): long, 1, from call 10 on.
    out = run([T] * 12, 1.0)
    assert shown(out) == [NONE] * 10 + [("long", 1)] * 2


def test_monitor_time_0_or_negative():
    # PT 0 (and a negative one, taken as 0) gives no pulse: each starting edge is classified in
    # its own call; long while held; cleared in the first call with trigger FALSE.
    for pt in (0.0, -0.05):
        out = run([T, T, F, T, F, F], pt)
        assert shown(out) == [("long", 1), ("long", 1), NONE, ("long", 1), NONE, NONE]


def test_monitor_time_taken_at_the_start():
    # PT 0.5 s taken at call 0; monitorTime 0.2 s from call 1 on does not shorten this window:
    # the result comes in call 5. The next window (edge in call 7) takes 0.2 s: result call 9.
    trigger = [T, F, F, F, F, F, F, T, F, F, F]
    out = run(trigger, [0.5] + [0.2] * 10)
    assert shown(out) == [NONE] * 5 + [("single", 1)] + [NONE] * 3 + [("single", 1), NONE]


def test_a_cycle_off_the_ms_grid():
    # cycle 3.3 ms, window 10 ms from 0: calls at 3.3, 6.6, 9.9 ms still in it; call 4 (13.2 ms).
    out = run([T, F, T, F, F, F], 0.01, cycle_us=3300)
    assert shown(out) == [NONE] * 4 + [("double", 2), NONE]


def test_256_edges_wrap_the_counter_to_0():
    # window 100 s; edges in calls 0, 2, …, 510 (256 edges): the counter wraps to 0; at the end
    # of the window (call 1000) nothing is shown and no flag is set, so nothing is cleared and
    # the TP keeps IN TRUE: the edge of call 1001 starts no window and is classified at once
    # (long, 1); call 1002 clears (the TP gets IN FALSE); the edge of call 1003 starts a window.
    trigger = [k % 2 == 0 and k <= 510 for k in range(1000)] + [F, T, F, T, T]
    out = run(trigger, 100.0)
    assert counts(out)[510] == 0
    assert all(s == NONE for s in shown(out)[:1001])
    assert shown(out)[1001:] == [("long", 1), NONE, NONE, NONE]


def test_255_edges():
    trigger = [k % 2 == 0 and k <= 508 for k in range(1000)] + [F]
    out = run(trigger, 100.0)
    assert shown(out)[1000] == ("severalEdges", 255)


def test_refused_monitor_time():
    m = CountBooleanEdges(100_000)
    for bad in (float("nan"), 2147484.0):
        with pytest.raises(ValueError):
            m.call(0, {"trigger": True, "monitorTime": bad})
