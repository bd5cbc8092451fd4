"""What the five LGF signal generators share, without an FMU: the REAL/UDINT helpers of their
models (tests/models/signal_ci.py) and the comparison of model and FMU for the sine and cosine
(tests/signal_generators.py, BlockSpec.same), against values worked out by hand."""

import math

import numpy as np
import pytest

from tests.block_spec import exact
from tests.blocks.LGF_SinusCI.model import SinusCI
from tests.models.signal_ci import (
    TWO_PI,
    TrigValue,
    periode_input,
    phase_shift_input,
    real,
    real_to_udint,
    udint,
    udint_to_real,
)
from tests.signal_generators import FLT_MAX, START, float32_ulps, same_within_trig_ulp

# --- REAL (docs/behaviour.md §1.4: nearest float32, halves to even; NaN and beyond ±3.4028235e38
# refused) ---


@pytest.mark.parametrize(
    "x, stored",
    [
        (0.1, 0.10000000149011612),
        (16777217.0, 16777216.0),  # halfway between 2^24 and 2^24 + 2: to even
        (16777219.0, 16777220.0),  # halfway between 2^24 + 2 and 2^24 + 4: to even
        (3.4028235e38, FLT_MAX),  # D1: the limit itself is accepted
        (-3.4028235e38, -FLT_MAX),
        (math.inf, math.inf),
        (-math.inf, -math.inf),
        (1e-46, 0.0),  # below half the smallest subnormal: to zero
    ],
)
def test_real_is_the_nearest_float32(x, stored):
    assert float(real("x", x)) == stored


@pytest.mark.parametrize("x", [math.nan, 3.4028236e38, -3.4028236e38, 1e39, 1e300])
def test_real_refuses_nan_and_finite_values_beyond_the_limit(x):
    with pytest.raises(ValueError):
        real("x", x)


def test_the_literal_6_283185_is_a_float32():
    assert float(TWO_PI) == 6.283185005187988 == 6588397 / 2**20


# --- UDINT (wraps modulo 2^32), REAL_TO_UDINT (halves to even), REAL(udint) ---


def test_udint_wraps_modulo_2_32():
    assert udint(4294967295 + 1) == 0
    assert udint(300 + 4294967040) == 44


@pytest.mark.parametrize(
    "x, n",
    [
        (0.5, 0),
        (1.5, 2),
        (2.5, 2),
        (3.5, 4),
        (2.4999998, 2),
        (2.5000002, 3),
        (4294967040.0, 4294967040),
        (-0.0, 0),
    ],
)
def test_real_to_udint_rounds_halves_to_even(x, n):
    assert real_to_udint(np.float32(x)) == n


def test_real_of_a_udint_is_the_nearest_float32():
    assert float(udint_to_real(16777217)) == 16777216.0
    assert float(udint_to_real(2147483647)) == 2147483648.0


# --- the checks of periode and phaseShift (docs/behaviour.md §6) ---


@pytest.mark.parametrize("periode", [0, -1, 4294967296])
def test_periode_outside_1_to_2_32_minus_1_is_refused(periode):
    with pytest.raises(ValueError):
        periode_input(periode)


@pytest.mark.parametrize(
    "x, stored",
    [
        (0.0, 0.0),
        (-0.0, 0.0),  # D2: -0.0 lies in 0 ... 4294967295
        (4294967040.0, 4294967040.0),  # the largest float32 within the range
        (4294967100.0, 4294967040.0),  # rounds down to it
    ],
)
def test_phase_shift_checked_on_its_float32_value_is_accepted(x, stored):
    assert float(phase_shift_input(x)) == stored


@pytest.mark.parametrize(
    "x",
    [
        -1.0,
        -1e-30,
        -1e-50,  # D2: negative as set, though -0.0 as a float32
        4294967295.0,
        4294967200.0,
        math.inf,
        -math.inf,
        math.nan,
    ],
)
def test_phase_shift_outside_the_range_is_refused(x):
    with pytest.raises(ValueError):
        phase_shift_input(x)


def test_cycle_runs_on_whole_ms_truncated():
    assert SinusCI(1999).ts == 1 and SinusCI(1000).ts == 1 and SinusCI(60_000_000).ts == 60000
    with pytest.raises(ValueError):
        SinusCI(999)


# --- model against FMU: the default and the sine's comparison ---

OUT = {"value": 0.5, "error": False, "status": 0, "subFunctionStatus": 0}
UP = float(np.nextafter(np.float32(0.5), np.float32(1)))  # 0.5 + 2^-24
UP2 = float(np.nextafter(np.float32(UP), np.float32(1)))


def test_the_default_comparison_is_equality():
    assert exact(OUT, dict(OUT))
    assert not exact(OUT, {**OUT, "value": UP})


def test_float32_ulps():
    assert float32_ulps(0.5, UP) == 1 and float32_ulps(0.5, UP2) == 2
    assert float32_ulps(-0.0, 0.0) == 0
    assert float32_ulps(2**-149, -(2**-149)) == 2  # the smallest subnormals
    assert float32_ulps(FLT_MAX, math.inf) == 1
    assert float32_ulps(0.5, 0.5 + 2**-30) == math.inf  # not a float32 value
    assert float32_ulps(math.nan, math.nan) == math.inf


def test_sine_comparison_allows_one_ulp_of_value_and_nothing_else():
    assert same_within_trig_ulp(OUT, dict(OUT))
    assert same_within_trig_ulp(OUT, {**OUT, "value": UP})
    assert not same_within_trig_ulp(OUT, {**OUT, "value": UP2})
    assert not same_within_trig_ulp(OUT, {**OUT, "value": 0.5 + 2**-30})
    assert not same_within_trig_ulp(OUT, {**OUT, "status": 1})
    assert not same_within_trig_ulp(OUT, {**OUT, "error": True})
    assert not same_within_trig_ulp(OUT, {"value": 0.5})
    nan = {**OUT, "value": math.nan}
    assert same_within_trig_ulp(nan, dict(nan))
    assert not same_within_trig_ulp(nan, OUT)


def test_sine_comparison_allows_what_a_sin_one_ulp_off_gives():
    # SIN s = 0.5 + 2^-24 (float32), amplitude 1, offset -0.5: value = 2^-24. A SIN one ulp
    # lower (0.5) gives 0.0, one higher gives 2^-23: 2^-24 ulps of value apart, yet allowed.
    value = TrigValue(2**-24, [0.0, 2**-23])
    want = {**OUT, "value": value}
    assert same_within_trig_ulp(want, {**OUT, "value": 0.0})
    assert same_within_trig_ulp(want, {**OUT, "value": 2**-23})
    assert not same_within_trig_ulp(want, {**OUT, "value": 2**-22})
    assert value == 2**-24 and want == {**OUT, "value": 2**-24}  # a float like any other


def test_the_sine_model_gives_the_values_of_a_sin_one_ulp_off():
    # counter 100 of the typical run: SIN = 0.5877852439880371; amplitude 3, offset -1.75:
    # fl(3 · s) + (-1.75) for s and its float32 neighbours 0.5877851843833923 and 0.5877853035926819
    out = SinusCI(100000).call(0, {**START, "amplitude": 3.0, "offset": -1.75})
    s = np.float32(0.5877852439880371)
    below, above = np.nextafter(s, np.float32(0)), np.nextafter(s, np.float32(1))
    expected = [float(t * np.float32(3.0) + np.float32(-1.75)) for t in (below, above)]
    assert float(out["value"]) == float(s * np.float32(3.0) + np.float32(-1.75))
    assert list(out["value"].allowed) == expected
    for value in expected:
        assert same_within_trig_ulp(out, {**out, "value": value})
