"""LGF_Impulse against the rules of docs/behaviour.md §9, with hand-computed expectations.

The rule of one call (§9.2): (1) frequency <= 0: impulse FALSE, countdown 0, nothing else. (2)
frequency != statFrequencyOld: P := TRUNC(fl32(1000000.0 / fl32(frequency * 1000.0))) ms. (3)
the TOF with IN = NOT Q (Q of its previous execution, FALSE at first) and PT = P: a falling edge
of IN starts it and takes PT; Q = IN OR (running AND t - t_start < PT); ET = 0 while IN is TRUE,
else min(whole ms since the start, PT). (4) impulse = NOT Q, countdown = P - ET. Call k is at
k * cycleTime; an input set before a step reaches the call at its end."""

import math

import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of

BLOCK = "LGF_Impulse"
SMALLEST = 4.656613157294487e-07  # float32 4.6566132e-07 (§9.4)


def impulse(cycle=0.1, frequency=1.0):
    return Slave(BLOCK, {"cycleTime": cycle}, {"frequency": frequency})


def run(s, calls, changes=None, h=None):
    """(impulse, countdown in ms) of call 0 and of `calls` further calls; changes[k] is set
    before call k."""
    h = h or s.get(["cycleTime"])["cycleTime"]
    changes = changes or {}

    def row(out):
        return (bool(out["impulse"]), round(out["countdown"] * 1000))

    rows = [row(s.outputs())]
    for k in range(1, calls + 1):
        if k in changes:
            s.set(changes[k])
        rows.append(row(s.step(h)))
    return rows


def pulses(rows):
    return [k for k, (pulse, _) in enumerate(rows) if pulse]


def test_worked_example_of_the_behaviour():
    # §9.3: cycle 0.1 s, 1 Hz: P = 1e6 / 1000 = 1000 ms, m = 10. Call 0: IN = NOT FALSE, Q TRUE,
    # ET 0: countdown 1000. Call 1: the falling edge starts the TOF (t 0.1), ET 0: 1000. Call
    # 1 + j: ET 100 j: 1000 - 100 j. Call 11: ET 1000 elapsed, Q FALSE: the pulse, countdown 0.
    # Call 12: IN TRUE, Q TRUE, ET 0: 1000. Call 13: starts again (t 1.3); pulse in call 23.
    rows = run(impulse(), 24)
    want = [(False, 1000), (False, 1000)] + [(False, 1000 - 100 * j) for j in range(1, 10)]
    want += [(True, 0), (False, 1000), (False, 1000)]
    want += [(False, 1000 - 100 * j) for j in range(1, 10)] + [(True, 0), (False, 1000)]
    assert rows == want


def test_start_value_shows_pulses_in_the_default_experiment():
    # §9.1: frequency 1.0 by default; pulses in calls 11, 23, 35, 47: at 1.1, 2.3, 3.5, 4.7 s.
    s = Slave(BLOCK)
    assert s.get(["frequency"])["frequency"] == 1.0
    assert pulses(run(s, 50)) == [11, 23, 35, 47]


@pytest.mark.parametrize(
    "cycle, frequency, period_ms, calls",
    [
        (0.1, 1.0, 1000, 12),  # m = 10
        (0.1, 2.0, 500, 7),  # m = 5
        (0.1, 3.0, 333, 6),  # 1e6 / 3000 = 333.33334 -> 333, m = 4
        (0.1, 20.0, 50, 3),  # m = 1: a period within one cycle
        (0.1, 1000.0, 1, 3),  # q = 1.0, P 1 ms, m = 1
        (0.1, 1001.0, 0, 2),  # q = 0.999, P 0: m = 0
        (0.1, 2000.0, 0, 2),
        (0.0015, 1.0, 1000, 669),  # m = ceil(1000000 / 1500) = 667
        (0.25, 1.0, 1000, 6),  # m = 4
        (0.3, 1.0, 1000, 6),  # m = ceil(1000 / 300) = 4
    ],
)
def test_a_pulse_every_m_plus_2_calls(cycle, frequency, period_ms, calls):
    s = impulse(cycle, frequency)
    rows = run(s, 3 * calls + 2)
    assert rows[0] == (False, period_ms)  # call 0: no pulse, countdown P
    found = pulses(rows)
    assert found[0] == calls - 1  # the first pulse in call 1 + m
    assert [b - a for a, b in zip(found, found[1:])] == [calls] * (len(found) - 1)
    assert all(rows[k][1] == 0 for k in found)


def test_countdown_of_a_period_truncated_to_whole_ms():
    # 3 Hz: P 333 ms, cycle 0.1 s. Calls 0, 1: 333; call 2: ET 100 -> 233; 3: 133; 4: 33;
    # call 5: 400 >= 333, pulse, ET = PT 333 -> 0; call 6: 333 (IN TRUE); call 7: 333 (start).
    assert run(impulse(frequency=3.0), 8) == [
        (False, 333),
        (False, 333),
        (False, 233),
        (False, 133),
        (False, 33),
        (True, 0),
        (False, 333),
        (False, 333),
        (False, 233),
    ]


@pytest.mark.parametrize(
    "frequency, period_ms",
    [
        (0.3, 3333),  # fl32(0.3) * 1000 = 300.0; 1e6 / 300 = 3333.3333
        (0.8, 1250),  # fl32(0.8) * 1000 = 800.0 (exactly 1249.99998 ms in real numbers)
        (1.6, 625),  # the same rounding: 1600.0, 625.0 (exactly 624.99999)
        (7.0, 142),  # 142.85715
        (999.0, 1),  # 1.001001
        (1000.0, 1),
        (1001.0, 0),
        (1e30, 0),  # fl32(1e33) = 1e33, q = 1e-27
        (1e36, 0),  # 1e36 * 1000 = +Inf, q = 0
        (math.inf, 0),
        (SMALLEST, 2147483520),  # q = 2147483520.0, the largest float32 below 2^31
    ],
)
def test_the_period_in_float32_and_trunc(frequency, period_ms):
    # countdown of call 0 (IN TRUE, ET 0) is P
    assert run(impulse(frequency=frequency), 0) == [(False, period_ms)]


def test_infinite_frequency_pulses_every_other_call():
    # P 0: call 0 IN TRUE (Q TRUE); call 1 starts and elapses at once (Q FALSE): a pulse; ...
    rows = run(impulse(frequency=math.inf), 7)
    assert rows == [(False, 0), (True, 0)] * 4


@pytest.mark.parametrize("frequency", [0.0, -0.0, -1.0, -1e38, -math.inf])
def test_no_frequency_no_pulses(frequency):
    assert run(impulse(frequency=frequency), 20) == [(False, 0)] * 21


def test_the_tof_measures_time_not_calls_while_the_frequency_is_0():
    # 1 Hz: the TOF starts in call 1 (t 0.1). frequency 0 in calls 6..14: off, the TOF is not
    # executed. frequency 1 again in call 15 (no new frequency: statFrequencyOld is still 1.0):
    # IN = NOT Q (Q TRUE from call 5) = FALSE, no edge, 1.5 - 0.1 >= 1.0: elapsed -> the pulse
    # in call 15, countdown 1000 - min(1400, 1000) = 0. Call 16: IN TRUE, 17 starts, 27 pulses.
    rows = run(impulse(), 28, changes={6: {"frequency": 0.0}, 15: {"frequency": 1.0}})
    assert rows[5] == (False, 600)
    assert rows[6:15] == [(False, 0)] * 9
    assert rows[15:18] == [(True, 0), (False, 1000), (False, 1000)]
    assert pulses(rows) == [15, 27]


def test_a_new_frequency_while_the_tof_runs():
    # §9.3: 1 Hz, the TOF from call 1 (t 0.1). 10 Hz before call 9 (ET 800): P 100 at once, the
    # TOF keeps PT 1000: countdown 100 - 800 = -700, then -800, and -900 in call 11 (the pulse,
    # ET 1000). Call 12: IN TRUE, ET 0: 100; call 13 starts with PT 100; call 14 pulses; then
    # every 3 calls.
    rows = run(impulse(), 20, changes={9: {"frequency": 10.0}})
    assert rows[8] == (False, 300)
    assert rows[9:15] == [
        (False, -700),
        (False, -800),
        (True, -900),
        (False, 100),
        (False, 100),
    ] + [(True, 0)]
    assert pulses(rows) == [11, 14, 17, 20]


def test_a_lower_frequency_while_the_tof_runs():
    # 2 Hz (P 500), TOF from call 1; 1 Hz before call 3 (ET 200): countdown 1000 - 200 = 800;
    # the pulse still comes at ET 500 (call 6) with countdown 1000 - 500 = 500; from call 8 on
    # the TOF takes 1000: the next pulse in call 18.
    rows = run(impulse(frequency=2.0), 20, changes={3: {"frequency": 1.0}})
    assert rows[3:8] == [(False, 800), (False, 700), (False, 600), (True, 500), (False, 1000)]
    assert pulses(rows) == [6, 18]


def test_the_same_frequency_again_recomputes_nothing():
    # setting 1.0 again (equal to statFrequencyOld) changes nothing: the same run as without
    a = run(impulse(), 30)
    b = run(impulse(), 30, changes={k: {"frequency": 1.0} for k in range(1, 31, 4)})
    assert a == b


def test_frequency_is_a_real():
    # §1.4: the value set is stored as the nearest float32
    s = impulse(frequency=0.1)
    assert s.get(["frequency"])["frequency"] == 0.10000000149011612
    # fl32(0.1) * 1000 = 100.0 (rounded), q = 10000.0: P 10000 ms
    assert run(s, 0) == [(False, 10000)]


@pytest.mark.parametrize(
    "value",
    [math.nan, 4.6e-7, 1.4e-45, 1e-38, 4.65661287e-07],  # the last: the float32 below SMALLEST
)
def test_refused_frequencies_are_not_applied(value):
    s = impulse(frequency=2.0)
    assert status_of(s.fmu.setReal, [s.vr("frequency")], [value]) == fmi2Error
    assert any("frequency" in text for _, _, text in s.log)
    assert s.get(["frequency"])["frequency"] == 2.0
    assert pulses(run(s, 20)) == [6, 13, 20]  # 2 Hz as before: first in call 1 + 5, every 7


def test_the_smallest_frequency_is_accepted():
    s = impulse(frequency=2.0)
    assert status_of(s.fmu.setReal, [s.vr("frequency")], [SMALLEST]) != fmi2Error
    assert s.step(0.1)["countdown"] == 2147483.52


def test_setting_an_output_is_refused():
    s = impulse()
    assert status_of(s.fmu.setBoolean, [s.vr("impulse")], [True]) == fmi2Error
    assert status_of(s.fmu.setReal, [s.vr("countdown")], [1.0]) == fmi2Error


def test_fmu_state_replays_the_period():
    s = impulse(frequency=3.0)
    run(s, 3)  # calls 0..3
    state = s.fmu.getFMUstate()
    first = run(s, 10, changes={4: {"frequency": 7.0}})[1:]
    s.fmu.setFMUstate(state)
    s.time = 0.3
    assert run(s, 10, changes={4: {"frequency": 7.0}})[1:] == first
    s.fmu.freeFMUstate(state)
