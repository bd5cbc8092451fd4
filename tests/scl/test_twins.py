"""Proof by twins (docs/scl.md §7): SCL versions of the first eight blocks, written here from
docs/behaviour.md as a PLC programmer would (tests/scl/twins/), compiled by lgf_fmus.scl, equal
the hand-written FMUs (fmus/<Block>.fmu) bit for bit: every output after every step, on the
random scenarios of the block's own property tests (tests/blocks/<Block>/spec.py), in
co-simulation and Model Exchange, FMI 2.0 and 3.0. LGF_SawTooth's twin is the PLC-exact timing
(plcTiming = true, docs/behaviour.md §2.5); the signal generators' twins follow §6, LGF_RampCI's
§4 with its table as an in/out ARRAY[*] of its UDT."""

from __future__ import annotations

import importlib
import math
import struct

import pytest
from fmpy import read_model_description
from hypothesis import given, settings
from hypothesis import strategies as st

from lgf_fmus import scl
from tests.scl.driver import TWINS, hand_written, run_cs, run_me

# the hand-written FMU's parameters that the twin's SCL fixes
TWINS_OF = {
    "LGF_LimRateOfChangeCI": {},
    "LGF_SawTooth": {"plcTiming": True},
    "LGF_SawToothCI": {},
    "LGF_TriangleCI": {},
    "LGF_RectangleCI": {},
    "LGF_SinusCI": {},
    "LGF_CosinusCI": {},
    "LGF_RampCI": {},
}


@pytest.fixture(scope="module")
def twin(tmp_path_factory):
    built = {}

    def get(block, fmi=2):
        if (block, fmi) not in built:
            out = tmp_path_factory.mktemp("twins") / f"{block}.fmu"
            built[block, fmi] = scl.compile(
                [TWINS / f"{block}.scl"],
                block=block,
                fmi=fmi,
                output=out,
                werror=True,
                win64=False,  # the native binary is compared; tests/scl/test_win64.py runs a DLL
            )
        return built[block, fmi]

    return get


def bits(rows):
    """Outputs with every Real as its bit pattern, so that -0.0 and 0.0 differ."""
    return [
        {k: struct.pack("<d", v) if isinstance(v, float) else v for k, v in row.items()}
        for row in rows
    ]


@st.composite
def scenarios(draw, spec):
    cycle_us = draw(spec.cycles_us)
    initial = {name: draw(strategy) for name, strategy in spec.inputs.items()}
    step_sizes = st.one_of(
        st.sampled_from([cycle_us, cycle_us, 2 * cycle_us, 3 * cycle_us, max(1, cycle_us // 2)]),
        st.integers(1, 4 * cycle_us),
    )
    steps = []
    for _ in range(draw(st.integers(1, 40))):
        names = draw(st.lists(st.sampled_from(sorted(spec.inputs)), max_size=3, unique=True))
        steps.append((draw(step_sizes), {n: draw(spec.inputs[n]) for n in names}))
    return cycle_us, initial, steps


@st.composite
def per_call_runs(draw, spec):
    cycle_us = draw(spec.cycles_us)
    per_call = [{name: draw(strategy) for name, strategy in spec.inputs.items()}]
    for _ in range(draw(st.integers(1, 30))):
        names = draw(st.lists(st.sampled_from(sorted(spec.inputs)), max_size=3, unique=True))
        per_call.append({**per_call[-1], **{n: draw(spec.inputs[n]) for n in names}})
    return cycle_us, per_call


def spec_of(block):
    return importlib.import_module(f"tests.blocks.{block}.spec").SPEC


@pytest.mark.parametrize("block", sorted(TWINS_OF))
def test_twin_has_the_interface_of_the_block(block, twin):
    variables = read_model_description(str(twin(block))).modelVariables
    # the twin's statics are FMI locals (docs/scl.md §4) and maxCycleTime the parameter of its
    # cycle watchdog (§3.4); the hand-written block has neither
    ours = {v.name: v for v in variables if v.causality != "local" and v.name != "maxCycleTime"}
    theirs = {v.name: v for v in read_model_description(str(hand_written(block))).modelVariables}
    fixed = set(TWINS_OF[block])
    assert set(ours) == set(theirs) - fixed
    for name, v in ours.items():
        w = theirs[name]
        assert (v.causality, v.type, v.variability) == (w.causality, w.type, w.variability), name
        if v.start is not None or w.start is not None:
            assert v.start == w.start, f"start value of {name}"


def assert_equal_bits(theirs, ours, after="step"):
    for k, (want, got) in enumerate(zip(bits(theirs), bits(ours))):
        assert got == want, f"after {after} {k}: twin {got}, hand-written {want}"


# the runs drawn (cycle_us, then the runner's arguments), their runner, the examples in FMI 2.0
# and 3.0 (Model Exchange's runs cost more), what a row of the run follows
INTERFACES = {
    "co_simulation": (scenarios, run_cs, {2: 25, 3: 10}, "step"),
    "model_exchange": (per_call_runs, run_me, {2: 20, 3: 8}, "call"),
}


@pytest.mark.parametrize("fmi", [2, 3])
@pytest.mark.parametrize("interface", sorted(INTERFACES))
@pytest.mark.parametrize("block", sorted(TWINS_OF))
def test_twin_equals_the_block(block, interface, fmi, twin):
    runs, run, examples, after = INTERFACES[interface]
    fixed = TWINS_OF[block]
    ours_fmu, theirs_fmu = twin(block, fmi), hand_written(block, fmi)

    @settings(max_examples=examples[fmi])
    @given(runs(spec_of(block)))
    def check(drawn):
        cycle_us, *arguments = drawn
        theirs = run(theirs_fmu, cycle_us, fixed, *arguments)
        ours = run(ours_fmu, cycle_us, {}, *arguments, names=list(theirs[0]))
        assert_equal_bits(theirs, ours, after)

    check()


def test_twin_sawtooth_example_1_of_the_behaviour(twin):
    """docs/behaviour.md §2.5, example 1, by hand: steps at 0.4 s, 0.9 s, 1.4 s, back at 1.9 s."""
    inputs = {"timeRange": 0.3, "numberSteps": 3, "incrementRange": 10, "startValue": 0}
    rows = run_cs(twin("LGF_SawTooth"), 100_000, {}, inputs, [(100_000, {})] * 20)
    values = [r["value"] for r in rows]
    assert values == [0, 0, 0, 0, 10, 10, 10, 10, 10, 20, 20, 20, 20, 20, 30, 30, 30, 30, 30, 0, 0]
    assert not math.isnan(values[0])


@pytest.mark.parametrize("fmi", [2, 3])
def test_twin_ramp_equals_the_block_on_random_tables(fmi, twin):
    """The twin of LGF_RampCI with the tables of its property tests (numberOfSetpoints 2 to 6,
    random values and times): its ARRAY[*] in/out is the table, numberOfSetpoints its size."""
    spec = spec_of("LGF_RampCI")
    ours_fmu, theirs_fmu = twin("LGF_RampCI", fmi), hand_written("LGF_RampCI", fmi)

    @settings(max_examples=INTERFACES["co_simulation"][2][fmi])  # as the twins' co-simulation
    @given(spec.parameters(), scenarios(spec))
    def check(table, scenario):
        cycle_us, initial, steps = scenario
        theirs = run_cs(theirs_fmu, cycle_us, table, initial, steps)
        ours = run_cs(ours_fmu, cycle_us, table, initial, steps, names=list(theirs[0]))
        assert_equal_bits(theirs, ours)

    check()


def test_twin_ramp_worked_example_of_the_behaviour(twin):
    """docs/behaviour.md §4.5 by hand: cycleTime 0.1 s, the table (0, 0.3 s), (30, 0.2 s),
    (30, 0.25 s), (0, 0 s); start FALSE in the first call, TRUE from 0.1 s on."""
    table = {"numberOfSetpoints": 4}
    for i, (value, time) in enumerate([(0.0, 0.3), (30.0, 0.2), (30.0, 0.25), (0.0, 0.0)]):
        table[f"setpoints[{i}].outputValue"], table[f"setpoints[{i}].time"] = value, time
    rows = run_cs(
        twin("LGF_RampCI"), 100_000, table, {"start": False}, [(100_000, {"start": True})] * 10
    )
    got = [
        (
            round(r["outputValue"], 9),
            r["actTimeTable"],
            r["stepNumber"],
            r["remainTime"],
            r["totalTime"],
            r["remainTotalTime"],
            r["status"],
        )
        for r in rows
    ]
    run, start, end = 0x7000, 0x7001, 0
    assert got == [
        (0, False, 0, 0, 0, 0, run),
        (0, True, 1, 0.3, 0.75, 0.75, start),
        (10, True, 1, 0.2, 0.75, 0.65, run),
        (20, True, 1, 0.1, 0.75, 0.55, run),
        (30, True, 2, 0.2, 0.75, 0.45, run),
        (30, True, 2, 0.1, 0.75, 0.35, run),
        (30, True, 3, 0.25, 0.75, 0.25, run),
        (18, True, 3, 0.15, 0.75, 0.15, run),
        (6, True, 3, 0.05, 0.75, 0.05, run),
        (0, False, 3, 0, 0.75, 0, end),
        (0, False, 3, 0, 0.75, 0, end),
    ]
