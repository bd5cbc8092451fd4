"""Hand-traced tests of the FloatingAverage model (docs/behaviour.md §15), without any FMU."""

import math

import numpy as np
import pytest

from .model import STATUS_WRONG_WINDOW_SIZE, FloatingAverage

F = np.float32
INF = math.inf


def inp(value=1.0, window=10, cyclic=True, trigger=False, reset=False):
    return {
        "cyclicExecution": cyclic,
        "trigger": trigger,
        "value": value,
        "windowSize": window,
        "reset": reset,
    }


def run(seq, cycle_us=100_000):
    b = FloatingAverage(cycle_us)
    return [b.call(k * cycle_us, i) for k, i in enumerate(seq)]


def avg(outs):
    return [o["average"] for o in outs]


def reached(outs):
    return [o["windowSizeReached"] for o in outs]


def test_worked_example():
    # §15.3: window 3, values 3, 6, 9, 12, 0: 3/1, 9/2, 18/3, ((18+12)-3)/3, ((27+0)-6)/3
    outs = run([inp(v, 3) for v in [3.0, 6.0, 9.0, 12.0, 0.0]])
    assert avg(outs) == [3.0, 4.5, 6.0, 9.0, 7.0]
    assert reached(outs) == [False, False, True, True, True]
    assert all(o["error"] is False and o["status"] == 0 for o in outs)


def test_start_values():
    # §15.1: value 1.0, window 10: average 1.0 from call 0, windowSizeReached from call 9
    outs = run([inp()] * 11)
    assert avg(outs) == [1.0] * 11
    assert reached(outs) == [False] * 9 + [True, True]


def test_float32_rounding_of_value_and_sum():
    # §15.1: value stored as float32: 0.1 -> 0.100000001490116...; window 2:
    # call 0: sum 0.1f, avg 0.1f/1; call 1: sum f32(0.1f + 0.2f) = 0.3f(+1ulp?) / 2
    outs = run([inp(0.1, 2), inp(0.2, 2), inp(0.7, 2)])
    s0 = F(0.1)
    s1 = F(s0 + F(0.2))
    s2 = F(F(s1 + F(0.7)) - F(0.1))
    assert avg(outs) == [float(s0), float(F(s1 / F(2))), float(F(s2 / F(2)))]
    # the float32 sum differs from the double one: 0.1f + 0.2f = 0.30000001192092896
    assert float(s1) == 0.30000001192092896 and float(s1) != 0.1 + 0.2
    assert float(s0) == 0.10000000149011612


def test_running_sum_keeps_its_rounding_error():
    # §15.3: window 1, 1e8 then 1.0, 1.0: (1e8 + 1) - 1e8 = 0 in float32, then (0 + 1) - 1 = 0
    outs = run([inp(1e8, 1), inp(1.0, 1), inp(1.0, 1), inp(1.0, 1)])
    assert avg(outs) == [1e8, 0.0, 0.0, 0.0]
    # a restart (reset) recovers: reset call reads a window of one: 1.0
    b = FloatingAverage(1000)
    for k, i in enumerate([inp(1e8, 1), inp(1.0, 1), inp(1.0, 1, reset=True), inp(1.0, 1)]):
        o = b.call(k * 1000, i)
    assert o["average"] == 1.0


def test_window_size_change_restarts():
    # §15.2 step 2: window 2: 4, 8 -> 4, 6; change to 3 with value 10: restart then read: 10
    outs = run([inp(4.0, 2), inp(8.0, 2), inp(10.0, 3), inp(2.0, 3)])
    assert avg(outs) == [4.0, 6.0, 10.0, 6.0]
    assert reached(outs) == [False, True, False, False]


def test_invalid_window_size():
    # §15.2 step 3 / §15.4: 0, 101, -1: error TRUE, 16#8200, average 0.0, reached FALSE
    for w in [0, 101, -1, 32767, -32768]:
        outs = run([inp(5.0, 3), inp(5.0, 3), inp(5.0, 3), inp(5.0, w), inp(5.0, 3)])
        assert avg(outs) == [5.0, 5.0, 5.0, 0.0, 5.0]
        assert reached(outs) == [False, False, True, False, False]
        assert outs[3]["error"] is True and outs[3]["status"] == STATUS_WRONG_WINDOW_SIZE == 33280
        assert outs[4]["error"] is False and outs[4]["status"] == 0


def test_invalid_from_first_call():
    # §15.2 step 3: invalid from the first call: 0.0, FALSE. windowSize 0 = statWindowSizeOld 0
    for w in [0, 200]:
        outs = run([inp(5.0, w)] * 3)
        assert [(o["average"], o["windowSizeReached"], o["status"]) for o in outs] == [
            (0.0, False, 0x8200)
        ] * 3


def test_window_100_is_valid():
    outs = run([inp(float(k), 100) for k in range(101)])
    # filling: sum 0+1+...+99 = 4950 / 100 = 49.5; call 100: (4950 + 100) - 0 = 5050 / 100
    assert outs[99]["average"] == 49.5 and outs[99]["windowSizeReached"] is True
    assert outs[100]["average"] == 50.5
    assert reached(outs)[:99] == [False] * 99


def test_trigger_edges():
    # §15.2 steps 1, 4: cyclic FALSE: read only at rising edges of trigger; memory starts FALSE
    trig = [True, True, False, True, False, False]
    vals = [2.0, 100.0, 100.0, 4.0, 100.0, 100.0]
    outs = run([inp(v, 3, cyclic=False, trigger=t) for v, t in zip(vals, trig)])
    assert avg(outs) == [2.0, 2.0, 2.0, 3.0, 3.0, 3.0]


def test_cyclic_and_edge_read_one_value():
    # §15.5: cyclic TRUE and a trigger edge: one value read
    outs = run([inp(2.0, 3, trigger=True), inp(4.0, 3, trigger=False)])
    assert avg(outs) == [2.0, 3.0]


def test_trigger_held_when_cyclic_falls_is_no_edge():
    # §15.5: the edge memory is updated while cyclic is TRUE, so a held trigger is no edge
    seq = [inp(2.0, 3, trigger=True), inp(4.0, 3, cyclic=False, trigger=True)]
    assert avg(run(seq)) == [2.0, 2.0]


def test_edge_memory_updated_in_error_call():
    # §15.2 step 1: a rising edge in an error call is consumed there
    seq = [
        inp(2.0, 3, cyclic=False, trigger=False),
        inp(2.0, 0, cyclic=False, trigger=True),  # error call, memory := TRUE
        inp(2.0, 3, cyclic=False, trigger=True),  # no edge: nothing read
    ]
    outs = run(seq)
    assert avg(outs) == [0.0, 0.0, 0.0] and outs[2]["status"] == 0


def test_no_read_in_holds():
    # §15.3: no read-in: average and windowSizeReached hold
    outs = run([inp(2.0, 1), inp(9.0, 1, cyclic=False)])
    assert avg(outs) == [2.0, 2.0] and reached(outs) == [True, True]


def test_reset_held_gives_window_of_one():
    # §15.3: reset held with cyclic: average = value in every call
    outs = run([inp(v, 5, reset=True) for v in [3.0, 7.0, -1.0]])
    assert avg(outs) == [3.0, 7.0, -1.0]
    assert reached(outs) == [False, False, False]


def positive_nan(x):
    return math.isnan(x) and math.copysign(1.0, x) == 1.0


def test_infinity_leaves_the_window_nan():
    # §15.3: window 2: Inf -> Inf; 1 -> Inf; 1 -> (Inf + 1) - Inf = NaN; stays NaN until restart
    outs = run([inp(INF, 2), inp(1.0, 2), inp(1.0, 2), inp(1.0, 2), inp(1.0, 2, reset=True)])
    a = avg(outs)
    assert a[:2] == [INF, INF]
    assert positive_nan(a[2]) and positive_nan(a[3])
    assert a[4] == 1.0


def test_opposite_infinities_nan():
    outs = run([inp(INF, 3), inp(-INF, 3)])
    assert avg(outs)[0] == INF and positive_nan(avg(outs)[1])


def test_finite_sum_overflows():
    # §15.3: 3e38 + 3e38 overflows float32 to +Inf; / 2 = Inf
    outs = run([inp(3e38, 2), inp(3e38, 2)])
    assert avg(outs) == [float(F(3e38)), INF]


@pytest.mark.parametrize("v", [1e-45, -0.0])
def test_tiny_values(v):
    # 1e-45 is the float32 subnormal 2**-149; -0.0: 0.0 + -0.0 = +0.0
    o = run([inp(v, 2)])[0]
    assert o["average"] == float(F(F(0.0) + F(v)) / F(1))
    assert math.copysign(1.0, o["average"]) == 1.0
