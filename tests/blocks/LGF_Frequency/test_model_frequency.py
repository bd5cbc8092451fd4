"""Hand traces of the Frequency model against the original block's program (no FMU): call k at
k · cycle, (clock, countdown in ms) after each call. The traces follow the original's statements
on S7 TOFs with the update on read (docs/behaviour.md §1.12): the pause TOF's Q is read at the
call's time before that timer runs, and clock is the pulse TOF's Q read at the call's time, also
while an input <= 0 switches the block off."""

import math

import numpy as np
import pytest

from .model import Frequency, times_ms

F, T = False, True


def run(inputs, cycle_us=100_000, n=None):
    """(clock, countdown ms) per call; inputs is one (frequency, ratio) or a list per call."""
    if not isinstance(inputs, list):
        inputs = [inputs] * n
    m = Frequency(cycle_us)
    out = []
    for k, (f, r) in enumerate(inputs):
        o = m.call(k * cycle_us, {"frequency": f, "pulsePauseRatio": r})
        out.append((o["clock"], round(o["countdown"] * 1000)))
    return out


def clocks(out):
    return [c for c, _ in out]


def countdowns(out):
    return [c for _, c in out]


def test_1_hz_ratio_1_the_pause_lasts_5_calls():
    # Pulse = pause = 500 ms, cycle 100 ms. Call 0: pause Q FALSE (never run), pulse IN TRUE: Q
    # TRUE, ET 0: 500; pause IN TRUE. Call 1: pause Q TRUE (its IN), the pulse TOF's falling
    # edge starts it at 0.1 s: 500. Calls 2-5: 400 … 100. Call 6 (0.6 s): pulse elapsed, Q
    # FALSE, ET 500: 0, so the pause TOF's falling edge starts it at 0.6 s: 500 - 0. Calls 7-10:
    # 400 … 100. Call 11 (1.1 s): the pause Q read before its TOF runs is already FALSE (500 ms
    # since 0.6 s), so the pulse IN is TRUE: clock TRUE, 500. Call 12: the pulse TOF starts at
    # 1.2 s, 500; … call 17 (1.7 s) elapses; call 22 (2.2 s) ends the pause.
    out = run((1.0, 1.0), n=23)
    assert clocks(out) == [T] * 6 + [F] * 5 + [T] * 6 + [F] * 5 + [T]
    pulse = [500, 500, 400, 300, 200, 100]
    pause = [500, 400, 300, 200, 100]
    assert countdowns(out) == pulse + pause + pulse + pause + [500]


def test_an_input_to_0_keeps_clock_at_the_pulse_timers_q():
    # 1 Hz, ratio 1 in calls 0-1 (the pulse TOF starts at 0.1 s), then frequency 0: the original
    # writes clock FALSE, then its last statement clock := pulse TOF's Q, read at the call's time:
    # TRUE until 0.6 s (500 ms after its start), FALSE from call 6 on; countdown 0.
    out = run([(1.0, 1.0)] * 2 + [(0.0, 1.0)] * 6)
    assert out[2:] == [(T, 0), (T, 0), (T, 0), (T, 0), (F, 0), (F, 0)]
    # the same with the ratio at 0
    out = run([(1.0, 1.0)] * 2 + [(1.0, 0.0)] * 2)
    assert out[2:] == [(T, 0), (T, 0)]


def test_stopped_after_the_first_call_of_a_pulse_keeps_clock_true():
    # Call 0 ran the pulse TOF with IN TRUE; stopped from call 1 on, its IN memory stays TRUE,
    # so the Q read in every call is TRUE.
    out = run([(1.0, 1.0)] + [(0.0, 1.0)] * 30)
    assert out[1:] == [(T, 0)] * 30


def test_off_from_the_start():
    # No timer ever runs: the pulse TOF's Q is FALSE.
    for f, r in ((0.0, 1.0), (-1.0, 1.0), (-math.inf, 1.0), (1.0, 0.0), (1.0, -0.0), (1.0, -2.0)):
        assert run((f, r), n=3) == [(F, 0)] * 3
    assert run((1.0, -math.inf), n=2) == [(F, 0)] * 2


def test_back_on_with_the_same_settings_the_timers_measured_the_time():
    # Calls 0-1 at 1 Hz (pulse TOF started at 0.1 s, pause TOF last run with IN TRUE), calls 2-7
    # off, call 8 (0.8 s) on again, same settings, no reset: the pause Q is TRUE (its IN), the
    # pulse TOF has elapsed (700 ms >= 500): clock FALSE, pulse part 500 - 500 = 0, the pause TOF
    # starts at 0.8 s: 500. Calls 9-12: 400 … 100; call 13 (1.3 s): the pause is over, TRUE.
    out = run([(1.0, 1.0)] * 2 + [(0.0, 1.0)] * 6 + [(1.0, 1.0)] * 6)
    assert out[8:] == [(F, 500), (F, 400), (F, 300), (F, 200), (F, 100), (T, 500)]


def test_ratio_3():
    # Pulse 750 ms, pause 250 ms. Calls 0-1: 750; calls 2-8: 650 … 50; call 9 (0.9 s): pulse
    # elapsed (800 ms since 0.1 s), ET 750: 0, the pause TOF starts at 0.9 s: 250; call 10: 150;
    # call 11: 50; call 12 (1.2 s): the pause Q read is FALSE (300 ms): TRUE, 750; call 13: the
    # pulse TOF starts, 750.
    out = run((1.0, 3.0), n=14)
    assert clocks(out) == [T] * 9 + [F] * 3 + [T] * 2
    assert countdowns(out) == [750, 750, 650, 550, 450, 350, 250, 150, 50, 250, 150, 50, 750, 750]


def test_times_in_real_arithmetic():
    # ratio 3.0: pulseRate 0.75, pauseRate 0.25. Ratio 2.0: pulseRate fl32(2/3) = 0.6666667,
    # 1000 · that = 666.6667 -> 667; pauseRate 0.3333333 -> 333.
    assert times_ms(np.float32(1.0), np.float32(3.0)) == (750, 250)
    assert times_ms(np.float32(1.0), np.float32(2.0)) == (667, 333)
    # from 2^24 on r + 1.0 = r in float32: pulseRate 1.0, pause 0 ms; a tiny ratio: pulse 0 ms.
    assert times_ms(np.float32(1.0), np.float32(2.0**24)) == (1000, 0)
    assert times_ms(np.float32(1.0), np.float32(1e-30)) == (0, 1000)
    # REAL_TO_UDINT to the nearest, halves to even: 500 / 16.0 = 31.25 -> 31, 500 / 200.0 = 2.5
    # -> 2, 500 / fl32(400 / 3) = 3.75 -> 4.
    assert times_ms(np.float32(16.0), np.float32(1.0)) == (31, 31)
    assert times_ms(np.float32(200.0), np.float32(1.0)) == (2, 2)
    assert times_ms(np.float32(400.0 / 3.0), np.float32(1.0)) == (4, 4)  # 3.75 -> 4


def test_pulse_of_0_ms():
    # Ratio 1e-30 at 1 Hz: pulse 0 ms, pause 1000 ms. Call 0: pulse TOF IN TRUE, 0 - 0 = 0, the
    # pause TOF with IN TRUE: 1000 - 0; call 1: the pulse TOF's falling edge with PT 0, Q FALSE
    # at once, ET 0: the pause TOF starts at 0.1 s: 1000; calls 2-10: 900 … 100; call 11 (1.1 s):
    # the pause is over, TRUE, 1000; call 12 FALSE again.
    out = run((1.0, 1e-30), n=13)
    assert clocks(out) == [T] + [F] * 10 + [T, F]
    assert countdowns(out) == [1000, 1000, 900, 800, 700, 600, 500, 400, 300, 200, 100, 1000, 1000]


def test_infinite_frequency_alternates():
    # Pulse = pause = 0 ms: call 0 TRUE; call 1 both TOFs fall with PT 0, FALSE; call 2 the pause
    # Q read is FALSE (it elapsed at its start), TRUE; and so on. countdown 0 throughout.
    assert run((math.inf, 1.0), n=6) == [(T, 0), (F, 0)] * 3


def test_new_settings_restart_with_a_pulse():
    # 1 Hz until call 2, then 2 Hz (250 ms each) from call 3 (0.3 s): both TOFs reset, the pause Q
    # FALSE: pulse IN TRUE, 250; call 4: the pulse TOF starts at 0.4 s, 250; 150, 50; call 7 (0.7
    # s): elapsed, the pause TOF starts: 250; 150, 50; call 10 (1.0 s): the pause is over, TRUE.
    out = run([(1.0, 1.0)] * 3 + [(2.0, 1.0)] * 8)
    assert out[3:] == [(T, 250), (T, 250), (T, 150), (T, 50)] + [(F, 250), (F, 150), (F, 50)] + [
        (T, 250)
    ]


def test_a_cycle_off_the_ms_grid():
    # Cycle 3.3 ms, 100 Hz, ratio 1: 5 ms each. Call 0 TRUE 5; call 1 (3.3 ms) the pulse TOF
    # starts: 5; call 2 (6.6 ms): ET 3 ms: 2; call 3 (9.9 ms): elapsed (6.6 >= 5), pause starts:
    # 5; call 4 (13.2 ms): ET 3: 2; call 5 (16.5 ms): the pause Q read is FALSE (6.6 ms): TRUE, 5.
    out = run((100.0, 1.0), cycle_us=3300, n=7)
    assert out == [(T, 5), (T, 5), (T, 2), (F, 5), (F, 2), (T, 5), (T, 5)]


def test_refused_values():
    m = Frequency(100_000)
    for f, r in ((math.nan, 1.0), (1.0, math.nan), (1.0, math.inf), (1e39, 1.0)):
        with pytest.raises(ValueError):
            m.call(0, {"frequency": f, "pulsePauseRatio": r})
    with pytest.raises(ValueError):  # 500 / 1e-7 = 5e9 ms does not fit a TIME
        m.call(0, {"frequency": 1e-7, "pulsePauseRatio": 1.0})
    # an input <= 0 makes the pair acceptable
    assert m.call(0, {"frequency": 1e-7, "pulsePauseRatio": 0.0}) == {
        "clock": False,
        "countdown": 0.0,
    }
