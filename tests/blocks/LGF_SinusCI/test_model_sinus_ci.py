"""The LGF_SinusCI model (model.py) alone against the runs worked out by hand (traces.py)."""

import math

import pytest

from tests.signal_generators import START, check_run, model_values

from . import traces
from .model import SinusCI


@pytest.mark.parametrize("run", traces.RUNS)
def test_model_reproduces_the_hand_traced_run(run):
    check_run(model_values(SinusCI, getattr(traces, run)), getattr(traces, run), ulps=traces.ULPS)


@pytest.mark.parametrize(
    "name, value",
    [
        ("periode", 0),
        ("phaseShift", -1.0),
        ("phaseShift", 4294967295.0),
        ("amplitude", math.nan),
        ("offset", math.nan),
        ("amplitude", 1e39),
    ],
)
def test_model_refuses_what_the_fmu_refuses(name, value):
    with pytest.raises(ValueError):
        SinusCI(100000).call(0, {**START, name: value})
