"""The PLC call clock of docs/behaviour.md §1.2-1.3, observed through LGF_LimRateOfChangeCI: with
value far away and setChangeRate·cycleTime = 1.0, delayedValue counts the calls executed so far."""

import pytest
from fmpy.fmi2 import fmi2Error
from hypothesis import given, settings
from hypothesis import strategies as st

from tests.harness import Slave, status_of
from tests.lgf_blocks import blocks

BLOCK = "LGF_LimRateOfChangeCI"
FAR = 1e12


def counter(cycle, start_time=0.0):
    return Slave(
        BLOCK,
        {"cycleTime": cycle},
        {"value": FAR, "setChangeRate": 1.0 / cycle},
        start_time=start_time,
    )


def calls(slave):
    return slave.get(["delayedValue"])["delayedValue"]


def test_first_call_happens_in_exit_initialization_mode():
    assert calls(counter(0.1)) == 1.0


@pytest.mark.parametrize("cycle", [0.001, 0.01, 0.1])
@pytest.mark.parametrize("master", ["t0 + n*h", "t += h"])
def test_a_million_steps_of_one_cycle_execute_a_million_calls(cycle, master):
    # docs/behaviour.md §1.3: a master that computes its communication points as t0 + n·h
    # (FMPy, Simulink, libcosim) passes points and step sizes a few ulps off the grid; one that
    # adds up its steps drifts by accumulated round-off (up to 1.7e-5 cycles after 10^6 steps).
    # Neither may lose or double a call: the count is checked every 1000 steps and at the end.
    s = counter(cycle)
    do_step, get_real = s.fmu.fmi2DoStep, s.fmu.getReal
    component, delayed = s.fmu.component, [s.vr("delayedValue")]
    n, t = 1_000_000, 0.0
    for i in range(n):
        if master == "t0 + n*h":
            t = i * cycle
            h = (i + 1) * cycle - t
        else:
            h = cycle
        assert do_step(component, t, h, 1) == 0, f"step {i} at t = {t!r}"
        if master == "t += h":
            t += h
        if i % 1000 == 999:
            assert get_real(delayed) == [i + 2], f"after step {i} at t = {t!r}"
    assert calls(s) == n + 1
    s.free()


@pytest.mark.parametrize("start_time", [0.0, 1000.0, -5.0, 123456.789])
def test_call_times_are_relative_to_the_start_time(start_time):
    s = counter(0.01, start_time)
    s.time = start_time
    s.step(0.005)
    assert calls(s) == 1.0  # no call in (t0, t0 + 0.005]
    s.step(0.005)
    assert calls(s) == 2.0  # the call at t0 + 0.01
    s.step(1.0)
    assert calls(s) == 102.0


def test_a_step_executes_every_call_in_it():
    s = counter(0.001)
    s.step(0.25)
    assert calls(s) == 251.0
    s.step(0.0004)
    s.step(0.0004)
    assert calls(s) == 251.0
    s.step(0.0002)  # ends exactly on the next call
    assert calls(s) == 252.0


def test_microsecond_cycles_at_large_times():
    # At t = 1e5 s one ulp is 1.5e-11 s, far more than 1e-9 of a 1 µs cycle: the tolerance
    # must grow with t or calls would be lost.
    s = counter(1e-6, start_time=1e5)
    for n in range(1000):
        t = 1e5 + n * 1e-6
        s.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=(1e5 + (n + 1) * 1e-6) - t)
        assert calls(s) == n + 2


# ---- step-size independence (docs/behaviour.md §1.3) ----

PATTERNS = {  # step sizes in cycles; all meet at multiples of 6 cycles
    "1": [1],
    "3": [3],
    "0.5": [0.5],
    "2,4": [2, 4],
    "irregular": [0.25, 1.75, 1, 0.5, 2.5],
}


def run_pattern(block, cycle, parameters, segments, pattern):
    """Inputs change only every 6 cycles; returns outputs at every multiple of 6 cycles."""
    s = Slave(block, {"cycleTime": cycle, **parameters}, segments[0])
    rows = [s.outputs()]
    elapsed = 0.0  # in cycles
    for inputs in segments[1:] + [{}]:
        target = elapsed + 6
        i = 0
        while elapsed < target - 1e-9:
            h = min(pattern[i % len(pattern)], target - elapsed)
            t0 = elapsed * cycle
            s.fmu.doStep(
                currentCommunicationPoint=t0, communicationStepSize=(elapsed + h) * cycle - t0
            )
            elapsed += h
            i += 1
        rows.append(s.outputs())
        s.set(inputs)
    s.free()
    return rows


@pytest.mark.parametrize("block", blocks(), ids=lambda b: b.name)
def test_outputs_do_not_depend_on_the_step_size(block):
    spec = block.spec

    @settings(max_examples=25, deadline=None)
    @given(st.data())
    def check(data):
        cycle = data.draw(spec.cycles_us) / 1e6
        parameters = data.draw(spec.parameters())
        segments = [{**block.active, **{n: data.draw(s) for n, s in spec.inputs.items()}}]
        for _ in range(data.draw(st.integers(1, 6))):
            names = data.draw(
                st.lists(st.sampled_from(sorted(spec.inputs)), max_size=3, unique=True)
            )
            segments.append({n: data.draw(spec.inputs[n]) for n in names})
        results = {
            name: run_pattern(block.name, cycle, parameters, segments, p)
            for name, p in PATTERNS.items()
        }
        for name, rows in results.items():
            assert rows == results["1"], name

    check()


def test_a_grid_that_doubles_cannot_resolve_is_refused():
    # One ulp of 1e12 s is 1.2e-4 s: a 1 µs cycle cannot be told apart there.
    s = Slave(BLOCK, initialize=False)
    s.fmu.setupExperiment(startTime=1e12)
    s.fmu.enterInitializationMode()
    s.set({"cycleTime": 1e-6})
    assert status_of(s.fmu.exitInitializationMode) == fmi2Error
    assert any("cannot resolve the call grid" in text for _, _, text in s.log)
    s.set({"cycleTime": 1.0})  # a 1 s cycle is fine there
    s.fmu.exitInitializationMode()
    s.free()
