"""What every block's spec (tests/blocks/<Block>/spec.py) is made of: the BlockSpec that the
property tests draw parameters, inputs and cycle times from, and the Hypothesis strategies the
blocks share."""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass
from typing import Callable

from hypothesis import strategies as st


def exact(want: dict, got: dict) -> bool:
    """The default comparison of a model's outputs (want) with an FMU's (got): equal, and a NaN
    only to a NaN of the same bits (docs/behaviour.md §1.4: the positive quiet NaN), which
    == alone never finds equal."""
    return got.keys() == want.keys() and all(_same(want[n], got[n]) for n in want)


def _same(want, got) -> bool:
    if isinstance(want, float) and math.isnan(want):
        return (
            isinstance(got, float)
            and math.isnan(got)
            and struct.pack("<d", got) == struct.pack("<d", want)
        )
    return got == want


@dataclass
class BlockSpec:
    make_model: Callable[[int, dict], object]  # (cycle_us, parameters) -> model
    cycles_us: st.SearchStrategy
    inputs: dict[str, st.SearchStrategy]  # every input with a strategy for its values
    # -> dict of fixed/tunable parameters; none by default, for a block that has none
    parameters: Callable[[], st.SearchStrategy] = lambda: st.just({})
    tunables: Callable[[dict], dict[str, st.SearchStrategy]] = lambda parameters: {}
    # (model's outputs, FMU's outputs) -> do they agree? For a block whose documented result
    # may differ from its model within a tolerance; the default demands equality.
    same: Callable[[dict, dict], bool] = exact


def time_ms(lo: int, hi: int) -> st.SearchStrategy:
    """TIME inputs as seconds, sometimes off the ms grid to exercise rounding."""
    return st.one_of(
        st.integers(lo, hi).map(lambda ms: ms / 1000),
        st.floats(lo / 1000, hi / 1000, allow_nan=False),
    )


reals = st.one_of(
    st.integers(-100, 100).map(float),
    st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False),
    st.sampled_from([0.0, -0.0, 1e300, -1e300]),
)
ints = st.one_of(
    st.integers(-20, 20), st.integers(-32768, 32767), st.sampled_from([-32768, -1, 0, 1, 32767])
)
rarely_true = st.sampled_from([False, False, False, True])
# The cycle times (µs) of most blocks' property tests: 1 ms to 1 s, 3.3 ms (no whole number of
# calls per second) and 7 µs (many calls per communication step).
cycles = st.sampled_from([1000, 10000, 100000, 1000000, 3300, 7])
