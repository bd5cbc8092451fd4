"""What the five signal generators (docs/behaviour.md §6) share, on each block's FMU and on its
model (tests/blocks/<Block>/model.py): every run worked out by hand in its traces.py (each Run
it defines; `value` within ULPS float32 ulps where the block's trace says so, everything else
exact), the input values refused and those accepted at their limits (tests/signal_generators.py),
a cycleTime below 1 ms refused and one of 1.5 ms accepted with a warning. What only one block
does stays in its own folder."""

import importlib

import pytest

from tests.lgf_blocks import find
from tests.signal_generators import (
    ACCEPTED,
    REFUSED,
    START,
    check_accepted,
    check_cycle_time_refused,
    check_refused,
    check_run,
    check_truncated_cycle_warns,
    fmu_values,
    model_values,
    runs,
)

GENERATORS = ["LGF_CosinusCI", "LGF_RectangleCI", "LGF_SawToothCI", "LGF_SinusCI", "LGF_TriangleCI"]


def traces(block: str):
    return importlib.import_module(f"tests.blocks.{block}.traces")


RUNS = [(block, run) for block in GENERATORS for run in runs(traces(block))]
VALUES = [(block, name, value) for block in GENERATORS for name, value in REFUSED]


def model_class(block: str):
    """The block's model as model_values takes it: (cycle in µs, parameters) -> model."""
    return find(block).spec.make_model


@pytest.mark.parametrize("block, run", RUNS)
def test_the_fmu_gives_the_hand_traced_run(block, run):
    trace = traces(block)
    ulps = getattr(trace, "ULPS", 0)
    check_run(fmu_values(block, getattr(trace, run)), getattr(trace, run), ulps=ulps)


@pytest.mark.parametrize("block, run", RUNS)
def test_the_model_gives_the_hand_traced_run(block, run):
    trace = traces(block)
    ulps = getattr(trace, "ULPS", 0)
    check_run(model_values(model_class(block), getattr(trace, run)), getattr(trace, run), ulps=ulps)


@pytest.mark.parametrize("block, name, value", VALUES)
def test_invalid_inputs_are_refused(block, name, value):
    check_refused(block, name, value)


@pytest.mark.parametrize("block, name, value", VALUES)
def test_the_model_refuses_what_the_fmu_refuses(block, name, value):
    with pytest.raises(ValueError):
        model_class(block)(100000, {}).call(0, {**START, name: value})


@pytest.mark.parametrize("block", GENERATORS)
@pytest.mark.parametrize("name, value", ACCEPTED, ids=[f"{n}={v}" for n, v in ACCEPTED])
def test_inputs_at_their_limits_are_accepted(block, name, value):
    check_accepted(block, name, value)


@pytest.mark.parametrize("block", GENERATORS)
@pytest.mark.parametrize("cycle", [0.0009, 0.0, -0.1])
def test_cycle_time_below_1_ms_is_refused(block, cycle):
    check_cycle_time_refused(block, cycle)


@pytest.mark.parametrize("block", GENERATORS)
def test_a_cycle_of_1_5_ms_warns_that_it_runs_on_ts_1_ms(block):
    check_truncated_cycle_warns(block, 0.0015)
