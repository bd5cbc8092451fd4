"""Assertions for control logic on simulation results, for tests in CI.

Each takes a result (the DataFrame of lgf_fmus.simulate, any DataFrame with a `time` column, or
FMPy's structured array), the name of a signal and the requirement; a failure is an
AssertionError whose message gives the times and values that break the requirement. An
argument out of its range (a NaN, a negative tolerance, start after end, a window without
samples) is refused with a ValueError (LgfValueError) naming the function, the argument and
what it allows. Under pytest either is reported at the test's line, without this module's
source.

    from lgf_fmus.testing import assert_settles, assert_within, assert_rate_limited

    assert_settles(result, "delayedValue", 100.0, within=2.5, tolerance=0.01, after=1.0)
    assert_within(result, "delayedValue", 0.0, 100.0)
    assert_rate_limited(result, "delayedValue", 40.0)
"""

from __future__ import annotations

import math

import numpy as np

from ._model import LgfValueError

__all__ = ["assert_settles", "assert_within", "assert_rate_limited", "assert_reaches", "signal"]


def _hide(excinfo) -> bool:
    """pytest's __tracebackhide__ for every frame of this module: a requirement that fails
    (AssertionError) or an argument it refuses (LgfValueError) is the test's failure, so pytest
    shows the test's line and the message, not the code here that found it; any other
    exception (a ValueError of numpy's included) is a fault of this module and keeps its
    frames."""
    return excinfo is not None and excinfo.errisinstance((AssertionError, LgfValueError))


# pytest reads __tracebackhide__ from a frame's locals, else from its globals: this one name
# covers the public functions and their helpers alike.
__tracebackhide__ = _hide


def signal(result, name: str) -> tuple[np.ndarray, np.ndarray]:
    """(time, values) of the signal `name` of a result, as float arrays; a ValueError names
    what the result lacks."""
    if isinstance(result, np.ndarray) and result.dtype.names is not None:
        names = list(result.dtype.names)
    elif hasattr(result, "columns"):
        names = list(result.columns)
    else:
        raise LgfValueError(
            "the result must be a DataFrame or a structured array with a 'time' column, "
            f"not {type(result).__name__}"
        )
    if "time" not in names:
        raise LgfValueError("the result has no 'time' column")
    if name not in names:
        signals = ", ".join(str(n) for n in names if n != "time")
        raise LgfValueError(f"the result has no signal {name!r}; it has {signals}")
    try:
        return (
            np.asarray(result["time"], dtype=np.float64),
            np.asarray(result[name], dtype=np.float64),
        )
    except (TypeError, ValueError):
        raise LgfValueError(f"the signal {name!r} (or time) of the result is not numeric") from None


def _samples(function: str, result, name: str) -> tuple[np.ndarray, np.ndarray]:
    """signal(), its refusal naming the function; a result without samples is refused too."""
    try:
        t, y = signal(result, name)
    except LgfValueError as error:
        raise LgfValueError(f"{function}: {error}") from None
    if t.size == 0:
        raise LgfValueError(f"{function}: the result has no samples")
    return t, y


def _number(function: str, argument: str, value, *, at_least=None, above=None, finite=True):
    """The argument as a float, or LgfValueError naming the function, the argument and its range:
    a real number (never a bool or a string), finite unless finite=False, never NaN."""
    if at_least is not None:
        allowed = f" >= {_s(at_least)}"
    elif above is not None:
        allowed = f" > {_s(above)}"
    else:
        allowed = ""
    kind = "a finite number" if finite else "a number (not NaN)"
    ok = isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(
        value, (bool, np.bool_)
    )
    x = float(value) if ok else math.nan
    ok = ok and not math.isnan(x) and (math.isfinite(x) or not finite)
    ok = ok and (at_least is None or x >= at_least) and (above is None or x > above)
    if not ok:
        raise LgfValueError(f"{function}: {argument} must be {kind}{allowed}, not {value!r}")
    return x


def _optional(function: str, argument: str, value, **limits):
    return None if value is None else _number(function, argument, value, **limits)


def _span(function: str, start, end, t, least: int = 1):
    """start and end checked (finite, start <= end), and the window of samples between them,
    refused if it holds fewer than `least` samples."""
    start = _optional(function, "start", start)
    end = _optional(function, "end", end)
    if start is not None and end is not None and start > end:
        raise LgfValueError(
            f"{function}: start must be <= end, not start = {_s(start)} > end = {_s(end)}"
        )
    keep = _window(t, start, end)
    if np.count_nonzero(keep) < least:
        samples = "a sample" if least == 1 else f"{least} samples"
        raise LgfValueError(
            f"{function}: the window start = {_none(start)} … end = {_none(end)} s must hold "
            f"{samples} of the result, which runs from t = {_s(t[0])} to {_s(t[-1])} s"
        )
    return keep


def _none(value) -> str:
    return "None" if value is None else _s(value)


def _window(t, start, end) -> np.ndarray:
    """The samples from start to end (s, inclusive, round-off forgiven), as a mask."""
    keep = np.ones(t.shape, dtype=bool)
    if start is not None:
        keep &= t >= start - 1e-9 * max(1.0, abs(start))
    if end is not None:
        keep &= t <= end + 1e-9 * max(1.0, abs(end))
    return keep


def _s(value: float) -> str:
    """The shortest text that reads back as the same double (30.000000000000004 is not 30)."""
    text = repr(float(value))
    return text[:-2] if text.endswith(".0") else text


def _d(value: float) -> str:
    """A derived figure (a rate, a difference), to 6 digits."""
    return f"{value:.6g}"


def assert_settles(
    result, name: str, target: float, *, within: float, tolerance: float, after: float | None = None
):
    """From `within` seconds after `after` on, to the end of the result, the signal `name`
    stays within `target` ± `tolerance` (inclusive).

    within     the settling time, s
    tolerance  the half-width of the band around `target`
    after      when the settling time starts, s (default: the first sample), e.g. the time of
               the setpoint step
    A result that ends before that deadline fails."""
    f = "assert_settles"
    t, y = _samples(f, result, name)
    target = _number(f, "target", target)
    within = _number(f, "within", within, at_least=0)
    tolerance = _number(f, "tolerance", tolerance, at_least=0)
    after = _optional(f, "after", after)
    begin = t[0] if after is None else after
    deadline = begin + within
    band = f"{_s(target)} ± {_s(tolerance)}"
    if t[-1] < deadline - 1e-9 * max(1.0, abs(deadline)):
        raise AssertionError(
            f"{name}: the result ends at t = {_s(t[-1])} s, before the settling "
            f"deadline t = {_s(deadline)} s ({_s(within)} s after "
            f"t = {_s(begin)} s)"
        )
    keep = _window(t, deadline, None)
    tw, yw = t[keep], y[keep]
    outside = np.flatnonzero(~(np.abs(yw - target) <= tolerance))
    if outside.size == 0:
        return
    first, last = outside[0], outside[-1]
    text = (
        f"{name} did not settle to {band} within {_s(within)} s after t = {_s(begin)} s: at "
        f"t = {_s(tw[first])} s it is {_s(yw[first])} (off by {_d(yw[first] - target)})"
    )
    if last + 1 < tw.size:
        text += (
            f"; the last sample outside the band is at t = {_s(tw[last])} s ({_s(yw[last])}), "
            f"it stays inside from t = {_s(tw[last + 1])} s on"
        )
    else:
        text += f"; it is still outside at the end, t = {_s(tw[last])} s ({_s(yw[last])})"
    raise AssertionError(text)


def assert_within(
    result,
    name: str,
    low: float | None = None,
    high: float | None = None,
    *,
    start: float | None = None,
    end: float | None = None,
):
    """Between `start` and `end` (s, inclusive; default: the whole result) the signal `name`
    stays in [`low`, `high`]; a bound given as None is not checked (low <= high, either may be
    infinite). NaN is always outside. The window must hold a sample."""
    f = "assert_within"
    t, y = _samples(f, result, name)
    low = _optional(f, "low", low, finite=False)
    high = _optional(f, "high", high, finite=False)
    if low is not None and high is not None and low > high:
        raise LgfValueError(f"{f}: low must be <= high, not low = {_s(low)} > high = {_s(high)}")
    keep = _span(f, start, end, t)
    t, y = t[keep], y[keep]
    bad = np.zeros(t.shape, dtype=bool)
    if low is not None:
        bad |= ~(y >= low)
    if high is not None:
        bad |= ~(y <= high)
    where = np.flatnonzero(bad)
    if where.size == 0:
        return
    i = where[0]
    below = (low if low is not None else np.inf) - y[where]
    above = y[where] - (high if high is not None else -np.inf)
    extreme = where[np.argmax(np.where(np.isnan(y[where]), np.inf, np.maximum(below, above)))]
    bounds = (
        f"[{_s(low) if low is not None else '-inf'}, {_s(high) if high is not None else 'inf'}]"
    )
    raise AssertionError(
        f"{name} leaves {bounds}: at t = {_s(t[i])} s it is {_s(y[i])}; "
        f"{where.size} of {t.size} samples are outside, the farthest "
        f"{_s(y[extreme])} at t = {_s(t[extreme])} s"
    )


def assert_rate_limited(
    result,
    name: str,
    max_rate: float,
    *,
    tolerance: float = 1e-9,
    start: float | None = None,
    end: float | None = None,
):
    """Between consecutive samples from `start` to `end` (s, inclusive; default: the whole
    result) the signal `name` changes by at most `max_rate` per second, either way, plus a
    relative `tolerance` (default 1e-9, >= 0) for round-off; max_rate is finite and > 0. A
    change between two samples at the same time is a jump and always fails. The window must
    hold two samples."""
    f = "assert_rate_limited"
    t, y = _samples(f, result, name)
    max_rate = _number(f, "max_rate", max_rate, above=0)
    tolerance = _number(f, "tolerance", tolerance, at_least=0)
    keep = _span(f, start, end, t, least=2)
    t, y = t[keep], y[keep]
    dt = np.diff(t)
    dy = np.diff(y)
    step = dt > 0
    rate = np.full(dy.shape, 0.0)
    rate[step] = np.abs(dy[step]) / dt[step]
    bad = (step & ~(rate <= max_rate * (1 + tolerance))) | (~step & (dy != 0))
    where = np.flatnonzero(bad)
    if where.size == 0:
        return
    i = where[0]
    worst = where[np.argmax(np.where(step[where], rate[where], np.inf))]

    def change(k):
        r = f"{_d(rate[k])}/s" if step[k] else "a jump at one instant"
        return f"from t = {_s(t[k])} s ({_s(y[k])}) to t = {_s(t[k + 1])} s ({_s(y[k + 1])}): {r}"

    text = f"{name} changes faster than {_s(max_rate)}/s {change(i)}"
    if worst != i:
        text += f"; the fastest change is {change(worst)}"
    raise AssertionError(text + f" ({where.size} such changes)")


def assert_reaches(result, name: str, threshold: float, *, by: float):
    """The signal `name` reaches `threshold` at the latest at time `by` (s, inclusive).

    The direction comes from the signal's first value: below `threshold` it must rise to it
    (a sample >= `threshold`), otherwise fall to it (a sample <= `threshold`), so a signal
    that starts at `threshold` has reached it. Only the first such sample counts: what the
    signal does after it is not checked (assert_within or assert_settles check that)."""
    f = "assert_reaches"
    t, y = _samples(f, result, name)
    threshold = _number(f, "threshold", threshold)
    by = _number(f, "by", by)
    rising = y[0] < threshold
    hit = np.flatnonzero(y >= threshold if rising else y <= threshold)
    if hit.size and t[hit[0]] <= by + 1e-9 * max(1.0, abs(by)):
        return
    direction = "rise to" if rising else "fall to"
    at_by = np.flatnonzero(t <= by)
    seen = f"; at t = {_s(t[at_by[-1]])} s it is {_s(y[at_by[-1]])}" if at_by.size else ""
    when = f"it first does at t = {_s(t[hit[0]])} s" if hit.size else "it never does"
    raise AssertionError(
        f"{name} does not {direction} {_s(threshold)} by t = {_s(by)} s{seen}; {when}"
    )
