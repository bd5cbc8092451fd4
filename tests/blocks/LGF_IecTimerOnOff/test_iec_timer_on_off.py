"""LGF_IecTimerOnOff against the rules of docs/behaviour.md §8, with hand-computed expectations.

The rule of one call (§8.2): (1) TON with IN = in, PT = timeOnDelay: a rising edge of in starts
it and takes PT (negative: 0); Q = in AND t - t_start >= PT. (2) TOF with IN = the TON's Q of
this call, PT = timeOffDelay: a falling edge starts it and takes PT; IN TRUE stops it; Q = IN OR
(running AND t - t_start < PT). (3) out = the TOF's Q. Call k is at k * cycleTime; the value of
in for call k is set before the step that ends at call k (call 0: during initialization)."""

import math

import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of

BLOCK = "LGF_IecTimerOnOff"
T, F = True, False


def timer(cycle=0.1, **inputs):
    defaults = {"in": False, "timeOnDelay": 0.3, "timeOffDelay": 0.2}
    return Slave(BLOCK, {"cycleTime": cycle}, {**defaults, **inputs})


def drive(s, ins, changes=None, h=None):
    """out of call 0 (in = ins[0], set at initialization) and of one call per further entry of
    ins; changes[k] are further inputs set before call k."""
    h = h or s.get(["cycleTime"])["cycleTime"]
    changes = changes or {}
    outs = [s.get(["out"])["out"]]
    for k, value in enumerate(ins[1:], start=1):
        s.set({"in": value, **changes.get(k, {})})
        outs.append(s.step(h)["out"])
    return outs


def test_worked_example_of_the_behaviour():
    # docs/behaviour.md §8.3: on 0.3 s, off 0.2 s, cycle 0.1 s.
    # TON starts in call 1 (t 0.1), elapses in call 4 (0.4 - 0.1 >= 0.3); TOF starts in call 6
    # (TON's Q falls with in), elapses in call 8 (0.8 - 0.6 >= 0.2). Call 9: TON restarts, in
    # falls in call 10 before it elapses: nothing reaches out.
    ins = [F, T, T, T, T, T, F, F, F, T, F, F, F]
    want = [F, F, F, F, T, T, T, T, F, F, F, F, F]
    assert drive(timer(**{"in": False}), ins) == want


def test_start_values_show_the_on_delay():
    # §8.1: in TRUE, on 0.1 s, off 0.2 s: call 0 is the rising edge (memory FALSE), the TON
    # elapses in call 1 (0.1 - 0 >= 0.1): out FALSE in call 0, TRUE from call 1 on.
    s = Slave(BLOCK)
    assert s.get(["in", "timeOnDelay", "timeOffDelay"]) == {
        "in": True,
        "timeOnDelay": 0.1,
        "timeOffDelay": 0.2,
    }
    outs = [s.get(["out"])["out"]] + [s.step(0.1)["out"] for _ in range(15)]
    assert outs == [F] + [T] * 15


def test_both_delays_zero_out_follows_in():
    # PT 0: the TON's Q is TRUE in the call of the rising edge, the TOF ends in the call of the
    # falling edge: out = in in every call.
    ins = [T, F, T, T, F, F, T, F, T, T, T, F]
    assert drive(timer(timeOnDelay=0.0, timeOffDelay=0.0, **{"in": True}), ins) == ins


@pytest.mark.parametrize("delay", [-0.001, -5.0, -2147483.647])
def test_negative_delays_act_as_zero(delay):
    ins = [F, T, T, F, T, F, F]
    assert drive(timer(timeOnDelay=delay, timeOffDelay=delay), ins) == ins


def test_on_delay_zero_off_delay_nonzero():
    # on 0: out TRUE in the call in rises; off 0.2 s: FALSE 2 calls after in falls.
    ins = [F, T, F, F, F, F]
    assert drive(timer(timeOnDelay=0.0), ins) == [F, T, T, T, F, F]


def test_on_delay_nonzero_off_delay_zero():
    # on 0.3 s: TON from call 0, Q in call 3; off 0: out FALSE in the call in falls.
    ins = [T, T, T, T, T, F, T]
    assert drive(timer(timeOffDelay=0.0, **{"in": True}), ins) == [F, F, F, T, T, F, F]


def test_delay_not_a_multiple_of_the_cycle_ends_at_the_next_call():
    # on 0.25 s from call 0: 0.2 < 0.25 <= 0.3, Q in call 3; off 0.15 s from call 5 (in falls):
    # 0.1 < 0.15 <= 0.2, the TOF elapses in call 7.
    ins = [T, T, T, T, T, F, F, F, F]
    outs = drive(timer(timeOnDelay=0.25, timeOffDelay=0.15, **{"in": True}), ins)
    assert outs == [F, F, F, T, T, T, T, F, F]


def test_elapsed_time_is_measured_in_microseconds():
    # cycle 1.5 ms, on 4 ms: call k at 1500 k µs; TON from call 0 elapses at the first call with
    # 1500 k >= 4000, k = 3 (4500 µs); off 2 ms from call 5 (7500): 1500 j >= 2000, j = 2 ->
    # FALSE in call 7.
    ins = [T, T, T, T, T, F, F, F, F]
    outs = drive(timer(cycle=0.0015, timeOnDelay=0.004, timeOffDelay=0.002, **{"in": T}), ins)
    assert outs == [F, F, F, T, T, T, T, F, F]


def test_time_inputs_are_rounded_to_whole_ms():
    # §1.4: 0.0025 s -> 3 ms (halves away from zero), 0.0014 s -> 1 ms. Cycle 1 ms: the TON
    # from call 0 elapses in call 3, the TOF from call 5 in call 6.
    s = timer(cycle=0.001, timeOnDelay=0.0025, timeOffDelay=0.0014, **{"in": True})
    assert s.get(["timeOnDelay", "timeOffDelay"]) == {"timeOnDelay": 0.003, "timeOffDelay": 0.001}
    assert drive(s, [T, T, T, T, T, F, F, F]) == [F, F, F, T, T, T, F, F]


def test_a_pulse_shorter_than_the_on_delay_never_reaches_out():
    # on 0.3 s: in TRUE in calls 1, 2 (and 4, 5, 6 once more, two calls short), never 3 calls.
    ins = [F, T, T, F, T, T, F, T, T, F, F]
    assert set(drive(timer(), ins)) == {False}


def test_retrigger_during_the_off_delay_without_a_gap():
    # on 0.1 s, off 0.3 s. in TRUE in calls 0..2: TON Q from call 1, out TRUE from call 1.
    # in FALSE in call 3: the TOF starts (t 0.3), would elapse in call 6 (0.6 - 0.3 >= 0.3).
    # in TRUE in call 4: TON from call 4, Q in call 5, before call 6: out stays TRUE.
    ins = [T, T, T, F, T, T, T, T]
    outs = drive(timer(timeOnDelay=0.1, timeOffDelay=0.3, **{"in": True}), ins)
    assert outs == [F, T, T, T, T, T, T, T]


def test_retrigger_on_delay_ends_in_the_call_the_off_delay_would_end():
    # on 0.2 s, off 0.3 s. TON from call 0, Q in call 2. in FALSE in call 4: TOF from t 0.4,
    # elapses in call 7. in TRUE again in call 5: TON from 0.5, Q in call 7 - the same call. The
    # TON runs first, so the TOF's IN is TRUE in call 7 and out never falls.
    ins = [T, T, T, T, F, T, T, T, T, T]
    outs = drive(timer(timeOnDelay=0.2, timeOffDelay=0.3, **{"in": True}), ins)
    assert outs == [F, F, T, T, T, T, T, T, T, T]


def test_retrigger_too_late_leaves_a_gap():
    # on 0.3 s, off 0.2 s. TON from call 0, Q in call 3. in FALSE in call 4: TOF from 0.4,
    # elapses in call 6. in TRUE in call 5: TON from 0.5, Q in call 8: out FALSE in calls 6, 7.
    ins = [T, T, T, T, F, T, T, T, T, T]
    outs = drive(timer(**{"in": True}), ins)
    assert outs == [F, F, F, T, T, T, F, F, T, T]


def test_a_new_on_delay_takes_effect_at_the_next_rising_edge():
    # on 0.3 s taken in call 0. Call 1: on 0.1 s (the TON keeps 0.3: Q in call 3, not 2).
    # in FALSE in call 5, TRUE in call 6: the TON takes 0.1 s, Q in call 7; the TOF (off 0.2
    # from call 5) would elapse in call 7: no gap.
    ins = [T, T, T, T, T, F, T, T, T]
    outs = drive(timer(**{"in": True}), ins, changes={1: {"timeOnDelay": 0.1}})
    assert outs == [F, F, F, T, T, T, T, T, T]


def test_a_new_off_delay_takes_effect_at_the_next_falling_edge():
    # on 0, off 0.3 s. in FALSE in call 2: the TOF takes 0.3 s (elapses in call 5). Call 3:
    # off 0.1 s, no effect: out TRUE in calls 0..4. in TRUE in call 6, FALSE in call 7: the TOF
    # takes 0.1 s, elapses in call 8.
    ins = [T, T, F, F, F, F, T, F, F, F]
    outs = drive(
        timer(timeOnDelay=0.0, timeOffDelay=0.3, **{"in": True}),
        ins,
        changes={3: {"timeOffDelay": 0.1}},
    )
    assert outs == [T, T, T, T, T, F, T, T, F, F]


def test_the_largest_on_delay_elapses_without_overflow():
    # cycle 60 s, on 2147483.647 s: the TON from call 0 elapses at the first call with
    # 60 k >= 2147483.647, k = 35792 (2147520 s). One doStep over 35791 calls, then one more.
    s = timer(cycle=60.0, timeOnDelay=2147483.647, **{"in": True})
    assert not s.step(60.0 * 35791)["out"]
    assert s.step(60.0)["out"]


@pytest.mark.parametrize(
    "name, value", [("timeOnDelay", math.nan), ("timeOffDelay", 2147483.648), ("timeOnDelay", -3e6)]
)
def test_invalid_time_is_refused_and_not_applied(name, value):
    s = timer(**{"in": True})
    assert status_of(s.fmu.setReal, [s.vr(name)], [value]) == fmi2Error
    assert any(name in text for _, _, text in s.log)
    assert s.get([name])[name] == {"timeOnDelay": 0.3, "timeOffDelay": 0.2}[name]
    # the run goes on with the old delays: TON from call 0, Q in call 3
    assert drive(s, [T, T, T, T]) == [F, F, F, T]


def test_setting_the_output_is_refused():
    s = timer()
    assert status_of(s.fmu.setBoolean, [s.vr("out")], [True]) == fmi2Error
    assert not s.get(["out"])["out"]


def test_fmu_state_replays_the_timers():
    # save in the middle of the on delay and of the off delay; a restore replays both exactly.
    s = timer(timeOnDelay=0.3, timeOffDelay=0.2, **{"in": True})
    drive(s, [T, T])  # calls 0, 1: the TON runs
    first, again = s.replayed(lambda: drive(s, [None, T, T, F, F, F])[1:])  # calls 2..6
    assert again == first == [F, T, T, T, F]
