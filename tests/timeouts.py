"""Hang guards for the programs the tests start (wine, fmutool, ...): never a fixed wall-clock
limit that a slow or loaded machine can hit. `hang_guard(seconds)` takes what is ample on an
idle machine and scales it like tools/hang-guard.sh does for the shell scripts: by the load
factor (see load_factor), measured when the guard is taken, and by
LGF_TIMEOUT_SCALE (default 1; 0: no guard, None for subprocess's timeout)."""

from __future__ import annotations

import os


def load_factor() -> float:
    """max(1, load / CPUs), the load being the larger of the 1-minute load average and the
    tasks runnable right now less this one (the average lags a load that just began)."""
    try:
        load = os.getloadavg()[0]
        cpus = len(os.sched_getaffinity(0))
    except (OSError, AttributeError):
        return 1.0
    try:
        with open("/proc/loadavg") as file:
            load = max(load, int(file.read().split()[3].split("/")[0]) - 1)
    except (OSError, IndexError, ValueError):
        pass
    return max(1.0, load / max(cpus, 1))


def timeout_scale() -> float:
    text = os.environ.get("LGF_TIMEOUT_SCALE", "1")
    try:
        scale = float(text)
    except ValueError:
        raise ValueError(
            f"LGF_TIMEOUT_SCALE must be a number (0: no guard), not {text!r}"
        ) from None
    if scale < 0:
        raise ValueError(f"LGF_TIMEOUT_SCALE must not be negative, not {text!r}")
    return scale


def hang_guard(seconds: float) -> float | None:
    """The timeout for a subprocess that takes well under `seconds` on an idle machine."""
    scale = timeout_scale()
    if scale == 0:
        return None
    return seconds * scale * load_factor()
