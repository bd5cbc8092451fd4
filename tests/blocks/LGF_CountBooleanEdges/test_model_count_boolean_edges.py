"""Hand traces of the CountBooleanEdges model against docs/behaviour.md §12 (no FMU): call k at
k · cycle."""

import pytest

from .model import CountBooleanEdges

F, T = False, True


def run(trigger, monitor, cycle_us=100_000):
    """Per call the shown result as (name or None, noOfEdges) and the model's edges after it."""
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


def test_worked_example_of_12_3():
    # §12.3: monitorTime 0.5 s. Call 0 rises (pulse 0 .. 0.5 s), call 2 rises (edges 2); call 5:
    # q FALSE, qPrevious TRUE, trigger FALSE -> double, 2, then edges 0. Call 8 rises (pulse 0.8 ..
    # 1.3 s), held: call 13 long, 1, held through call 14; call 15: trigger FALSE -> cleared.
    trigger = [T, F, T, F, F, F, F, F, T, T, T, T, T, T, T, F, F, F]
    out = run(trigger, 0.5)
    assert [e for _, _, e in out] == [1, 1, 2, 2, 2, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0]
    expected = [(None, 0)] * 5 + [("double", 2)] + [(None, 0)] * 7
    expected += [("long", 1), ("long", 1)] + [(None, 0)] * 3
    assert shown(out) == expected


def test_single_lasts_exactly_one_call():
    # §12.3: one edge, trigger FALSE when the time (0.3 s) ends in call 3: single, 1, for one call.
    out = run([T, F, F, F, F], 0.3)
    assert shown(out) == [(None, 0)] * 3 + [("single", 1), (None, 0)]


def test_several_edges_and_held_double():
    # §12.3: three edges in 0.5 s (calls 0, 2, 4), trigger FALSE at the end (call 5): severalEdges,
    # 3. Two edges with trigger held at the end: double while held, cleared when it falls.
    out = run([T, F, T, F, T, F, F], 0.5)
    assert shown(out)[5] == ("severalEdges", 3)
    out = run([T, F, T, T, T, T, T, F, F], 0.5)
    assert shown(out)[5:] == [("double", 2), ("double", 2), (None, 0), (None, 0)]
    assert [e for _, _, e in out][5:] == [2, 2, 0, 0]


def test_edge_in_the_call_the_time_ends_merges_windows():
    # §12.3: pulse 0 .. 0.3 s; an edge in call 3 (where it ends) restarts the TP at once: q stays
    # TRUE, no result; its edge counts on: edges 2 -> pulse 0.3 .. 0.6 s ends in call 6 with
    # trigger FALSE: double, 2.
    out = run([T, F, F, T, F, F, F, F], 0.3)
    assert shown(out) == [(None, 0)] * 6 + [("double", 2), (None, 0)]


def test_monitor_time_zero_or_negative_classifies_each_edge_in_its_own_call():
    # §12.3: q is never TRUE: long (1) while trigger stays TRUE after an edge; cleared when it
    # falls. A one-call pulse: the edge is long in its own call (trigger TRUE), then cleared.
    for pt in (0.0, -1.0):
        out = run([T, T, F, T, F, F], pt)
        long = ("long", 1)
        assert shown(out) == [long, long, (None, 0), long, (None, 0), (None, 0)]


def test_new_monitor_time_takes_effect_at_the_next_starting_edge():
    # §12.3, §1.12: 0.2 s taken at the edge of call 0; 1.0 s from call 1 does not lengthen it:
    # single in call 2. The next edge (call 4) takes 1.0 s: ends at 1.4 s = call 14.
    trigger = [T, F, F, F, T] + [F] * 11
    monitor = [0.2] + [1.0] * 15
    out = run(trigger, monitor)
    assert shown(out)[2] == ("single", 1)
    assert [k for k, (name, _) in enumerate(shown(out)) if name] == [2, 14]


def test_monitor_time_rounded_to_whole_ms():
    # §1.4: 0.0015 s -> 1.5 ms, halves away from zero -> 2 ms. Cycle 1 ms: the PT of 2 ms taken in
    # call 0 ends in call 2.
    out = run([T, F, F, F], 0.0015, cycle_us=1000)
    assert shown(out) == [(None, 0), (None, 0), ("single", 1), (None, 0)]


def test_usint_wraps():
    # §12.2 step 3: edges is a USINT. Cycle 1 ms, monitorTime 0.6 s: the window 0 .. 600 ms ends in
    # call 600, trigger FALSE there. Edges in calls 0, 2, 4, …:
    # 255 edges (calls 0 … 508): severalEdges, 255;
    out = run([T, F] * 255 + [F] * 100, 0.6, cycle_us=1000)
    assert shown(out)[600] == ("severalEdges", 255)
    # 256 edges (calls 0 … 510): 255 + 1 wraps to 0: no result (edges = 0: none);
    out = run([T, F] * 256 + [F] * 100, 0.6, cycle_us=1000)
    assert out[599][2] == 0 and [name for name, _ in shown(out)] == [None] * len(out)
    # 257 edges (calls 0 … 512): 0 + 1 = 1: single, 1.
    out = run([T, F] * 257 + [F] * 100, 0.6, cycle_us=1000)
    assert shown(out)[600] == ("single", 1)


def test_start_values_give_long_from_1_s():
    # §12.1: trigger TRUE, monitorTime 1.0 s: the first call is an edge; from call 10 (1.0 s) on
    # long, 1, as long as trigger stays TRUE.
    out = run([T] * 13, 1.0)
    assert shown(out) == [(None, 0)] * 10 + [("long", 1)] * 3


def test_refused_values():
    m = CountBooleanEdges(100_000)
    for bad in (float("nan"), 2147483.648, -2147483.648):
        with pytest.raises(ValueError):
            m.call(0, {"trigger": True, "monitorTime": bad})
