"""lgf_fmus.testing: each assertion passes on a run that meets it, and its failure message gives
the times and the values."""

from __future__ import annotations

import inspect
import re
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from lgf_fmus import testing
from lgf_fmus.testing import assert_rate_limited, assert_reaches, assert_settles, assert_within


def ramp():
    k = np.arange(31)
    t = k / 10  # the nearest doubles to 0, 0.1, ..., 3
    y = np.clip((k - 10) * 5.0, 0.0, 40.0)  # exact: 50 per second from t = 1 s
    return pd.DataFrame({"time": t, "y": y})


def test_settles():
    r = ramp()
    assert_settles(r, "y", 40.0, within=0.8, tolerance=1e-9, after=1.0)
    with pytest.raises(
        AssertionError,
        match=r"y did not settle to 40 ± 0.5 within 0.5 s after t = "
        r"1 s: at t = 1.5 s it is 25 \(off by -15\); the last "
        r"sample outside the band is at t = 1.7 s \(35\), it "
        r"stays inside from t = 1.8 s on",
    ):
        assert_settles(r, "y", 40.0, within=0.5, tolerance=0.5, after=1.0)
    with pytest.raises(AssertionError, match=r"still outside at the end, t = 3 s \(40\)"):
        assert_settles(r, "y", 50.0, within=0.5, tolerance=0.5)
    with pytest.raises(
        AssertionError, match="ends at t = 3 s, before the settling deadline t = 4 s"
    ):
        assert_settles(r, "y", 40.0, within=4.0, tolerance=0.5)


def test_within():
    r = ramp()
    assert_within(r, "y", 0.0, 40.0)
    with pytest.raises(
        AssertionError,
        match=r"y leaves \[0, 30\]: at t = 1.7 s it is 35; 14 of 31 "
        r"samples are outside, the farthest 40 at t = 1.8 s",
    ):
        assert_within(r, "y", 0.0, 30.0)
    assert_within(r, "y", high=30.0, end=1.6)
    assert_within(r, "y", low=5.0, start=1.1)


def test_rate_limited():
    r = ramp()
    assert_rate_limited(r, "y", 50.0)
    with pytest.raises(
        AssertionError,
        match=r"y changes faster than 20/s from t = 1 s \(0\) to t "
        r"= 1.1 s \(5\): 50/s; the fastest change is from t = "
        r"1.1 s \(5\) to t = 1.2 s \(10\): 50/s \(8 such "
        r"changes\)",
    ):
        assert_rate_limited(r, "y", 20.0)
    jump = pd.DataFrame({"time": [0.0, 1.0, 1.0, 2.0], "y": [0.0, 0.0, 5.0, 5.0]})
    with pytest.raises(
        AssertionError,
        match=r"from t = 1 s \(0\) to t = 1 s \(5\): a jump at one "
        r"instant",
    ):
        assert_rate_limited(jump, "y", 100.0)


def test_reaches_and_fmpy_results():
    r = ramp()
    assert_reaches(r, "y", 40.0, by=1.8)
    with pytest.raises(
        AssertionError,
        match=r"y does not rise to 40 by t = 1.5 s; at t = 1.5 s it "
        r"is 25; it first does at t = 1.8 s",
    ):
        assert_reaches(r, "y", 40.0, by=1.5)
    structured = np.array(list(zip(r["time"], r["y"])), dtype=[("time", float), ("y", float)])
    assert_within(structured, "y", 0.0, 40.0)
    with pytest.raises(ValueError, match="no signal 'z'; it has y"):
        assert_within(r, "z", 0.0)


README = Path(__file__).resolve().parents[2] / "README.md"
ASSERTIONS = [name for name in testing.__all__ if name.startswith("assert_")]


def test_every_argument_is_documented():
    """Each assertion names every argument after `result` in its docstring (as `arg`), and the
    README shows it as a call with the same arguments in the same order."""
    readme = README.read_text(encoding="utf-8")
    assert len(ASSERTIONS) == 4
    for name in ASSERTIONS:
        function = getattr(testing, name)
        arguments = list(inspect.signature(function).parameters)
        doc = inspect.getdoc(function)
        missing = [a for a in arguments[1:] if f"`{a}`" not in doc]
        assert not missing, f"{name}'s docstring does not name {missing}"
        shown = re.findall(rf"`{name}\(([^)`]*)\)`", readme)
        assert len(shown) == 1, f"the README shows {name}(...) {len(shown)} times, not once"
        # each argument as the README writes it: `name`, `name=default`, or the `*` marker
        names = [a.split("=")[0].strip() for a in shown[0].split(",")]
        assert [a for a in names if a != "*"] == arguments, f"README: {name}({shown[0]})"
