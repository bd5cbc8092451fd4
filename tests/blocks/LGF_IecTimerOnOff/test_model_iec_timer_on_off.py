"""Hand traces of the IecTimerOnOff model against docs/behaviour.md §8 (no FMU): call k at
k · cycle, `out` after each call."""

import pytest

from .model import IecTimerOnOff

F, T = False, True


def run(ins, on, off, cycle_us=100_000):
    """`out` per call; on/off are one delay in s for every call, or a list per call."""
    n = len(ins)
    on = on if isinstance(on, list) else [on] * n
    off = off if isinstance(off, list) else [off] * n
    m = IecTimerOnOff(cycle_us)
    return [
        m.call(k * cycle_us, {"in": ins[k], "timeOnDelay": on[k], "timeOffDelay": off[k]})["out"]
        for k in range(n)
    ]


def test_worked_example_of_8_3():
    # §8.3 table: on 0.3 s, off 0.2 s. TON starts in call 1, elapses in call 4 (0.4 - 0.1 >= 0.3);
    # TOF starts in call 6, elapses in call 8 (0.8 - 0.6 >= 0.2); the pulse in call 9 is too short.
    ins = [F, T, T, T, T, T, F, F, F, T, F, F, F]
    out = [F, F, F, F, T, T, T, T, F, F, F, F, F]
    assert run(ins, 0.3, 0.2) == out


def test_start_values_show_the_on_delay():
    # §8.1: in TRUE, on 1 s, off 2 s, cycle 0.1 s: out FALSE up to 0.9 s, TRUE from 1.0 s on.
    out = run([T] * 15, 1.0, 2.0)
    assert out == [F] * 10 + [T] * 5


def test_both_delays_zero_out_equals_in():
    # §8.3: TON PT 0 gives Q in the rising call; TOF PT 0 gives Q FALSE in the falling call.
    ins = [F, T, F, T, T, F, F, T]
    assert run(ins, 0.0, 0.0) == ins


def test_negative_delays_act_as_zero():
    # §8.1, §1.12: a negative PT is taken as 0.
    ins = [T, T, F, T, F]
    assert run(ins, -1.0, -2147483.647) == ins


def test_call_0_in_true_is_a_rising_edge():
    # §8.2: with on 0.1 s the TON starts in call 0 and elapses in call 1 (0.1 - 0 >= 0.1).
    assert run([T, T, T], 0.1, 0.0) == [F, T, T]


def test_off_delay_and_retrigger_without_gap():
    # §8.3: on 0.1 s, off 0.3 s. TON: start call 0, Q from call 1. in falls in call 3 (TOF start
    # 0.3 s, would elapse at 0.6 s = call 6). in rises in call 4, TON elapses in call 5
    # (0.5 - 0.4 >= 0.1) before call 6: out stays TRUE without a gap.
    ins = [T, T, T, F, T, T, T, T]
    assert run(ins, 0.1, 0.3) == [F, T, T, T, T, T, T, T]


def test_off_delay_and_retrigger_with_gap():
    # §8.3: on 0.3 s, off 0.2 s. Q_TON from call 3; in falls in call 4 (TOF 0.4 .. 0.6 s); in rises
    # in call 5, TON would elapse in call 8 (0.8 - 0.5 >= 0.3): out falls in call 6, rises in 8.
    ins = [T, T, T, T, F, T, T, T, T]
    assert run(ins, 0.3, 0.2) == [F, F, F, T, T, T, F, F, T]


def test_ton_elapsing_in_the_call_the_tof_would_elapse_leaves_no_gap():
    # §8.3 "at or before the one in which the TOF would elapse (the TON runs first)". On 0.2 s:
    # Q_TON from call 2; in falls in call 3 (TOF started at 0.3 s); in rises in call 4 (TON
    # started at 0.4 s, elapses at 0.6 s = call 6).
    ins = [T, T, T, F, T, T, T, T]
    # off 0.2 s: the TOF elapses at 0.5 s = call 5, before the TON: out FALSE in call 5 only.
    assert run(ins, 0.2, 0.2) == [F, F, T, T, T, F, T, T]
    # off 0.3 s: the TOF would elapse at 0.6 s = call 6, where the TON's Q is TRUE first: no gap.
    assert run(ins, 0.2, 0.3) == [F, F, T, T, T, T, T, T]


def test_short_pulse_never_reaches_out():
    # §8.3: on 0.3 s; in TRUE for 3 calls (0.0 .. 0.2 s) never has the TON elapsed.
    assert run([T, T, T, F, F], 0.3, 0.0) == [F] * 5


def test_delay_changed_while_running_takes_effect_at_next_start():
    # §8.3, §1.12: on 0.5 s at the edge of call 0; 0.1 s from call 1 on does not shorten it
    # (elapses in call 5); the next start (call 7) takes 0.1 s and elapses in call 8.
    ins = [T, T, T, T, T, T, F, T, T]
    on = [0.5] + [0.1] * 8
    assert run(ins, on, 0.0) == [F, F, F, F, F, T, F, F, T]


def test_off_delay_taken_at_the_falling_edge_of_the_ton_q():
    # §8.3: off 0.1 s when Q_TON falls in call 2; 0.5 s afterwards does not lengthen it: out falls
    # in call 3 (0.3 - 0.2 >= 0.1).
    ins = [T, T, F, F, F, F]
    off = [0.1, 0.1, 0.1, 0.5, 0.5, 0.5]
    assert run(ins, 0.0, off) == [T, T, T, F, F, F]


def test_delays_off_the_cycle_grid_end_at_the_next_call():
    # §8.3: cycle 0.1 s, on 0.25 s: out TRUE 0.3 s after t_on (call 3 for t_on = 0).
    assert run([T] * 5, 0.25, 0.0) == [F, F, F, T, T]


def test_timers_measure_time_in_us_with_a_cycle_off_the_ms_grid():
    # §8.2: elapsed = t_k - t_start >= PT·1000 µs. Cycle 3300 µs, on 0.01 s = 10 ms: calls at
    # 0, 3300, 6600, 9900, 13200 µs: elapsed first at 13200 >= 10000, call 4.
    assert run([T] * 6, 0.01, 0.0, cycle_us=3300) == [F, F, F, F, T, T]


def test_time_inputs_are_rounded_to_whole_ms():
    # §1.4: 0.0005 s -> 0.5 ms, halves away from zero -> 1 ms. Cycle 100 µs: the TON started at 0
    # elapses in call 10 (1000 µs >= 1 ms).
    assert run([T] * 12, 0.0005, 0.0, cycle_us=100) == [F] * 10 + [T] * 2
    # 0.0004 s -> 0.4 ms -> 0 ms: Q in the rising call.
    assert run([T, T], 0.0004, 0.0, cycle_us=100) == [T, T]


def test_refused_values():
    m = IecTimerOnOff(100_000)
    with pytest.raises(ValueError):
        m.call(0, {"in": True, "timeOnDelay": float("nan"), "timeOffDelay": 0.0})
    with pytest.raises(ValueError):
        m.call(0, {"in": True, "timeOnDelay": 0.0, "timeOffDelay": 2147483.648})
    with pytest.raises(ValueError):
        IecTimerOnOff(60_000_001)
