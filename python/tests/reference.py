"""The expectations: fmpy.simulate_fmu on the bundled FMU, with an input array built here from
the step tables as their documented meaning says (every input at its start value until its
first row, a row holding from its time on), independently of lgf_fmus' own merging."""

from __future__ import annotations

import numpy as np
from fmpy import read_model_description, simulate_fmu

import lgf_fmus

_DTYPES = {"Real": np.float64, "Integer": np.int32, "Boolean": np.bool_}
_PYTHON = {"Real": float, "Integer": int, "Boolean": lambda s: s in ("true", "1", True)}


def fmpy_run(block, stop_time, parameters, steps, output_interval, outputs=None, start_time=0.0):
    """simulate_fmu with every input as a column (so FMPy warns of none), as a dict of arrays."""
    path = str(lgf_fmus.fmu_path(block))
    md = read_model_description(path)
    inputs = [v for v in md.modelVariables if v.causality == "input"]
    tunables = [v for v in md.modelVariables if v.name in steps and v.causality != "input"]
    driven = inputs + tunables
    times = sorted({start_time} | {float(t) for rows in steps.values() for t, _ in rows})
    rows = []
    for t in times:
        row = [t]
        for v in driven:
            value = parameters.get(v.name, _PYTHON[v.type](v.start))
            for time, x in sorted(steps.get(v.name, []), key=lambda r: r[0]):
                if time <= t:
                    value = x
            row.append(value)
        rows.append(tuple(row))
    rows.append((float(stop_time), *rows[-1][1:]))  # FMPy needs two rows
    dtype = [("time", np.float64)] + [(v.name, _DTYPES[v.type]) for v in driven]
    signals = np.array(rows, dtype=dtype)
    result = simulate_fmu(
        path,
        start_time=start_time,
        stop_time=stop_time,
        output_interval=output_interval,
        start_values=dict(parameters),
        input=signals,
        output=outputs,
    )
    return {name: result[name] for name in result.dtype.names}


def identical(a, b) -> bool:
    """Equal bit for bit (floats compared as their bits, so NaN equals NaN and -0.0 is not 0.0)."""
    a, b = np.ascontiguousarray(a), np.ascontiguousarray(b)
    if a.shape != b.shape or a.dtype != b.dtype:
        return False
    if a.dtype == np.float64:
        return np.array_equal(a.view(np.uint64), b.view(np.uint64))
    return np.array_equal(a, b)


def assert_same(reference: dict, frame, what=""):
    for name, expected in reference.items():
        got = frame[name].to_numpy() if hasattr(frame, "columns") else frame[name]
        assert identical(expected, got), (
            f"{what}{name} differs from fmpy.simulate_fmu: {len(expected)} vs {len(got)} samples; "
            f"first values {expected[:5]} vs {got[:5]}"
        )
