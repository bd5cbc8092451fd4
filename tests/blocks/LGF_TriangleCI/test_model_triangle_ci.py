"""The LGF_TriangleCI model (model.py) alone against the runs worked out by hand (traces.py)."""

import math

import pytest

from tests.signal_generators import START, check_run, model_values

from . import traces
from .model import TriangleCI

RUNS = [
    "WORKED_EXAMPLE",
    "RESET",
    "FIRST_SAMPLE",
    "UDINT_WRAP",
    "PHASE_BEYOND_PERIODE",
    "PHASE_250",
    "TRUNCATED_CYCLE",
    "INFINITE_AMPLITUDE",
    "INFINITE_OFFSET",
]


@pytest.mark.parametrize("run", RUNS)
def test_model_reproduces_the_hand_traced_run(run):
    check_run(model_values(TriangleCI, getattr(traces, run)), getattr(traces, run))


@pytest.mark.parametrize(
    "name, value",
    [
        ("periode", 0),
        ("phaseShift", -0.5),
        ("phaseShift", 4294967295.0),
        ("amplitude", math.nan),
        ("offset", 3.5e38),
    ],
)
def test_model_refuses_what_the_fmu_refuses(name, value):
    with pytest.raises(ValueError):
        TriangleCI(100000).call(0, {**START, name: value})
