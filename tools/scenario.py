"""The Scenario class of the demo scenarios. Each block has one or more, in
src/blocks/<Block>/scenarios.py (SCENARIOS); tools/blocks.py collects them. The build simulates
them for each FMU's documentation and compatibility information, `make demo` plots them; the
test suite compares a fresh run of each with its committed reference result
(tests/blocks/<Block>/references/<scenario>.csv) and with the independent Python model of the
block."""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Callable

import numpy as np


@dataclass
class Scenario:
    name: str
    title: str
    stop_time: float
    # The block's modelIdentifier: left out in a block's scenarios.py, whose folder names it
    # (tools/blocks.py fills it in).
    block: str = ""
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


def signal_scenario(
    name: str, title: str, stop_time: float, periode: int, changes: list, phase_shift: float = 0.0
) -> Scenario:
    """A scenario of a signal generator (LGF_SinusCI, LGF_CosinusCI, LGF_TriangleCI,
    LGF_SawToothCI, LGF_RectangleCI: src/iec/signal_generator.h): amplitude 1 around offset 0,
    a period of `periode` ms and a phase shift of `phase_shift` ms from the start, then the
    input rows of `changes`."""
    start = {
        "amplitude": 1.0,
        "offset": 0.0,
        "periode": periode,
        "phaseShift": phase_shift,
        "reset": False,
    }
    return Scenario(name, title, stop_time, inputs=[(0.0, start), *changes])


def harmonic_scenario(block: str, wave: str) -> Scenario:
    """The typical run of LGF_SinusCI and LGF_CosinusCI, whose `wave` is a sine or a cosine."""
    return signal_scenario(
        block.removeprefix("LGF_").replace("CI", "_ci").lower(),
        f"{block}: a 2 s {wave} of amplitude 1, then amplitude 2 around offset 1, a "
        "quarter-period phase shift, a 1 s period and a reset (value 0.0)",
        10.0,
        2000,
        [
            (4.0, {"amplitude": 2.0, "offset": 1.0}),
            (5.0, {"phaseShift": 500.0}),
            (7.0, {"periode": 1000}),
            (8.5, {"reset": True}),
            (8.8, {"reset": False}),
        ],
    )


def slope_scenario(name: str, title: str) -> Scenario:
    """The typical run of LGF_TriangleCI and LGF_SawToothCI: a 1 s period, then amplitude 2
    around offset 1, a quarter-period phase shift, a 2 s period and a reset."""
    return signal_scenario(
        name,
        title,
        8.0,
        1000,
        [
            (2.0, {"amplitude": 2.0, "offset": 1.0}),
            (3.0, {"phaseShift": 250.0}),
            (4.0, {"periode": 2000}),
            (6.5, {"reset": True}),  # value = offset while reset is TRUE
            (6.8, {"reset": False}),
        ],
    )


def scattered_sine(k: int, amplitude: float, period: float, jitter: int) -> float:
    """A scattered measurement at sample k, as the demos of LGF_FloatingAverage and
    LGF_SimpleSmoothingFB give them: a sine of `period` samples with a deterministic jitter of
    up to ±jitter / 2 in steps of 0.5 (the same numbers on every run), rounded to 0.001."""
    scatter = ((k * 7919) % (2 * jitter + 1) - jitter) * 0.5
    return round(amplitude * math.sin(2.0 * math.pi * k / period) + scatter, 3)


def sampled(
    start: dict, calls: int, value: Callable[[int], float], changes: dict[float, dict]
) -> list[tuple[float, dict]]:
    """The input rows of LGF_SimpleSmoothingFB's and LGF_DifferenceQuotientFB's demos: `start` at
    0 s, then `calls` calls of 0.1 s in which insert rises in every other one with sample
    value(n), n = 0, 1, ...: a sample every 0.2 s; and the other `changes` by time."""
    rows = {0.0: dict(start)}
    for k in range(calls):
        change = rows.setdefault(round(k * 0.1, 1), {})
        change["insert"] = k % 2 == 1
        if k % 2 == 1:
            change["value"] = value(k // 2)
    for t, change in changes.items():
        rows.setdefault(t, {}).update(change)
    return sorted(rows.items())


def setpoints(fields: tuple[str, str], points) -> dict:
    """The FMI variables of a block's array of setpoints (LGF_RampCI's, docs/behaviour.md §4.1;
    LGF_NonLinearInterpolation's, §20.1): {"setpoints[i].<field>": value} of points, each a pair
    of the two fields' values, point by point (the values may also be Hypothesis strategies)."""
    entries = {}
    for i, point in enumerate(points):
        for name, value in zip(fields, point, strict=True):
            entries[f"setpoints[{i}].{name}"] = value
    return entries


def setpoint_table(fields: tuple[str, str], *points) -> dict:
    """The parameters of such a table: numberOfSetpoints, then the points."""
    return {"numberOfSetpoints": len(points), **setpoints(fields, points)}


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
