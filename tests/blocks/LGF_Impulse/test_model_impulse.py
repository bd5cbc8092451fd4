"""Hand traces of the Impulse model against the original block's program (no FMU): call k at
k · cycle, (impulse, countdown in ms) after each call. The original reads the TOF's Q before it
executes the TOF, with the S7 update on read (docs/behaviour.md §1.12), and computes the period
as T#1000s / TRUNC(frequency · 1000.0), a TIME divided by a DINT."""

import math

import numpy as np
import pytest

from .model import Impulse, period_ms

F, T = False, True


def run(frequencies, cycle_us=100_000, n=None):
    """(impulse, countdown ms) per call; frequencies is one value or a list per call."""
    if not isinstance(frequencies, list):
        frequencies = [frequencies] * n
    m = Impulse(cycle_us)
    out = []
    for k, f in enumerate(frequencies):
        o = m.call(k * cycle_us, {"frequency": f})
        out.append((o["impulse"], round(o["countdown"] * 1000)))
    return out


def pulses(out):
    return [k for k, (i, _) in enumerate(out) if i]


def test_1_hz_pulses_in_call_0_and_every_11_calls():
    # Period 1000 ms, cycle 100 ms. Call 0: the TOF never ran, Q FALSE: impulse TRUE; IN TRUE,
    # Q TRUE, ET 0: 1000. Call 1: Q TRUE, no pulse; IN FALSE starts the TOF at 0.1 s: 1000.
    # Calls 2-10: 900 … 100. Call 11 (1.1 s): Q read before the TOF runs is FALSE (1000 ms since
    # 0.1 s): impulse TRUE; IN TRUE stops it, ET 0: 1000. Call 12 starts it at 1.2 s; call 22.
    out = run(1.0, n=24)
    assert pulses(out) == [0, 11, 22]
    one = [1000, 1000, 900, 800, 700, 600, 500, 400, 300, 200, 100]
    assert [c for _, c in out] == one + one + [1000, 1000]


def test_periods_as_time_divided_by_dint():
    # TRUNC(f · 1000.0) in float32, then 1000000 ms DIV it, truncating.
    assert period_ms(np.float32(0.0123)) == 83333  # TRUNC(12.3) = 12: 83333.3 -> 83333 ms
    assert period_ms(np.float32(1.0)) == 1000
    assert period_ms(np.float32(3.0)) == 333  # 1000000 / 3000
    assert period_ms(np.float32(0.3)) == 3333  # 0.300000011… · 1000 = 300.0 in float32
    assert period_ms(np.float32(0.8)) == 1250  # 800.0 in float32
    assert period_ms(np.float32(0.0017)) == 1000000  # TRUNC(1.7) = 1
    assert period_ms(np.float32(7.9999)) == 125  # TRUNC(7999.9) = 7999: 125.01 -> 125
    assert period_ms(np.float32(1000.0)) == 1
    assert period_ms(np.float32(999.0)) == 1  # 1000000 / 999000
    assert period_ms(np.float32(1001.0)) == 0
    assert period_ms(np.float32(1e30)) == 0  # TRUNC beyond the DINT range: its limit
    assert period_ms(np.float32(math.inf)) == 0


def test_below_1_mhz_divides_by_zero():
    # TRUNC(0.0005 · 1000.0) = 0: TIME / 0, taken as 0 ms (docs/scl.md §3.3 rule).
    assert period_ms(np.float32(0.0005)) == 0
    assert period_ms(np.float32(4.656613157294487e-07)) == 0
    # a period of 0: a pulse every 2 calls (the falling edge with PT 0 ends at once)
    assert run(0.0005, n=5) == [(T, 0), (F, 0), (T, 0), (F, 0), (T, 0)]


def test_period_0_or_shorter_than_a_cycle_pulses_every_2_calls():
    # 2000 Hz: 0 ms. 1000 Hz: 1 ms, elapsed in the call after the start.
    assert run(2000.0, n=4) == [(T, 0), (F, 0), (T, 0), (F, 0)]
    assert run(1000.0, n=4) == [(T, 1), (F, 1), (T, 1), (F, 1)]


def test_no_frequency():
    for f in (0.0, -0.0, -1.0, -math.inf):
        assert run(f, n=3) == [(F, 0)] * 3


def test_a_new_frequency_while_the_tof_runs():
    # 1 Hz, TOF started at 0.1 s with PT 1000. Call 9 (0.9 s): 10 Hz, period 100 ms: countdown
    # 100 - 800 = -700; call 10: -800; call 11 (1.1 s): the old PT elapsed, pulse, 100; call 12:
    # the TOF starts with PT 100: 100; call 13 (1.3 s): elapsed, pulse.
    out = run([1.0] * 9 + [10.0] * 5)
    assert out[9:] == [(F, -700), (F, -800), (T, 100), (F, 100), (T, 100)]
    # to 0.5 Hz (2000 ms) at call 5 (ET 400): 1600 … 1100 in call 10; pulse in call 11 (old PT).
    out = run([1.0] * 5 + [0.5] * 8)
    assert [c for _, c in out[5:11]] == [1600, 1500, 1400, 1300, 1200, 1100]
    assert out[11] == (T, 2000)


def test_off_for_a_while_the_tof_measured_the_time():
    # 1 Hz in calls 0-1 (TOF started at 0.1 s), off in calls 2-14, on in call 15 (1.5 s): the
    # TOF elapsed meanwhile, so call 15 pulses; call 16 starts it again.
    out = run([1.0] * 2 + [0.0] * 13 + [1.0] * 3)
    assert out[2:15] == [(F, 0)] * 13
    assert out[15:] == [(T, 1000), (F, 1000), (F, 900)]


def test_a_cycle_off_the_ms_grid():
    # 250 Hz: 4 ms; cycle 1.5 ms. Call 0 pulse; call 1 (1.5 ms) starts it: 4; call 2 (3 ms):
    # ET 1: 3; call 3 (4.5 ms): ET 3: 1; call 4 (6 ms): Q read FALSE (4.5 ms >= 4): pulse, 4.
    out = run(250.0, cycle_us=1500, n=6)
    assert out == [(T, 4), (F, 4), (F, 3), (F, 1), (T, 4), (F, 4)]


def test_refused_values():
    m = Impulse(100_000)
    for f in (math.nan, 1e39, -1e39):
        with pytest.raises(ValueError):
            m.call(0, {"frequency": f})
