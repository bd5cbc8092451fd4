"""Dropped into a model with no input connected, every FMU shows its block working: its default
experiment (the modelDescription's DefaultExperiment, start values only, nothing set) moves an
output — or, for a block that cannot (it maps inputs to outputs, or acts only on input edges,
and says why in its scenarios.py's STEADY_DEFAULT), holds every output at the value its start
values give — and equals the block's independent Python model run with the same start values
(docs/behaviour.md §2.1, §3.1, §4.1: the decisions on start values)."""

import numpy as np
import pytest
from fmpy import simulate_fmu

from tests.harness import fmu_path, unpacked
from tests.lgf_blocks import blocks
from tests.test_references import model_rows
from tools.scenario import Scenario

BLOCKS = blocks()


@pytest.mark.parametrize("block", BLOCKS, ids=[b.name for b in BLOCKS])
def test_default_experiment_shows_the_block_working(block):
    md, _ = unpacked(block.name)
    experiment = md.defaultExperiment
    result = simulate_fmu(str(fmu_path(block.name)))  # no start values, no input
    assert result["time"][-1] == pytest.approx(float(experiment.stopTime))
    outputs = [u.variable.name for u in md.outputs]
    moving = [name for name in outputs if len(np.unique(result[name])) > 1]
    if block.steady_default:
        assert moving == [], f"STEADY_DEFAULT says no output moves, but {moving} do"
    else:
        assert moving, f"no output of {outputs} moves in the default experiment"

    default_run = Scenario(
        name=f"{block.name}_default",
        block=block.name,
        title="default experiment",
        stop_time=float(experiment.stopTime),
        output_interval=float(experiment.stepSize),
    )
    expected = model_rows(block, default_run)
    assert len(expected) == len(result)
    for want, row in zip(expected, result):
        assert {n: float(row[n]) for n in want} == {n: float(v) for n, v in want.items()}, (
            f"t = {row['time']}"
        )
