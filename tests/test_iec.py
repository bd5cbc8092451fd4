"""The IEC data-type helpers that the independent models share (tests/models/iec.py,
docs/behaviour.md §1.4), against values worked out by hand."""

import math

import pytest

from tests.models.iec import check_int, int16, time_ms_to_s, time_s_to_ms


def test_int16_wrap():
    assert int16(32767 + 1) == -32768
    assert int16(-32768 - 1) == 32767
    assert int16(32760 + 10) == -32766
    assert int16(123) == 123


def test_check_int():
    assert check_int("x", -32768) == -32768 and check_int("x", 32767) == 32767
    for bad in (-32769, 32768):
        with pytest.raises(ValueError):
            check_int("x", bad)


def test_time_rounding():
    assert time_s_to_ms(0.3) == 300
    assert time_s_to_ms(0.1) == 100
    assert time_s_to_ms(1.9) == 1900
    assert time_s_to_ms(-0.3) == -300
    assert time_s_to_ms(0.0005) == 1 and time_s_to_ms(-0.0005) == -1  # halves away from zero
    assert time_s_to_ms(0.0015) == 2 and time_s_to_ms(0.0025) == 3
    assert time_s_to_ms(-0.0025) == -3
    assert time_s_to_ms(0.00049) == 0 and time_s_to_ms(0.0004999) == 0
    assert time_s_to_ms(2147483.647) == 2147483647
    assert time_s_to_ms(-2147483.647) == -2147483647
    for bad in (math.nan, 2147483.648, -2147483.649, 2147483.6474, math.inf, -math.inf):
        with pytest.raises(ValueError):
            time_s_to_ms(bad)


def test_time_output():
    assert time_ms_to_s(300) == 0.3 and time_ms_to_s(-1) == -0.001
