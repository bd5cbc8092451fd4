"""LGF_StoreMinMax against the rules of docs/behaviour.md §14, with expectations traced by hand
from the block's original code (two comparisons first, the reset after them). The outputs after
initialization are those of call 0, from the inputs set during initialization."""

import math
import struct

from fmpy.fmi2 import fmi2Error

from tests.harness import Slave

BLOCK = "LGF_StoreMinMax"
LREAL_MAX = 1.7976931348623157e308
INF = math.inf
CLEARED = {"minValue": LREAL_MAX, "maxValue": -LREAL_MAX}


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


def test_a_reset_call_shows_the_clearing_values_and_loses_its_value():
    # §14.2, §14.3, the example. Call 0, value 5 with reset: 5 < LREAL_MAX -> min 5,
    # 5 > -LREAL_MAX -> max 5, then the reset clears both -> (LREAL_MAX, -LREAL_MAX). Call 1,
    # value 3, reset FALSE: 3 < LREAL_MAX -> min 3, 3 > -LREAL_MAX -> max 3 -> (3, 3).
    s = slave(value=5.0, reset=True)
    assert s.outputs() == CLEARED
    assert run(s, [{"reset": False, "value": 3.0}]) == [extremes(3.0, 3.0)]


def test_reset_is_a_level_applied_after_the_comparisons_of_each_call():
    # call 0: -4 -> (-4, -4); call 1: 10 -> (-4, 10). Calls 2-4 with reset TRUE: each compares
    # and then clears (call 2: 1 against (-4, 10) changes nothing; call 3: 7 against the cleared
    # pair stores (7, 7); call 4: -20 stores (-20, -20)), so each shows (LREAL_MAX, -LREAL_MAX).
    # Call 5, reset FALSE, 0.0 -> (0, 0): the values of the reset calls are not counted.
    # Call 6: 3.5 -> (0, 3.5).
    s = slave(value=-4.0)
    assert run(s, [10.0]) == [extremes(-4.0, 10.0)]
    assert run(s, [{"reset": True, "value": 1.0}, {"value": 7.0}, {"value": -20.0}]) == [
        CLEARED,
        CLEARED,
        CLEARED,
    ]
    assert run(s, [{"reset": False, "value": 0.0}, {"value": 3.5}]) == [
        extremes(0.0, 0.0),
        extremes(0.0, 3.5),
    ]


def test_a_reset_call_clears_the_extreme_its_own_comparison_stored():
    # call 0: 2 -> (2, 2); call 1: 100 with reset: 100 > 2 stores max 100, then the reset
    # clears it -> (LREAL_MAX, -LREAL_MAX); call 2: 50 -> (50, 50): the 100 never counts
    s = slave(value=2.0)
    assert run(s, [{"value": 100.0, "reset": True}, {"value": 50.0, "reset": False}]) == [
        CLEARED,
        extremes(50.0, 50.0),
    ]


def test_comparisons_are_strict_so_the_first_zero_stays():
    # §14.3: -0.0 < +0.0 and +0.0 > -0.0 are false
    s = slave(value=0.0)
    out = run(s, [-0.0])[0]
    assert bits(out["minValue"]) == bits(0.0) and bits(out["maxValue"]) == bits(0.0)
    s = slave(value=-0.0)
    out = run(s, [0.0])[0]
    assert bits(out["minValue"]) == bits(-0.0) and bits(out["maxValue"]) == bits(-0.0)


def test_infinities_against_the_clearing_values():
    # call 0: +Inf < LREAL_MAX is false: min stays LREAL_MAX; +Inf > -LREAL_MAX: max +Inf
    s = slave(value=INF)
    assert s.outputs() == extremes(LREAL_MAX, INF)
    # -Inf < LREAL_MAX: min -Inf; -Inf > +Inf is false
    assert run(s, [-INF, 12.0]) == [extremes(-INF, INF), extremes(-INF, INF)]
    # a reset call with -Inf (compared, then cleared); then -Inf: -Inf < LREAL_MAX -> min -Inf,
    # -Inf > -LREAL_MAX is false -> max stays -LREAL_MAX; then 1.5 -> max 1.5
    assert run(
        s,
        [{"reset": True, "value": -INF}, {"reset": False, "value": -INF}, {"value": 1.5}],
    ) == [CLEARED, extremes(-INF, -LREAL_MAX), extremes(-INF, 1.5)]
    # a reset call with +Inf; then +Inf -> (LREAL_MAX, +Inf); then -3 replaces min LREAL_MAX
    assert run(
        s,
        [{"reset": True, "value": INF}, {"reset": False, "value": INF}, {"value": -3.0}],
    ) == [CLEARED, extremes(LREAL_MAX, INF), extremes(-3.0, INF)]


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


def test_a_reset_held_over_several_calls_of_one_step():
    # calls 1-3 of one step all have reset TRUE: each ends cleared; the next step's call takes
    # its value alone
    s = slave(value=1.0)
    s.set({"value": 9.0, "reset": True})
    assert s.step(0.3) == CLEARED  # calls at 0.1, 0.2, 0.3
    s.set({"value": -1.0, "reset": False})
    assert s.step(0.1) == extremes(-1.0, -1.0)


def test_model_exchange_takes_the_value_set_at_the_event():
    s = Slave(BLOCK, {"cycleTime": 0.1}, {"value": 1.0}, model_exchange=True)
    s.fmu.newDiscreteStates()
    s.fmu.enterContinuousTimeMode()
    # call 1 at t = 0.1 with value -3.0
    assert s.event(0.1, {"value": -3.0}) == extremes(-3.0, 1.0)
    s.fmu.newDiscreteStates()  # a second iteration at the same instant: no call
    s.set({"value": 50.0})
    s.fmu.newDiscreteStates()
    assert s.outputs() == extremes(-3.0, 1.0)
