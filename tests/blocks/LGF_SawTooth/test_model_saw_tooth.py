"""Tests of the SawTooth reference model against hand traces from docs/behaviour.md §2 (the IEC
helpers it uses are tested in tests/test_iec.py)."""

import pytest

from tests.models.iec import int16, time_s_to_ms

from .model import SawTooth
from .spec import EXAMPLE_1, inp


def trace(b, cycle_us, n_calls, inputs, k0=0):
    """Values of n_calls calls; inputs is a dict or a function k -> dict."""
    f = inputs if callable(inputs) else (lambda k: inputs)
    return [b.call((k0 + k) * cycle_us, f(k0 + k))["value"] for k in range(n_calls)]


def change_times(values, cycle_us):
    return [k * cycle_us for k in range(1, len(values)) if values[k] != values[k - 1]]


# ---------------------------------------------------------------- PLC-exact timing
def test_plc_exact_worked_example():
    # §2.5: cycle 0.1 s, timeRange 0.3 s, numberSteps 3, increment 10
    # -> steps at 0.4, 0.9, 1.4 s, back to start at 1.9 s.
    cyc = 100_000
    b = SawTooth(cyc, plcTiming=True)
    v = trace(b, cyc, 40, EXAMPLE_1)
    # the first level lasts one call less: the TON starts in the latching call itself
    exp = (
        [0] * 4
        + [10] * 5
        + [20] * 5
        + [30] * 5
        + [0] * 5
        + [10] * 5
        + [20] * 5
        + [30] * 5
        + [0] * 1
    )
    assert v == exp
    assert change_times(v, cyc)[:4] == [400_000, 900_000, 1_400_000, 1_900_000]


@pytest.mark.parametrize(
    "cyc,tr",
    [
        (100_000, 0.3),
        (100_000, 0.25),
        (30_000, 0.1),
        (10_000, 0.005),
        (100_000, 1.0),
        (1_000, 0.0105),
    ],
)
def test_plc_exact_step_duration(cyc, tr):
    # §2.5: each step lasts ceil(timeRange/cycleTime)*cycleTime + 2*cycleTime.
    tr_us = time_s_to_ms(tr) * 1000
    per_step = (-(-tr_us // cyc) + 2) * cyc
    b = SawTooth(cyc, plcTiming=True)
    v = trace(b, cyc, 12 * per_step // cyc + 1, inp(start=5, tr=tr, inc=-3, n=2))
    ct = change_times(v, cyc)
    assert len(ct) >= 10
    assert ct[0] == per_step - cyc  # first level: the TON starts in the latching call
    assert all(b_ - a == per_step for a, b_ in zip(ct, ct[1:]))
    assert sorted(set(v)) == [-1, 2, 5]  # levels start, start+inc, start+2inc


@pytest.mark.parametrize("tr", [0.0, -0.5])
def test_plc_exact_time_range_zero_or_negative(tr):
    # timeRange 0: a step every 2 calls; negative behaves like 0.
    b = SawTooth(100_000, plcTiming=True)
    v = trace(b, 100_000, 9, inp(start=0, tr=tr, inc=1, n=100))
    assert v == [0, 1, 1, 2, 2, 3, 3, 4, 4]


def test_plc_exact_reset_does_not_restart_timer():
    cyc = 100_000
    b = SawTooth(cyc, plcTiming=True)
    # reset TRUE only at the call at 0.2 s: latches new parameters but the TON started at 0 runs on
    f = lambda k: inp(start=100 if k >= 2 else 0, tr=0.3, inc=1, n=3, reset=(k == 2))
    v = trace(b, cyc, 10, f)
    assert v == [0, 0, 100, 100, 101, 101, 101, 101, 101, 102]


def test_plc_exact_reset_held():
    cyc = 100_000
    b = SawTooth(cyc, plcTiming=True)
    # reset held in calls 3..6 (0.3 to 0.6 s). docs/behaviour.md §2: a reset call never steps and
    # never stops the timer (IN is TRUE in every reset call).
    # TON started at call 0; Q TRUE from call 3 (ET 0.3) and it stays TRUE through the reset
    # calls 3..6; call 7 (reset released) steps at once (7 -> 8), IN FALSE; call 8 restarts the
    # timer, Q at call 11, step at call 12 (8 -> 9).
    f = lambda k: inp(start=7, tr=0.3, inc=1, n=3, reset=(3 <= k <= 6))
    v = trace(b, cyc, 14, f)
    assert v == [7] * 7 + [8] * 5 + [9] * 2


# The TON takes PT over at the rising edge of IN and keeps it until IN falls (docs/behaviour.md
# §2.5). Notation: call k at k*0.1 s; a TON whose IN rises in call s with PT p has Q from the
# first call k with (k - s)*0.1 s >= p (p <= 0: Q in call s itself); a call whose previous Q is
# TRUE and whose reset is FALSE steps with IN FALSE, so the next call is a rising edge.
@pytest.mark.parametrize("tr_after", [0.2, 1.0])
def test_plc_exact_time_range_latched_by_reset_reaches_timer_at_next_start(tr_after):
    # §2.5 worked example: cycleTime 0.1 s, increment 1, numberSteps 100, timeRange 1.0 s; in
    # call 3 timeRange 0.2 s with reset TRUE in that call only -> value 0 until call 10, 1 from
    # call 11 (not from call 4). What the input is after call 3 does not matter (no latch).
    # call 0: latch tr 1.0, IN rises, PT 1.0 (start 0.0 s).
    # call 3 (reset): latch tr 0.2, value 0; IN TRUE, no edge: PT stays 1.0 (ET 0.3 s).
    #   (Had PT 0.2 reached the running timer: ET 0.3 >= 0.2, Q in call 3, step in call 4.)
    # call 10: ET 1.0 -> Q.  call 11: step 0 -> 1, IN FALSE.
    # call 12: IN rises, PT 0.2 (the latched one); Q in call 14; call 15: 2, IN FALSE.
    # call 16 rises, Q 18, call 19: 3.  call 20 rises, Q 22, call 23: 4.  24, 26, call 27: 5.
    cyc = 100_000
    b = SawTooth(cyc, plcTiming=True)
    f = lambda k: inp(
        start=0, tr=1.0 if k < 3 else (0.2 if k == 3 else tr_after), inc=1, n=100, reset=(k == 3)
    )
    v = trace(b, cyc, 28, f)
    assert v[:11] == [0] * 11 and v[11] == 1
    assert v == [0] * 11 + [1] * 4 + [2] * 4 + [3] * 4 + [4] * 4 + [5]
    # the steps after the first last ceil(0.2/0.1) + 2 = 4 calls, the new timeRange's duration
    assert change_times(v, cyc) == [1_100_000, 1_500_000, 1_900_000, 2_300_000, 2_700_000]


def test_plc_exact_reset_in_the_restart_call_takes_the_new_time_range_at_once():
    # cycleTime 0.1 s, timeRange 0.3 s, increment 10, numberSteps 100; reset only in call 5, the
    # call right after the first step, with startValue 5 and timeRange 0.1 s.
    # call 0: latch, IN rises with PT 0.3; Q in call 3; call 4: step 0 -> 10, IN FALSE.
    # call 5 (reset): (1) latch start 5, tr 0.1 -> value 5; (2) Q of call 4 FALSE, no step;
    #   (3) IN rises in this call, after the latch: PT 0.1, start 0.5 s.
    # call 6: ET 0.1 -> Q.  call 7: 5 -> 15, IN FALSE.  call 8 rises, Q 9, call 10: 25.
    # call 11 rises, Q 12, call 13: 35.  call 14 rises, Q 15, call 16: 45.
    cyc = 100_000
    b = SawTooth(cyc, plcTiming=True)
    f = lambda k: inp(
        start=0 if k < 5 else 5, tr=0.3 if k < 5 else 0.1, inc=10, n=100, reset=(k == 5)
    )
    v = trace(b, cyc, 17, f)
    assert v == [0] * 4 + [10] + [5] * 2 + [15] * 3 + [25] * 3 + [35] * 3 + [45]


@pytest.mark.parametrize("tr_new", [0.0, -0.3, -0.0004])
def test_plc_exact_pt_zero_or_negative_latched_while_timer_runs(tr_new):
    # timeRange 1.0 s latched in call 0; reset in call 3 latches tr_new (-0.0004 s is TIME 0 ms,
    # -0.3 s is -300 ms, which the TON sets to 0 when it takes it over).
    # call 0: IN rises, PT 1.0; call 3 (reset): PT stays 1.0; call 10: Q; call 11: 0 -> 1.
    # call 12: IN rises with PT <= 0 -> Q in that same call; call 13: 1 -> 2, IN FALSE.
    # call 14 rises, Q; call 15: 3.  call 16: Q; call 17: 4.  call 18: Q; call 19: 5.
    cyc = 100_000
    b = SawTooth(cyc, plcTiming=True)
    f = lambda k: inp(start=0, tr=1.0 if k < 3 else tr_new, inc=1, n=100, reset=(k == 3))
    v = trace(b, cyc, 20, f)
    assert v == [0] * 11 + [1, 1, 2, 2, 3, 3, 4, 4, 5]


@pytest.mark.parametrize("tr0", [0.0, -0.5])
def test_plc_exact_pt_zero_at_the_edge_kept_until_the_next_start(tr0):
    # timeRange tr0 (<= 0) latched in call 0; reset in call 1 latches 1.0 s.
    # call 0: IN rises with PT 0 (negative set to 0) -> Q in call 0 already.
    # call 1 (reset): latch 1.0, value 0; no step (reset); IN TRUE, no edge: PT stays 0, Q TRUE.
    # call 2: Q of call 1 TRUE, reset FALSE -> step 0 -> 1, IN FALSE.
    # call 3: IN rises with PT 1.0 (start 0.3 s); Q in call 13; call 14: 2.
    # call 15 rises, Q in call 25, call 26: 3 (each step now 10 + 2 = 12 calls).
    cyc = 100_000
    b = SawTooth(cyc, plcTiming=True)
    f = lambda k: inp(start=0, tr=tr0 if k == 0 else 1.0, inc=1, n=100, reset=(k == 1))
    v = trace(b, cyc, 27, f)
    assert v == [0] * 2 + [1] * 12 + [2] * 12 + [3]


# ---------------------------------------------------------------- documented timing
def test_documented_multiple_of_cycle():
    # step m at t_ref + m*timeRange; tooth lasts timeRange*(numberSteps+1) (seed formula).
    cyc = 100_000
    b = SawTooth(cyc)
    v = trace(b, cyc, 30, EXAMPLE_1)
    exp = ([0] * 3 + [10] * 3 + [20] * 3 + [30] * 3) * 2 + [0] * 3 + [10] * 3
    assert v == exp
    ct = change_times(v, cyc)
    assert ct[:5] == [300_000, 600_000, 900_000, 1_200_000, 1_500_000]
    assert ct[3] - 0 == 300_000 * (3 + 1)  # tooth duration


def test_documented_non_multiple():
    # timeRange 0.25 s at cycle 0.1 s: steps at first call >= 0.25, 0.5, 0.75, 1.0, ...
    cyc = 100_000
    b = SawTooth(cyc)
    v = trace(b, cyc, 21, inp(start=0, tr=0.25, inc=1, n=1000))
    ct = change_times(v, cyc)
    assert ct == [300_000, 500_000, 800_000, 1_000_000, 1_300_000, 1_500_000, 1_800_000, 2_000_000]
    # tooth of numberSteps=1 lasts 2*0.25 = 0.5 s on average (returns to start every 0.5 s)
    b = SawTooth(cyc)
    v = trace(b, cyc, 21, inp(start=0, tr=0.25, inc=1, n=1))
    assert [t for t, x in zip(range(21), v) if x == 0 and t and v[t - 1] == 1] == [5, 10, 15, 20]


def test_documented_time_range_shorter_than_cycle_one_step_per_call():
    cyc = 100_000
    b = SawTooth(cyc)
    v = trace(b, cyc, 6, inp(start=0, tr=0.03, inc=1, n=100))
    assert v == [0, 1, 2, 3, 4, 5]


@pytest.mark.parametrize("tr", [0.0, -1.0])
def test_documented_time_range_zero_steps_every_call(tr):
    b = SawTooth(100_000)
    v = trace(b, 100_000, 8, inp(start=1, tr=tr, inc=2, n=2))
    assert v == [1, 3, 5, 1, 3, 5, 1, 3]


def test_documented_reset_restarts_tref():
    cyc = 100_000
    b = SawTooth(cyc)
    f = lambda k: inp(start=50 if k >= 2 else 0, tr=0.3, inc=1, n=3, reset=(k == 2))
    v = trace(b, cyc, 10, f)
    # t_ref = 0.2 s -> steps at 0.5, 0.8
    assert v == [0, 0, 50, 50, 50, 51, 51, 51, 52, 52]


# ---------------------------------------------------------------- common rules
@pytest.mark.parametrize("plc", [False, True])
def test_endless_wrap(plc):
    b = SawTooth(100_000, plcTiming=plc)
    v = trace(b, 100_000, 9, inp(start=32765, tr=0.0, inc=1, n=0, endless=True))
    exp = (
        [32765, 32766, 32767, -32768, -32767, -32766, -32765, -32764, -32763]
        if not plc
        else [32765, 32766, 32766, 32767, 32767, -32768, -32768, -32767, -32767]
    )
    assert v == exp


def test_endless_negative_increment_wrap():
    b = SawTooth(100_000)
    v = trace(b, 100_000, 4, inp(start=-32767, tr=0.0, inc=-2, endless=True, n=1))
    assert v == [-32767, 32767, 32765, 32763]


@pytest.mark.parametrize("plc", [False, True])
@pytest.mark.parametrize("n", [0, -1, -32768])
def test_number_steps_le_zero_constant(plc, n):
    b = SawTooth(100_000, plcTiming=plc)
    assert trace(b, 100_000, 20, inp(start=-12, tr=0.0, inc=5, n=n)) == [-12] * 20


def test_non_endless_wrap_inside_tooth():
    b = SawTooth(100_000)
    v = trace(b, 100_000, 5, inp(start=32000, tr=0.0, inc=500, n=2))
    assert v == [32000, 32500, int16(33000), 32000, 32500]


@pytest.mark.parametrize("plc", [False, True])
def test_input_changes_ignored_without_reset(plc):
    cyc = 100_000
    ref = trace(SawTooth(cyc, plc), cyc, 25, inp(start=0, tr=0.2, inc=3, n=2))
    f = lambda k: (
        inp(start=0, tr=0.2, inc=3, n=2)
        if k == 0
        else inp(start=99, tr=0.0, inc=-7, n=5, endless=True)
    )
    assert trace(SawTooth(cyc, plc), cyc, 25, f) == ref


@pytest.mark.parametrize("plc", [False, True])
def test_reset_level_latches_every_call(plc):
    cyc = 100_000
    b = SawTooth(cyc, plc)
    # while reset is TRUE the output is startValue (tracking changes of startValue), no steps
    f = lambda k: inp(start=k, tr=0.0, inc=1, n=10, reset=True)
    assert trace(b, cyc, 6, f) == [0, 1, 2, 3, 4, 5]


@pytest.mark.parametrize("plc", [False, True])
def test_first_call_latches_without_reset(plc):
    b = SawTooth(100_000, plc)
    assert b.call(0, inp(start=-4, tr=0.0, inc=1, n=3)) == {"value": -4}
