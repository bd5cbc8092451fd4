"""The LGF_CosinusCI model (model.py) alone against the runs worked out by hand (traces.py)."""

import math

import pytest

from tests.signal_generators import START, check_run, model_values

from . import traces
from .model import CosinusCI


@pytest.mark.parametrize("run", traces.RUNS)
def test_model_reproduces_the_hand_traced_run(run):
    check_run(model_values(CosinusCI, getattr(traces, run)), getattr(traces, run), ulps=traces.ULPS)


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
        CosinusCI(100000).call(0, {**START, name: value})
