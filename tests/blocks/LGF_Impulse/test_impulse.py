"""LGF_Impulse against the rules of docs/behaviour.md §9, with hand-computed expectations
traced through the block's original SCL.

The rule of one call (§9.2): (1) frequency <= 0: impulse FALSE, countdown 0, nothing else. (2)
frequency != statFrequencyOld: P := 1000000 / TRUNC(fl32(frequency * 1000.0)) ms (TIME / DINT,
towards zero; a divisor of 0 gives 0). (3) impulse := NOT the TOF's Q, read before the TOF runs
(update on read: Q = IN OR (running AND t - t_start < PT) at this call's time t; FALSE before
the first call). (4) the TOF runs with IN = NOT that Q and PT = P: a falling edge of IN starts
it and takes PT, IN TRUE stops it. (5) countdown = P - ET (ET = 0 while IN is TRUE, else
min(whole ms since the start, PT)). Call k is at k * cycleTime; an input set before a step
reaches the call at its end."""

import math

import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of, step_rows

BLOCK = "LGF_Impulse"
BELOW_1E_3 = 0.0009999999310821295  # the float32 below fl32(0.001); times 1000: 0.99999994


def impulse(cycle=0.1, frequency=1.0):
    return Slave(BLOCK, {"cycleTime": cycle}, {"frequency": frequency})


def run(s, calls, changes=None, h=None):
    """(impulse, countdown in ms) of call 0 and of `calls` further calls; changes[k] is set
    before call k."""
    return step_rows(
        s, calls, lambda out: (bool(out["impulse"]), round(out["countdown"] * 1000)), changes, h
    )


def pulses(rows):
    return [k for k, (pulse, _) in enumerate(rows) if pulse]


def test_worked_example_of_the_behaviour():
    # §9.3: cycle 0.1 s, 1 Hz: P = 1000000 / TRUNC(1000.0) = 1000 ms, m = 10. Call 0: the TOF
    # never ran, its Q FALSE: the pulse; the TOF runs with IN TRUE: ET 0, countdown 1000. Call
    # 1: Q TRUE (its IN): no pulse; IN FALSE, the falling edge starts it (t 0.1): 1000. Call
    # 1 + j: ET 100 j: 1000 - 100 j. Call 11 (t 1.1): the read finds it elapsed, Q FALSE: the
    # pulse; IN TRUE stops it, ET 0: 1000. Call 12 starts it again (t 1.2); pulse in call 22.
    rows = run(impulse(), 24)
    want = [(True, 1000), (False, 1000)] + [(False, 1000 - 100 * j) for j in range(1, 10)]
    want += [(True, 1000), (False, 1000)] + [(False, 1000 - 100 * j) for j in range(1, 10)]
    want += [(True, 1000), (False, 1000), (False, 900)]
    assert rows == want


def test_start_value_shows_pulses_in_the_default_experiment():
    # §9.1: frequency 1.0 by default; pulses in calls 0, 11, 22, 33, 44: at 0, 1.1, ... 4.4 s.
    s = Slave(BLOCK)
    assert s.get(["frequency"])["frequency"] == 1.0
    assert pulses(run(s, 50)) == [0, 11, 22, 33, 44]


def test_the_first_call_with_a_positive_frequency_pulses():
    # frequency 0 in calls 0..4: no pulse, the TOF neither runs nor is read. 2 Hz from call 5:
    # P 500; the TOF never ran, its Q is FALSE: a pulse in call 5, countdown 500; it starts in
    # call 6 (t 0.6), elapses at 1.1 s: the next pulse in call 11.
    rows = run(impulse(frequency=0.0), 12, changes={5: {"frequency": 2.0}})
    assert rows[:5] == [(False, 0)] * 5
    assert rows[5:8] == [(True, 500), (False, 500), (False, 400)]
    assert pulses(rows) == [5, 11]


@pytest.mark.parametrize(
    "cycle, frequency, period_ms, calls",
    [
        (0.1, 1.0, 1000, 11),  # m = 10
        (0.1, 2.0, 500, 6),  # 1000000 / 2000, m = 5
        (0.1, 3.0, 333, 5),  # 1000000 / 3000 = 333, m = 4
        (0.1, 20.0, 50, 2),  # m = 1: a period within one cycle
        (0.1, 1000.0, 1, 2),  # 1000000 / 1000000, m = 1
        (0.1, 1001.0, 0, 2),  # 1000000 / 1001000 = 0: m = 0, still every other call
        (0.1, 2000.0, 0, 2),
        (0.0015, 1.0, 1000, 668),  # m = ceil(1000000 / 1500) = 667
        (0.25, 1.0, 1000, 5),  # m = 4
        (0.3, 1.0, 1000, 5),  # m = ceil(1000 / 300) = 4
    ],
)
def test_a_pulse_every_m_plus_1_calls(cycle, frequency, period_ms, calls):
    # the pulse (IN TRUE), the falling edge, and m - 1 calls until it elapses; the call in
    # which it has elapsed reads Q FALSE and is the next pulse: max(m, 1) + 1 calls
    s = impulse(cycle, frequency)
    rows = run(s, 3 * calls + 1)
    assert pulses(rows) == [0, calls, 2 * calls, 3 * calls]
    assert all(rows[k][1] == period_ms for k in pulses(rows))  # IN TRUE in a pulse: ET 0


def test_countdown_of_a_period_truncated_to_whole_ms():
    # 3 Hz: P 333 ms, cycle 0.1 s. Call 0: pulse, 333; call 1 starts the TOF (t 0.1): 333;
    # call 2: ET 100 -> 233; 3: 133; 4: 33; call 5 (t 0.5, 400 >= 333): pulse, ET 0 -> 333;
    # call 6 starts it again: 333; call 7: 233.
    assert run(impulse(frequency=3.0), 8) == [
        (True, 333),
        (False, 333),
        (False, 233),
        (False, 133),
        (False, 33),
        (True, 333),
        (False, 333),
        (False, 233),
        (False, 133),
    ]


@pytest.mark.parametrize(
    "frequency, period_ms",
    [
        (0.0123, 83333),  # fl32(0.0123 * 1000) = 12.299999: TRUNC 12, 1000000 / 12
        (0.012, 83333),  # 12.0: the same divisor
        (0.3, 3333),  # fl32(0.3) * 1000 = 300.0: 1000000 / 300 = 3333
        (0.8, 1250),  # 800.0
        (1.6, 625),  # 1600.0
        (7.0, 142),  # 1000000 / 7000 = 142.857 -> 142
        (0.7, 1428),  # fl32(0.7) * 1000 = 699.99998... rounds to 700.0
        (999.0, 1),  # 1000000 / 999000
        (1000.0, 1),
        (1001.0, 0),
        (0.001, 1000000),  # fl32(0.001) * 1000 = 1.0: the longest period, 1000 s
        (0.0015, 1000000),  # 1.5: TRUNC 1
        (0.002, 500000),  # 2.0
        (BELOW_1E_3, 0),  # 0.99999994: TRUNC 0, a division by 0 gives 0 (§9.5)
        (1e-4, 0),  # 0.1: TRUNC 0
        (4.656613157294487e-07, 0),
        (1.4e-45, 0),  # the smallest float32: the product is tiny, TRUNC 0
        (2147483.0, 0),  # 2147483008.0 fits a DINT: 1000000 / 2147483008 = 0
        (1e30, 0),  # 1e33 does not fit a DINT: 0 whatever the conversion gives (§9.2)
        (1e36, 0),  # 1e36 * 1000 = +Inf
        (math.inf, 0),
    ],
)
def test_the_period_is_a_time_divided_by_a_dint(frequency, period_ms):
    # call 0: the pulse, IN TRUE, ET 0: countdown P
    assert run(impulse(frequency=frequency), 0) == [(True, period_ms)]


def test_a_period_of_83_333_s():
    # 0.0123 Hz: P 83333 ms (1/f would be 81.3 s), cycle 1 s: m = 84, a pulse every 85 calls
    rows = run(impulse(cycle=1.0, frequency=0.0123), 170)
    assert pulses(rows) == [0, 85, 170]
    assert rows[1] == (False, 83333) and rows[84] == (False, 333)


@pytest.mark.parametrize("frequency", [math.inf, 2000.0, 1e-4, BELOW_1E_3, 1.4e-45])
def test_a_period_of_0_pulses_every_other_call(frequency):
    # P 0: call 0 pulses (IN TRUE, Q TRUE); call 1: Q TRUE, no pulse; the falling edge starts
    # the TOF with PT 0, elapsed at once; call 2 reads Q FALSE: a pulse; ...
    rows = run(impulse(frequency=frequency), 7)
    assert rows == [(True, 0), (False, 0)] * 4


@pytest.mark.parametrize("frequency", [0.0, -0.0, -1.0, -1e38, -math.inf])
def test_no_frequency_no_pulses(frequency):
    assert run(impulse(frequency=frequency), 20) == [(False, 0)] * 21


def test_the_tof_measures_time_not_calls_while_the_frequency_is_0():
    # 1 Hz: the TOF starts in call 1 (t 0.1). frequency 0 in calls 6..14: no pulse, the TOF is
    # neither executed nor read. frequency 1 again in call 15 (no new frequency: statFrequencyOld
    # is still 1.0): the read finds the TOF elapsed (1.5 - 0.1 >= 1.0): Q FALSE, the pulse;
    # IN TRUE, ET 0: 1000. Call 16 starts it (t 1.6): 1000; 17: 900; the pulse in call 26.
    rows = run(impulse(), 28, changes={6: {"frequency": 0.0}, 15: {"frequency": 1.0}})
    assert rows[5] == (False, 600)
    assert rows[6:15] == [(False, 0)] * 9
    assert rows[15:18] == [(True, 1000), (False, 1000), (False, 900)]
    assert pulses(rows) == [0, 15, 26]


def test_a_new_frequency_while_the_tof_runs():
    # §9.3: 1 Hz, the TOF from call 1 (t 0.1). 10 Hz before call 9 (ET 800): P 100 at once, the
    # TOF keeps PT 1000: countdown 100 - 800 = -700, then -800. Call 11 (t 1.1): elapsed, the
    # pulse, IN TRUE, ET 0: 100. Call 12 starts it with PT 100; call 13 reads it elapsed: a
    # pulse; from then on every other call.
    rows = run(impulse(), 20, changes={9: {"frequency": 10.0}})
    assert rows[8] == (False, 300)
    assert rows[9:16] == [
        (False, -700),
        (False, -800),
        (True, 100),
        (False, 100),
        (True, 100),
        (False, 100),
        (True, 100),
    ]
    assert pulses(rows) == [0, 11, 13, 15, 17, 19]


def test_a_lower_frequency_while_the_tof_runs():
    # 2 Hz (P 500), the TOF from call 1 (t 0.1); 1 Hz before call 3 (ET 200): countdown 1000 -
    # 200 = 800; the pulse still comes at ET 500, in call 6, with countdown 1000 - 0; call 7
    # starts the TOF with PT 1000 (t 0.7): the next pulse in call 17.
    rows = run(impulse(frequency=2.0), 20, changes={3: {"frequency": 1.0}})
    assert rows[:8] == [
        (True, 500),
        (False, 500),
        (False, 400),
        (False, 800),
        (False, 700),
        (False, 600),
        (True, 1000),
        (False, 1000),
    ]
    assert pulses(rows) == [0, 6, 17]


def test_the_same_frequency_again_recomputes_nothing():
    # setting 1.0 again (equal to statFrequencyOld) changes nothing: the same run as without
    a = run(impulse(), 30)
    b = run(impulse(), 30, changes={k: {"frequency": 1.0} for k in range(1, 31, 4)})
    assert a == b


def test_frequency_is_a_real():
    # §1.4: the value set is stored as the nearest float32
    s = impulse(frequency=0.1)
    assert s.get(["frequency"])["frequency"] == 0.10000000149011612
    # fl32(0.1) * 1000 = 100.0 (rounded), 1000000 / 100: P 10000 ms
    assert run(s, 0) == [(True, 10000)]


def test_nan_is_refused_and_not_applied():
    s = impulse(frequency=2.0)
    assert status_of(s.fmu.setReal, [s.vr("frequency")], [math.nan]) == fmi2Error
    assert any("frequency" in text for _, _, text in s.log)
    assert s.get(["frequency"])["frequency"] == 2.0
    assert pulses(run(s, 20)) == [0, 6, 12, 18]  # 2 Hz as before: every 6 calls


@pytest.mark.parametrize("value", [4.6e-7, 1.4e-45, 1e-38, 4.65661287e-07, 3e9])
def test_every_other_frequency_is_accepted(value):
    # values the FMU's first version refused (as 1/f, the period would not fit a TIME): the
    # original's period is at most 1000000 ms, and 0 ms below 0.001 Hz (and above 1000 Hz)
    s = impulse(frequency=2.0)
    assert status_of(s.fmu.setReal, [s.vr("frequency")], [value]) != fmi2Error
    assert s.step(0.1)["countdown"] == 0.0


def test_setting_an_output_is_refused():
    s = impulse()
    assert status_of(s.fmu.setBoolean, [s.vr("impulse")], [True]) == fmi2Error
    assert status_of(s.fmu.setReal, [s.vr("countdown")], [1.0]) == fmi2Error


def test_fmu_state_replays_the_period():
    s = impulse(frequency=3.0)
    run(s, 3)  # calls 0..3
    first, again = s.replayed(lambda: run(s, 10, changes={4: {"frequency": 7.0}})[1:])
    assert again == first
