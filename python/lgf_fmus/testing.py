"""Assertions for control logic on simulation results, for tests in CI.

Each takes a result (the DataFrame of lgf_fmus.simulate, any DataFrame with a `time` column, or
FMPy's structured array), the name of a signal and the requirement; a failure is an
AssertionError whose message gives the times and values that break the requirement. Under
pytest the failure is reported at the test's line, without this module's source.

    from lgf_fmus.testing import assert_settles, assert_within, assert_rate_limited

    assert_settles(result, "delayedValue", 100.0, within=2.5, tolerance=0.01, after=1.0)
    assert_within(result, "delayedValue", 0.0, 100.0)
    assert_rate_limited(result, "delayedValue", 40.0)
"""

from __future__ import annotations

import numpy as np

__all__ = ["assert_settles", "assert_within", "assert_rate_limited", "assert_reaches", "signal"]


def _hide(excinfo) -> bool:
    """pytest's __tracebackhide__ for every frame of this module: a requirement that fails
    (AssertionError) or an argument it refuses (ValueError) is the test's failure, so pytest
    shows the test's line and the message, not the code here that found it; any other
    exception is a fault of this module and keeps its frames."""
    return excinfo is not None and excinfo.errisinstance((AssertionError, ValueError))


# pytest reads __tracebackhide__ from a frame's locals, else from its globals: this one name
# covers the public functions and their helpers alike.
__tracebackhide__ = _hide


def signal(result, name: str) -> tuple[np.ndarray, np.ndarray]:
    """(time, values) of the signal `name` of a result, as float arrays; a ValueError names
    what the result lacks."""
    names = result.dtype.names if isinstance(result, np.ndarray) else list(result.columns)
    if "time" not in names:
        raise ValueError("the result has no 'time' column")
    if name not in names:
        signals = ", ".join(n for n in names if n != "time")
        raise ValueError(f"the result has no signal {name!r}; it has {signals}")
    return (
        np.asarray(result["time"], dtype=np.float64),
        np.asarray(result[name], dtype=np.float64),
    )


def _window(t, y, start, end):
    keep = np.ones(t.shape, dtype=bool)
    if start is not None:
        keep &= t >= start - 1e-9 * max(1.0, abs(start))
    if end is not None:
        keep &= t <= end + 1e-9 * max(1.0, abs(end))
    return t[keep], y[keep]


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
    t, y = signal(result, name)
    begin = t[0] if after is None else after
    deadline = begin + within
    band = f"{_s(target)} ± {_s(tolerance)}"
    if t[-1] < deadline - 1e-9 * max(1.0, abs(deadline)):
        raise AssertionError(
            f"{name}: the result ends at t = {_s(t[-1])} s, before the settling "
            f"deadline t = {_s(deadline)} s ({_s(within)} s after "
            f"t = {_s(begin)} s)"
        )
    tw, yw = _window(t, y, deadline, None)
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
    stays in [`low`, `high`]; a bound given as None is not checked. NaN is always outside."""
    t, y = _window(*signal(result, name), start, end)
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
    relative `tolerance` (default 1e-9) for round-off. A change between two samples at the same
    time is a jump and always fails."""
    t, y = _window(*signal(result, name), start, end)
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
    t, y = signal(result, name)
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
