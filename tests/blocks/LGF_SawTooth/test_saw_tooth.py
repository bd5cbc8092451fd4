"""LGF_SawTooth against the rules of docs/behaviour.md §2, with hand-computed expectations."""

import math

import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of

from .spec import EXAMPLE_1

BLOCK = "LGF_SawTooth"


def saw(cycle=0.1, plc=False, **inputs):
    return Slave(BLOCK, {"cycleTime": cycle, "plcTiming": plc}, {**EXAMPLE_1, **inputs})


def trace(s, steps, h=None):
    """value after initialization and after each of `steps` steps of one cycle."""
    h = h or s.get(["cycleTime"])["cycleTime"]
    return [s.get(["value"])["value"]] + [s.step(h)["value"] for _ in range(steps)]


def test_documented_timing_by_hand():
    # t:      0   .1  .2  .3  .4  .5  .6  .7  .8  .9  1.0 1.1 1.2  (timeRange 0.3, 3 steps)
    assert trace(saw(), 12) == [0, 0, 0, 10, 10, 10, 20, 20, 20, 30, 30, 30, 0]


def test_plc_timing_worked_example():
    # docs/behaviour.md §2.5: steps at 0.4, 0.9, 1.4 s, back to start at 1.9 s, then every 0.5 s.
    values = trace(saw(plc=True), 25)
    changes = [(round(k * 0.1, 1), v) for k, v in enumerate(values) if k and v != values[k - 1]]
    assert changes == [(0.4, 10), (0.9, 20), (1.4, 30), (1.9, 0), (2.4, 10)]


@pytest.mark.parametrize(
    "cycle, time_range, steps",
    [(0.1, 0.3, 3), (0.01, 0.05, 4), (0.25, 1.0, 2), (1.0, 2.0, 5), (0.001, 0.007, 1)],
)
def test_tooth_duration_is_time_range_times_steps_plus_one(cycle, time_range, steps):
    s = saw(cycle, timeRange=time_range, numberSteps=steps, incrementRange=1)
    calls_per_tooth = round(time_range * (steps + 1) / cycle)
    values = trace(s, 3 * calls_per_tooth)
    restarts = [k for k in range(1, len(values)) if values[k] == 0 and values[k - 1] != 0]
    assert restarts == [calls_per_tooth, 2 * calls_per_tooth, 3 * calls_per_tooth]


@pytest.mark.parametrize("cycle, time_range", [(0.1, 0.3), (0.1, 0.25), (0.05, 0.0), (0.2, 1.0)])
def test_plc_timing_step_duration(cycle, time_range):
    s = saw(cycle, plc=True, timeRange=time_range, numberSteps=100, incrementRange=1)
    values = trace(s, 60)
    steps = [k for k in range(1, len(values)) if values[k] != values[k - 1]]
    period = math.ceil(round(time_range / cycle, 9)) + 2
    assert [b - a for a, b in zip(steps, steps[1:])] == [period] * (len(steps) - 1)


def test_negative_increment():
    assert trace(saw(startValue=100, incrementRange=-30, timeRange=0.1, numberSteps=2), 7) == [
        100,
        70,
        40,
        100,
        70,
        40,
        100,
        70,
    ]


@pytest.mark.parametrize("steps", [0, -5])
def test_number_of_steps_not_positive_gives_a_constant(steps):
    assert set(trace(saw(startValue=7, timeRange=0.1, numberSteps=steps), 10)) == {7}


def test_endless_wraps_from_32767_to_minus_32768_and_goes_on():
    s = saw(startValue=32760, incrementRange=5, timeRange=0.1, endlessSteps=True)
    assert trace(s, 4) == [32760, 32765, -32766, -32761, -32756]


def test_non_endless_levels_wrap_too():
    s = saw(startValue=32767, incrementRange=1, timeRange=0.1, numberSteps=2)
    assert trace(s, 4) == [32767, -32768, -32767, 32767, -32768]


def test_input_changes_take_effect_only_with_reset():
    s = saw(timeRange=0.1, numberSteps=3)
    assert trace(s, 2) == [0, 10, 20]
    s.set({"startValue": 500, "incrementRange": 1, "numberSteps": 1, "timeRange": 0.5})
    assert [s.step(0.1)["value"] for _ in range(3)] == [30, 0, 10]  # still the latched inputs
    s.set({"reset": True})
    assert [s.step(0.1)["value"] for _ in range(3)] == [500, 500, 500]  # reset is a level
    s.set({"reset": False})
    # the new inputs, timed from the last reset call: steps 0.5 s after it
    assert [s.step(0.1)["value"] for _ in range(11)] == [500] * 4 + [501] * 5 + [500, 500]


def test_reset_does_not_restart_the_plc_timer():
    s = saw(plc=True)  # steps due at 0.4, 0.9, ...
    trace(s, 2)  # t = 0.2
    s.set({"reset": True})
    assert s.step(0.1)["value"] == 0  # t = 0.3: reset call
    s.set({"reset": False})
    # the timer started at 0 runs on: the step of 0.4 s comes as before
    assert [s.step(0.1)["value"] for _ in range(6)] == [10, 10, 10, 10, 10, 20]


def test_time_range_is_rounded_to_whole_ms():
    s = saw(timeRange=0.0996)  # 100 ms: one step per 0.1 s cycle
    assert s.get(["timeRange"])["timeRange"] == 0.1
    assert trace(s, 3) == [0, 10, 20, 30]


@pytest.mark.parametrize(
    "name, value", [("startValue", 40000), ("incrementRange", -32769), ("numberSteps", 2**31 - 1)]
)
def test_int_inputs_outside_int_range_are_refused(name, value):
    s = saw()
    assert status_of(s.fmu.setInteger, [s.vr(name)], [value]) == fmi2Error
    assert any(name in text and "-32768 to 32767" in text for _, _, text in s.log)
    assert trace(s, 4) == [0, 0, 0, 10, 10]


# ---------------------------------------------------------------- docs/behaviour.md §2 hand traces
# PLC timing, per call: (1) latch if first call or reset; (2) if the TON's Q of the previous call
# is TRUE and reset is FALSE: step, and the TON's IN is FALSE in this call; (3) TON with IN (TRUE
# in every other call, reset calls included) and PT = the latched timeRange. Step counter: an INT,
# count := count + 1, back to startValue (count := 0) when count > numberSteps.
# Call k is the call at k * cycleTime; trace() lists call 0 (initialization) and one call per step.


def steps(s, n):
    return [s.step(s.get(["cycleTime"])["cycleTime"])["value"] for _ in range(n)]


def test_plc_reset_in_calls_1_to_4_worked_example():
    # docs/behaviour.md §2: cycleTime 0.1, timeRange 0.2, increment 1, numberSteps 100, reset in
    # calls 1-4.
    # TON from call 0, Q TRUE from call 2 (ET 0.2) and kept through the reset calls 3, 4 (no step
    # in a reset call, IN TRUE); call 5 steps (IN FALSE); call 6 restarts, Q at 8, step at 9; then
    # a step every 4 calls (13, 17).
    s = saw(plc=True, timeRange=0.2, incrementRange=1, numberSteps=100)
    values = trace(s, 0)
    s.set({"reset": True})
    values += steps(s, 4)  # calls 1..4
    s.set({"reset": False})
    values += steps(s, 13)  # calls 5..17
    assert values == [0] * 5 + [1] * 4 + [2] * 4 + [3] * 4 + [4]


def test_documented_reset_in_calls_1_to_4():
    # documented timing: t_ref = 0.4 s (call 4, the last latching call): steps at calls 6, 8, 10.
    s = saw(timeRange=0.2, incrementRange=1, numberSteps=100)
    values = trace(s, 0)
    s.set({"reset": True})
    values += steps(s, 4)
    s.set({"reset": False})
    values += steps(s, 7)  # calls 5..11
    assert values == [0] * 6 + [1] * 2 + [2] * 2 + [3] * 2


def test_plc_reset_held_across_elapsed_timer_steps_at_once_after_release():
    # timeRange 0.3, increment 10, numberSteps 3; startValue 5, then 50 with reset in calls 2..7.
    # TON from call 0, Q TRUE from call 3 and kept through the reset calls; call 8 (released)
    # steps at once to 60; call 9 restarts the timer, Q at 12, step at 13 (70), 18 (80), 23 (50).
    s = saw(plc=True, startValue=5)
    values = trace(s, 1)  # calls 0, 1
    s.set({"reset": True, "startValue": 50})
    values += steps(s, 6)  # calls 2..7
    s.set({"reset": False})
    values += steps(s, 16)  # calls 8..23
    assert values == [5] * 2 + [50] * 6 + [60] * 5 + [70] * 5 + [80] * 5 + [50]


def test_plc_one_call_reset_on_the_call_where_a_step_is_due():
    # timeRange 0.3, increment 10, numberSteps 3. TON from call 0, Q TRUE in call 3, step due in
    # call 4. reset (with startValue 100) only in call 4: latch (100), no step, IN TRUE so the
    # timer is not restarted (Q still TRUE). call 5 steps to 110 (IN FALSE); call 6 restarts,
    # Q at 9, step at 10 (120), 15 (130), 20 (count 4 > 3: 100), 25 (110).
    s = saw(plc=True)
    values = trace(s, 3)  # calls 0..3
    s.set({"reset": True, "startValue": 100})
    values += steps(s, 1)  # call 4
    s.set({"reset": False})
    values += steps(s, 21)  # calls 5..25
    assert values == [0] * 4 + [100] + [110] * 5 + [120] * 5 + [130] * 5 + [100] * 5 + [110]


@pytest.mark.parametrize("plc", [False, True])
@pytest.mark.parametrize("number_steps", [32767, 32766])
def test_int_step_counter_number_steps_32767_never_returns(plc, number_steps):
    # timeRange 0, increment 1, startValue 0. Documented timing: call k is step k. PLC timing
    # (PT 0: Q TRUE in the call IN rises): step s in call 2s-1, so after call k, (k+1)//2 steps.
    # numberSteps 32767: the INT count wraps 32767 -> -32768 and never exceeds 32767, so value
    # = int16(steps) forever (32767 -> -32768, no return). numberSteps 32766: step 32767 has
    # count 32767 > 32766 and returns to 0, so value = steps mod 32767.
    # The communication points are computed as FMPy does (i*h, not t += h), so that this test
    # sees the step counter and not the master's round-off.
    s = saw(plc=plc, timeRange=0.0, incrementRange=1, numberSteps=number_steps)
    values = [s.get(["value"])["value"]]
    for i in range(70_000):
        s.fmu.doStep(
            currentCommunicationPoint=i * 0.1, communicationStepSize=(i + 1) * 0.1 - i * 0.1
        )
        values.append(s.get(["value"])["value"])
    for k, v in enumerate(values):
        n = (k + 1) // 2 if plc else k
        want = ((n + 32768) % 65536) - 32768 if number_steps == 32767 else n % 32767
        assert v == want, f"call {k}"
    wrap = 65535 if plc else 32768  # the call with the 32768th step
    if number_steps == 32767:
        assert values[wrap - (2 if plc else 1)] == 32767 and values[wrap] == -32768
    else:
        assert values[wrap - (2 if plc else 1)] == 0 and values[wrap] == 1
