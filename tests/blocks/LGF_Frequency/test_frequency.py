"""LGF_Frequency against the rules of docs/behaviour.md §10, with hand-computed expectations
traced through the block's original SCL.

The rule of one call (§10.2): (1) frequency <= 0 or pulsePauseRatio <= 0: countdown 0, no timer
is executed. Otherwise (2) new settings: reset both TOFs; pulseRate = r / (r + 1), pauseRate = 1
- pulseRate, Pp = REAL_TO_UDINT(1000 * pulseRate / f), Pz likewise, in float32. (3) the pause
TOF's Q is read (update on read: at this call's time) and the pulse TOF runs with IN = NOT that
Q, PT = Pp; (4) countdown = Pp - its ET; (5) the pause TOF runs with IN = the pulse TOF's Q, PT
= Pz; (6) countdown = Pz - its ET if it was 0. (7) In every call, off or not: clock = the pulse
TOF's Q read at this call's time. A TOF: a falling edge of IN starts it and takes PT; Q = IN OR
(running AND t - t_start < PT), at the time of the reading call; ET = 0 while IN is TRUE, else
min(whole ms since the start, PT). Call k is at k * cycleTime; an input set before a step
reaches the call at its end."""

import math

import numpy as np
import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of, step_rows

BLOCK = "LGF_Frequency"
FLT_MAX = float(np.finfo(np.float32).max)


def clock(cycle=0.1, frequency=1.0, ratio=1.0):
    return Slave(BLOCK, {"cycleTime": cycle}, {"frequency": frequency, "pulsePauseRatio": ratio})


def run(s, calls, changes=None, h=None):
    """(clock, countdown in ms) of call 0 and of `calls` further calls; changes[k] is set before
    call k."""
    return step_rows(
        s, calls, lambda out: (bool(out["clock"]), round(out["countdown"] * 1000)), changes, h
    )


def phases(rows):
    """The clock as (level, calls) runs."""
    runs = []
    for level, _ in rows:
        if runs and runs[-1][0] == level:
            runs[-1][1] += 1
        else:
            runs.append([level, 1])
    return [tuple(r) for r in runs]


T, F = True, False


def test_worked_example_of_the_behaviour():
    # §10.3: cycle 0.1 s, 1 Hz, ratio 1: pulseRate 0.5, Pp = Pz = 500 ms. Call 0: new settings,
    # the pause TOF's Q FALSE, the pulse TOF's IN TRUE: clock TRUE, ET 0: 500; the pause TOF runs
    # with IN TRUE. Call 1: the pause TOF's Q TRUE (its IN), the pulse TOF's falling edge (t 0.1):
    # 500; calls 2..5: 400..100. Call 6: the pulse TOF elapsed (0.5 s): clock FALSE, ET 500: 0
    # -> the pause TOF's falling edge (t 0.6): 500 - 0. Calls 7..10: 400..100. Call 11: the read
    # of the pause TOF's Q finds it elapsed (1.1 - 0.6 >= 0.5): FALSE, the pulse TOF's IN TRUE:
    # clock TRUE, 500 (the pause lasted 5 calls). Call 12 starts the pulse TOF again: 500, 400.
    want = [(T, 500), (T, 500), (T, 400), (T, 300), (T, 200), (T, 100)]
    want += [(F, 500), (F, 400), (F, 300), (F, 200), (F, 100)]
    want += [(T, 500), (T, 500), (T, 400), (T, 300)]
    assert run(clock(), 14) == want


def test_start_values_show_a_clock_in_the_default_experiment():
    # TRUE in calls 0..5, FALSE in 6..10, a period of 11 calls
    s = Slave(BLOCK)
    assert s.get(["frequency", "pulsePauseRatio"]) == {"frequency": 1.0, "pulsePauseRatio": 1.0}
    assert phases(run(s, 49)) == [(T, 6), (F, 5)] * 4 + [(T, 6)]


@pytest.mark.parametrize(
    "cycle, frequency, ratio, pulse_ms, pause_ms, pulse_calls, pause_calls",
    [
        (0.1, 1.0, 1.0, 500, 500, 6, 5),  # m = 5: TRUE m + 1 calls, FALSE m calls
        (0.1, 1.0, 3.0, 750, 250, 9, 3),  # 0.75 / 0.25: mp = 8, mz = 3
        (0.1, 2.0, 0.5, 167, 333, 3, 4),  # 166.66667 -> 167, 333.3333 -> 333: mp 2, mz 4
        (0.1, 1.0, 2.0, 667, 333, 8, 4),  # fl32(2/3) = 0.6666667: 666.6667 -> 667, 333.3333
        (0.1, 5.0, 1.0, 100, 100, 2, 1),
        (0.1, 2000.0, 1.0, 0, 0, 1, 1),  # 0.25 ms -> 0: each phase one call
        (0.1, 1.0, 1e9, 1000, 0, 11, 1),  # r + 1 = r: pulseRate 1.0, pause 0 ms: one call
        (0.1, 1.0, FLT_MAX, 1000, 0, 11, 1),  # the largest ratio accepted
        (0.0015, 10.0, 1.0, 50, 50, 35, 34),  # m = ceil(50000 / 1500) = 34
        (0.25, 1.0, 1.0, 500, 500, 3, 2),  # m = 2
        (0.3, 1.0, 1.0, 500, 500, 3, 2),  # m = ceil(500 / 300) = 2
    ],
)
def test_the_pulse_lasts_m_plus_1_calls_and_the_pause_m_calls(
    cycle, frequency, ratio, pulse_ms, pause_ms, pulse_calls, pause_calls
):
    # The pulse: the call with the pulse TOF's IN TRUE, its falling edge, and mp - 1 calls until
    # it elapses. The pause TOF starts in the call the pulse TOF elapses, and the call mz later
    # reads its Q as FALSE already (update on read), so it is TRUE again: max(mz, 1) calls.
    period = pulse_calls + pause_calls
    rows = run(clock(cycle, frequency, ratio), 3 * period - 1)
    assert phases(rows) == [(T, pulse_calls), (F, pause_calls)] * 3
    assert rows[0][1] == (pulse_ms or pause_ms)  # call 0: Pp - 0, or Pz - 0 when Pp is 0
    assert rows[pulse_calls][1] == pause_ms  # the first FALSE call: the pause TOF just started
    assert rows[period][1] == (pulse_ms or pause_ms)  # TRUE again: as in call 0


def test_countdown_of_a_cycle_that_does_not_divide_the_times():
    # cycle 0.3 s, Pp = Pz = 500. Call 0: 500; call 1 starts the pulse TOF (t 0.3): 500; call 2
    # (ET 300): 200; call 3 (t 0.9, 600 >= 500): FALSE, the pause TOF starts: 500; call 4 (ET
    # 300): 200; call 5 (t 1.5): the pause TOF read as elapsed: TRUE, 500; call 6 (t 1.8): 500.
    assert run(clock(cycle=0.3), 6) == [
        (T, 500),
        (T, 500),
        (T, 200),
        (F, 500),
        (F, 200),
        (T, 500),
        (T, 500),
    ]


def test_infinite_frequency_alternates():
    # Pp = Pz = 0 (1000 * 0.5 / Inf = 0): call 0 TRUE; call 1: the pulse TOF starts and elapses
    # at once (PT 0), FALSE, and the pause TOF too; call 2 reads the pause TOF's Q FALSE: TRUE.
    assert run(clock(frequency=math.inf), 7) == [(T, 0), (F, 0)] * 4


def test_pulse_of_0_ms_shows_the_pause_countdown():
    # ratio 1e-9: pulseRate 1e-9, Pp = REAL_TO_UDINT(1e-6) = 0, Pz = 1000. Call 0: the pulse
    # TOF's IN TRUE (ET 0): 0 - 0 = 0 -> the pause TOF (IN TRUE, ET 0): 1000. Call 1: the pulse
    # TOF starts and elapses (PT 0): clock FALSE, 0 -> the pause TOF starts (t 0.1): 1000. Calls
    # 2..10: 900..100; call 11 (t 1.1) reads the pause TOF's Q as elapsed: TRUE, 0 -> 1000 - 0.
    # Call 12: the pulse TOF starts and elapses, the pause TOF starts: FALSE, 1000.
    rows = run(clock(ratio=1e-9), 12)
    assert rows == [(T, 1000), (F, 1000)] + [(F, 1000 - 100 * j) for j in range(1, 10)] + [
        (T, 1000),
        (F, 1000),
    ]


@pytest.mark.parametrize(
    "frequency, ratio",
    [(0.0, 1.0), (-1.0, 1.0), (-math.inf, 1.0), (1.0, 0.0), (1.0, -0.0), (1.0, -math.inf)],
)
def test_an_input_not_positive_from_the_start_keeps_the_clock_false(frequency, ratio):
    # clock is the pulse TOF's Q, and that TOF never ran: FALSE
    assert run(clock(frequency=frequency, ratio=ratio), 15) == [(F, 0)] * 16


@pytest.mark.parametrize("off", [{"frequency": 0.0}, {"pulsePauseRatio": -1.0}])
def test_off_during_a_pulse_the_pulse_runs_out(off):
    # 1 Hz, ratio 1 in calls 0, 1 (the pulse TOF's falling edge in call 1, t 0.1); an input <= 0
    # from call 2: no timer runs, countdown 0, but clock is still the pulse TOF's Q read at the
    # call's time: TRUE while 0.1 + 0.5 s has not passed (calls 2..5), FALSE from call 6 (t 0.6).
    rows = run(clock(), 10, changes={2: off})
    assert rows[:2] == [(T, 500), (T, 500)]
    assert rows[2:] == [(T, 0)] * 4 + [(F, 0)] * 5


def test_off_before_the_pulse_timer_starts_holds_the_clock_true():
    # 1 Hz, ratio 1 in call 0 only: the pulse TOF ran with IN TRUE. Off from call 1: it is never
    # executed again, its IN stays TRUE, so its Q (and clock) is TRUE in every call while off.
    rows = run(clock(), 30, changes={1: {"frequency": -1.0}})
    assert rows == [(T, 500)] + [(T, 0)] * 30


def test_new_settings_restart_with_a_pulse():
    # 1 Hz, ratio 1: FALSE from call 6. Ratio 3 before call 8: both TOFs reset (the pause TOF's
    # Q FALSE), Pp 750, Pz 250: call 8 TRUE (750), the pulse TOF starts in call 9 (t 0.9) and
    # elapses at 1.65 s, in call 17: TRUE in calls 8..16; the pause TOF from call 17 (t 1.7,
    # 250) elapses at 1.95 s: FALSE in calls 17..19 (250, 150, 50); call 20 reads it elapsed:
    # TRUE, 750.
    rows = run(clock(), 22, changes={8: {"pulsePauseRatio": 3.0}})
    assert rows[6:10] == [(F, 500), (F, 400), (T, 750), (T, 750)]
    assert rows[16:21] == [(T, 50), (F, 250), (F, 150), (F, 50), (T, 750)]
    assert phases(rows) == [(T, 6), (F, 2), (T, 9), (F, 3), (T, 3)]


def test_the_same_settings_after_off_go_on_with_the_timers():
    # 1 Hz, ratio 1: the pulse TOF from call 1 (t 0.1). frequency 0 in calls 3..9: no timer
    # runs, countdown 0, clock the pulse TOF's Q read then: TRUE in calls 3..5, FALSE from call
    # 6 (t 0.6 = 0.1 + 0.5). Frequency 1 again from call 10: no new settings. Call 10: the pause
    # TOF's Q is its IN of call 2, TRUE: the pulse TOF's IN FALSE, elapsed, ET 500: 0 -> the
    # pause TOF's falling edge (t 1.0): 500. Calls 11..14: 400..100; call 15 (t 1.5) reads it
    # elapsed: TRUE, 500; call 16 starts the pulse TOF: 500; call 17: 400.
    rows = run(clock(), 17, changes={3: {"frequency": 0.0}, 10: {"frequency": 1.0}})
    assert rows[:3] == [(T, 500), (T, 500), (T, 400)]
    assert rows[3:10] == [(T, 0)] * 3 + [(F, 0)] * 4
    assert rows[10:] == [(F, 500), (F, 400), (F, 300), (F, 200), (F, 100)] + [
        (T, 500),
        (T, 500),
        (T, 400),
    ]


def test_a_change_of_either_input_is_new_settings():
    # the ratio back to the value it had: still new settings (statPulsePauseRatioOld is 3.0)
    rows = run(clock(), 15, changes={2: {"pulsePauseRatio": 3.0}, 4: {"pulsePauseRatio": 1.0}})
    # call 2: restart, 750 ms; call 4: restart again, 500 ms, the pulse TOF from call 5 (t 0.5)
    # to t 1.0: TRUE in calls 0..9; the pause TOF from call 10 to t 1.5: FALSE in 10..14
    assert rows[2] == (T, 750) and rows[4] == (T, 500)
    assert phases(rows) == [(T, 10), (F, 5), (T, 1)]


def test_inputs_are_reals():
    s = clock(frequency=0.1, ratio=0.1)
    assert s.get(["frequency", "pulsePauseRatio"]) == {
        "frequency": 0.10000000149011612,
        "pulsePauseRatio": 0.10000000149011612,
    }
    # pulseRate = fl32(0.1 / 1.1) = 0.09090909, pauseRate = 0.9090909; Pp = 1000 * 0.09090909 /
    # 0.1 = 909.09094 -> 909, Pz = 9090.908 -> 9091 (in float32)
    rows = run(s, 11)
    assert rows[0] == (T, 909)
    # m = ceil(909 / 100) = 10: TRUE in calls 0..10, the first FALSE call is 11
    assert rows[10] == (T, 9) and rows[11] == (F, 9091)


@pytest.mark.parametrize(
    "name, value",
    [
        ("frequency", math.nan),
        ("pulsePauseRatio", math.nan),
        ("pulsePauseRatio", math.inf),
        ("frequency", 2e-7),  # Pp = Pz = 500 / 2e-7 = 2.5e9 ms
        ("frequency", 1.4e-45),
    ],
)
def test_refused_values_are_not_applied(name, value):
    s = clock()
    assert status_of(s.fmu.setReal, [s.vr(name)], [value]) == fmi2Error
    assert any(name in text for _, _, text in s.log)
    assert s.get(["frequency", "pulsePauseRatio"]) == {"frequency": 1.0, "pulsePauseRatio": 1.0}
    assert phases(run(s, 11)) == [(T, 6), (F, 5), (T, 1)]


def test_the_pair_is_checked_on_the_values_held_after_the_set():
    s = clock()
    f, r = s.vr("frequency"), s.vr("pulsePauseRatio")
    # 4e-7 Hz at ratio 1: 500 / 4e-7 = 1.25e9 ms, fits
    assert status_of(s.fmu.setReal, [f], [4e-7]) != fmi2Error
    # ratio 1e-9 with it: the pause 1000 / 4e-7 = 2.5e9 ms does not fit
    assert status_of(s.fmu.setReal, [r], [1e-9]) == fmi2Error
    assert any("pause" in text for _, _, text in s.log)
    # both in one call: 2e-7 Hz with ratio 0 (off) is accepted, then ratio 1 alone refused
    assert status_of(s.fmu.setReal, [f, r], [2e-7, 0.0]) != fmi2Error
    assert status_of(s.fmu.setReal, [r], [1.0]) == fmi2Error
    # both together back to a valid pair
    assert status_of(s.fmu.setReal, [f, r], [2.0, 1.0]) != fmi2Error
    # and a refused pair in one call changes neither
    assert status_of(s.fmu.setReal, [f, r], [1e-9, 3.0]) == fmi2Error
    assert s.get(["frequency", "pulsePauseRatio"]) == {"frequency": 2.0, "pulsePauseRatio": 1.0}


def test_setting_an_output_is_refused():
    s = clock()
    assert status_of(s.fmu.setBoolean, [s.vr("clock")], [False]) == fmi2Error
    assert status_of(s.fmu.setReal, [s.vr("countdown")], [1.0]) == fmi2Error


def test_fmu_state_replays_the_clock():
    s = clock(frequency=3.0, ratio=2.0)
    run(s, 4)
    first, again = s.replayed(lambda: run(s, 12, changes={5: {"pulsePauseRatio": 0.5}})[1:])
    assert again == first
