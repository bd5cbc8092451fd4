"""sweep(): many runs of one block, on Dask distributed, one row of metrics per run.

The runs are split into chunks; a chunk is one task, which a worker runs with the native runner
(the FMU extracted once per worker process, its instance reset between runs) and reduces to its
metrics (and its traces, as one flat array per column) before anything is sent back. Without
a cluster (workers=0, or a sweep smaller than a cluster's cost) the chunks run in this process;
the sweeps of a process share one LocalCluster, started by the first that needs it."""

from __future__ import annotations

import atexit
import itertools
import logging
import math
import os
import threading
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

import numpy as np

from . import _runner
from ._model import LgfValueError, Model, _article, check_array
from ._model import model as model_of
from ._tables import _csv, merge, step_tables, table_parameters
from .simulation import DTYPES, setup

METRICS = ("final", "min", "max", "mean")
TABLE = "table"  # a run column holding a table of points (LGF_RampCI's setpoints)
CYCLE = "cycleTime"  # a run's own output interval by default, as in simulate()
CHUNK_BYTES = 64 << 20  # the buffers of one chunk at most
SAMPLES_PER_TASK = 4_000_000  # about 0.2 s of the runner: below it, one task per thread
# Where a sweep without workers=, client= or scheduler= runs: in this process if its work (steps:
# PLC calls and samples, see _steps) is below what Dask would cost it, else on the LocalCluster
# that the sweeps of this process share. The native loop makes some 50-250 million steps a
# second on a core, so START_STEPS is a second or a few of work, what starting a LocalCluster
# costs (2-5 s); WARM_STEPS, once that cluster runs, some tens of ms: a sweep's round trip
# through the scheduler and back.
START_STEPS = 200_000_000
WARM_STEPS = 20_000_000
GROUP_VALUES = 8 << 20  # trace values per column in a Parquet row group (64 MB of float64)


class Trace(dict):
    """What a metric function gets for each run: {"time": array, output: array, ...} with
    FMPy's dtypes, and `run`, the run's row ({column: value})."""

    run: dict


@dataclass
class Job:
    """What every chunk of a sweep shares; sent with each task."""

    block: str  # a bundled block's name, or the path of an FMU
    fmi_version: int
    plans: list[_runner.Plan]  # one per output interval (the runs' own cycleTimes)
    metrics: tuple
    metric_outputs: list[str]
    reach: list[tuple[str, float, str]]  # (output, threshold, column)
    functions: dict[str, Callable]
    traces: bool

    @property
    def plan(self) -> _runner.Plan:
        """The plan with the most samples (the shortest interval): the buffers' size."""
        return min(self.plans, key=lambda plan: plan.output_interval)


@dataclass
class Chunk:
    first: int  # index of its first run
    plan_of: np.ndarray  # [run]: its plan in Job.plans
    start_values: np.ndarray  # [run, start name]
    rows_begin: np.ndarray  # [run + 1]: the run's input rows
    input_times: np.ndarray
    input_values: np.ndarray  # [row, input]
    runs: list[dict] = field(default_factory=list)  # the run rows, for metric functions


@dataclass
class Packed:
    """One column of traces of consecutive runs as one flat array: run i's samples are
    values[offsets[i]:offsets[i + 1]], None where present[i] is False (a failed run). A chunk
    sends each trace column back so, a few arrays instead of one per run, and Parquet takes
    offsets and values as they are."""

    offsets: np.ndarray  # [run + 1], int64
    values: np.ndarray
    present: np.ndarray  # [run], bool

    def cells(self) -> list:
        """Each run's samples (a view of values) or None."""
        o, v = self.offsets, self.values
        return [v[o[i] : o[i + 1]] if p else None for i, p in enumerate(self.present.tolist())]

    @staticmethod
    def scatter(parts, n: int) -> "Packed":
        """The runs of parts [(members, Packed)] (members: each part's runs among n) in order."""
        lengths = np.zeros(n, dtype=np.int64)
        present = np.zeros(n, dtype=bool)
        for members, part in parts:
            lengths[members] = np.diff(part.offsets)
            present[members] = part.present
        offsets = np.concatenate([[0], np.cumsum(lengths)]).astype(np.int64)
        values = np.empty(int(offsets[-1]), dtype=parts[0][1].values.dtype)
        for members, part in parts:
            own = np.diff(part.offsets)
            # where each of the part's values goes: its run's new offset + its place in the run
            to = np.repeat(offsets[members] - part.offsets[:-1], own) + np.arange(own.sum())
            values[to] = part.values
        return Packed(offsets, values, present)


def _grid(runs: dict):
    import pandas as pd

    names = list(runs)
    values = []
    for name in names:
        v = runs[name]
        if isinstance(v, (str, bytes)) or not hasattr(v, "__iter__"):
            v = [v]
        values.append(list(v))
    rows = list(itertools.product(*values))
    frame = pd.DataFrame(rows, columns=names) if rows else pd.DataFrame(columns=names)
    # a column of tables (lists) keeps its cells as Python objects
    return frame


def runs_frame(runs):
    """The runs as a DataFrame, one row per run: a dict is a grid (every combination, the first
    name varying slowest), a DataFrame or a list of dicts lists the runs."""
    import pandas as pd

    if isinstance(runs, pd.DataFrame):
        return runs.reset_index(drop=True)
    if isinstance(runs, dict):
        return _grid(runs)
    if isinstance(runs, (str, Path)):
        return _csv(runs, "runs")
    if isinstance(runs, (list, tuple)) and any(isinstance(r, dict) for r in runs):
        for i, r in enumerate(runs):
            if not isinstance(r, dict):
                raise LgfValueError(
                    f"runs: run {i} is {_article(type(r).__name__)} ({r!r}), "
                    "not a dict: in a list of runs every run is a dict"
                )
        frame = pd.DataFrame(list(runs))
        # a name a run does not give keeps the common value (not NaN) in that run
        frame.attrs["absent"] = {
            str(c): np.array([c not in r for r in runs]) for c in frame.columns
        }
        return frame
    raise LgfValueError(
        "runs must be a dict (a grid of values per name), a DataFrame, a CSV file "
        f"or a list of dicts, not {type(runs).__name__}"
    )


def _run_list(indices) -> str:
    """'run 2', 'runs 1 and 3', 'runs 0, 1, 2, 3, 4 and 7 more'."""
    indices = [int(i) for i in indices]
    if len(indices) == 1:
        return f"run {indices[0]}"
    if len(indices) <= 6:
        return f"runs {', '.join(map(str, indices[:-1]))} and {indices[-1]}"
    return f"runs {', '.join(map(str, indices[:5]))} and {len(indices) - 5} more"


def _is_rows(cell) -> bool:
    return isinstance(cell, (list, tuple, np.ndarray)) and not isinstance(cell, str)


def _prepare(model: Model, frame, base, own_cycles: bool, what="runs"):
    """Checks every run column and turns the runs into the start-value matrix and input tables
    of the runner: (plans, each run's plan, start matrix, rows_begin, times, values). With
    own_cycles, a run samples at its own cycleTime (a plan per interval), else all at
    base.output_interval."""
    n = len(frame)
    scalar_columns, table_column, input_cells = {}, None, {}
    for column in frame.columns:
        name = str(column)
        cells = frame[column].tolist()
        listed = name in frame.attrs.get("absent", {})  # a list of dicts: not every run has it
        absent = frame.attrs["absent"][name] if listed else np.zeros(n, dtype=bool)
        # where an error in this column is: the runs that give the name (every run of a grid)
        where = f"{what}: {_run_list(np.flatnonzero(~absent))}: " if listed else f"{what}: "
        if name == TABLE or name in model.tables:
            table_column = [
                {} if a else table_parameters(model, c, f"{what}: table of run {i}")
                for i, (a, c) in enumerate(zip(absent, cells))
            ]
            continue
        try:
            variable = model.variable(name, "parameter or input")
            tables = [i for i, c in enumerate(cells) if _is_rows(c)]
            if tables:
                model.input(name)
        except LgfValueError as error:
            raise LgfValueError(f"{where}{error}") from None
        if tables:
            held = [(None, base.parameters.get(name, variable.start))]
            cells = [base.tables.get(name, held) if a else c for a, c in zip(absent, cells)]
            single = [i for i, c in enumerate(cells) if not _is_rows(c)]
            if single:
                i = single[0]
                verb = "gives" if len(tables) == 1 else "give"
                raise LgfValueError(
                    f"{what}: run {i}: {name} is a single value ({cells[i]!r}), "
                    f"but {_run_list(tables)} {verb} it a step table; give "
                    f"every run a step table for {name}"
                )
            input_cells[name] = cells
            continue
        try:
            model.settable(name)
        except LgfValueError as error:
            raise LgfValueError(f"{where}{error}") from None
        if name in base.tables:
            raise LgfValueError(
                f"{where}a single value for {name}, which inputs= drives with "
                f"a step table; give each run its own table for {name} instead"
            )
        cells = frame[column].to_numpy(dtype=object).copy()
        cells[absent] = base.parameters.get(name, variable.start)
        scalar_columns[name] = check_array(
            variable, cells.tolist(), lambda i, name=name: f"{what}: run {i}: "
        )
    # a run's value replaces the common one
    start_names = list(dict.fromkeys(list(base.parameters) + list(scalar_columns)))
    if table_column is not None:
        for entries in table_column:
            for key in entries:
                if key not in start_names:
                    start_names.append(key)
    input_names_all = [v for v in model.variables if v in base.tables or v in input_cells]
    intervals = np.full(n, base.output_interval)
    if own_cycles and CYCLE in scalar_columns:
        intervals = np.asarray(scalar_columns[CYCLE], dtype=np.float64)
    distinct, plan_of = np.unique(intervals, return_inverse=True)
    plans = [
        _runner.Plan.make(
            model,
            start_names,
            input_names_all,
            base.outputs,
            base.start_time,
            base.stop_time,
            float(interval),
        )
        for interval in distinct
    ]
    plan = plans[0]

    start = np.empty((n, len(plan.start_names)))
    for j, name in enumerate(plan.start_names):
        if name in scalar_columns:
            start[:, j] = scalar_columns[name]
        else:
            default = base.parameters.get(name, model.variables[name].start)
            start[:, j] = float(default)
            if table_column is not None:
                for i, entries in enumerate(table_column):
                    if name in entries:
                        start[i, j] = float(entries[name])

    # Input tables: one merge for all runs unless a run brings its own tables.
    if not input_cells:
        names, times, values = merge(model, base.tables, base.parameters, base.start_time)
        assert names == plan.input_names
        rows = len(times)
        rows_begin = np.arange(n + 1, dtype=np.int64) * rows
        all_times = np.tile(times, n)
        all_values = np.tile(values.reshape(rows, len(names)), (n, 1))
    else:
        pieces_t, pieces_v, begin = [], [], [0]
        for i in range(n):
            tables = dict(base.tables)
            for name, cells in input_cells.items():
                tables[name] = [tuple(r) for r in cells[i]]
            starts = dict(base.parameters)
            for name, column in scalar_columns.items():
                starts[name] = column[i]
            names, times, values = merge(
                model, tables, starts, base.start_time, f"{what}: run {i}: inputs"
            )
            assert names == plan.input_names
            pieces_t.append(times)
            pieces_v.append(values.reshape(len(times), len(names)))
            begin.append(begin[-1] + len(times))
        rows_begin = np.array(begin, dtype=np.int64)
        all_times = np.concatenate(pieces_t)
        all_values = np.concatenate(pieces_v)
    return plans, plan_of.astype(np.int32), start, rows_begin, all_times, all_values


def _chunk_size(n: int, threads: int, plan: _runner.Plan, max_rows: int) -> int:
    """Runs per task: every thread gets one task of a small sweep (a task costs a round trip
    through the scheduler, some ms on a loaded machine), up to four of a large one (for the
    balance between workers and the progress bar), and no task needs more than CHUNK_BYTES of
    buffers."""
    samples = plan.max_samples(max_rows)
    per_run = samples * (len(plan.output_names) + 1) * 8
    by_memory = max(1, CHUNK_BYTES // per_run)
    rounds = min(4, max(1, math.ceil(n * samples / (threads * SAMPLES_PER_TASK))))
    by_balance = max(1, math.ceil(n / (rounds * max(1, threads))))
    return int(min(by_memory, by_balance))


def _chunks(n, size, plan_of, start, rows_begin, times, values, frame, with_runs: bool):
    for first in range(0, n, size):
        last = min(n, first + size)
        b0, b1 = rows_begin[first], rows_begin[last]
        runs = frame.iloc[first:last].to_dict("records") if with_runs else []
        yield Chunk(
            first,
            plan_of[first:last],
            start[first:last],
            rows_begin[first : last + 1] - b0,
            times[b0:b1],
            values[b0:b1],
            runs,
        )


# ---- in a worker: run a chunk and reduce it to metrics ----------------------------------------


def run_chunk(job: Job, chunk: Chunk) -> dict:
    """Runs a chunk and returns its columns: metrics, ok, message (and traces). The runs of
    each plan (output interval) in the chunk run as one batch."""
    runner = _runner.runner(model_of(job.block, job.fmi_version))
    groups = np.unique(chunk.plan_of)
    if len(groups) == 1:
        plan = job.plans[groups[0]]
        batch = runner.run(
            plan, chunk.start_values, chunk.rows_begin, chunk.input_times, chunk.input_values
        )
        return summarize(job, plan, batch, chunk.runs)
    n = len(chunk.start_values)
    lengths = np.diff(chunk.rows_begin)
    columns: dict[str, object] = {}
    packed: dict[str, list] = {}
    for group in groups:
        members = np.flatnonzero(chunk.plan_of == group)
        rows = np.concatenate(
            [np.arange(chunk.rows_begin[i], chunk.rows_begin[i + 1]) for i in members]
        ).astype(np.int64)
        begin = np.concatenate([[0], np.cumsum(lengths[members])]).astype(np.int64)
        plan = job.plans[group]
        batch = runner.run(
            plan,
            chunk.start_values[members],
            begin,
            chunk.input_times[rows],
            chunk.input_values[rows],
        )
        part = summarize(job, plan, batch, [chunk.runs[i] for i in members] if chunk.runs else [])
        for key, value in part.items():
            if isinstance(value, Packed):
                packed.setdefault(key, []).append((members, value))
            elif isinstance(value, np.ndarray):
                column = columns.setdefault(key, np.empty(n, dtype=value.dtype))
                column[members] = value
            else:
                column = columns.setdefault(key, [None] * n)
                for i, x in zip(members, value):
                    column[i] = x
    for key, parts in packed.items():
        columns[key] = Packed.scatter(parts, n)
    return columns


def summarize(job: Job, plan: _runner.Plan, batch: _runner.Batch, runs: list[dict]) -> dict:
    n, S = batch.times.shape
    counts = batch.n_samples.astype(np.int64)
    ok = batch.status != _runner.RUN_FAILED
    last = np.clip(counts - 1, 0, None)
    if n and counts[0] > 0 and (counts == counts[0]).all():  # the common case: equal runs
        S = int(counts[0])
        valid, full = True, True
    else:
        full = False
        valid = np.arange(S)[None, :] < counts[:, None]
    rows = np.arange(n)
    columns: dict[str, object] = {}
    index = {name: k for k, name in enumerate(plan.output_names)}
    with np.errstate(invalid="ignore"):
        for name in job.metric_outputs:
            y = batch.samples[:, :S, index[name]]
            for metric in job.metrics:
                if metric == "final":
                    value = y[rows, last]
                elif metric in ("min", "max"):
                    # the first sample at which the output is smallest / largest (so a sample,
                    # signed zero and all; NaN if the output has one)
                    fill = np.inf if metric == "min" else -np.inf
                    masked = y if full else np.where(valid, y, fill)
                    at = (
                        (np.argmin if metric == "min" else np.argmax)(masked, axis=1)
                        if masked.shape[1]
                        else np.zeros(n, dtype=np.int64)
                    )
                    value = masked[rows, at] if masked.shape[1] else np.full(n, np.nan)
                else:
                    value = _means(batch.samples[:, :, index[name]], counts)
                columns[f"{name}.{metric}"] = np.where(ok & (counts > 0), value, np.nan)
        for name, threshold, column in job.reach:
            y = batch.samples[:, :S, index[name]]
            first = y[:, :1]
            hit = (
                np.where(
                    first < threshold,
                    y >= threshold,
                    np.where(first > threshold, y <= threshold, True),
                )
                & valid
            )
            at = np.argmax(hit, axis=1)
            found = hit[rows, at] & ok
            columns[column] = np.where(found, batch.times[rows, at], np.nan)
    messages = list(batch.messages)
    ran = ok.copy()  # the runs the FMU ran: a function that raises fails its row, not its run
    if job.functions:
        traces = [_trace(plan, batch, i) for i in range(n)]
        for column, function in job.functions.items():
            values = []
            for i, trace in enumerate(traces):
                value = np.nan
                if ran[i]:
                    trace.run = runs[i] if runs else {}
                    try:
                        value = function(trace)
                    except Exception as error:  # the run's row says what went wrong
                        ok[i] = False
                        messages[i] = (
                            f"{messages[i]}\n" if messages[i] else ""
                        ) + f"metric {column!r} raised {type(error).__name__}: {error}"
                values.append(value)
            columns[column] = values
    if job.traces:
        # each run's samples, one after the other: a failed run has none (None in the result)
        lengths = np.where(ran, counts, 0)
        keep = np.arange(batch.times.shape[1])[None, :] < lengths[:, None]
        offsets = np.concatenate([[0], np.cumsum(lengths)]).astype(np.int64)
        columns["time"] = Packed(offsets, batch.times[keep], ran.copy())
        for k, (name, kind) in enumerate(zip(plan.output_names, plan.output_kinds)):
            # the boolean index has copied already: no second copy for Real outputs
            values = batch.samples[:, :, k][keep].astype(DTYPES[kind], copy=False)
            columns[name] = Packed(offsets, values, ran.copy())
    columns["ok"] = ok
    columns["message"] = messages
    return columns


def _means(samples: np.ndarray, counts: np.ndarray) -> np.ndarray:
    """numpy.mean of each run's own samples (samples[run, sample], counts[run]), bit for bit:
    the runs of one length as one C-contiguous block, whose mean along its rows sums each row
    as numpy.mean sums that row alone (pairwise, over the row's length); a run's value so
    never depends on the lengths of the others, as a mean over padded rows would."""
    value = np.full(len(counts), np.nan)
    for count in np.unique(counts[counts > 0]):
        members = np.flatnonzero(counts == count)
        block = np.ascontiguousarray(samples[members, :count])
        value[members] = block.mean(axis=1)
    return value


def _trace(plan, batch, i) -> Trace:
    n = int(batch.n_samples[i])
    trace = Trace(time=batch.times[i, :n].copy())
    for k, (name, kind) in enumerate(zip(plan.output_names, plan.output_kinds)):
        trace[name] = batch.samples[i, :n, k].astype(DTYPES[kind])
    return trace


# ---- the sweep --------------------------------------------------------------------------------


def sweep(
    block,
    runs,
    stop_time=None,
    outputs=None,
    *,
    parameters=None,
    inputs=None,
    table=None,
    start_time=None,
    output_interval=None,
    metrics=("final", "min", "max"),
    reach=None,
    functions=None,
    traces=False,
    out=None,
    workers=None,
    scheduler=None,
    client=None,
    chunk_size=None,
    progress=True,
    fmi_version: int = 2,
):
    """Runs a block once per run and returns a DataFrame with one row per run: the run's columns,
    its metrics, `ok` and `message` (the FMU's message for a failed run, its warnings for
    another), and with traces=True the samples (`time` and each output, as arrays).

    runs        a grid {name: values} (every combination), or a DataFrame / list of dicts /
                CSV of runs; a column names a parameter or input (its start value for the
                run), an input with a step table per run ([(time, value), ...] cells), or
                `table` (a table of points per run)
    stop_time, parameters, inputs, table, start_time, output_interval, fmi_version
                as for simulate(), common to every run; without output_interval each run
                samples at its own cycleTime (a run column cycleTime, else the common one)
    outputs     the outputs recorded (default: every output)
    metrics     computed for each output from the run's own samples alone: "final", "min",
                "max", "mean" (columns "<output>.<metric>"; min and max are the first sample
                at which the output is smallest or largest, NaN if it has one; mean is
                numpy.mean of the samples as float64)
    reach       {output: threshold or [thresholds]}: the first sample time at which the output
                has reached the threshold, coming from its start value (column
                "<output>.reach(<threshold>)"); NaN if it never does
    functions   {column: f(trace)}: f gets a Trace ({"time": ..., output: ...}, .run) and
                returns the column's value for the run; f may run here or in a worker process
                (see workers), so it must be picklable and free of side effects
    out         a .parquet (or .csv) file the rows are also written to
    workers     worker processes of the LocalCluster that the sweeps of this process share
                (started by the first sweep that needs it, closed at exit or by
                lgf_fmus.sweeps.close_cluster(); another number of workers replaces it, or
                is refused with a RuntimeError while a sweep of another thread runs on it);
                0 runs everything in this process, without Dask. By default (None) the
                running shared cluster whatever its size, else one of a worker per core, and
                a sweep of less than START_STEPS steps (its runs' PLC calls and samples) runs
                in this process, since starting the cluster would cost more, as does one of
                less than WARM_STEPS once the cluster runs; the progress bar says where it
                runs. An interrupted or failed sweep cancels its tasks, and closes the shared
                cluster if one of them was still running there (unless another sweep uses it)
    scheduler   the address of a running Dask scheduler to use instead (e.g. "tcp://host:8786")
    client      a dask.distributed.Client to use instead
    chunk_size  runs per task (default: from the runs, the workers and the memory)
    progress    show a progress bar

    Every name and value is checked before the first run (LgfValueError naming the variable and
    its range). A run that the FMU refuses becomes a row with ok False and the FMU's message,
    its metrics missing (NaN; pandas' NA in the Int64 and boolean columns of Integer and
    Boolean outputs); the sweep goes on."""
    import pandas as pd

    metrics = _check_options(metrics, reach, chunk_size, workers, out)
    base = setup(
        block,
        stop_time,
        parameters,
        None,
        table=table,
        start_time=start_time,
        output_interval=output_interval,
        outputs=outputs,
        fmi_version=fmi_version,
    )
    base.tables = step_tables(inputs)
    for name in base.tables:
        base.model.input(name)
    model = base.model
    frame = runs_frame(runs)
    if len(frame) == 0:
        raise LgfValueError("runs is empty")
    for metric in metrics:
        if metric not in METRICS:
            raise LgfValueError(
                f"unknown metric {metric!r}: the metrics are {', '.join(METRICS)} "
                "(use functions= for others)"
            )
    reach_list = []
    for name, thresholds in (reach or {}).items():
        variable = model.output(name)
        if variable.name not in base.outputs:
            raise LgfValueError(f"reach names {name}, which outputs= does not record")
        many = isinstance(thresholds, (list, tuple, np.ndarray))
        for threshold in list(thresholds) if many else [thresholds]:
            if isinstance(threshold, (bool, np.bool_)) or not isinstance(
                threshold, (int, float, np.integer, np.floating)
            ):
                raise LgfValueError(f"reach[{name!r}]: the threshold {threshold!r} is not a number")
            threshold = float(threshold)
            if math.isnan(threshold):
                raise LgfValueError(f"reach[{name!r}]: the threshold must not be NaN")
            reach_list.append((name, threshold, f"{name}.reach({threshold:g})"))
    functions = dict(functions or {})
    for column, function in functions.items():
        if not callable(function):
            raise LgfValueError(f"functions[{column!r}] is not callable")

    plans, plan_of, start, rows_begin, times, values = _prepare(
        model, frame, base, output_interval is None
    )
    job = Job(
        block=str(model.path) if str(block).endswith(".fmu") else model.identifier,
        fmi_version=model.fmi_version,
        plans=plans,
        metrics=metrics,
        metric_outputs=list(base.outputs),
        reach=reach_list,
        functions=functions,
        traces=bool(traces),
    )
    n = len(frame)
    max_rows = int(np.max(np.diff(rows_begin)))

    from tqdm.auto import tqdm

    here = client is None and scheduler is None and workers == 0
    where = "in this process"
    if client is None and scheduler is None and workers is None:
        # the shared cluster's cost: its start, or once it runs a round trip through it
        with _shared_lock:  # read once: another thread may close it
            warm = _shared is not None and _shared.running()
        if _steps(model, job, plan_of, start) < (WARM_STEPS if warm else START_STEPS):
            here = True
            cost = "a round trip through the Dask cluster" if warm else "starting a Dask cluster"
            where = f"in this process ({_runs(n)}: less work than {cost})"
    bar = tqdm(
        total=n,
        unit="run",
        desc=f"{model.identifier} {where}" if here else model.identifier,
        disable=not progress,
        leave=False,
    )

    def chunks(threads):
        """The runs in chunks of chunk_size, else of the size that suits the threads."""
        size = chunk_size or _chunk_size(n, threads, job.plan, max_rows)
        return _chunks(n, size, plan_of, start, rows_begin, times, values, frame, bool(functions))

    try:
        if here:
            results = []
            for chunk in chunks(1):
                results.append((chunk.first, run_chunk(job, chunk)))
                bar.update(len(chunk.start_values))
        else:
            results = _on_dask(job, chunks, workers, scheduler, client, bar)
    finally:
        bar.close()
    results.sort(key=lambda r: r[0])
    result = frame.copy()
    result.attrs = {}
    result.insert(0, "run", np.arange(n))
    for key in results[0][1]:
        parts = [r[1][key] for r in results]
        if isinstance(parts[0], Packed):  # views of each chunk's array: no copy of the traces
            result[key] = pd.Series([x for p in parts for x in p.cells()], dtype=object)
        elif isinstance(parts[0], np.ndarray):
            result[key] = np.concatenate(parts)
        else:
            result[key] = pd.Series([x for p in parts for x in p], dtype=object)
    _typed(result, job.plan, job)
    if out is not None:
        write(result, out)
    return result


def _runs(n: int) -> str:
    return f"{n} run" if n == 1 else f"{n} runs"


def _steps(model: Model, job: Job, plan_of: np.ndarray, start: np.ndarray) -> float:
    """A sweep's work as the runner's steps: each run's PLC calls (duration / its cycleTime) and
    samples (duration / its output interval). Metric functions, which run in Python, are not
    counted."""
    duration = job.plan.stop_time - job.plan.start_time
    intervals = np.array([plan.output_interval for plan in job.plans])[plan_of]
    if CYCLE in job.plan.start_names:
        cycles = start[:, job.plan.start_names.index(CYCLE)]
    else:
        cycles = np.full(len(start), model.cycle_time({}) or np.inf)
    return float(np.sum(duration / cycles) + np.sum(duration / intervals))


def _whole(value) -> bool:
    return isinstance(value, (int, np.integer)) and not isinstance(value, (bool, np.bool_))


def _names(value, what: str) -> list[str]:
    """A name or an iterable of names as a list, or LgfValueError."""
    if isinstance(value, str):
        return [value]
    try:
        names = list(value) if not isinstance(value, dict) else None
    except TypeError:
        names = None
    if names is None or not all(isinstance(name, str) for name in names):
        raise LgfValueError(
            f"{what} must be {_article(what[:-1])}'s name or a list of them, not {value!r}"
        )
    return names


def _check_options(metrics, reach, chunk_size, workers, out) -> tuple:
    """The options of sweep() that no modelDescription checks, before anything starts; the
    metrics as a tuple."""
    metrics = tuple(_names(metrics, "metrics")) if metrics is not None else ()
    if reach is not None and not isinstance(reach, dict):
        raise LgfValueError(
            f"reach must be a dict {{output: threshold or [thresholds]}}, not {reach!r}"
        )
    if chunk_size is not None and not (_whole(chunk_size) and chunk_size > 0):
        raise LgfValueError(f"chunk_size must be a whole number of runs > 0, not {chunk_size!r}")
    if workers is not None and not (_whole(workers) and workers >= 0):
        raise LgfValueError(f"workers must be a whole number >= 0 (0: no Dask), not {workers!r}")
    if out is not None and not isinstance(out, (str, os.PathLike)):
        raise LgfValueError(f"out must be the name of a .parquet or .csv file, not {out!r}")
    return metrics


def _typed(result, plan, job):
    """Metrics of Integer and Boolean outputs in their own dtype (nullable where a run failed)."""
    kinds = dict(zip(plan.output_names, plan.output_kinds))
    for name in job.metric_outputs:
        if kinds[name] == "Real":
            continue
        for metric in job.metrics:
            if metric == "mean":
                continue
            column = f"{name}.{metric}"
            result[column] = result[column].astype(
                "Int64" if kinds[name] == "Integer" else "boolean"
            )
    result["ok"] = result["ok"].astype(bool)
    result["message"] = result["message"].astype(str)


def write(result, out):
    """The rows to a .csv file, or to Parquet (any other name)."""
    out = Path(out)
    out.parent.mkdir(parents=True, exist_ok=True)
    if out.suffix.lower() == ".csv":
        frame = result.copy()
        for column in frame.columns:
            if frame[column].dtype == object:
                frame[column] = [_plain(x) for x in frame[column]]
        frame.to_csv(out, index=False)
    else:
        _write_parquet(result, out)


def _write_parquet(result, out: Path):
    """A column of arrays (the traces) becomes an Arrow list column built from offsets and the
    runs' samples concatenated, a row group at a time (GROUP_VALUES values at most per column):
    no Python list of samples, and memory for one row group of traces beyond the result. The
    other columns go through pandas' own conversion (their dtypes come back from the file)."""
    import pyarrow as pa
    import pyarrow.parquet as pq

    lists = {}
    for column in result.columns:
        if result[column].dtype == object:
            dtype = _array_cells(result[column])
            if dtype is not None:
                lists[column] = dtype
    rest = result.drop(columns=list(lists))
    for column in rest.columns:
        if rest[column].dtype == object:
            rest[column] = [_plain(x) for x in rest[column]]
    scalars = pa.Table.from_pandas(rest, preserve_index=False)
    fields = {f.name: f for f in scalars.schema}
    for column, dtype in lists.items():
        fields[column] = pa.field(column, pa.list_(pa.from_numpy_dtype(dtype)))
    schema = pa.schema([fields[str(c)] for c in result.columns], metadata=scalars.schema.metadata)
    n = len(result)
    longest = max(
        [1] + [max((len(x) for x in result[c] if x is not None), default=0) for c in lists]
    )
    rows = max(1, GROUP_VALUES // longest) if lists else max(1, n)
    # dictionary encoding of the traces' floats costs as much again as the rest of the writing
    # and saves little: kept for the other columns only
    scalar_names = [str(c) for c in rest.columns]
    with pq.ParquetWriter(out, schema, use_dictionary=scalar_names) as writer:
        for first in range(0, n, rows):
            last = min(n, first + rows)
            arrays = []
            for column in result.columns:
                if column in lists:
                    cells = result[column].iloc[first:last].tolist()
                    arrays.append(_list_array(cells, lists[column], schema.field(str(column))))
                else:
                    arrays.append(scalars.column(str(column)).slice(first, last - first))
            writer.write_table(pa.Table.from_arrays(arrays, schema=schema))


def _array_cells(cells):
    """The dtype of a column whose cells are 1-D numeric or bool arrays of one dtype, or None
    (a run without samples); None if it is no such column."""
    dtype = None
    for x in cells:
        if x is None:
            continue
        if not (isinstance(x, np.ndarray) and x.ndim == 1 and x.dtype.kind in "biuf"):
            return None
        if dtype is None:
            dtype = x.dtype
        elif x.dtype != dtype:
            return None
    return dtype


def _list_array(cells, dtype, field):
    import pyarrow as pa

    present = np.array([x is not None for x in cells], dtype=bool)
    lengths = np.array([len(x) if x is not None else 0 for x in cells], dtype=np.int64)
    offsets = np.concatenate([[0], np.cumsum(lengths)]).astype(np.int32)
    given = [x for x in cells if x is not None]
    values = np.concatenate(given) if given else np.empty(0, dtype=dtype)
    return pa.ListArray.from_arrays(
        pa.array(offsets),
        pa.array(values),
        type=field.type,
        mask=None if present.all() else pa.array(~present),
    )


def _plain(x):
    if isinstance(x, np.ndarray):
        return x.tolist()
    if isinstance(x, (list, tuple)):
        return [_plain(e) for e in x]
    return x


def _on_dask(job, chunks, workers, scheduler, client, bar):
    """The results of the runs, (first run, columns) per chunk, run on a Dask cluster: the
    caller's client, a client of `scheduler`, else the shared cluster; chunks(threads) cuts the
    runs for that many worker threads."""
    from dask.distributed import Client, as_completed

    own_client = shared = None
    submitted = []
    try:
        if client is None:
            if scheduler is not None:
                try:
                    client = own_client = Client(scheduler)
                except (ValueError, OSError) as error:  # an address it cannot read or reach
                    raise LgfValueError(
                        f"cannot connect to the scheduler {scheduler!r}: {error}"
                    ) from None
            else:
                shared = _use_shared(workers)
                client = shared.client
        threads = _threads(client)
        if not bar.disable:
            plural = "s" if threads != 1 else ""
            bar.set_description(f"{bar.desc} on Dask ({threads} worker thread{plural})")
        cut = list(chunks(threads))
        # one message to the scheduler for all the tasks
        submitted = client.map(run_chunk, [job] * len(cut), cut, pure=False)
        futures = {f: (c.first, len(c.start_values)) for f, c in zip(submitted, cut)}
        # each chunk's result is fetched as soon as its task ends (a failed task raises here),
        # while the workers run the others: the transfers of the traces overlap the work
        # instead of following it. The shared cluster's client fetches them from the workers
        # directly (_use_shared), not through the scheduler, which in a LocalCluster runs in
        # this process and would hold a second, serialized copy of every result.
        results = []
        for future, result in as_completed(futures, loop=client.loop, with_results=True):
            results.append((futures[future][0], result))
            bar.update(futures[future][1])
            future.release()  # the worker may drop its copy
        return results
    except BaseException:
        # an interrupt (KeyboardInterrupt included) or a failed task: none of the sweep's tasks
        # may go on on a cluster that outlives the sweep (a kept traceback keeps the futures)
        _stop(client, submitted, shared)
        raise
    finally:
        if shared is not None:
            _release(shared)
        if own_client is not None:
            own_client.close()


def _stop(client, submitted, shared):
    """Cancels the sweep's tasks. Cancelling cannot stop a chunk that a worker already runs (in
    native code): the shared cluster, if this sweep alone uses it, is then closed (the next
    sweep starts another); a cluster of another sweep or of the caller keeps it to its end."""
    unfinished = [f for f in submitted if not f.done()]
    if not unfinished:
        return
    try:
        client.cancel(unfinished, force=True)
    except Exception:  # a client already closed or lost: its tasks are gone with it
        pass
    if shared is not None:
        with _shared_lock:
            if shared.users == 1:
                _close(shared)


@dataclass
class _Shared:
    """The LocalCluster of this process's sweeps and the sweeps running on it (users)."""

    workers: int
    cluster: object
    client: object
    users: int = 0

    def running(self) -> bool:
        return self.client.status == "running"


_shared: _Shared | None = None
_shared_lock = threading.RLock()
_atexit_registered = False


def _use_shared(workers: int | None) -> _Shared:
    """The LocalCluster that the sweeps of this process share, counted as used by the caller
    until _release: started by the first sweep that needs it (workers, or one per core), kept
    for the next ones (its start costs seconds, a sweep on it some ms), closed at exit or by
    close_cluster(). A sweep without workers uses it whatever its size; one that asks for
    another number replaces it, or is refused while another sweep runs on it."""
    global _shared, _atexit_registered
    from dask.distributed import Client, LocalCluster

    with _shared_lock:
        shared = _shared
        if shared is not None and shared.running() and workers in (None, shared.workers):
            shared.users += 1
            return shared
        if shared is not None:
            if shared.running() and shared.users:
                raise RuntimeError(
                    f"sweep(workers={workers}): {_in_use(shared)}; give workers=None or "
                    f"workers={shared.workers} to share it, or client= for a cluster of its own"
                )
            _close(shared)
        count = workers or default_workers()
        cluster = LocalCluster(
            n_workers=count,
            threads_per_worker=1,
            processes=True,
            host="127.0.0.1",
            dashboard_address="127.0.0.1:0",
            silence_logs=logging.ERROR,
        )
        try:
            # not the default client: the caller's own Dask code keeps its scheduler; results
            # come from the workers directly (see _on_dask)
            client = Client(cluster, set_as_default=False, direct_to_workers=True)
        except BaseException:
            cluster.close()
            raise
        _shared = _Shared(count, cluster, client, users=1)
        if not _atexit_registered:
            # registered after distributed's own exit handler, so it runs before that one
            atexit.register(_close_at_exit)
            _atexit_registered = True
        return _shared


def _release(shared: _Shared):
    with _shared_lock:
        shared.users -= 1


def _in_use(shared: _Shared) -> str:
    sweeps = "1 sweep runs" if shared.users == 1 else f"{shared.users} sweeps run"
    plural = "s" if shared.workers != 1 else ""
    return f"{sweeps} on the shared Dask cluster of {shared.workers} worker{plural}"


def _close(shared: _Shared):
    """Closes the cluster (the caller holds _shared_lock)."""
    global _shared
    if _shared is shared:
        _shared = None
    shared.client.close()
    shared.cluster.close()


def close_cluster():
    """Closes the LocalCluster that the sweeps of this process share, if one runs (the next
    sweep that needs one starts it again). While a sweep (in another thread) runs on it, it is
    refused with a RuntimeError instead: close it once that sweep has ended."""
    with _shared_lock:
        if _shared is not None:
            if _shared.users:
                raise RuntimeError(f"close_cluster(): {_in_use(_shared)}; close it when it ends")
            _close(_shared)


def _close_at_exit():
    with _shared_lock:
        if _shared is not None:
            _close(_shared)


def _threads(client) -> int:
    """The worker threads of the cluster: from the cluster object's own record where the client
    has one (a LocalCluster, dask-jobqueue), which saves a round trip to the scheduler."""
    cluster = getattr(client, "cluster", None)
    workers = getattr(cluster, "scheduler_info", {}).get("workers") if cluster is not None else None
    if workers:
        return max(1, sum(int(w.get("nthreads", 1)) for w in workers.values()))
    return max(1, sum(client.nthreads().values()))


def default_workers() -> int:
    """One worker process per core this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1
