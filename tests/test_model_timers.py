"""Hand traces of the timer models of tests/models/timers.py against docs/behaviour.md §1.12 (the
rules T1-T8 of that module), without any FMU or C: call k at k · 100 ms unless a test says
otherwise, (Q, ET in ms) after each call."""

from tests.models.timers import TOF, TON, TP

F, T = False, True
CYCLE_US = 100_000


def run(timer, ins, pts, cycle_us=CYCLE_US):
    out = []
    for k, (i, pt) in enumerate(zip(ins, pts)):
        q = timer(k * cycle_us, i, pt)
        out.append((q, timer.et_ms))
    return out


def test_ton_q_once_in_has_been_true_for_pt():
    # T4: start at call 1 (100 ms); elapsed when t - 100 >= 300, i.e. call 4. IN FALSE in call 5
    # resets Q and ET; the rising edge in call 6 starts again (ET 0 in its own call).
    ins = [F, T, T, T, T, F, T]
    expected = [(F, 0), (F, 0), (F, 100), (F, 200), (T, 300), (F, 0), (F, 0)]
    assert run(TON(), ins, [300] * 7) == expected


def test_ton_keeps_the_pt_of_its_rising_edge():
    # T2: PT 300 at the edge in call 0; PT 100 later does not shorten it (Q at call 3); the next
    # start (call 5) takes 100 ms and elapses in call 6.
    ins = [T, T, T, T, F, T, T]
    pts = [300, 100, 100, 100, 100, 100, 100]
    expected = [(F, 0), (F, 100), (F, 200), (T, 300), (F, 0), (F, 0), (T, 100)]
    assert run(TON(), ins, pts) == expected


def test_ton_pt_zero_or_negative_gives_q_in_the_rising_call():
    # T2/T4: -500 is taken as 0: Q at once, ET 0 = PT; the later PT 300 does not apply (running).
    assert run(TON(), [T, T], [-500, 300]) == [(T, 0), (T, 0)]
    assert run(TON(), [T], [0]) == [(T, 0)]


def test_ton_et_counts_whole_ms_truncated():
    # T7 with a cycle of 3300 µs: elapsed 3300 µs -> 3 ms, 6600 -> 6 ms, 9900 -> 9 ms; PT 9 ms:
    # 9900 >= 9000, Q in call 3.
    assert run(TON(), [T, T, T, T], [9] * 4, cycle_us=3300) == [(F, 0), (F, 3), (F, 6), (T, 9)]


def test_tof_q_while_in_and_for_pt_after_it_falls():
    # T5: Q FALSE before any start (call 0); IN TRUE in calls 1-2; falling edge in call 3 (300 ms,
    # Q TRUE, ET 0); elapsed at 500 ms (call 5): Q FALSE, ET stays 200; IN TRUE in call 7 resets
    # ET to 0; the falling edge in call 8 restarts it.
    ins = [F, T, T, F, F, F, F, T, F]
    expected = [(F, 0), (T, 0), (T, 0), (T, 0), (T, 100), (F, 200), (F, 200), (T, 0), (T, 0)]
    assert run(TOF(), ins, [200] * 9) == expected


def test_tof_keeps_the_pt_of_its_falling_edge():
    # T2: PT 200 taken at the falling edge in call 1; 500 later does not lengthen it.
    ins = [T, F, F, F, F]
    pts = [200, 200, 500, 500, 500]
    assert run(TOF(), ins, pts) == [(T, 0), (T, 0), (T, 100), (F, 200), (F, 200)]


def test_tof_pt_zero_gives_no_pulse_beyond_the_edge():
    # T5: falling edge in call 1 with PT -7 (taken as 0): elapsed at once, Q FALSE in that call.
    assert run(TOF(), [T, F, F], [-7, -7, 300]) == [(T, 0), (F, 0), (F, 0)]


def test_tof_reset_timer():
    # T8: after RESET_TIMER the IN memory is FALSE, so IN FALSE is no falling edge: Q FALSE.
    tof = TOF()
    assert tof(0, T, 500) is True
    tof.reset()
    assert tof(100_000, F, 500) is False and tof.et_ms == 0


def test_tp_a_pulse_of_pt_that_ignores_edges_during_it():
    # T6: pulse from call 1 (100 ms) to 400 ms exclusive; the edge in call 3 is ignored; ET stays
    # 300 after it while IN is TRUE (call 5), 0 once IN is FALSE (call 6); call 7 starts anew.
    ins = [F, T, F, T, T, T, F, T]
    expected = [(F, 0), (T, 0), (T, 100), (T, 200), (F, 300), (F, 300), (F, 0), (T, 0)]
    assert run(TP(), ins, [300] * 8) == expected


def test_tp_keeps_the_pt_of_its_rising_edge_and_zero_gives_no_pulse():
    assert run(TP(), [T, T, T, F], [200, 900, 900, 900]) == [(T, 0), (T, 100), (F, 200), (F, 0)]
    assert run(TP(), [T, T], [0, 300]) == [(F, 0), (F, 0)]


def test_tp_edge_in_the_call_the_pulse_ends_starts_the_next_pulse():
    # T6 (§12.3): pulse 0 .. 200 ms; IN falls in call 1 and rises in call 2 (200 ms), the call in
    # which the pulse ends: the new pulse starts there, Q stays TRUE, ET 0; it ends at 400 ms.
    ins = [T, F, T, T, T]
    assert run(TP(), ins, [200] * 5) == [(T, 0), (T, 100), (T, 0), (T, 100), (F, 200)]


def test_tp_pulse_goes_on_after_in_falls_and_et_is_zero_after_it():
    # T6/T7: IN FALSE during the pulse does not end it; ET counts; at the end with IN FALSE ET = 0.
    assert run(TP(), [T, F, F, F], [200] * 4) == [(T, 0), (T, 100), (F, 0), (F, 0)]


def test_a_timer_not_executed_measures_the_time_since_its_start():
    # T1/T3: a TOF started at 0 and not executed until 1 s has elapsed there (time, not calls).
    tof = TOF()
    tof(0, T, 300)
    assert tof(100_000, F, 300) is True  # falling edge at 100 ms
    assert tof(1_000_000, F, 300) is False and tof.et_ms == 300
