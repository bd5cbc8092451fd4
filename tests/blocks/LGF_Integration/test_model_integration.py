"""Hand-traced tests of the Integration model (docs/behaviour.md §18), without any FMU."""

import math

import pytest

from .model import Integration

INF = math.inf


def inp(value=1.0, enable=True, reset=False):
    return {"value": value, "enable": enable, "reset": reset}


def run(seq, cycle_us=100_000):
    b = Integration(cycle_us)
    return [b.call(k * cycle_us, i)["integral"] for k, i in enumerate(seq)]


def test_start_values_ramp():
    # §18.4: v 1.0, 0.1 s: call 0 adds ((1 + 0) * 0.0)/2 = 0; then ((1+1)*0.1)/2 = 0.1 each:
    # 0.0, 0.1, 0.2, 0.30000000000000004
    assert run([inp()] * 4) == [0.0, 0.1, 0.2, 0.30000000000000004]


def test_outputs_and_status():
    # §18.1, §18.5: error FALSE, status 0, subFunctionStatus 0 always
    b = Integration(100_000)
    assert b.call(0, inp()) == {
        "integral": 0.0,
        "error": False,
        "status": 0,
        "subFunctionStatus": 0,
    }


def test_first_call_adds_signed_zero_and_stays_positive():
    # §18.4: v = -3: call 0 adds ((-3 + 0) * 0.0)/2 = -0.0; 0.0 + -0.0 = +0.0
    out = run([inp(-3.0)])[0]
    assert out == 0.0 and math.copysign(1.0, out) == 1.0


def test_step_adds_the_trapezoid():
    # 1 s cycle: values 2, 4, 4: call 0: 0; call 1: ((4+2)*1.0)/2 = 3; call 2: ((4+4)*1)/2 = 4 -> 7
    assert run([inp(2.0), inp(4.0), inp(4.0)], cycle_us=1_000_000) == [0.0, 3.0, 7.0]


def test_order_of_the_trapezoid():
    # §18.2 step 7: ((v + old) * dt) / 2.0; with 0.1 s: values 0.7 then 0.1:
    # s = 0.1 + 0.7 = 0.7999999999999999, * 0.1 = 0.07999999999999999, / 2 = 0.039999999999999994
    s = 0.1 + 0.7
    p = s * 0.1
    area = p / 2.0
    assert run([inp(0.7), inp(0.1)])[1] == 0.0 + area


def test_dt_is_the_nearest_double_of_d_over_1000():
    # §18.2 step 5: d = 100 -> 0.1; 7 µs... cycle 3300 µs: readings 0, 3, 6, 9 -> d 3 -> 0.003
    assert run([inp(2.0)] * 3, cycle_us=3300) == [0.0, 0.006, 0.006 + 0.006]


def test_sub_ms_cycle_readings_step_unevenly():
    # §18.3: cycle 1.5 ms: readings 0, 1, 3, 4, 6 -> d 0, 1, 2, 1, 2; value 1:
    # areas 0, 0.001, 0.002, 0.001, 0.002
    exp, acc = [], 0.0
    for d in [0, 1, 2, 1, 2]:
        acc = acc + ((1.0 + (0.0 if d == 0 and not exp else 1.0)) * (d / 1000.0)) / 2.0
        exp.append(acc)
    assert run([inp()] * 5, cycle_us=1500) == exp
    # cycle 0.5 ms: readings 0, 0, 1, 1, 2 -> d 0, 0, 1, 0, 1
    assert run([inp()] * 5, cycle_us=500) == [0.0, 0.0, 0.001, 0.001, 0.002]


def test_disable_holds_and_next_enable_adds_nothing():
    # §18.2 step 2 / §18.4: 1 s cycle, value 1: 0, 1, [disabled: 1, 1], enabled again: d 0 -> 1,
    # then 1 + ((5 + 5) * 1)/2 = 6 (the jump from 1 to 5 is not integrated)
    seq = [inp(), inp(), inp(enable=False), inp(enable=False), inp(5.0), inp(5.0)]
    assert run(seq, cycle_us=1_000_000) == [0.0, 1.0, 1.0, 1.0, 1.0, 6.0]


def test_reset_has_priority_and_next_call_adds_nothing():
    # §18.2 step 1: reset gives 0 whatever enable is; after release the first call adds nothing
    seq = [inp(), inp(), inp(reset=True), inp(reset=True, enable=False), inp(3.0), inp(3.0)]
    assert run(seq, cycle_us=1_000_000) == [0.0, 1.0, 0.0, 0.0, 0.0, 3.0]


def test_negative_values_integrate_negative():
    assert run([inp(-2.0)] * 3, cycle_us=1_000_000) == [0.0, -2.0, -4.0]


def test_long_run_of_calls_on_the_grid():
    # §18.2: d is the cycle in ms at every call for a whole-ms cycle: 10 ms, value 1: sum of 0.01
    out = run([inp()] * 101, cycle_us=10_000)
    acc = 0.0
    for _ in range(100):
        acc = acc + ((1.0 + 1.0) * 0.01) / 2.0
    assert out[-1] == acc and out[-1] == pytest.approx(1.0)


def positive_nan(x):
    return math.isnan(x) and math.copysign(1.0, x) == 1.0


def test_inf_in_first_integrating_call_gives_nan_until_reset():
    # §18.4: ((Inf + 0) * 0.0) / 2 = NaN; stays NaN; disabling holds it; reset clears it
    seq = [inp(INF), inp(1.0), inp(enable=False), inp(reset=True), inp(1.0), inp(1.0)]
    out = run(seq, cycle_us=1_000_000)
    assert all(positive_nan(x) for x in out[:3])
    assert out[3:] == [0.0, 0.0, 1.0]


def test_inf_then_minus_inf_gives_nan():
    # §18.4: calls 1 s: 1, +Inf -> ((Inf + 1) * 1)/2 = Inf, then -Inf: (-Inf + Inf) = NaN
    out = run([inp(1.0), inp(INF), inp(-INF)], cycle_us=1_000_000)
    assert out[:2] == [0.0, INF] and positive_nan(out[2])
    # an infinite sum plus the opposite infinity: Inf, Inf, then -Inf, -Inf: ... Inf + NaN...
    out = run([inp(1.0), inp(INF), inp(INF)], cycle_us=1_000_000)
    assert out == [0.0, INF, INF]


def test_old_value_never_nan():
    # §18.4: statInputOldValue holds an input or 0.0
    b = Integration(1000)
    b.call(0, inp(INF))
    assert b.statInputOldValue == INF
    b.call(1000, inp(enable=False))
    assert b.statInputOldValue == 0.0 and b.statLastTime is None
