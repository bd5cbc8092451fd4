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


README = Path(__file__).resolve().parents[2] / "docs" / "python.md"  # the package's page
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


NAN, INF = float("nan"), float("inf")
EMPTY = pd.DataFrame({"time": np.array([], dtype=float), "y": np.array([], dtype=float)})


def refused(call, function, says):
    """The call is refused with a ValueError that names the function and what it allows (the
    message written here, not taken from the module)."""
    with pytest.raises(ValueError, match=f"^{re.escape(function)}: {says}"):
        call()


@pytest.mark.parametrize(
    "arguments, says",
    [
        (dict(within=NAN), r"within must be a finite number >= 0, not nan"),
        (dict(within=-0.5), r"within must be a finite number >= 0, not -0.5"),
        (dict(within=INF), r"within must be a finite number >= 0, not inf"),
        (dict(within="1"), r"within must be a finite number >= 0, not '1'"),
        (dict(within=True), r"within must be a finite number >= 0, not True"),
        (dict(tolerance=-1), r"tolerance must be a finite number >= 0, not -1"),
        (dict(tolerance=NAN), r"tolerance must be a finite number >= 0, not nan"),
        (dict(target=NAN), r"target must be a finite number, not nan"),
        (dict(target=None), r"target must be a finite number, not None"),
        (dict(after=NAN), r"after must be a finite number, not nan"),
    ],
)
def test_settles_refuses_bad_arguments(arguments, says):
    # without the check a NaN within passed for a signal that never reaches the target
    given = {"target": 99.0, "within": 1.0, "tolerance": 0.1, **arguments}
    target = given.pop("target")
    refused(lambda: assert_settles(ramp(), "y", target, **given), "assert_settles", says)


@pytest.mark.parametrize(
    "arguments, says",
    [
        (dict(low=20.0, high=5.0), r"low must be <= high, not low = 20 > high = 5"),
        (dict(low=NAN), r"low must be a number \(not NaN\), not nan"),
        (dict(high="5"), r"high must be a number \(not NaN\), not '5'"),
        (dict(start=NAN), r"start must be a finite number, not nan"),
        (dict(end=INF), r"end must be a finite number, not inf"),
        (dict(start=2.0, end=1.0), r"start must be <= end, not start = 2 > end = 1"),
        # a window after the end, or between two samples: nothing in it would be checked
        (dict(start=50.0), r"the window start = 50 … end = None s must hold a sample"),
        (dict(start=1.01, end=1.09), r"the window start = 1.01 … end = 1.09 s must hold"),
    ],
)
def test_within_refuses_bad_arguments(arguments, says):
    given = {"low": 0.0, "high": 40.0, **arguments}
    low, high = given.pop("low"), given.pop("high")
    refused(lambda: assert_within(ramp(), "y", low, high, **given), "assert_within", says)


@pytest.mark.parametrize(
    "arguments, says",
    [
        (dict(max_rate=-1), r"max_rate must be a finite number > 0, not -1"),
        (dict(max_rate=0), r"max_rate must be a finite number > 0, not 0"),
        (dict(max_rate=INF), r"max_rate must be a finite number > 0, not inf"),
        (dict(tolerance=INF), r"tolerance must be a finite number >= 0, not inf"),
        (dict(tolerance=-1e-9), r"tolerance must be a finite number >= 0, not -1e-09"),
        (dict(start=3.0, end=0.0), r"start must be <= end, not start = 3 > end = 0"),
        # one sample has no change to check
        (dict(start=3.0), r"the window start = 3 … end = None s must hold 2 samples"),
    ],
)
def test_rate_limited_refuses_bad_arguments(arguments, says):
    given = {"max_rate": 50.0, **arguments}
    max_rate = given.pop("max_rate")
    call = lambda: assert_rate_limited(ramp(), "y", max_rate, **given)  # noqa: E731
    refused(call, "assert_rate_limited", says)


def test_reaches_refuses_bad_arguments():
    r = ramp()
    refused(lambda: assert_reaches(r, "y", 40.0, by=None), "assert_reaches", "by must be a finite")
    refused(lambda: assert_reaches(r, "y", 40.0, by=NAN), "assert_reaches", "by must be a finite")
    refused(lambda: assert_reaches(r, "y", NAN, by=1.0), "assert_reaches", "threshold must be a")


def test_a_result_without_samples_or_numbers_is_refused():
    refused(lambda: assert_within(EMPTY, "y", 0, 1), "assert_within", "the result has no samples")
    refused(
        lambda: assert_settles(EMPTY, "y", 0, within=1, tolerance=1),
        "assert_settles",
        "the result has no samples",
    )
    refused(lambda: assert_reaches(EMPTY, "y", 1, by=1), "assert_reaches", "the result has no")
    refused(lambda: assert_rate_limited(EMPTY, "y", 1), "assert_rate_limited", "the result has")
    words = pd.DataFrame({"time": [0.0, 1.0], "y": ["a", "b"]})
    refused(lambda: assert_within(words, "y", 0), "assert_within", "the signal 'y' .* not numeric")
    refused(lambda: assert_within([1, 2], "y", 0), "assert_within", "the result must be a")
    refused(lambda: assert_within(ramp(), "z", 0), "assert_within", "the result has no signal 'z'")


def test_the_arguments_at_their_limits_are_taken():
    r = ramp()  # 0 until 1 s, then 50 per second up to 40 at 1.8 s
    assert_settles(r, "y", 40.0, within=0.0, tolerance=0.0, after=1.8)
    assert_within(r, "y", 40.0, 40.0, start=1.8, end=1.8)
    assert_within(r, "y", -INF, INF)
    assert_rate_limited(r, "y", 50.0, start=1.0, end=1.1)


def test_only_refused_arguments_and_failures_hide_the_module():
    """A ValueError raised inside the module by something else (here numpy's) is a fault of the
    module: pytest keeps its frames."""

    class Info:
        def __init__(self, error):
            self.error = error

        def errisinstance(self, kinds):
            return isinstance(self.error, kinds)

    assert testing._hide(Info(AssertionError("x")))
    assert testing._hide(Info(testing.LgfValueError("x")))
    assert not testing._hide(Info(ValueError("numpy's")))
