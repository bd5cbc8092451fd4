"""The Scenario class of the demo scenarios. Each block has one or more, in
src/blocks/<Block>/scenarios.py (SCENARIOS); tools/blocks.py collects them. The build simulates
them for each FMU's documentation and compatibility information, `make demo` plots them; the
test suite compares a fresh run of each with its committed reference result
(tests/blocks/<Block>/references/<scenario>.csv) and with the independent Python model of the
block."""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


@dataclass
class Scenario:
    name: str
    block: str
    title: str
    stop_time: float
    parameters: dict = field(default_factory=dict)  # start values of parameters (and inputs)
    # Piecewise-constant inputs: (time, changes) rows; each change holds until the next one.
    # Times lie on the output grid, so FMPy's communication points are exactly that grid.
    inputs: list[tuple[float, dict]] = field(default_factory=list)
    output_interval: float = 0.1
    # Why the FMU warns in this scenario, if it does on purpose: the demo and the build print
    # its warnings as deliberate, with this reason (tools/simulate.py, Messages).
    expected_warning: str = ""

    def input_signals(self, defaults: dict):
        """The inputs as the structured array FMPy's simulate_fmu takes (discrete inputs hold
        the value of the latest row at or before t); `defaults` holds every input's start
        value, so that FMPy finds a signal for each input."""
        names = sorted(defaults)
        current, rows = dict(defaults), []
        for time, changes in sorted(self.inputs, key=lambda row: row[0]):
            current.update(changes)
            rows.append((time, current.copy()))
        rows.append((self.stop_time, current.copy()))  # FMPy needs two rows; no change here
        dtype = [("time", np.float64)] + [(n, _dtype(rows[-1][1][n])) for n in names]
        return np.array([(t, *[values[n] for n in names]) for t, values in rows], dtype=dtype)

    def cycle_time(self, model_description) -> float:
        """The cycleTime the scenario runs with: its own or the FMU's start value."""
        if "cycleTime" in self.parameters:
            return self.parameters["cycleTime"]
        [variable] = [v for v in model_description.modelVariables if v.name == "cycleTime"]
        return float(variable.start)


def input_defaults(model_description) -> dict:
    """Every input of an FMU (FMI 2.0 or 3.0) with its start value, typed."""
    boolean = lambda text: text in ("true", "1")  # noqa: E731
    convert = {
        "Real": float,
        "Float64": float,
        "Float32": float,
        "Integer": int,
        "Int16": int,
        "UInt16": int,
        "UInt32": int,
        "Int32": int,
        "Int8": int,
        "UInt8": int,
        "Boolean": boolean,
    }
    return {
        v.name: convert[v.type](v.start)
        for v in model_description.modelVariables
        if v.causality == "input"
    }


def _dtype(value):
    return (
        np.bool_ if isinstance(value, bool) else np.int32 if isinstance(value, int) else np.float64
    )
