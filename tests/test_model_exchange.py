"""Model Exchange (docs/behaviour.md §1.11), driven as an event-driven importer runs it: the first
call in fmi2ExitInitializationMode, then a time event at every call time announced by
nextEventTime, where fmi2NewDiscreteStates executes the call once with the inputs set in that
event mode. Checked against the independent models and against co-simulation fed the same
inputs per call, with random inputs per call; then every demo scenario through FMPy's own Model
Exchange solver."""

import numpy as np
import pytest
from fmpy.fmi2 import fmi2Error
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.harness import (
    Slave,
    Trace,
    fmu_path,
    model_exchange_run,
    run_fmu,
    status_of,
    unpacked,
)
from tests.lgf_blocks import blocks, scenarios
from tools.simulate import simulate


def run_exchange(block, cycle_us, parameters, per_call, extra_events=()):
    """Outputs after each call k of an ME run in which call k sees the inputs per_call[k]. Between
    calls the importer integrates (setTime, completedIntegratorStep); at the times of
    extra_events (fractions of a cycle after a call) it handles an event of its own, which must
    execute no call."""
    cycle = cycle_us / 1e6
    s = Slave(block, {"cycleTime": cycle, **parameters}, per_call[0], model_exchange=True)
    rows = [s.outputs()]
    needed, terminate, _, _, defined, next_time = s.fmu.newDiscreteStates()  # initial iteration
    assert (needed, terminate, defined) == (False, False, True)
    assert s.outputs() == rows[0], "the initial event iteration executed a call"
    s.fmu.enterContinuousTimeMode()
    for k, inputs in enumerate(per_call[1:], start=1):
        assert next_time == k * cycle_us / 1e6, f"nextEventTime before call {k}"
        s.fmu.setTime((k - 1) * cycle + 0.25 * cycle)
        assert s.fmu.completedIntegratorStep() == (False, False)
        if k - 1 in extra_events:  # an event of the importer's own model between two calls
            s.fmu.setTime((k - 1) * cycle + 0.5 * cycle)
            s.fmu.enterEventMode()
            assert s.fmu.newDiscreteStates()[5] == next_time
            assert s.outputs() == rows[-1], (
                f"an event between calls {k - 1} and {k} executed a call"
            )
            s.fmu.enterContinuousTimeMode()
        s.fmu.setTime(next_time)
        s.fmu.enterEventMode()
        s.set(inputs)
        needed, terminate, _, _, defined, next_time = s.fmu.newDiscreteStates()
        assert (needed, terminate, defined) == (False, False, True)
        rows.append(s.outputs())
        assert s.fmu.newDiscreteStates()[5] == next_time  # a second iteration: no call
        assert s.outputs() == rows[-1], f"a second event iteration at call {k} executed a call"
        s.fmu.enterContinuousTimeMode()
    s.fmu.terminate()
    s.free()
    return rows


@st.composite
def runs(draw, spec):
    cycle_us = draw(spec.cycles_us)
    parameters = draw(spec.parameters())
    per_call = [{name: draw(strategy) for name, strategy in spec.inputs.items()}]
    for _ in range(draw(st.integers(1, 30))):
        names = draw(st.lists(st.sampled_from(sorted(spec.inputs)), max_size=3, unique=True))
        per_call.append({**per_call[-1], **{n: draw(spec.inputs[n]) for n in names}})
    extra = draw(st.sets(st.integers(0, len(per_call) - 2), max_size=3))
    return cycle_us, parameters, per_call, extra


@pytest.mark.parametrize("block", blocks(), ids=lambda b: b.name)
def test_exchange_equals_the_model_and_co_simulation(block):
    spec = block.spec

    @settings(max_examples=60)
    @given(runs(spec))
    def check(run):
        cycle_us, parameters, per_call, extra = run
        model = spec.make_model(cycle_us, parameters)
        expected = [model.call(k * cycle_us, dict(inputs)) for k, inputs in enumerate(per_call)]
        exchange = run_exchange(block.name, cycle_us, parameters, per_call, extra)
        # Co-simulation: the inputs set before the step that executes call k reach call k.
        trace = Trace(per_call[0], [(cycle_us, inputs) for inputs in per_call[1:]])
        cosimulation = run_fmu(block.name, cycle_us, trace, parameters)
        for k, (want, got, cs) in enumerate(zip(expected, exchange, cosimulation)):
            assert spec.same(want, got), (
                f"after call {k}: Model Exchange differs from the model: {got}, model {want}"
            )
            assert got == cs, f"after call {k}: Model Exchange differs from co-simulation"

    check()


def exchange_slave(block, **kwargs):
    return Slave(block.name, inputs=block.active, model_exchange=True, **kwargs)


@pytest.mark.parametrize("block", blocks(), ids=lambda b: b.name)
def test_exchange_state_machine_refuses_misuse(block):
    s = exchange_slave(block)
    before = s.outputs()
    f = s.fmu
    refused = {
        "fmi2EnterEventMode is fine, fmi2CompletedIntegratorStep is not (event mode)": lambda: (
            f.completedIntegratorStep()
        ),
        "fmi2SetContinuousStates (event mode)": lambda: f.fmi2SetContinuousStates(
            f.component, None, 0
        ),
        "nx = 1": lambda: f.fmi2GetDerivatives(f.component, None, 1),
        "time before the first call": lambda: f.setTime(-1.0),
        "time NaN": lambda: f.setTime(float("nan")),
    }
    for label, call in refused.items():
        assert status_of(call) == fmi2Error, label
    f.enterContinuousTimeMode()
    for label, call in {
        "fmi2NewDiscreteStates (continuous-time mode)": lambda: f.newDiscreteStates(),
        "a fixed parameter (continuous-time mode)": lambda: s.set({"cycleTime": 1.0}),
        "fmi2EnterContinuousTimeMode twice": lambda: f.enterContinuousTimeMode(),
    }.items():
        assert status_of(call) == fmi2Error, label
    assert s.outputs() == before
    assert all(text.startswith("fmi2") for status, _, text in s.log if status == fmi2Error)
    s.free()


@pytest.mark.parametrize("block", blocks(), ids=lambda b: b.name)
def test_an_input_set_in_continuous_time_mode_waits_for_the_next_call(block):
    """OMSimulator and the FMI Compliance Checker set Integer and Boolean inputs in
    continuous-time mode (FMI 2.0 3.2.3 lets importers do so in event mode only). The FMU takes
    them, says so once in a warning, and the next call reads them: outputs do not change before
    it, and after it they equal a run that set the same values in event mode."""
    changed = block.active  # from the start values to those under which the block works
    runs = []
    for set_in_continuous_time in (True, False):
        s = Slave(block.name, {"cycleTime": 0.1}, {}, model_exchange=True)
        s.fmu.newDiscreteStates()
        s.fmu.enterContinuousTimeMode()
        before = s.outputs()
        s.fmu.setTime(0.05)
        if set_in_continuous_time:
            s.set(changed)
            s.set(changed)
            assert s.outputs() == before, "an input set in continuous-time mode acted at once"
        s.fmu.setTime(0.1)
        s.fmu.enterEventMode()
        if not set_in_continuous_time:
            s.set(changed)
        s.fmu.newDiscreteStates()
        runs.append(s.outputs())
        warnings = [text for status, _, text in s.log if "continuous-time mode" in text]
        assert len(warnings) == (1 if set_in_continuous_time else 0), warnings
        s.free()
    assert runs[0] == runs[1]


@pytest.mark.parametrize("block", blocks(), ids=lambda b: b.name)
def test_exchange_time_may_go_back_but_not_before_the_last_call(block):
    # An integrator may step past the next call time and return to it (FMPy's CVODE does).
    s = Slave(block.name, {"cycleTime": 0.1}, block.active, model_exchange=True)
    s.fmu.enterContinuousTimeMode()
    s.fmu.setTime(0.114)
    s.fmu.setTime(0.1)
    s.fmu.enterEventMode()
    s.fmu.newDiscreteStates()  # call 1, at 0.1 s
    s.fmu.enterContinuousTimeMode()
    s.fmu.setTime(0.15)
    assert status_of(s.fmu.setTime, 0.099) == fmi2Error  # before call 1
    assert any("fmi2SetTime" in text and "last PLC call" in text for _, _, text in s.log)
    s.fmu.setTime(0.1)
    # At most 1e6 calls may wait for the next event (docs/behaviour.md §1.11): no hour-long
    # catch-up.
    s.fmu.setTime(0.1 + 1e6 * 0.1)
    assert status_of(s.fmu.setTime, 0.1 + 1.5e6 * 0.1) == fmi2Error
    assert any("fmi2SetTime" in text and "1000000 PLC calls" in text for _, _, text in s.log)
    s.free()


@pytest.mark.parametrize("block", blocks(), ids=lambda b: b.name)
def test_states_stay_with_their_interface(block):
    me, cs = exchange_slave(block), Slave(block.name, inputs=block.active)
    me_state, cs_state = me.fmu.getFMUstate(), cs.fmu.getFMUstate()
    assert status_of(me.fmu.setFMUstate, cs_state) == fmi2Error
    assert status_of(cs.fmu.setFMUstate, me_state) == fmi2Error
    assert (
        status_of(me.fmu.deSerializeFMUstate, bytes(cs.fmu.serializeFMUstate(cs_state)))
        == fmi2Error
    )
    # within one interface a state round trip replays bit for bit
    me.fmu.setFMUstate(me_state)
    me.fmu.freeFMUstate(me_state)
    cs.fmu.freeFMUstate(cs_state)
    me.free()
    cs.free()


# ---- every demo scenario through FMPy's Model Exchange solver ----


@pytest.mark.parametrize("scenario", scenarios())
def test_fmpy_model_exchange_equals_co_simulation(scenario):
    md, _ = unpacked(scenario.block)
    expected, outputs, _ = simulate(scenario, fmu_path(scenario.block).parent)
    fmu = fmu_path(scenario.block)
    result = model_exchange_run(fmu, scenario, md, outputs, validate=True)
    assert np.array_equal(result["time"], expected["time"])
    for name in outputs:
        assert np.array_equal(result[name], expected[name]), name
