"""LGF_Frequency against the rules of docs/behaviour.md §10, with hand-computed expectations.

The rule of one call (§10.2): (1) frequency <= 0 or pulsePauseRatio <= 0: clock FALSE,
countdown 0, nothing else. (2) new settings: reset both TOFs (and their Q); pulseRate = r / (r +
1), pauseRate = 1 - pulseRate, Pp = REAL_TO_UDINT(1000 * pulseRate / f), Pz likewise, in float32.
(3) pulse TOF with IN = NOT pauseQ, PT = Pp; countdown = Pp - its ET. (5) pause TOF with IN =
pulseQ, PT = Pz; (6) countdown = Pz - its ET if it was 0. (7) clock = pulseQ. A TOF: a falling
edge of IN starts it and takes PT; Q = IN OR (running AND t - t_start < PT); ET = 0 while IN is
TRUE, else min(whole ms since the start, PT). Call k is at k * cycleTime; an input set before a
step reaches the call at its end."""

import math

import numpy as np
import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of

BLOCK = "LGF_Frequency"
FLT_MAX = float(np.finfo(np.float32).max)


def clock(cycle=0.1, frequency=1.0, ratio=1.0):
    return Slave(BLOCK, {"cycleTime": cycle}, {"frequency": frequency, "pulsePauseRatio": ratio})


def run(s, calls, changes=None, h=None):
    """(clock, countdown in ms) of call 0 and of `calls` further calls; changes[k] is set before
    call k."""
    h = h or s.get(["cycleTime"])["cycleTime"]
    changes = changes or {}

    def row(out):
        return (bool(out["clock"]), round(out["countdown"] * 1000))

    rows = [row(s.outputs())]
    for k in range(1, calls + 1):
        if k in changes:
            s.set(changes[k])
        rows.append(row(s.step(h)))
    return rows


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
    # §10.3: cycle 0.1 s, 1 Hz, ratio 1: pulseRate 0.5, Pp = Pz = 500 ms. Call 0: pauseQ FALSE,
    # the pulse TOF's IN TRUE: clock TRUE, ET 0: 500. Call 1: its falling edge (t 0.1): 500;
    # calls 2..5: 400..100. Call 6: elapsed (0.5 s): clock FALSE, countdown 0 -> the pause TOF
    # starts (t 0.6): 500 - 0. Calls 7..10: 400..100. Call 11: the pause TOF elapsed: 0. Call
    # 12: pauseQ FALSE: the pulse TOF's IN TRUE: clock TRUE, 500; call 13 starts it: 500.
    want = [(T, 500), (T, 500), (T, 400), (T, 300), (T, 200), (T, 100)]
    want += [(F, 500), (F, 400), (F, 300), (F, 200), (F, 100), (F, 0)]
    want += [(T, 500), (T, 500), (T, 400)]
    assert run(clock(), 14) == want


def test_start_values_show_a_clock_in_the_default_experiment():
    s = Slave(BLOCK)
    assert s.get(["frequency", "pulsePauseRatio"]) == {"frequency": 1.0, "pulsePauseRatio": 1.0}
    assert phases(run(s, 49)) == [(T, 6), (F, 6)] * 4 + [(T, 2)]


@pytest.mark.parametrize(
    "cycle, frequency, ratio, pulse_ms, pause_ms, pulse_calls, pause_calls",
    [
        (0.1, 1.0, 1.0, 500, 500, 6, 6),  # m = 5: each phase m + 1 calls
        (0.1, 1.0, 3.0, 750, 250, 9, 4),  # 0.75 / 0.25
        (0.1, 2.0, 0.5, 167, 333, 3, 5),  # 166.66667 -> 167, 333.3333 -> 333
        (0.1, 1.0, 2.0, 667, 333, 8, 5),  # fl32(2/3) = 0.6666667: 666.6667 -> 667, 333.3333
        (0.1, 5.0, 1.0, 100, 100, 2, 2),
        (0.1, 2000.0, 1.0, 0, 0, 1, 1),  # 0.25 ms -> 0: phases of 0 ms last one call
        (0.1, 1.0, 1e9, 1000, 0, 11, 1),  # r + 1 = r: pulseRate 1.0, pause 0
        (0.1, 1.0, FLT_MAX, 1000, 0, 11, 1),  # the largest ratio accepted
        (0.0015, 10.0, 1.0, 50, 50, 35, 35),  # m = ceil(50000 / 1500) = 34
        (0.25, 1.0, 1.0, 500, 500, 3, 3),  # m = 2
    ],
)
def test_each_phase_lasts_m_plus_1_calls(
    cycle, frequency, ratio, pulse_ms, pause_ms, pulse_calls, pause_calls
):
    period = pulse_calls + pause_calls
    rows = run(clock(cycle, frequency, ratio), 3 * period - 1)
    assert phases(rows) == [(T, pulse_calls), (F, pause_calls)] * 3
    assert rows[0][1] == (pulse_ms or pause_ms)  # call 0: Pp - 0, or Pz - 0 when Pp is 0
    assert rows[pulse_calls][1] == pause_ms  # the first FALSE call: the pause TOF just started


def test_infinite_frequency_alternates():
    # Pp = Pz = 0 (1000 * 0.5 / Inf = 0): TRUE and FALSE in turn, countdown always 0
    assert run(clock(frequency=math.inf), 7) == [(T, 0), (F, 0)] * 4


def test_pulse_of_0_ms_shows_the_pause_countdown():
    # ratio 1e-9: pulseRate 1e-9, Pp = REAL_TO_UDINT(1e-6) = 0, Pz = 1000. Call 0: the pulse
    # TOF's IN TRUE (ET 0): 0 - 0 = 0 -> the pause TOF (IN TRUE, ET 0): 1000. Call 1: the pulse
    # TOF starts and elapses (PT 0): clock FALSE, 0 -> the pause TOF starts: 1000. Calls 2..10:
    # 900..100; call 11: 0; call 12: clock TRUE again, 1000.
    rows = run(clock(ratio=1e-9), 12)
    assert rows == [(T, 1000), (F, 1000)] + [(F, 1000 - 100 * j) for j in range(1, 10)] + [
        (F, 0),
        (T, 1000),
    ]


@pytest.mark.parametrize(
    "frequency, ratio",
    [(0.0, 1.0), (-1.0, 1.0), (-math.inf, 1.0), (1.0, 0.0), (1.0, -0.0), (1.0, -math.inf)],
)
def test_an_input_not_positive_switches_the_clock_off(frequency, ratio):
    assert run(clock(frequency=frequency, ratio=ratio), 15) == [(F, 0)] * 16


def test_new_settings_restart_with_a_pulse():
    # 1 Hz, ratio 1: FALSE from call 6. Ratio 3 before call 8: both TOFs reset, Pp 750, Pz 250:
    # call 8 TRUE (750), the pulse TOF starts in call 9 (t 0.9) and elapses at 1.65 s, in call
    # 17: TRUE in calls 8..16; the pause TOF from call 17 (t 1.7) elapses at 1.95 s, in call 20:
    # FALSE in calls 17..20; TRUE from call 21.
    rows = run(clock(), 22, changes={8: {"pulsePauseRatio": 3.0}})
    assert rows[8:10] == [(T, 750), (T, 750)]
    assert rows[17] == (F, 250)
    assert phases(rows) == [(T, 6), (F, 2), (T, 9), (F, 4), (T, 2)]


def test_the_same_settings_after_off_go_on_with_the_timers():
    # 1 Hz, ratio 1: the pulse TOF from call 1 (t 0.1). frequency 0 in calls 3..9 (no timer
    # runs), 1 again from call 10: no new settings. Call 10: the pulse TOF's IN = NOT pauseQ
    # (TRUE since call 0) = FALSE, 1.0 - 0.1 >= 0.5: elapsed, clock FALSE, ET 500: 0 -> the pause
    # TOF's falling edge (t 1.0): 500. It elapses in call 15 (0); call 16: TRUE, 500.
    rows = run(clock(), 18, changes={3: {"frequency": 0.0}, 10: {"frequency": 1.0}})
    assert rows[:3] == [(T, 500), (T, 500), (T, 400)]
    assert rows[3:10] == [(F, 0)] * 7
    assert rows[10:18] == [(F, 500), (F, 400), (F, 300), (F, 200), (F, 100), (F, 0), (T, 500)] + [
        (T, 500)
    ]


def test_a_change_of_either_input_is_new_settings():
    # the ratio back to the value it had: still new settings (statPulsePauseRatioOld is 3.0)
    rows = run(clock(), 14, changes={2: {"pulsePauseRatio": 3.0}, 4: {"pulsePauseRatio": 1.0}})
    # call 2: restart, 750 ms; call 4: restart again, 500 ms: TRUE in calls 0..9 (4..9: 6 calls)
    assert rows[2] == (T, 750) and rows[4] == (T, 500)
    assert phases(rows) == [(T, 10), (F, 5)]


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
    assert phases(run(s, 11)) == [(T, 6), (F, 6)]


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
    state = s.fmu.getFMUstate()
    first = run(s, 12, changes={5: {"pulsePauseRatio": 0.5}})[1:]
    s.fmu.setFMUstate(state)
    s.time = 0.4
    assert run(s, 12, changes={5: {"pulsePauseRatio": 0.5}})[1:] == first
    s.fmu.freeFMUstate(state)
