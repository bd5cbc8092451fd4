"""Hand traces of the Impulse model against docs/behaviour.md §9 (no FMU): call k at k · cycle,
(impulse, countdown in ms) after each call."""

import math

import numpy as np
import pytest

from .model import Impulse, period_ms

F, T = False, True


def run(freqs, cycle_us=100_000, n=None):
    """(impulse, countdown ms) per call; freqs is one frequency or a list per call."""
    if not isinstance(freqs, list):
        freqs = [freqs] * n
    m = Impulse(cycle_us)
    out = []
    for k, f in enumerate(freqs):
        o = m.call(k * cycle_us, {"frequency": f})
        out.append((o["impulse"], round(o["countdown"] * 1000)))
    return out


def pulses(out):
    return [k for k, (imp, _) in enumerate(out) if imp]


def test_worked_example_of_9_3():
    # §9.3: 1 Hz, P = 1000 ms, m = 10: call 0 countdown P (TOF stopped, Q TRUE); call 1 the falling
    # edge starts it (ET 0, countdown 1000); then 900, 800, ... 100 in call 10; pulse in call 11
    # (ET 1000, countdown 0); call 12 IN TRUE (countdown 1000); call 13 starts again; pulse 23.
    out = run(1.0, n=25)
    cd = [1000, 1000, 900, 800, 700, 600, 500, 400, 300, 200, 100, 0]
    cd += [1000, 1000, 900, 800, 700, 600, 500, 400, 300, 200, 100, 0, 1000]
    assert [c for _, c in out] == cd
    assert pulses(out) == [11, 23]


def test_start_value_pulses_at_1_1_2_3_3_5_4_7_s():
    # §9.1: 1 Hz at 0.1 s: period m + 2 = 12 calls, first pulse in call 1 + m = 11.
    assert pulses(run(1.0, n=50)) == [11, 23, 35, 47]


def test_no_frequency_gives_no_pulse_and_countdown_zero():
    # §9.2 step 1: frequency <= 0.0 (also -0.0 and -Inf).
    for f in (0.0, -0.0, -1.0, -math.inf):
        assert run(f, n=5) == [(F, 0)] * 5


def test_frequency_above_1000_hz_gives_a_pulse_every_2_calls():
    # §9.3: 1001 Hz: a = 1001000.0, q = 0.999001 < 1, P = 0, m = 0: first pulse in call 1, then
    # every 2 calls; countdown 0 - 0 = 0 throughout.
    assert period_ms(1001.0) == 0
    out = run(1001.0, n=7)
    assert out == [(F, 0), (T, 0), (F, 0), (T, 0), (F, 0), (T, 0), (F, 0)]


def test_infinite_frequency_gives_period_0():
    # §9.2 step 2: +Inf: a = +Inf, q = 0.0, P = 0 ms.
    assert period_ms(math.inf) == 0
    assert pulses(run(math.inf, n=6)) == [1, 3, 5]


def test_period_of_at_most_one_cycle_pulses_every_3_calls():
    # §9.3: 10 Hz: a = 10000.0, q = 100.0, P = 100 ms = one cycle, m = 1: pulse in call 2, then
    # every 3 calls. countdown: call 0: 100, call 1 (start): 100, call 2 (ET 100): 0.
    out = run(10.0, n=9)
    assert out[:3] == [(F, 100), (F, 100), (T, 0)]
    assert pulses(out) == [2, 5, 8]


def test_float32_period_examples():
    # §9.3: 3.0 -> a 3000.0, q 333.33334, P 333; 0.3 (0.30000001192...) -> a 300.0, q 3333.3333,
    # P 3333.
    assert period_ms(3.0) == 333
    assert period_ms(0.3) == 3333
    # 0.8 (0.80000001192…): a = 800.0 (800.0000095 rounded to float32), q = 1250.0, P = 1250,
    # where 1000 / 0.80000001192… in real numbers is 1249.99998.
    assert period_ms(0.8) == 1250
    # 3 Hz at 0.1 s: m = ceil(333000 / 100000) = 4, pulse in call 5; countdown 333, 333 (start),
    # 333 - 100, 333 - 200, 333 - 300, 0 (ET capped at PT 333).
    out = run(3.0, n=7)
    assert out == [(F, 333), (F, 333), (F, 233), (F, 133), (F, 33), (T, 0), (F, 333)]


def test_new_frequency_while_the_tof_runs():
    # §9.3: from P = 1000 ms (TOF started in call 1 at 0.1 s), frequency 10.0 (P = 100 ms) set in
    # call 9, when ET is 800: countdown 100 - 800 = -700, then -800, -900 in the pulse (call 11,
    # ET 1000 at the old PT). Call 12: IN TRUE, countdown 100; call 13 starts with PT 100;
    # call 14: elapsed 100 -> pulse, countdown 0.
    freqs = [1.0] * 9 + [10.0] * 8
    out = run(freqs)
    assert out[8:15] == [(F, 300), (F, -700), (F, -800), (T, -900), (F, 100), (F, 100), (T, 0)]
    assert pulses(out) == [11, 14]


def test_zero_for_a_while_the_tof_goes_on_measuring_time():
    # §9.3: TOF started at 0.1 s (call 1). Frequency 0 in calls 2-4: (F, 0), TOF not executed.
    # Call 5: 1.0 again = statFrequencyOld (nothing recomputed): IN = NOT Q = FALSE, elapsed
    # 400 ms: countdown 600.
    out = run([1.0, 1.0, 0.0, 0.0, 0.0, 1.0])
    assert out == [(F, 1000), (F, 1000), (F, 0), (F, 0), (F, 0), (F, 600)]
    # Off through call 11 (1.1 s): call 12 sees 1100 ms >= 1000: the pulse at once.
    out = run([1.0, 1.0] + [-1.0] * 10 + [1.0, 1.0])
    assert out[12:] == [(T, 0), (F, 1000)]


def test_first_positive_frequency_after_a_start_without_one():
    # §9.3: "or the first call with a positive frequency": calls 0-2 with 0.0, then 1 Hz from
    # call 3: Q TRUE there (countdown 1000), start in call 4, pulse in call 4 + 10 = 14.
    out = run([0.0] * 3 + [1.0] * 13)
    assert out[3] == (F, 1000) and pulses(out) == [14]


def test_cycle_off_the_ms_grid():
    # §9.2 step 3: ET in whole ms. 100 Hz: a = 100000.0, q = 10.0, P = 10 ms; cycle 3300 µs:
    # start in call 1 (3300 µs); ET 3, 6, 9 ms at 6600, 9900, 13200 µs; 16500 - 3300 = 13200 µs
    # >= 10 ms: pulse in call 5 (m = ceil(10000 / 3300) = 4), countdown 0.
    out = run(100.0, cycle_us=3300, n=6)
    assert out == [(F, 10), (F, 10), (F, 7), (F, 4), (F, 1), (T, 0)]


def test_smallest_accepted_frequency():
    # §9.4: the float32 4.6566132e-07 (4.656613157294487e-07) gives q = 2147483520.0, the largest
    # float32 below 2^31: P = 2147483520 ms; the next smaller float32 gives q = 2^31: refused.
    f = np.float32(4.656613157294487e-07)
    assert period_ms(f) == 2147483520
    with pytest.raises(ValueError):
        period_ms(np.nextafter(f, np.float32(0.0)))


def test_refused_values():
    # §9.4: q >= 2^31 refused. 4.65e-7 Hz: q = 2150537728.0; 4.6567e-7 Hz: q = 2147443328.0 < 2^31
    # (accepted, P = 2147443328 ms).
    with pytest.raises(ValueError):
        period_ms(4.65e-7)
    assert period_ms(4.6567e-7) == 2147443328
    m = Impulse(100_000)
    for bad in (float("nan"), 4.65e-7, 3.5e38, 1e-45):
        with pytest.raises(ValueError):
            m.call(0, {"frequency": bad})
    # the smallest positive accepted frequency gives the longest period: countdown 24.8 days
    assert m.call(0, {"frequency": 4.6567e-7}) == {"impulse": False, "countdown": 2147443.328}
