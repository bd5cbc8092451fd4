"""A second co-simulation engine: every demo scenario, run through libcosim (the engine of the
Open Simulation Platform, Python package libcosimpy) with a fixed step of cycleTime, gives the
outputs of FMPy's run (tools.simulate.simulate, as for the references) bit for bit, Reals,
Integers and Booleans, at every time point the two runs share.

libcosim counts time in integer nanoseconds: the step is cycleTime in ns (exact, as the FMU
holds cycleTime as whole µs), and FMPy's communication points k·output_interval are matched
to libcosim's by rounding them to ns. The inputs that FMPy's Input sets at a communication
point t (from the scenario's signal table, with FMPy's own lookup) are given to libcosim's
override manipulator before the step that starts at t, so that they reach the PLC calls in
(t, t + h] in both engines; those at the start time are initial values, as in FMPy.

Observations: the last-value observer after each step, for every output. The values after
initialization (t = 0) are overwritten before the first step() returns, so they come from the
observers' records: Reals and Integers from the time-series observer (which holds no
Booleans), Booleans from the file observer's CSV (which prints Reals with 6 digits only).
"""

from __future__ import annotations

import csv

import numpy as np
import pytest
from fmpy.simulation import Input

from tests.harness import ROOT, fmu_path
from tests.lgf_blocks import scenarios
from tools.scenario import input_defaults
from tools.simulate import simulate

NS = 1_000_000_000


def libcosim():
    """The libcosimpy modules. libcosimpy is pinned in requirements.txt, so a missing or
    unloadable one fails the test: it is never skipped."""
    try:
        from libcosimpy import (
            CosimEnums,
            CosimExecution,
            CosimLogging,
            CosimManipulator,
            CosimObserver,
            CosimSlave,
        )

        # The first call into the C library loads libcosimc.so; libcosim logs at debug level
        # by default, keep its warnings and errors only.
        CosimLogging.log_output_level(CosimLogging.CosimLogLevel.WARNING)
    except (ImportError, OSError) as e:
        pytest.fail(
            f"libcosimpy (libcosim) cannot be used: {e!r}. requirements.txt pins "
            "libcosimpy==0.0.6, whose only wheels are for CPython 3.11 to 3.13 on x86_64 "
            "Linux (glibc >= 2.28): run `make venv` with such a Python."
        )
    return CosimEnums, CosimExecution, CosimManipulator, CosimObserver, CosimSlave


def fmpy_inputs(signals, names, time, after_event):
    """The values FMPy's Input.apply sets at `time`, looked up with FMPy's own function (the
    inputs are all discrete, so FMPy holds a row's value, never interpolates)."""
    return {
        n: Input.interpolate(
            time=time,
            t=signals["time"],
            table=signals[n][np.newaxis, :],
            discrete=True,
            after_event=after_event,
        )[0][0]
        for n in names
    }


PYTHON_TYPE = {"Real": float, "Integer": int, "Boolean": bool}


def typed(variable, value):
    return PYTHON_TYPE[variable.type](value)


def run_libcosim(
    scenario, md, inputs_at: dict[int, dict], step_ns: int, stop_ns: int, log_dir
) -> dict[int, dict]:
    """The scenario in libcosim, with the inputs of `inputs_at` (ns -> values) given before the
    step that starts there (those at 0 as initial values). Returns {ns: {output: value}} at the
    end of every step and, Booleans left out, at t = 0; the file observer writes its CSV
    into log_dir, completely once the execution is gone (it writes in batches), that is once
    this function has returned."""
    CosimEnums, CosimExecution, CosimManipulator, CosimObserver, CosimSlave = libcosim()
    variables = {v.name: v for v in md.modelVariables}
    outputs = [v for v in md.modelVariables if v.causality == "output"]
    numeric = [v for v in outputs if v.type != "Boolean"]  # what the time series can hold

    execution = CosimExecution.CosimExecution.from_step_size(step_ns)
    slave = CosimSlave.CosimLocalSlave(str(fmu_path(scenario.block)), scenario.name)
    index = execution.add_local_slave(slave)
    assert index >= 0, f"libcosim could not add {scenario.block}.fmu"
    last = CosimObserver.CosimObserver.create_last_value()
    series = CosimObserver.CosimObserver.create_time_series()
    files = CosimObserver.CosimObserver.create_to_dir(str(log_dir))
    override = CosimManipulator.CosimManipulator.create_override()
    assert all(execution.add_observer(o) for o in (last, series, files))
    assert execution.add_manipulator(override)
    for v in numeric:
        kind = CosimEnums.CosimVariableType[v.type.upper()]
        assert series.start_time_series(index, v.valueReference, kind), v.name

    for name, value in {**scenario.parameters, **inputs_at[0]}.items():
        v = variables[name]
        set_initial = getattr(execution, f"{v.type.lower()}_initial_value")
        assert set_initial(index, v.valueReference, typed(v, value)), name

    current = dict(inputs_at[0])
    rows = {}
    for now in range(0, stop_ns, step_ns):
        for name, value in inputs_at.get(now, {}).items() if now else ():
            if value != current[name]:
                v = variables[name]
                set_override = getattr(override, f"slave_{v.type.lower()}_values")
                assert set_override(index, [v.valueReference], [typed(v, value)]), name
                current[name] = value
        assert execution.step(), f"libcosim step from t = {now} ns failed"
        assert execution.status().current_time == now + step_ns
        rows[now + step_ns] = {
            v.name: getattr(last, f"last_{v.type.lower()}_values")(index, [v.valueReference])[0]
            for v in outputs
        }
        if now == 0:
            rows[0] = after_initialization(series, index, numeric)
    return rows


def after_initialization(series, index, variables) -> dict:
    """The values of step 0 (t = 0) in the time series, read after the first step (the series
    is a bounded buffer). Its Python wrapper drops the last sample it is asked for: ask for
    two."""
    values = {}
    for v in variables:
        samples = getattr(series, f"time_series_{v.type.lower()}_samples")
        times, steps, data = samples(index, v.valueReference, from_step=0, sample_count=2)
        assert times[:1] == [0] and steps[:1] == [0], (v.name, times, steps)
        values[v.name] = data[0]
    return values


def booleans_after_initialization(md, log_dir) -> dict:
    """The Boolean outputs at t = 0 from the file observer's CSV (row of step 0, 0 or 1)."""
    [csv_file] = log_dir.glob("*.csv")
    with open(csv_file) as f:
        first = next(csv.DictReader(f), None)
    assert first is not None and first["StepCount"] == "0", f"{csv_file.name}: no row of step 0"
    values = {}
    for v in md.modelVariables:
        if v.causality == "output" and v.type == "Boolean":
            assert first[v.name] in ("0", "1"), (v.name, first[v.name])
            values[v.name] = first[v.name] == "1"
    return values


@pytest.mark.parametrize("scenario", scenarios())
def test_libcosim_equals_fmpy(scenario, tmp_path):
    libcosim()  # fails here, with its message, when libcosim cannot be used
    result, outputs, md = simulate(scenario, ROOT / "fmus")
    variables = {v.name: v for v in md.modelVariables}
    defaults = input_defaults(md)
    assert all(variables[n].variability == "discrete" for n in defaults), "FMPy would interpolate"
    signals = scenario.input_signals(defaults)

    # FMPy's communication points are its output grid k·output_interval (no extra event
    # points: the scenario's input times lie on that grid).
    interval_ns = round(scenario.output_interval * NS)
    stop_ns = round(scenario.stop_time * NS)
    expected_rows = stop_ns // interval_ns + 1
    assert len(result) == expected_rows > 1
    points = [round(t * NS) for t in result["time"]]
    assert points == [k * interval_ns for k in range(expected_rows)]

    cycle = scenario.cycle_time(md)
    step_ns = round(cycle * NS)
    assert step_ns == round(cycle * 1e6) * 1000, "cycleTime is held as whole µs"
    assert all(p % step_ns == 0 for p in points), "FMPy's points must lie on libcosim's grid"

    # What FMPy sets: at initialization (after_event=False), then before each doStep.
    inputs_at = {0: fmpy_inputs(signals, defaults, result["time"][0], after_event=False)}
    for t, p in zip(result["time"][1:-1], points[1:-1]):
        inputs_at[p] = fmpy_inputs(signals, defaults, t, after_event=True)
    changed = {n for p in inputs_at for n in defaults if inputs_at[p][n] != inputs_at[0][n]}
    assert changed or len(scenario.inputs) <= 1, "the scenario's input changes were lost"

    rows = run_libcosim(scenario, md, inputs_at, step_ns, points[-1], tmp_path)
    rows[0].update(booleans_after_initialization(md, tmp_path))
    assert len(rows) == points[-1] // step_ns + 1

    common = [k for k, p in enumerate(points) if p in rows]
    assert len(common) == expected_rows
    assert any(len(set(result[n].tolist())) > 1 for n in outputs), "no output changes"
    mismatches = []
    for name in outputs:
        wanted = PYTHON_TYPE[variables[name].type]
        assert all(type(rows[points[k]][name]) is wanted for k in common), f"{name}: not {wanted}"
        fmpy = result[name][common]
        cosim = np.array([rows[points[k]][name] for k in common], dtype=fmpy.dtype)
        assert len(fmpy) == len(cosim) == expected_rows
        if fmpy.dtype == np.float64:  # bit for bit: tells -0.0 from 0.0, compares NaNs
            differ = fmpy.view(np.uint64) != cosim.view(np.uint64)
        else:
            differ = fmpy != cosim
        for k in np.flatnonzero(differ)[:3]:
            mismatches.append(
                f"{name} at t = {points[common[k]] / NS:g} s: "
                f"FMPy {fmpy[k]!r}, libcosim {cosim[k]!r}"
            )
    assert not mismatches, "\n".join(mismatches)
