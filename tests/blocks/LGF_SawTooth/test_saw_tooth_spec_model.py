"""The SawTooth model alone against the worked examples and rules of docs/behaviour.md §2.

Every expectation below is derived by hand from docs/behaviour.md §2; the derivations are in the
comments.
Notation: call k happens at k*cycleTime (call 0 at t0 = 0, the first call, which latches).
PLC timing (plcTiming true), per call: (1) latch if first call or reset; (2) if the TON's Q of
the previous call is TRUE and reset is FALSE: step, and the TON's IN is FALSE in this call;
(3) TON with IN (TRUE in every other call, reset calls included), PT = latched timeRange.
A TON whose IN rises in call s has Q TRUE from the first call with (k - s)*cycleTime >= PT.
Step counter: count := count + 1 in INT; if count > numberSteps: value := startValue,
count := 0; otherwise value := value + incrementRange (INT wrap).
"""

import pytest

from tests.models.iec import int16

from .model import SawTooth
from .spec import inp

CYC = 100_000  # 0.1 s in µs


def run(plc, n_calls, inputs, cycle_us=CYC):
    """Values of calls 0 .. n_calls-1; inputs is a dict or a function k -> dict."""
    f = inputs if callable(inputs) else (lambda k: inputs)
    b = SawTooth(cycle_us, plcTiming=plc)
    return [b.call(k * cycle_us, f(k))["value"] for k in range(n_calls)]


def change_calls(values):
    return [k for k in range(1, len(values)) if values[k] != values[k - 1]]


# ------------------------------------------------------------------ (a) PLC worked example
def test_a_plc_worked_example():
    # cycleTime 0.1 s, timeRange 0.3 s, numberSteps 3, increment 10.
    # call 0: latch, TON IN rises (start 0). Q TRUE at call 3 (ET 0.3).
    # call 4: step 0 -> 10 (count 1), IN FALSE. call 5: IN rises, Q at call 8. call 9: 20 (count 2).
    # call 10 rises, Q 13, call 14: 30 (count 3). call 15 rises, Q 18, call 19: count 4 > 3 -> 0.
    # call 20 rises, Q 23, call 24: 10.
    v = run(True, 25, inp(start=0, tr=0.3, inc=10, n=3))
    assert v == [0] * 4 + [10] * 5 + [20] * 5 + [30] * 5 + [0] * 5 + [10]
    assert change_calls(v) == [4, 9, 14, 19, 24]  # 0.4, 0.9, 1.4 s, back to start at 1.9 s


# ------------------------------------------------------------------ (b) reset in calls 1..4
def test_b_plc_reset_calls_1_to_4():
    # cycleTime 0.1 s, timeRange 0.2 s, increment 1, numberSteps 100, reset TRUE in calls 1..4.
    # call 0: latch (value 0), TON starts at call 0.
    # call 1 (reset): latch, no step, IN TRUE: ET 0.1, Q FALSE.
    # call 2 (reset): ET 0.2 -> Q TRUE.  calls 3, 4 (reset): Q TRUE, but a reset call never steps,
    #   and IN stays TRUE, so the timer is neither stopped nor restarted.
    # call 5: Q of call 4 TRUE, reset FALSE -> step 0 -> 1, IN FALSE (Q FALSE).
    # call 6: IN rises (start 0.6); Q at call 8 (ET 0.2).  call 9: step -> 2.
    # call 10 rises, Q 12, call 13: 3.  call 14 rises, Q 16, call 17: 4.
    f = lambda k: inp(start=0, tr=0.2, inc=1, n=100, reset=(1 <= k <= 4))
    v = run(True, 18, f)
    assert v == [0] * 5 + [1] * 4 + [2] * 4 + [3] * 4 + [4]


def test_b_documented_reset_calls_1_to_4():
    # The same inputs in documented timing: t_ref = 0.4 s (call 4, the last latching call);
    # step m at the first call at or after 0.4 + m*0.2 s -> calls 6, 8, 10.
    f = lambda k: inp(start=0, tr=0.2, inc=1, n=100, reset=(1 <= k <= 4))
    v = run(False, 12, f)
    assert v == [0] * 6 + [1] * 2 + [2] * 2 + [3] * 2


# ------------------------------------------------------------------ (c) reset held, timer elapsed
def test_c_plc_reset_held_across_elapsed_timer_steps_at_once_after_release():
    # cycleTime 0.1 s, timeRange 0.3 s, increment 10, numberSteps 3; startValue 5 in calls 0, 1,
    # then 50; reset TRUE in calls 2..7.
    # call 0: latch start 5, TON starts at call 0.  call 1: Q FALSE (ET 0.1), value 5.
    # call 2 (reset): latch start 50 -> value 50; IN TRUE, ET 0.2, Q FALSE.
    # call 3 (reset): ET 0.3 -> Q TRUE.  calls 4..7 (reset): latch, no step, IN TRUE, Q stays TRUE.
    # call 8 (released): Q of call 7 TRUE -> step at once 50 -> 60 (count 1), IN FALSE.
    # call 9 rises (start 0.9), Q at 12, call 13: 70.  call 14 rises, Q 17, call 18: 80 (count 3).
    # call 19 rises, Q 22, call 23: count 4 > 3 -> back to 50.
    # (A reset call that stopped the timer would give: IN FALSE in call 4, rising in call 5,
    # Q only in call 8, so no step in call 8.)
    f = lambda k: inp(start=5 if k < 2 else 50, tr=0.3, inc=10, n=3, reset=(2 <= k <= 7))
    v = run(True, 24, f)
    assert v == [5] * 2 + [50] * 6 + [60] * 5 + [70] * 5 + [80] * 5 + [50]


def test_c_plc_time_range_latched_during_the_reset_reaches_the_timer_at_its_next_start():
    # PT is taken over by the TON at the rising edge of IN and kept until IN falls
    # (docs/behaviour.md §2.5): timeRange 1.0 s latched at call 0, 0.2 s latched by the reset
    # calls 1..2 while the timer started at call 0 runs on with PT 1.0.
    # call 0: latch tr 1.0, TON starts (PT 1.0).  calls 1, 2 (reset): latch tr 0.2, no edge.
    # call 10: ET 1.0 -> Q TRUE.  call 11: step 0 -> 1, IN FALSE.
    # call 12: IN rises, PT 0.2; Q at call 14, call 15: 2.  call 16 rises, Q 18, call 19: 3.
    f = lambda k: inp(start=0, tr=1.0 if k == 0 else 0.2, inc=1, n=100, reset=(1 <= k <= 2))
    v = run(True, 20, f)
    assert v == [0] * 11 + [1] * 4 + [2] * 4 + [3]


# ---------------------------------------------------------------- (d) one-call reset on a due step
def test_d_plc_one_call_reset_on_the_call_where_a_step_is_due():
    # cycleTime 0.1 s, timeRange 0.3 s, increment 10, numberSteps 3; startValue 0 in calls 0..3,
    # then 100; reset TRUE only in call 4, the call where the first step is due.
    # call 0: latch start 0, TON starts at call 0.  calls 1, 2: Q FALSE.  call 3: ET 0.3 -> Q TRUE.
    # call 4 (reset): (1) latch start 100 -> value 100, count 0; (2) Q of call 3 is TRUE but reset
    #   is TRUE -> no step; (3) IN TRUE (not a stepping call), so the timer started at call 0 is
    #   not restarted: ET 0.4, Q TRUE.
    # call 5: Q of call 4 TRUE, reset FALSE -> step 100 -> 110 (count 1), IN FALSE.
    #   (Had the reset call restarted the timer, call 5 would not step: Q only at call 8, step at
    #   9.)
    # call 6 rises (start 0.6), Q at 9, call 10: 120.  call 11 rises, Q 14, call 15: 130 (count 3).
    # call 16 rises, Q 19, call 20: count 4 > 3 -> 100.  call 21 rises, Q 24, call 25: 110.
    f = lambda k: inp(start=0 if k < 4 else 100, tr=0.3, inc=10, n=3, reset=(k == 4))
    v = run(True, 26, f)
    assert v == [0] * 4 + [100] + [110] * 5 + [120] * 5 + [130] * 5 + [100] * 5 + [110]


# ------------------------------------------------------------------ (e) the INT step counter
N_CALLS = 70_000


def test_e_documented_number_steps_32767_never_returns():
    # timeRange 0, documented timing: every call k >= 1 is step k. The count after step k is
    # int16(k): it wraps 32767 -> -32768 and never exceeds 32767, so value never returns to
    # startValue; value = int16(0 + k*1), wrapping 32767 -> -32768 at call 32768.
    v = run(False, N_CALLS, inp(start=0, tr=0.0, inc=1, n=32767))
    assert v[32767] == 32767 and v[32768] == -32768 and v[32769] == -32767
    assert v[65535] == -1 and v[65536] == 0 and v[65537] == 1  # plain INT wrap, not a return
    assert all(v[k] == int16(k) for k in range(N_CALLS))
    assert all(int16(v[k] - v[k - 1]) == 1 for k in range(1, N_CALLS))  # never snaps back


def test_e_documented_number_steps_32766_returns():
    # count 32767 > 32766 at step 32767 (call 32767) -> value 0, count 0; period 32767 calls.
    v = run(False, N_CALLS, inp(start=0, tr=0.0, inc=1, n=32766))
    assert v[32766] == 32766 and v[32767] == 0 and v[32768] == 1
    assert v[65533] == 32766 and v[65534] == 0
    assert all(v[k] == k % 32767 for k in range(N_CALLS))


def test_e_plc_number_steps_32767_never_returns():
    # timeRange 0, PLC timing: the TON with PT 0 has Q TRUE in the call its IN rises, so call 0
    # (latch, IN rises, Q TRUE), call 1 steps (IN FALSE), call 2 IN rises (Q TRUE), call 3 steps...
    # step s happens at call 2s-1; value after call k = int16((k+1)//2). Step 32767 at call 65533
    # gives 32767, step 32768 at call 65535 gives -32768 (count -32768, not > 32767).
    v = run(True, N_CALLS, inp(start=0, tr=0.0, inc=1, n=32767))
    assert v[65532] == 32766 and v[65533] == 32767 and v[65534] == 32767
    assert v[65535] == -32768 and v[65536] == -32768 and v[65537] == -32767
    assert all(v[k] == int16((k + 1) // 2) for k in range(N_CALLS))


def test_e_plc_number_steps_32766_returns():
    # step 32767 (call 65533): count 32767 > 32766 -> back to 0; then 1 at call 65535.
    v = run(True, N_CALLS, inp(start=0, tr=0.0, inc=1, n=32766))
    assert v[65531] == 32766 and v[65532] == 32766 and v[65533] == 0 and v[65534] == 0
    assert v[65535] == 1
    assert all(v[k] == ((k + 1) // 2) % 32767 for k in range(N_CALLS))


@pytest.mark.parametrize("plc", [False, True])
def test_e_counter_small_number_steps_levels(plc):
    # numberSteps 2, startValue -3, increment 4: levels -3, 1, 5, then -3 again (count 3 > 2).
    v = run(plc, 13, inp(start=-3, tr=0.0, inc=4, n=2))
    if plc:  # steps at calls 1, 3, 5, 7, ...
        assert v == [-3, 1, 1, 5, 5, -3, -3, 1, 1, 5, 5, -3, -3]
    else:  # steps at every call
        assert v == [-3, 1, 5, -3, 1, 5, -3, 1, 5, -3, 1, 5, -3]
