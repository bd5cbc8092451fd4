"""Each FMU against its independent Python model (tests/blocks/<Block>/model.py, written from
docs/behaviour.md), on random parameters, random inputs and random communication step patterns:
the outputs must be identical after every step, Reals bit for bit (or agree as the block's
BlockSpec.same says, for a block whose documented result has a tolerance)."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.block_spec import exact
from tests.harness import Trace, run_fmu, run_model
from tests.lgf_blocks import blocks


@st.composite
def scenarios(draw, spec):
    cycle_us = draw(spec.cycles_us)
    parameters = draw(spec.parameters())
    initial = {name: draw(strategy) for name, strategy in spec.inputs.items()}
    changeable = {**spec.inputs, **spec.tunables(parameters)}
    step_sizes = st.one_of(
        st.sampled_from([cycle_us, cycle_us, 2 * cycle_us, 3 * cycle_us, max(1, cycle_us // 2)]),
        st.integers(1, 4 * cycle_us),
    )
    steps = []
    for _ in range(draw(st.integers(1, 40))):
        names = draw(st.lists(st.sampled_from(sorted(changeable)), max_size=3, unique=True))
        steps.append((draw(step_sizes), {n: draw(changeable[n]) for n in names}))
    return cycle_us, parameters, Trace(initial, steps)


@pytest.mark.parametrize("block", blocks(), ids=lambda b: b.name)
def test_fmu_equals_model(block):
    spec = block.spec

    @settings(max_examples=150)
    @given(scenarios(spec))
    def check(scenario):
        cycle_us, parameters, trace = scenario
        expected = run_model(spec.make_model(cycle_us, parameters), cycle_us, trace)
        actual = run_fmu(block.name, cycle_us, trace, parameters)
        for step, (want, got) in enumerate(zip(expected, actual)):
            assert spec.same(want, got), f"after step {step}: FMU {got}, model {want}"

    check()


def test_exact_takes_a_nan_only_for_the_same_nan():
    """The default comparison: the positive quiet NaN of docs/behaviour.md §1.4 equals itself
    (== never does), not a negative NaN nor a number; True and 1 are one value (FMPy's Integer
    outputs against a model's BOOL status bits)."""
    negative_nan = -math.nan
    assert exact({"y": math.nan, "e": False}, {"y": float("nan"), "e": 0})
    assert not exact({"y": math.nan}, {"y": negative_nan})
    assert not exact({"y": math.nan}, {"y": 0.0})
    assert not exact({"y": 1.0}, {"y": math.nan})
    assert not exact({"y": 1.0}, {"y": 1.0, "z": 2.0})
