"""Regression: every demo scenario, simulated afresh with FMPy, equals its committed reference
result (tests/references, regenerated only by `make references`, whose diff is reviewed), and
each reference equals the block's independent Python model run in FMPy's frame."""
import csv
import sys

import pytest

from blocks import SPECS
from harness import ROOT, Trace, run_model, unpacked

sys.path.insert(0, str(ROOT / "demo"))
from run_demo import simulate  # noqa: E402
from scenarios import SCENARIOS, input_defaults  # noqa: E402

REFERENCES = ROOT / "tests" / "references"


def read_reference(name):
    with open(REFERENCES / f"{name}.csv") as f:
        rows = list(csv.DictReader(f))
    return [{k: float(v) for k, v in row.items()} for row in rows]


def as_number(value):
    return float(value)  # Booleans become 0.0/1.0 as in the CSV


def model_rows(scenario):
    """The scenario on the Python model: FMPy sets the inputs of row t at communication point
    t, so a change at t reaches the calls in (t, t + interval]."""
    md, _ = unpacked(scenario.block)
    parameters = dict(scenario.parameters)
    cycle_us = round(parameters.pop("cycleTime", 0.1) * 1e6)
    if scenario.block == "LGF_SawTooth":
        parameters.setdefault("plcTiming", False)
    interval_us = round(scenario.output_interval * 1e6)
    changes = {}
    for time, values in scenario.inputs:
        changes.setdefault(round(time * 1e6), {}).update(values)
    initial = {**input_defaults(md), **changes.pop(0, {})}
    steps = [(interval_us, changes.get(i * interval_us, {}))
             for i in range(round(scenario.stop_time * 1e6) // interval_us)]
    model = SPECS[scenario.block].make_model(cycle_us, parameters)
    return run_model(model, cycle_us, Trace(initial, steps))


@pytest.mark.parametrize("scenario", SCENARIOS, ids=lambda s: s.name)
def test_fresh_run_equals_reference(scenario):
    reference = read_reference(scenario.name)
    result, outputs, _ = simulate(scenario, ROOT / "fmus")
    assert len(result) == len(reference)
    for row, ref in zip(result, reference):
        assert {n: as_number(row[n]) for n in ref} == ref, f"t = {ref['time']}"


@pytest.mark.parametrize("scenario", SCENARIOS, ids=lambda s: s.name)
def test_reference_equals_independent_model(scenario):
    reference = read_reference(scenario.name)
    expected = model_rows(scenario)
    assert len(expected) == len(reference)
    for want, ref in zip(expected, reference):
        assert {n: ref[n] for n in want} == {n: as_number(v) for n, v in want.items()}, f"t = {ref['time']}"
