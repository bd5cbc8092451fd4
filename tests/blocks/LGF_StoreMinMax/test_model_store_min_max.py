"""Hand-traced tests of the StoreMinMax model (docs/behaviour.md §14), without any FMU."""

import math

from .model import LREAL_MAX, LREAL_MIN, StoreMinMax

INF = math.inf


def run(values, resets=None, cycle_us=100_000):
    b = StoreMinMax(cycle_us)
    resets = resets or [False] * len(values)
    return [
        b.call(k * cycle_us, {"value": v, "reset": r})
        for k, (v, r) in enumerate(zip(values, resets))
    ]


def mm(o):
    return (o["minValue"], o["maxValue"])


def test_sentinels():
    # §14.1: LREAL_MAX = +1.7976931348623157e308, "LREAL_MIN" = its negative (§14.4)
    assert LREAL_MAX == 1.7976931348623157e308 and LREAL_MIN == -LREAL_MAX
    b = StoreMinMax(1000)
    assert (b.statStoreMinValue, b.statStoreMaxValue) == (LREAL_MAX, LREAL_MIN)


def test_first_call_counts_its_value():
    # §14.3: first call gives min = max = value (no reset needed, §14.4)
    assert mm(run([3.5])[0]) == (3.5, 3.5)
    # an always negative signal: max is the signal, not 2.2e-308 (§14.4)
    assert [mm(o) for o in run([-5.0, -7.0, -6.0])] == [(-5.0, -5.0), (-7.0, -5.0), (-7.0, -5.0)]


def test_trace_min_never_rises_max_never_falls():
    # 2 -> (2,2); 5 -> (2,5); 1 -> (1,5); 3 -> (1,5); -1 -> (-1,5); 9 -> (-1,9)
    outs = [mm(o) for o in run([2.0, 5.0, 1.0, 3.0, -1.0, 9.0])]
    assert outs == [(2.0, 2.0), (2.0, 5.0), (1.0, 5.0), (1.0, 5.0), (-1.0, 5.0), (-1.0, 9.0)]


def test_reset_is_a_level_and_counts_its_own_value():
    # §14.2 step 1 then 2, 3: reset call with 4 -> (4,4); reset held: outputs follow value
    values = [1.0, 10.0, 4.0, 7.0, 2.0, 3.0, 8.0]
    resets = [False, False, True, True, True, False, False]
    outs = [mm(o) for o in run(values, resets)]
    assert outs == [(1.0, 1.0), (1.0, 10.0), (4.0, 4.0), (7.0, 7.0), (2.0, 2.0), (2.0, 3.0),
                    (2.0, 8.0)]  # fmt: skip


def test_one_value_updates_both():
    # §14.2: two separate IFs: after a reset the sentinels are both beaten by one value
    b = StoreMinMax(1000)
    assert mm(b.call(0, {"value": 0.0, "reset": True})) == (0.0, 0.0)


def test_signed_zeros_first_seen_kept():
    # §14.3: 0.0 then -0.0: -0.0 < +0.0 false, -0.0 > +0.0 false -> min stays +0.0
    o = run([0.0, -0.0])[1]
    assert math.copysign(1.0, o["minValue"]) == 1.0 and math.copysign(1.0, o["maxValue"]) == 1.0
    o = run([-0.0, 0.0])[1]
    assert math.copysign(1.0, o["minValue"]) == -1.0 and math.copysign(1.0, o["maxValue"]) == -1.0


def test_infinities_after_reset():
    # §14.3: +Inf: min stays LREAL_MAX (Inf < MAX false), max = +Inf
    assert mm(run([INF])[0]) == (LREAL_MAX, INF)
    # -Inf: min = -Inf, max stays -LREAL_MAX
    assert mm(run([-INF])[0]) == (-INF, LREAL_MIN)
    # a later finite value replaces the sentinel
    assert mm(run([INF, 2.0])[1]) == (2.0, INF)
    assert mm(run([-INF, 2.0])[1]) == (-INF, 2.0)


def test_lreal_max_value_leaves_min_unchanged_which_is_the_same_number():
    # §14.3: value = LREAL_MAX after a reset: min unchanged (equal), so min = value
    assert mm(run([LREAL_MAX])[0]) == (LREAL_MAX, LREAL_MAX)
    assert mm(run([LREAL_MIN])[0]) == (LREAL_MIN, LREAL_MIN)


def test_outputs_are_the_interface_names():
    assert set(run([1.0])[0]) == {"minValue", "maxValue"}
