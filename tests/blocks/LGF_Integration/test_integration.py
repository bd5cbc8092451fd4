"""LGF_Integration against the rules of docs/behaviour.md §18, with hand-computed expectations
(the arithmetic in the comments). The outputs after initialization are those of call 0, from the
inputs set during initialization; the clock reads the call's time since call 0 in whole ms."""

import math
import struct

import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave

BLOCK = "LGF_Integration"
INF = math.inf


def slave(cycle, start_time=0.0, **inputs):
    return Slave(BLOCK, {"cycleTime": cycle}, inputs, start_time=start_time)


def integral(s):
    return s.get(["integral"])["integral"]


def run(s, cycle, changes):
    """One call per entry (the changes set before the step of one cycle); the integrals."""
    out = []
    for change in changes:
        s.set(change)
        out.append(s.step(cycle)["integral"])
    return out


def repeated_sum(term, n):
    """term added n times to 0.0 in double, as the block's sum adds it."""
    total = 0.0
    for _ in range(n):
        total += term
    return total


def test_start_values_integrate_1_per_second():
    # §18.1, §18.4: call 0 reads 0 ms with the last time cleared: d = 0, area ((1 + 0) * 0) / 2
    # = 0.0. Call k reads 100·k ms: d = 100, dt = 100 / 1000.0 = 0.1, area ((1 + 1) * 0.1) / 2 =
    # 0.1, so integral = 0.1 added k times: 0.1, 0.2, 0.30000000000000004, ...
    s = Slave(BLOCK)
    assert s.get(["enable", "value", "reset"]) == {"enable": True, "value": 1.0, "reset": False}
    assert s.outputs() == {"integral": 0.0, "error": False, "status": 0, "subFunctionStatus": 0}
    values = [s.step(0.1)["integral"] for _ in range(100)]
    assert values[:3] == [0.1, 0.2, 0.30000000000000004]
    assert values == [repeated_sum(0.1, k) for k in range(1, 101)]
    assert values[-1] == pytest.approx(10.0, rel=1e-14)  # seconds, not ms (§18.3)


def test_trapezoids_of_a_step():
    # cycle 1 s: call 0 stores value 2.0 (area 0); call 1 with 4.0: ((4 + 2) * 1.0) / 2 = 3.0;
    # call 2 with 4.0: ((4 + 4) * 1.0) / 2 = 4.0 -> 7.0; call 3 with -1.0: ((-1 + 4) * 1) / 2 = 1.5
    s = slave(1.0, value=2.0)
    assert integral(s) == 0.0
    assert run(s, 1.0, [{"value": 4.0}, {}, {"value": -1.0}]) == [3.0, 7.0, 8.5]


def test_negative_values_integrate_to_negative_areas():
    # cycle 0.5 s: dt = 500 / 1000.0 = 0.5; ((-3 + -3) * 0.5) / 2 = -1.5 per call after call 0
    s = slave(0.5, value=-3.0)
    assert run(s, 0.5, [{}, {}, {}]) == [-1.5, -3.0, -4.5]


def test_disable_holds_and_the_first_call_after_it_adds_nothing():
    # cycle 1 s, value 2.0: call 0 0.0, call 1 2.0, call 2 4.0; disabled: 4.0 held twice; enabled
    # again with 10.0: last time cleared, d = 0: ((10 + 0) * 0) / 2 = 0 -> 4.0; then
    # ((10 + 10) * 1) / 2 = 10 -> 14.0
    s = slave(1.0, value=2.0)
    assert run(s, 1.0, [{}, {}]) == [2.0, 4.0]
    assert run(s, 1.0, [{"enable": False, "value": 99.0}, {}]) == [4.0, 4.0]
    assert run(s, 1.0, [{"enable": True, "value": 10.0}, {}]) == [4.0, 14.0]


def test_reset_clears_and_wins_over_enable():
    s = slave(1.0, value=2.0)
    run(s, 1.0, [{}, {}])  # 4.0
    # reset TRUE gives 0.0 in every call, enabled or not
    assert run(s, 1.0, [{"reset": True}, {"enable": False}, {"enable": True}]) == [0.0] * 3
    # released: the first call adds ((2 + 0) * 0) / 2 = 0, then 2.0 per call
    assert run(s, 1.0, [{"reset": False}, {}, {}]) == [0.0, 2.0, 4.0]


def test_reset_in_the_first_call():
    s = slave(1.0, value=5.0, reset=True)
    assert integral(s) == 0.0
    s.set({"reset": False})
    assert run(s, 1.0, [{}, {}]) == [0.0, 5.0]  # the first call after the reset adds nothing


def test_reset_while_disabled_leaves_the_held_value_at_0():
    s = slave(1.0, value=2.0)
    run(s, 1.0, [{}, {"enable": False}])  # 2.0, held
    assert run(s, 1.0, [{"reset": True}, {"reset": False}]) == [0.0, 0.0]


@pytest.mark.parametrize("cycle, ms", [(0.01, 10), (1.0, 1000), (60.0, 60000)])
def test_dt_is_the_cycle_in_whole_ms_over_1000(cycle, ms):
    # d = the cycle in ms; dt = d / 1000.0 (0.01, 1.0, 60.0); ((1 + 1) * dt) / 2 = dt per call
    s = slave(cycle, value=1.0)
    assert run(s, cycle, [{}, {}, {}]) == [repeated_sum(ms / 1000.0, k) for k in (1, 2, 3)]


def test_sub_ms_cycle_steps_by_the_whole_ms_readings():
    # §18.3: cycle 1500 µs; call k reads floor(1.5·k ms) = 0, 1, 3, 4, 6: d = 1, 2, 1, 2 ms;
    # value 1.0: areas dt = 0.001, 0.002, 0.001, 0.002 (each d / 1000.0)
    s = slave(0.0015, value=1.0)
    got = run(s, 0.0015, [{}, {}, {}, {}])
    want, total = [], 0.0
    for d in (1, 2, 1, 2):
        total += d / 1000.0
        want.append(total)
    assert got == want
    assert got[-1] == pytest.approx(0.006, rel=1e-15)  # 6 ms over four calls of 1.5 ms


def test_half_ms_cycle_measures_every_second_call():
    # cycle 500 µs: readings 0, 0, 1, 1, 2: d = 0, 1, 0, 1: areas 0, 0.001, 0, 0.001
    s = slave(0.0005, value=1.0)
    assert run(s, 0.0005, [{}, {}, {}, {}]) == [0.0, 0.001, 0.001, 0.002]


def test_the_clock_counts_from_call_0_whatever_the_start_time():
    # §18.3: only the time since call 0 is read; a start time of 0.7 ms changes nothing
    s = slave(0.0015, start_time=0.0007, value=1.0)
    assert run(s, 0.0015, [{}, {}]) == [0.001, 0.001 + 0.002]


def test_several_calls_in_one_step():
    s = slave(0.1, value=2.0)
    # calls at 0.1, 0.2, 0.3, each ((2 + 2) * 0.1) / 2 = 0.2: 0.2, 0.4, 0.6000000000000001
    assert s.step(0.3)["integral"] == repeated_sum(0.2, 3)


def test_order_of_the_trapezoid():
    # §18.2 step 7: ((value + old) * dt) / 2.0. With old 1e308 and value 1e308 at dt 1.0 the sum
    # overflows to +Inf before the halving: +Inf (the other order, (sum / 2) * dt, would be finite)
    s = slave(1.0, value=1e308)
    assert run(s, 1.0, [{}]) == [INF]


def bits(x):
    return struct.pack(">d", x).hex()


def test_infinity_in_a_first_call_gives_nan_until_reset():
    # §18.4: call 0 with +Inf: ((inf + 0) * 0.0) / 2 = NaN, got as the positive quiet NaN
    s = slave(1.0, value=INF)
    assert bits(integral(s)) == "7ff8000000000000"
    assert bits(run(s, 1.0, [{"value": 1.0}])[0]) == "7ff8000000000000"  # NaN + 1 = NaN
    assert bits(run(s, 1.0, [{"enable": False}])[0]) == "7ff8000000000000"  # held
    assert run(s, 1.0, [{"enable": True, "reset": True}, {"reset": False}, {}]) == [0.0, 0.0, 1.0]


def test_opposite_infinities_give_nan():
    # call 1 with +Inf: ((inf + 1) * 1) / 2 = inf; call 2 with -Inf: (-inf + inf) = NaN
    s = slave(1.0, value=1.0)
    assert run(s, 1.0, [{"value": INF}]) == [INF]
    assert bits(run(s, 1.0, [{"value": -INF}])[0]) == "7ff8000000000000"


def test_status_outputs_never_change():
    s = slave(0.1, value=-4.0)
    for change in [{}, {"enable": False}, {"reset": True}, {"value": INF, "reset": False}]:
        s.set(change)
        out = s.step(0.1)
        assert (out["error"], out["status"], out["subFunctionStatus"]) == (False, 0, 0)


def test_nan_is_refused_and_not_applied():
    s = slave(1.0, value=2.0)
    assert s.status_of(s.fmu.setReal, [s.vr("value")], [math.nan]) == fmi2Error
    assert s.get(["value"]) == {"value": 2.0}
    assert run(s, 1.0, [{}]) == [2.0]


def test_an_input_reaches_the_calls_of_the_following_step():
    s = slave(1.0, value=2.0)
    s.set({"value": 6.0})
    assert integral(s) == 0.0  # call 0 saw 2.0
    assert s.step(0.5)["integral"] == 0.0  # no call in (0, 0.5]
    assert s.step(0.5)["integral"] == 4.0  # the call at 1.0: ((6 + 2) * 1) / 2


def test_model_exchange_integrates_the_value_set_at_the_event():
    s = Slave(BLOCK, {"cycleTime": 1.0}, {"value": 2.0}, model_exchange=True)
    s.fmu.newDiscreteStates()
    s.fmu.enterContinuousTimeMode()
    s.event(1.0, {"value": 4.0})  # call 1 at t = 1 with 4.0: ((4 + 2) * 1) / 2 = 3.0
    assert integral(s) == 3.0
    s.fmu.newDiscreteStates()  # no further call at the same instant
    assert integral(s) == 3.0
