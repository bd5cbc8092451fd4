"""Hand-traced tests of the StoreMinMax model against the original block's logic (compare
first, reset after), without any FMU. Calls are numbered from 0, cycle 0.1 s."""

import math

from .model import LREAL_MAX, LREAL_MIN, StoreMinMax

INF = math.inf
CYCLE = 100_000


def run(values, resets=None):
    b = StoreMinMax(CYCLE)
    resets = resets or [False] * len(values)
    return [
        (o["minValue"], o["maxValue"])
        for o in (
            b.call(k * CYCLE, {"value": v, "reset": r})
            for k, (v, r) in enumerate(zip(values, resets))
        )
    ]


def test_sentinels_are_the_extreme_finite_lreals():
    assert LREAL_MAX == 1.7976931348623157e308 and LREAL_MIN == -LREAL_MAX
    b = StoreMinMax(CYCLE)
    assert (b.statStoreMinValue, b.statStoreMaxValue) == (LREAL_MAX, LREAL_MIN)


def test_reset_call_outputs_the_sentinels_and_loses_its_value():
    # call 0: 5 compared (min 5, max 5), then reset -> (1.797e308, -1.797e308);
    # call 1: 3 < 1.797e308 -> min 3, 3 > -1.797e308 -> max 3
    assert run([5.0, 3.0], [True, False]) == [(LREAL_MAX, LREAL_MIN), (3.0, 3.0)]


def test_first_call_without_reset_counts_its_value():
    # the statics start at the sentinels: 3.5 beats both
    assert run([3.5]) == [(3.5, 3.5)]
    # an always negative signal: its maximum is its own, not a tiny positive number
    assert run([-5.0, -7.0, -6.0]) == [(-5.0, -5.0), (-7.0, -5.0), (-7.0, -5.0)]


def test_min_never_rises_max_never_falls():
    outs = run([2.0, 5.0, 1.0, 3.0, -1.0, 9.0])
    assert outs == [(2.0, 2.0), (2.0, 5.0), (1.0, 5.0), (1.0, 5.0), (-1.0, 5.0), (-1.0, 9.0)]


def test_reset_held_keeps_the_sentinels_and_the_next_call_starts_afresh():
    # calls 0-1 collect 1 and 10; calls 2-4 reset (4, 7, 2 lost); call 5: 3 -> (3, 3);
    # call 6: 8 -> (3, 8)
    values = [1.0, 10.0, 4.0, 7.0, 2.0, 3.0, 8.0]
    resets = [False, False, True, True, True, False, False]
    S = (LREAL_MAX, LREAL_MIN)
    assert run(values, resets) == [(1.0, 1.0), (1.0, 10.0), S, S, S, (3.0, 3.0), (3.0, 8.0)]


def test_one_value_updates_both():
    # two separate IFs, not ELSIF: after the sentinels one value sets both
    assert run([0.0]) == [(0.0, 0.0)]


def test_signed_zeros_first_seen_kept():
    # 0.0 then -0.0: -0.0 < +0.0 and -0.0 > +0.0 are both false -> +0.0 stays
    (mn, mx) = run([0.0, -0.0])[1]
    assert math.copysign(1.0, mn) == 1.0 and math.copysign(1.0, mx) == 1.0
    (mn, mx) = run([-0.0, 0.0])[1]
    assert math.copysign(1.0, mn) == -1.0 and math.copysign(1.0, mx) == -1.0


def test_infinities():
    # +Inf < LREAL_MAX false: min stays the sentinel; +Inf > LREAL_MIN: max +Inf
    assert run([INF]) == [(LREAL_MAX, INF)]
    assert run([-INF]) == [(-INF, LREAL_MIN)]
    assert run([INF, 2.0])[1] == (2.0, INF)
    assert run([-INF, 2.0])[1] == (-INF, 2.0)
    # an infinite value in a reset call is lost like any other
    assert run([INF, 1.0], [True, False]) == [(LREAL_MAX, LREAL_MIN), (1.0, 1.0)]


def test_sentinel_values_as_input():
    # LREAL_MAX equals the stored minimum (no change, same number); it beats the maximum
    assert run([LREAL_MAX]) == [(LREAL_MAX, LREAL_MAX)]
    assert run([LREAL_MIN]) == [(LREAL_MIN, LREAL_MIN)]


def test_outputs_are_the_interface_names():
    b = StoreMinMax(CYCLE)
    assert set(b.call(0, {"value": 1.0, "reset": False})) == {"minValue", "maxValue"}
