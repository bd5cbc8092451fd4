"""Tests of the LimRateOfChangeCI reference model against hand traces from docs/behaviour.md §3."""

import math
import re
from pathlib import Path

import pytest

from .model import STATUS_NEG_RATE, LimRateOfChangeCI

BEHAVIOUR = Path(__file__).resolve().parents[3] / "docs" / "behaviour.md"


def inp(value=0.0, rate=0.0, default=0.0, en=False):
    return {
        "value": value,
        "setChangeRate": rate,
        "defaultOutValue": default,
        "enDefaultOutValue": en,
    }


def run(block, cycle_us, seq, k0=0):
    """Call the block once per entry of seq (input dicts); return the list of outputs."""
    return [block.call((k0 + k) * cycle_us, i) for k, i in enumerate(seq)]


@pytest.mark.parametrize("cycle_us,per_call", [(1_000_000, 10.0), (100_000, 1.0), (10_000, 0.1)])
def test_seed_example_rate_10(cycle_us, per_call):
    # Seed 001 / §3.4: rate 10.0 at 1 s / 100 ms / 10 ms moves 10.0 / 1.0 / 0.1 per call.
    b = LimRateOfChangeCI(cycle_us)
    dt = cycle_us / 1e6
    assert 10.0 * dt == per_call
    p = 0.0
    for k in range(5):
        o = b.call(k * cycle_us, inp(value=1000.0, rate=10.0))
        p = p + 10.0 * dt  # same double arithmetic as the rule
        assert o["delayedValue"] == p
        assert o["delayedValue"] == pytest.approx((k + 1) * per_call)
        assert o == {"delayedValue": p, "error": False, "status": 0, "subFunctionStatus": 0}


def test_rise_lands_exactly_on_value_then_holds():
    b = LimRateOfChangeCI(1_000_000)
    outs = [o["delayedValue"] for o in run(b, 1_000_000, [inp(value=2.5, rate=1.0)] * 5)]
    assert outs == [1.0, 2.0, 2.5, 2.5, 2.5]


def test_fall_lands_exactly_on_value():
    b = LimRateOfChangeCI(100_000)
    # first rise to 1.0 quickly, then fall to -0.25 at 2 units/s (0.2 per call)
    b.call(0, inp(value=1.0, rate=1e9))
    outs = [o["delayedValue"] for o in run(b, 100_000, [inp(value=-0.25, rate=2.0)] * 8, k0=1)]
    exp, p = [], 1.0
    for _ in range(8):
        p = max(p - 2.0 * 0.1, -0.25)
        exp.append(p)
    assert outs == exp
    assert outs[-1] == -0.25 and outs[6] == -0.25 and outs[5] > -0.25


def test_rate_zero_freezes_output():
    b = LimRateOfChangeCI(100_000)
    run(b, 100_000, [inp(value=5.0, rate=10.0)] * 3)  # 1, 2, 3
    outs = run(b, 100_000, [inp(value=5.0, rate=0.0)] * 3, k0=3)
    assert [o["delayedValue"] for o in outs] == [3.0, 3.0, 3.0]
    assert all(not o["error"] and o["status"] == 0 for o in outs)


def test_negative_rate_error_frozen_and_recovers():
    b = LimRateOfChangeCI(100_000)
    run(b, 100_000, [inp(value=10.0, rate=10.0)] * 2)  # 1.0, 2.0
    bad = run(b, 100_000, [inp(value=10.0, rate=-1.0)] * 3, k0=2)
    for o in bad:
        assert o == {"delayedValue": 2.0, "error": True, "status": 0x8200, "subFunctionStatus": 0}
    good = run(b, 100_000, [inp(value=10.0, rate=10.0)] * 2, k0=5)
    assert [o["delayedValue"] for o in good] == [3.0, 4.0]  # continues from frozen value
    assert all(o["error"] is False and o["status"] == 0 for o in good)


def test_the_negative_rate_code_is_the_documented_fmi_integer():
    # docs/behaviour.md §3.5 gives each status as the FMI integer an importer reads: 16#8200 is
    # 33280, and so is the model's code (and the status of a negative rate, below).
    text = BEHAVIOUR.read_text(encoding="utf-8")
    section = text[text.index("\n## 3 ") : text.index("\n## 4 ")]
    rows = re.findall(r"^\| 16#8200 \| (\d+) \|", section, re.M)
    assert rows == ["33280"]
    assert STATUS_NEG_RATE == 33280


def test_negative_rate_wins_over_default():
    # docs/behaviour.md §3.2: rule 1 (negative rate) ends the call before rule 2 (pre-assignment).
    b = LimRateOfChangeCI(100_000)
    o = b.call(0, inp(value=1.0, rate=-0.5, default=7.0, en=True))
    assert o == {"delayedValue": 0.0, "error": True, "status": 0x8200, "subFunctionStatus": 0}
    o = b.call(100_000, inp(value=1.0, rate=0.5, default=7.0, en=True))
    assert o == {"delayedValue": 7.0, "error": False, "status": 0, "subFunctionStatus": 0}


def test_negative_rate_at_first_call_keeps_initial_zero():
    b = LimRateOfChangeCI(100_000)
    o = b.call(0, inp(value=5.0, rate=-10.0))
    assert o["delayedValue"] == 0.0 and o["error"] and o["status"] == 33280


def test_default_jump_then_ramp_back():
    b = LimRateOfChangeCI(100_000)
    run(b, 100_000, [inp(value=2.0, rate=10.0)] * 3)  # 1.0, 2.0, 2.0
    # FALSE -> TRUE: immediate jump to defaultOutValue, held while TRUE
    outs = run(b, 100_000, [inp(value=2.0, rate=10.0, default=-3.0, en=True)] * 2, k0=3)
    assert [o["delayedValue"] for o in outs] == [-3.0, -3.0]
    # TRUE -> FALSE: ramp from defaultOutValue to value at 1.0 per call
    outs = run(b, 100_000, [inp(value=2.0, rate=10.0, default=-3.0)] * 6, k0=5)
    assert [o["delayedValue"] for o in outs] == [-2.0, -1.0, 0.0, 1.0, 2.0, 2.0]


def test_default_at_first_call_and_rate_zero():
    b = LimRateOfChangeCI(100_000)
    assert b.call(0, inp(value=1.0, rate=0.0, default=4.0, en=True))["delayedValue"] == 4.0
    assert b.call(100_000, inp(value=1.0, rate=0.0, default=4.0))["delayedValue"] == 4.0


def test_first_call_ramps_from_zero():
    b = LimRateOfChangeCI(10_000)
    assert b.call(0, inp(value=-1.0, rate=10.0))["delayedValue"] == 0.0 - 10.0 * 0.01


def test_infinite_rate_jumps_and_infinite_value():
    b = LimRateOfChangeCI(100_000)
    assert b.call(0, inp(value=42.0, rate=math.inf))["delayedValue"] == 42.0
    assert b.call(100_000, inp(value=-math.inf, rate=10.0))["delayedValue"] == 41.0
    assert b.call(200_000, inp(value=-math.inf, rate=math.inf))["delayedValue"] == -math.inf


def test_dt_is_us_over_1e6():
    b = LimRateOfChangeCI(333_333)
    assert b.call(0, inp(value=100.0, rate=3.0))["delayedValue"] == 3.0 * (333_333 / 1e6)


@pytest.mark.parametrize(
    "cycle_us,dt",
    [
        # §3.3: dt = UDINT_TO_REAL(us) / 1e6: the µs count rounded to float32, then a double
        # division.
        # float32 holds every integer up to 2^24 = 16777216; from 2^24 to 2^25 its spacing is 2,
        # from 2^25 to 2^26 (67108864 > 60 s) it is 4; ties go to the even significand.
        (16_777_216, 16.777216),  # 2^24: exact
        (16_777_217, 16.777216),  # 2^24 + 1: tie between 2^24 (even) and 2^24 + 2 -> 2^24
        (16_777_219, 16.77722),  # tie between 2^24 + 2 (odd) and 2^24 + 4 (even) -> 2^24 + 4
        (33_554_435, 33.554436),  # 2^25 + 3: nearest multiple of 4 is 2^25 + 4 = 33554436
        (59_999_999, 60.0),  # nearest multiple of 4 is 60000000
        (59_999_000, 59.999),  # whole ms: a multiple of 8, exact in float32
    ],
)
def test_dt_is_us_rounded_to_real_then_over_1e6(cycle_us, dt):
    assert LimRateOfChangeCI(cycle_us).dt == dt


def test_first_call_moves_dt_of_the_real_rounded_cycle():
    # cycleTime 16.777217 s (16777217 µs, §3.3): dt = 16777216 / 1e6 = 16.777216 s, so rate 1.0
    # moves exactly 16.777216 in the first call (not 16.777217), and 2 * 16.777216 in the second.
    cyc = 16_777_217
    b = LimRateOfChangeCI(cyc)
    assert b.call(0, inp(value=1000.0, rate=1.0))["delayedValue"] == 16.777216
    assert b.call(cyc, inp(value=1000.0, rate=1.0))["delayedValue"] == 16.777216 + 16.777216
    # downwards from 0.0 as well, with rate 2.0: 0.0 - 2.0 * 16.777216 = -33.554432
    b = LimRateOfChangeCI(cyc)
    assert b.call(0, inp(value=-1000.0, rate=2.0))["delayedValue"] == -33.554432
