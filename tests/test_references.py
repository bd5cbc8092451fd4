"""Regression: every demo scenario of every block, simulated afresh with FMPy, equals its
committed reference result (tests/blocks/<Block>/references/<scenario>.csv, regenerated only by
`make references`, whose diff is reviewed), and each reference equals the block's independent
Python model run in FMPy's frame."""

import csv

import pytest

from tests.harness import ROOT, Trace, run_model, unpacked
from tests.lgf_blocks import blocks, param_id
from tools.scenario import input_defaults
from tools.simulate import simulate

SCENARIOS = [(block, scenario) for block in blocks() for scenario in block.scenarios]
IDS = [param_id(scenario) for _, scenario in SCENARIOS]


def read_reference(block, scenario):
    path = block.reference(scenario)
    if not path.exists():
        pytest.fail(f"{path.relative_to(ROOT)} is missing: run `make references` and review it")
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return [{k: float(v) for k, v in row.items()} for row in rows]


def as_number(value):
    return float(value)  # Booleans become 0.0/1.0 as in the CSV


def model_rows(block, scenario):
    """The scenario on the Python model: FMPy sets the inputs of row t at communication point
    t, so a change at t reaches the calls in (t, t + interval]."""
    md, _ = unpacked(block.name)
    parameters = dict(scenario.parameters)
    parameters.pop("cycleTime", None)
    cycle_us = round(scenario.cycle_time(md) * 1e6)
    interval_us = round(scenario.output_interval * 1e6)
    changes = {}
    for time, values in scenario.inputs:
        changes.setdefault(round(time * 1e6), {}).update(values)
    initial = {**input_defaults(md), **changes.pop(0, {})}
    steps = [
        (interval_us, changes.get(i * interval_us, {}))
        for i in range(round(scenario.stop_time * 1e6) // interval_us)
    ]
    model = block.spec.make_model(cycle_us, parameters)
    return run_model(model, cycle_us, Trace(initial, steps))


@pytest.mark.parametrize("block, scenario", SCENARIOS, ids=IDS)
def test_fresh_run_equals_reference(block, scenario):
    reference = read_reference(block, scenario)
    result, outputs, _ = simulate(scenario, ROOT / "fmus")
    assert len(result) == len(reference)
    for row, ref in zip(result, reference):
        assert {n: as_number(row[n]) for n in ref} == ref, f"t = {ref['time']}"


@pytest.mark.parametrize("block, scenario", SCENARIOS, ids=IDS)
def test_reference_equals_independent_model(block, scenario):
    reference = read_reference(block, scenario)
    expected = model_rows(block, scenario)
    assert len(expected) == len(reference)
    for want, ref in zip(expected, reference):
        got = {n: ref[n] for n in want}  # numbers; the model's Booleans equal 0.0/1.0
        assert block.spec.same(want, got), f"t = {ref['time']}: reference {got}, model {want}"
