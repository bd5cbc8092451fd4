"""The LGF_SawToothCI model (model.py) alone against the runs worked out by hand (traces.py)."""

import math

import pytest

from tests.signal_generators import START, check_run, model_values

from . import traces
from .model import SawToothCI

RUNS = [
    "WORKED_EXAMPLE",
    "RESET",
    "FIRST_SAMPLE",
    "UDINT_WRAP",
    "TRUNCATED_CYCLE",
    "NEW_PERIODE",
    "INFINITE_OFFSET",
    "INFINITE_AMPLITUDE",
    "OVERFLOW",
]


@pytest.mark.parametrize("run", RUNS)
def test_model_reproduces_the_hand_traced_run(run):
    check_run(model_values(SawToothCI, getattr(traces, run)), getattr(traces, run))


def test_model_reset_with_offset_minus_zero_gives_plus_zero():
    value = SawToothCI(100000).call(0, {**START, "offset": -0.0, "reset": True})["value"]
    assert value == 0.0 and math.copysign(1.0, value) == 1.0


def test_model_values_are_float32_values_widened():
    values = model_values(SawToothCI, traces.WORKED_EXAMPLE)
    assert values[0] == -0.800000011920929 and values[0] != -0.8
    assert all(isinstance(v, float) for v in values)


@pytest.mark.parametrize(
    "name, value",
    [
        ("periode", 0),
        ("phaseShift", -1.0),
        ("phaseShift", 4294967295.0),
        ("phaseShift", math.inf),
        ("amplitude", math.nan),
        ("offset", math.nan),
        ("amplitude", 1e39),
        ("offset", -1e39),
    ],
)
def test_model_refuses_what_the_fmu_refuses(name, value):
    with pytest.raises(ValueError):
        SawToothCI(100000).call(0, {**START, name: value})


@pytest.mark.parametrize("cycle_us", [999, 0, 60_000_001])
def test_model_refuses_cycles_outside_1_ms_to_60_s(cycle_us):
    with pytest.raises(ValueError):
        SawToothCI(cycle_us)
