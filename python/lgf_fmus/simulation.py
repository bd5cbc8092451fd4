"""simulate(): one run of a bundled FMU with the native runner, returned as a DataFrame."""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass

import numpy as np

from . import _runner
from ._model import LgfValueError, Model, SimulationError, check_value
from ._model import model as model_of
from ._tables import merge, step_tables, table_parameters


class FMUWarning(UserWarning):
    """A warning the FMU logged during a run (e.g. a cycleTime rounded to whole µs)."""


DTYPES = {"Real": np.float64, "Integer": np.int32, "Boolean": np.bool_}


@dataclass
class Setup:
    """A run's settings, checked against the modelDescription."""

    model: Model
    parameters: dict  # start values (parameters, inputs, the table's entries)
    tables: dict  # input step tables {name: [(time, value), ...]}
    outputs: list[str]
    start_time: float
    stop_time: float
    output_interval: float


def _number(value, what: str, positive: bool = False) -> float:
    if (
        isinstance(value, bool)
        or not isinstance(value, (int, float, np.integer, np.floating))
        or not math.isfinite(float(value))
        or (positive and float(value) <= 0)
    ):
        raise LgfValueError(
            f"{what} must be a finite number{' > 0' if positive else ''}, not {value!r}"
        )
    return float(value)


def check_parameters(model: Model, parameters: dict | None, what: str = "parameters") -> dict:
    checked = {}
    for name, value in (parameters or {}).items():
        checked[name] = check_value(model.settable(name), value, f"{what}: ")
    return checked


def setup(
    block,
    stop_time=None,
    parameters=None,
    inputs=None,
    *,
    table=None,
    start_time=None,
    output_interval=None,
    outputs=None,
    fmi_version: int = 2,
) -> Setup:
    model = model_of(block, fmi_version)
    if parameters is not None and not isinstance(parameters, dict):
        raise LgfValueError(f"parameters must be a dict {{name: start value}}, not {parameters!r}")
    if model.fmi_version != 2:
        raise LgfValueError(
            f"simulate and sweep run FMI 2.0 FMUs; the FMI "
            f"{model.fmi_version}.0 FMU of {model.identifier} is bundled for "
            f"other importers: "
            f"fmu_path({model.identifier!r}, {model.fmi_version})"
        )
    parameters = dict(parameters or {})
    for name in [n for n in parameters if n == "table" or n in model.tables]:
        if table is not None:
            raise LgfValueError(f"give the table once: table= or parameters[{name!r}]")
        table = parameters.pop(name)  # the table of points given among the parameters
    parameters = check_parameters(model, parameters)
    entries = table_parameters(model, table)
    both = sorted(set(entries) & set(parameters))
    if both:
        raise LgfValueError(f"table and parameters both set {', '.join(both)}")
    parameters.update(entries)
    tables = step_tables(inputs)
    for name in tables:
        model.input(name)
    start = _number(
        start_time if start_time is not None else (model.start_time or 0.0), "start_time"
    )
    if stop_time is None:
        stop_time = model.stop_time if model.stop_time is not None else start + 1.0
    stop = _number(stop_time, "stop_time")
    if stop <= start:
        raise LgfValueError(f"stop_time ({stop:g}) must be after start_time ({start:g})")
    if output_interval is None:
        output_interval = model.cycle_time(parameters) or model.step_size or (stop - start) / 500
    interval = _number(output_interval, "output_interval", positive=True)
    if outputs is None:
        outputs = model.outputs
    elif isinstance(outputs, str):
        outputs = [outputs]
    try:
        names = list(outputs) if not isinstance(outputs, dict) else None
    except TypeError:
        names = None
    if names is None or not all(isinstance(name, str) for name in names):
        raise LgfValueError(f"outputs must be an output's name or a list of them, not {outputs!r}")
    outputs = [model.output(name).name for name in names]
    if not outputs:
        raise LgfValueError("outputs is empty: name at least one output")
    return Setup(model, parameters, tables, outputs, start, stop, interval)


def frame(plan: _runner.Plan, times: np.ndarray, samples: np.ndarray, n: int):
    """One run's samples as the DataFrame FMPy's result would give: time, then the outputs with
    FMPy's dtypes (float64, int32, bool)."""
    import pandas as pd

    columns = {"time": times[:n].copy()}
    for k, (name, kind) in enumerate(zip(plan.output_names, plan.output_kinds)):
        columns[name] = samples[:n, k].astype(DTYPES[kind])
    return pd.DataFrame(columns)


def simulate(
    block,
    stop_time=None,
    parameters=None,
    inputs=None,
    *,
    table=None,
    start_time=None,
    output_interval=None,
    outputs=None,
    fmi_version: int = 2,
):
    """Simulates a bundled block (or an FMU given by its path) and returns a pandas DataFrame:
    `time` and the outputs (every output unless `outputs` names some), sampled at the start and
    after every communication step, exactly as fmpy.simulate_fmu would return them.

        simulate("LGF_LimRateOfChangeCI", 5.0, {"cycleTime": 0.01},
                 inputs={"value": [(0.0, 0.0), (1.0, 100.0)], "setChangeRate": 50.0})

    parameters   start values: parameters and inputs (held unless `inputs` drives them)
    inputs       step tables: {name: [(time, value), ...]} (a scalar: held from the start),
                 a CSV (a `time` column and one per input) or a DataFrame of that shape; an
                 input keeps its start value until its first row; a row at time t is set at
                 communication point t, so it reaches the PLC calls in (t, t + h]
    table        a table of points for a block that has one (LGF_RampCI: rows of
                 (outputValue, time), or a CSV with those columns): sets numberOfSetpoints and
                 setpoints[i].*; also accepted as parameters["table"] or parameters["setpoints"]
    output_interval  the communication step, default the cycleTime (every PLC call)
    stop_time    default: the FMU's default experiment

    Names and values are checked first (LgfValueError naming the variable and its range; a
    fractional value for an Integer is refused, not truncated). An FMU error raises
    SimulationError with the FMU's message; the FMU's warnings become FMUWarning."""
    s = setup(
        block,
        stop_time,
        parameters,
        inputs,
        table=table,
        start_time=start_time,
        output_interval=output_interval,
        outputs=outputs,
        fmi_version=fmi_version,
    )
    names, times, values = merge(s.model, s.tables, s.parameters, s.start_time)
    plan = _runner.Plan.make(
        s.model, list(s.parameters), names, s.outputs, s.start_time, s.stop_time, s.output_interval
    )
    start = np.array([[float(s.parameters[n]) for n in plan.start_names]]).reshape(
        1, len(plan.start_names)
    )
    batch = _runner.runner(s.model).run(
        plan, start, np.array([0, len(times)]), times, values.reshape(len(times), len(names))
    )
    message = batch.messages[0]
    if not message.startswith(s.model.identifier):
        message = f"{s.model.identifier}: {message}"
    if batch.status[0] == _runner.RUN_FAILED:
        raise SimulationError(message)
    if batch.status[0] == _runner.RUN_WARNING:
        warnings.warn(message, FMUWarning, stacklevel=2)
    return frame(plan, batch.times[0], batch.samples[0], int(batch.n_samples[0]))
