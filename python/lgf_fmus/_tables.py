"""Inputs as step tables and a block's table of points (LGF_RampCI's setpoints), read from the
forms the API takes and checked against the modelDescription before anything runs.

Step tables: {name: [(time, value), ...]} (a scalar: that value from the start), a CSV file
with a `time` column and one column per input (Booleans 0/1 or true/false), a pandas DataFrame
of the same shape (or with its index named `time`), or FMPy's structured array. Each input
holds its value from the row's time until its next row; before its first row it keeps its start
value (from the parameters, else the modelDescription). The tables of all inputs are merged into
the one table of rows an FMPy master gets, so that a row at time t is set at communication
point t and reaches the PLC calls in (t, t + h] (docs/behaviour.md §1.3)."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ._model import LgfValueError, Model, check_value


def _frame_columns(frame, what: str) -> dict[str, list]:
    import pandas as pd

    if not isinstance(frame, pd.DataFrame):
        raise LgfValueError(f"{what}: expected a DataFrame, got {type(frame).__name__}")
    if "time" not in frame.columns:
        if frame.index.name == "time":
            frame = frame.reset_index()
        else:
            raise LgfValueError(
                f"{what} needs a 'time' column (or an index named 'time'); its "
                f"columns are {', '.join(map(str, frame.columns))}"
            )
    times = frame["time"].tolist()
    # A table is written in time order: rows that go back in time are a mistake in it, not
    # something to sort away (equal times are allowed: the last row wins).
    for row, (before, after) in enumerate(zip(times, times[1:]), start=2):
        try:
            back = float(after) < float(before)
        except (TypeError, ValueError):
            break  # a time that is no number: _rows names it
        if back:
            raise LgfValueError(
                f"{what}: the time goes back from {float(before):g} to {float(after):g} at data "
                f"row {row}; the rows must be in time order"
            )
    return {str(c): list(zip(times, frame[c].tolist())) for c in frame.columns if c != "time"}


def _csv(path, what: str):
    import pandas as pd

    path = Path(path)
    if not path.is_file():
        raise LgfValueError(f"{what}: no file {path}")
    try:
        return pd.read_csv(path, skipinitialspace=True)
    except ValueError as error:  # pandas' ParserError and EmptyDataError, a UnicodeDecodeError
        raise LgfValueError(f"{what}: {path} cannot be read as CSV: {error}") from None


def step_tables(source, what: str = "inputs") -> dict[str, list[tuple[float, object]]]:
    """Any accepted form of inputs as {name: [(time, value), ...]}."""
    import pandas as pd

    if source is None:
        return {}
    if isinstance(source, (str, Path)):
        return _frame_columns(_csv(source, what), f"{what} {source}")
    if isinstance(source, pd.DataFrame):
        return _frame_columns(source, what)
    if isinstance(source, np.ndarray) and source.dtype.names:
        names = source.dtype.names
        times = source[names[0]].tolist()
        return {n: list(zip(times, source[n].tolist())) for n in names[1:]}
    if isinstance(source, dict):
        tables = {}
        for name, rows in source.items():
            if isinstance(rows, (list, tuple)) and not isinstance(rows, str):
                tables[str(name)] = list(rows)
            elif isinstance(rows, np.ndarray) and rows.ndim == 2:
                tables[str(name)] = [tuple(r) for r in rows.tolist()]
            else:
                tables[str(name)] = [(None, rows)]  # a scalar: from the start on
        return tables
    raise LgfValueError(
        f"{what}: expected a dict of name -> [(time, value), ...], a CSV file or a "
        f"DataFrame, got {type(source).__name__}"
    )


def _rows(name: str, rows, variable, start_time: float, what: str) -> list[tuple[float, float]]:
    """One input's rows as (time, value) floats, sorted; at equal times the last row wins."""
    checked = []
    for row in rows:
        try:
            time, value = row
        except (TypeError, ValueError):
            raise LgfValueError(f"{what}[{name!r}]: a row is (time, value), not {row!r}") from None
        if time is None:
            time = start_time
        if (
            isinstance(time, bool)
            or not isinstance(time, (int, float, np.integer, np.floating))
            or not math.isfinite(float(time))
        ):
            raise LgfValueError(f"{what}[{name!r}]: the time {time!r} is not a finite number")
        where = f"{what}[{name!r}] at t = {float(time):g}: "
        checked.append((float(time), float(check_value(variable, value, where))))
    if not checked:
        raise LgfValueError(f"{what}[{name!r}] has no rows")
    checked.sort(key=lambda r: r[0])  # stable: rows at one time keep their order
    merged: dict[float, float] = {}
    for time, value in checked:
        merged[time] = value
    return sorted(merged.items())


def merge(
    model: Model, tables: dict, start_values: dict, start_time: float, what: str = "inputs"
) -> tuple[list[str], np.ndarray, np.ndarray]:
    """The step tables as one table: (input names, times, values[row, input]); every input
    holds its start value until its first row."""
    if not tables:
        return [], np.zeros(0), np.zeros((0, 0))
    columns = {}
    for name, rows in tables.items():
        variable = model.input(name)
        columns[name] = _rows(name, rows, variable, start_time, what)
    names = [n for n in model.variables if n in columns]  # modelDescription order
    times = sorted({t for rows in columns.values() for t, _ in rows})
    if times[0] > start_time:
        times.insert(0, start_time)
    values = np.empty((len(times), len(names)))
    for j, name in enumerate(names):
        variable = model.variables[name]
        current = float(
            check_value(variable, start_values.get(name, variable.start), "the start value of ")
        )
        rows, k = columns[name], 0
        for i, t in enumerate(times):
            while k < len(rows) and rows[k][0] <= t:
                current = rows[k][1]
                k += 1
            values[i, j] = current
    return names, np.array(times), values


def table_parameters(model: Model, table, what: str = "table") -> dict:
    """A table of points (LGF_RampCI: rows of (outputValue, time), a CSV with those columns or a
    DataFrame) as the start values that set it: the count parameter and every field of every
    row."""
    import pandas as pd

    if table is None:
        return {}
    if not model.tables:
        raise LgfValueError(
            f"{model.identifier} has no table of points; {what} is only for blocks that have one"
        )
    if len(model.tables) > 1:
        raise LgfValueError(
            f"{model.identifier} has several tables ({', '.join(model.tables)}); "
            f"set their entries as parameters"
        )
    [spec] = model.tables.values()
    if isinstance(table, (str, Path)):
        table = _csv(table, what)
    if not isinstance(table, (pd.DataFrame, list, tuple, np.ndarray)):
        raise LgfValueError(
            f"{what} must be rows of ({', '.join(spec.fields)}), a CSV file or "
            f"a DataFrame, not {table!r}"
        )
    if isinstance(table, pd.DataFrame):
        columns = [c for c in spec.fields if c in table.columns]
        if len(columns) != len(spec.fields):
            if table.shape[1] < len(spec.fields):
                raise LgfValueError(f"{what} needs the columns {', '.join(spec.fields)}")
            columns = list(table.columns[: len(spec.fields)])
        rows = table[columns].values.tolist()
    else:
        rows = []
        for i, r in enumerate(table):
            if not isinstance(r, (dict, list, tuple, np.ndarray)):
                raise LgfValueError(f"{what} row {i} is {r!r}: a row is ({', '.join(spec.fields)})")
            rows.append(list(r.values()) if isinstance(r, dict) else list(r))
    count = model.variables.get(spec.count) if spec.count else None
    low = int(count.min) if count is not None and count.min is not None else 1
    high = spec.size
    if count is not None and count.max is not None:
        high = min(spec.size, int(count.max))
    if not low <= len(rows) <= high:
        raise LgfValueError(
            f"{what} has {len(rows)} rows: {model.identifier} takes {low} to "
            f"{high} rows of ({', '.join(spec.fields)})"
        )
    parameters = {spec.count: len(rows)} if spec.count else {}
    for i, row in enumerate(rows):
        if len(row) != len(spec.fields):
            raise LgfValueError(f"{what} row {i} is {row!r}: a row is ({', '.join(spec.fields)})")
        for field_name, value in zip(spec.fields, row):
            name = f"{spec.name}[{i}].{field_name}"
            parameters[name] = check_value(model.variables[name], value, f"{what} row {i}: ")
    return parameters
