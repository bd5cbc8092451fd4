"""LGF_StoreMinMax against the rules of docs/behaviour.md §14, with hand-computed expectations.
The outputs after initialization are those of call 0, from the inputs set during
initialization."""

import math
import struct

from fmpy.fmi2 import fmi2Error

from tests.harness import Slave

BLOCK = "LGF_StoreMinMax"
LREAL_MAX = 1.7976931348623157e308
INF = math.inf


def slave(cycle=0.1, **inputs):
    return Slave(BLOCK, {"cycleTime": cycle}, inputs)


def extremes(lo, hi):
    return {"minValue": lo, "maxValue": hi}


def run(s, values, cycle=0.1):
    """One call per value (set before the step that contains the call)."""
    rows = []
    for v in values:
        s.set(v if isinstance(v, dict) else {"value": v})
        rows.append(s.step(cycle))
    return rows


def bits(x):
    return struct.pack(">d", x).hex()


def test_start_values_are_the_lgf_defaults_and_the_first_call_takes_the_value():
    # §14.1: value 0.0, reset FALSE; call 0: 0.0 < LREAL_MAX -> min 0.0; 0.0 > -LREAL_MAX -> max 0.0
    s = Slave(BLOCK)
    assert s.get(["value", "reset"]) == {"value": 0.0, "reset": False}
    assert s.outputs() == extremes(0.0, 0.0)
    assert s.step(0.1) == extremes(0.0, 0.0)


def test_extremes_since_the_first_call():
    # call 0: 3 -> (3, 3); then 5 -> max 5; -2 -> min -2; 4 and 0.5 change nothing; 9.75 -> max
    s = slave(value=3.0)
    assert s.outputs() == extremes(3.0, 3.0)
    assert run(s, [5.0, -2.0, 4.0, 0.5, 9.75]) == [
        extremes(3.0, 5.0),
        extremes(-2.0, 5.0),
        extremes(-2.0, 5.0),
        extremes(-2.0, 5.0),
        extremes(-2.0, 9.75),
    ]


def test_reset_is_a_level_that_takes_the_value_of_its_own_call():
    # §14.2 step 1 and §14.3: each call with reset TRUE restarts and then takes its value
    s = slave(value=-4.0)
    run(s, [10.0])  # (-4, 10)
    assert run(s, [{"reset": True, "value": 1.0}, {"value": 7.0}, {"value": 2.0}]) == [
        extremes(1.0, 1.0),
        extremes(7.0, 7.0),
        extremes(2.0, 2.0),
    ]
    # released: the extremes count from the last reset call's value 2.0
    assert run(s, [{"reset": False, "value": 0.0}, {"value": 3.5}]) == [
        extremes(0.0, 2.0),
        extremes(0.0, 3.5),
    ]


def test_reset_in_the_first_call():
    s = slave(value=6.0, reset=True)
    assert s.outputs() == extremes(6.0, 6.0)


def test_comparisons_are_strict_so_the_first_zero_stays():
    # §14.3: -0.0 < +0.0 and +0.0 > -0.0 are false
    s = slave(value=0.0)
    out = run(s, [-0.0])[0]
    assert bits(out["minValue"]) == bits(0.0) and bits(out["maxValue"]) == bits(0.0)
    s = slave(value=-0.0)
    out = run(s, [0.0])[0]
    assert bits(out["minValue"]) == bits(-0.0) and bits(out["maxValue"]) == bits(-0.0)


def test_infinities_against_the_reset_values():
    # +Inf < LREAL_MAX is false: the minimum stays LREAL_MAX; +Inf > -LREAL_MAX: max +Inf
    s = slave(value=INF)
    assert s.outputs() == extremes(LREAL_MAX, INF)
    # -Inf < LREAL_MAX: min -Inf; -Inf > +Inf is false
    assert run(s, [-INF, 12.0]) == [extremes(-INF, INF), extremes(-INF, INF)]
    # a reset with -Inf: min -Inf, max stays -LREAL_MAX, until a finite value arrives
    assert run(s, [{"reset": True, "value": -INF}, {"reset": False, "value": 1.5}]) == [
        extremes(-INF, -LREAL_MAX),
        extremes(-INF, 1.5),
    ]
    # a reset with +Inf, then a finite value replaces the LREAL_MAX sentinel
    assert run(s, [{"reset": True, "value": INF}, {"reset": False, "value": -3.0}]) == [
        extremes(LREAL_MAX, INF),
        extremes(-3.0, INF),
    ]


def test_the_largest_and_smallest_finite_values():
    # LREAL_MAX < LREAL_MAX is false (min stays LREAL_MAX, the same number); > -LREAL_MAX: max
    s = slave(value=LREAL_MAX)
    assert s.outputs() == extremes(LREAL_MAX, LREAL_MAX)
    s = slave(value=-LREAL_MAX)
    assert s.outputs() == extremes(-LREAL_MAX, -LREAL_MAX)


def test_nan_is_refused_and_not_applied():
    s = slave(value=2.0)
    assert s.status_of(s.fmu.setReal, [s.vr("value")], [math.nan]) == fmi2Error
    assert s.get(["value"]) == {"value": 2.0}
    assert run(s, [1.0]) == [extremes(1.0, 2.0)]


def test_an_input_reaches_the_calls_of_the_following_step():
    # §1.3: a value set at t reaches the calls in (t, t + h]; a step without a call changes
    # nothing; several calls of one step all see the same value
    s = slave(value=1.0)
    s.set({"value": -5.0})
    assert s.outputs() == extremes(1.0, 1.0)
    assert s.step(0.05) == extremes(1.0, 1.0)  # no call in (0, 0.05]
    assert s.step(0.05) == extremes(-5.0, 1.0)  # the call at 0.1
    s.set({"value": 8.0})
    assert s.step(0.3) == extremes(-5.0, 8.0)  # calls at 0.2, 0.3, 0.4


def test_model_exchange_takes_the_value_set_at_the_event():
    s = Slave(BLOCK, {"cycleTime": 0.1}, {"value": 1.0}, model_exchange=True)
    fmu = s.fmu
    fmu.newDiscreteStates()
    fmu.enterContinuousTimeMode()
    fmu.setTime(0.1)
    fmu.enterEventMode()
    s.set({"value": -3.0})
    fmu.newDiscreteStates()  # call 1 at t = 0.1 with value -3.0
    assert s.outputs() == extremes(-3.0, 1.0)
    fmu.newDiscreteStates()  # a second iteration at the same instant: no call
    s.set({"value": 50.0})
    fmu.newDiscreteStates()
    assert s.outputs() == extremes(-3.0, 1.0)
