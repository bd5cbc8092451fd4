"""Hand traces of the Frequency model against docs/behaviour.md §10 (no FMU): call k at
k · cycle, (clock, countdown in ms) after each call."""

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


def test_worked_example_of_10_3():
    # §10.3: 1 Hz, ratio 1.0: pulseRate 0.5, Pp = Pz = 500 ms, mp = mz = 5.
    # Call 0: pulse TOF IN TRUE (pauseQ FALSE after the reset), countdown 500; call 1: its falling
    # edge (start 0.1 s), 500; calls 2-5: 400 .. 100; call 6: it elapses (clock FALSE, pulse part
    # 500 - 500 = 0), the pause TOF starts: 500 - 0; calls 7-10: 400 .. 100; call 11: pause
    # elapses, 0; call 12: pulse IN TRUE again, 500.
    out = run((1.0, 1.0), n=15)
    assert clocks(out) == [T] * 6 + [F] * 6 + [T] * 3
    cd = [500, 500, 400, 300, 200, 100, 500, 400, 300, 200, 100, 0, 500, 500, 400]
    assert [c for _, c in out] == cd


def test_start_values_true_in_calls_0_to_5():
    # §10.1: TRUE in calls 0 … 5, FALSE in calls 6 … 11, and so on (period mp + mz + 2 = 12).
    out = clocks(run((1.0, 1.0), n=36))
    assert out == ([T] * 6 + [F] * 6) * 3


def test_off_when_an_input_is_zero_or_negative():
    # §10.2 step 1
    for f, r in ((0.0, 1.0), (-1.0, 1.0), (-math.inf, 1.0), (1.0, 0.0), (1.0, -0.0), (1.0, -2.0)):
        assert run((f, r), n=3) == [(F, 0)] * 3
    assert run((1.0, -math.inf), n=2) == [(F, 0)] * 2


def test_ratio_3_and_ratio_2_times():
    # §10.3: ratio 3.0: pulseRate 3/4 = 0.75, pauseRate 0.25: 750 ms and 250 ms. Ratio 2.0:
    # pulseRate fl32(2/3) = 0.6666667, 1000 · that = 666.6667 -> 667; pauseRate 0.3333333 -> 333.
    assert times_ms(np.float32(1.0), np.float32(3.0)) == (750, 250)
    assert times_ms(np.float32(1.0), np.float32(2.0)) == (667, 333)


def test_ratio_3_phases_last_m_plus_1_calls():
    # §10.3: Pp 750 (mp = 8), Pz 250 (mz = 3): TRUE 9 calls, FALSE 4 calls. countdown: 750, 750,
    # 650 … 50 (call 8, 700 ms since the start at 0.1 s); call 9: pulse elapses, pause starts:
    # 250; 150, 50; call 12: pause elapses: 0; call 13: TRUE again, 750.
    out = run((1.0, 3.0), n=14)
    assert clocks(out) == [T] * 9 + [F] * 4 + [T]
    cd = [750, 750, 650, 550, 450, 350, 250, 150, 50, 250, 150, 50, 0, 750]
    assert [c for _, c in out] == cd


def test_huge_and_tiny_ratios():
    # §10.3: from 2^24 on r + 1.0 = r in float32: pulseRate 1.0, pause 0 ms; a tiny ratio gives
    # pulseRate ~1e-30, 1000 · that / 1 rounds to a pulse of 0 ms.
    assert times_ms(np.float32(1.0), np.float32(2.0**24)) == (1000, 0)
    assert times_ms(np.float32(1.0), np.float32(1e-30)) == (0, 1000)


def test_pulse_of_0_ms_shows_the_pause_countdown():
    # §10.3: Pp = 0: clock TRUE for 1 call, FALSE for mz + 1 = 11 calls; the pulse part of the
    # countdown is always 0, so it shows the pause TOF: call 0: 1000 - 0 (pause TOF stopped, IN
    # TRUE); call 1: pause TOF starts (0.1 s): 1000; then 900 … 100 (call 10); call 11: it elapses:
    # 0; call 12: TRUE again, 1000.
    out = run((1.0, 1e-30), n=13)
    assert clocks(out) == [T] + [F] * 11 + [T]
    assert [c for _, c in out] == [1000, 1000, 900, 800, 700, 600, 500, 400, 300, 200, 100, 0, 1000]


def test_infinite_frequency_alternates():
    # §10.3: +Inf gives Pp = Pz = 0 ms: TRUE and FALSE in alternate calls, countdown 0.
    assert times_ms(np.float32(math.inf), np.float32(1.0)) == (0, 0)
    assert run((math.inf, 1.0), n=6) == [(T, 0), (F, 0)] * 3


def test_new_settings_restart_with_a_true_phase_in_the_same_call():
    # §10.2 step 2, §10.3: 1 Hz to call 7 (clock FALSE since call 6); 2 Hz in call 8: Pp = Pz = 250
    # ms, both TOFs reset: clock TRUE, countdown 250 in call 8, 250 in call 9 (start), 150, 50,
    # then call 12 (250 ms after the start at 0.9 s): FALSE, pause 250.
    out = run([(1.0, 1.0)] * 8 + [(2.0, 1.0)] * 5)
    assert out[6:8] == [(F, 500), (F, 400)]
    assert out[8:] == [(T, 250), (T, 250), (T, 150), (T, 50), (F, 250)]
    # a new ratio alone is a new setting too
    out = run([(1.0, 1.0)] * 8 + [(1.0, 3.0)])
    assert out[8] == (T, 750)


def test_off_and_back_to_the_same_values_goes_on_from_where_the_tofs_were():
    # §10.3: calls 0-2 at 1 Hz (pulse TOF started at 0.1 s, pauseQ TRUE); off in calls 3-7; call 8
    # (0.8 s), the same values: no new settings. Pulse TOF: IN = NOT pauseQ = FALSE, 700 ms >= 500:
    # Q FALSE, countdown part 0; pause TOF: IN FALSE after TRUE (call 2): starts at 0.8 s,
    # countdown 500; call 9: 400.
    out = run([(1.0, 1.0)] * 3 + [(0.0, 1.0)] * 5 + [(1.0, 1.0)] * 2)
    assert out[3:8] == [(F, 0)] * 5
    assert out[8:] == [(F, 500), (F, 400)]


def test_cycle_off_the_ms_grid():
    # §10.2: ET in whole ms. 100 Hz, ratio 1: Pp = Pz = 5 ms; cycle 3300 µs: mp = mz = 2.
    # Call 0: 5; call 1 (start at 3300 µs): 5; call 2 (6600, ET 3): 2; call 3 (9900, 6600 µs >=
    # 5 ms): FALSE, pause starts: 5; call 4: 5 - 3 = 2; call 5: pause elapses: 0; call 6: TRUE, 5.
    out = run((100.0, 1.0), cycle_us=3300, n=7)
    assert out == [(T, 5), (T, 5), (T, 2), (F, 5), (F, 2), (F, 0), (T, 5)]


def test_refused_values():
    # §10.4: NaN in either input, +Inf in pulsePauseRatio, a time of 2^31 ms or more with both
    # inputs positive. Ratio 1: 500 / f >= 2^31 for f <= 2.328e-7 (3e-7 gives 1.667e9: accepted);
    # ratio 1e6: pulseRate ~1, 1000 / 3e-7 = 3.3e9: refused.
    m = Frequency(100_000)
    for f, r in (
        (float("nan"), 1.0),
        (1.0, float("nan")),
        (1.0, math.inf),
        (2.3e-7, 1.0),
        (3e-7, 1e6),
        (3.5e38, 1.0),
        (1.0, -3.5e38),
    ):
        with pytest.raises(ValueError):
            m.call(0, {"frequency": f, "pulsePauseRatio": r})
    assert times_ms(np.float32(3e-7), np.float32(1.0))[0] == 1666666624
    # a pair with an input <= 0 is always accepted
    assert m.call(0, {"frequency": 1e-30, "pulsePauseRatio": 0.0}) == {
        "clock": False,
        "countdown": 0.0,
    }
