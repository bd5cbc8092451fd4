"""The one plotting module: the demo's pictures (demo/run_demo.py, `make demo`) and each FMU's
documentation (tools/documentation.py: its typical run and its icon) are drawn here, so that an
engineer reads them the same way everywhere:

- one lane per output, then one lane per input the scenario changes during the run (inputs it
  only sets once, at t = 0, are listed under the title), all on one time axis;
- Booleans as FALSE/TRUE traces; WORD status codes (an Integer whose description starts with
  "WORD") as evenly spaced levels labelled 16#xxxx, so that 16#7000, 16#7001 and 16#7002 never
  lie on top of each other;
- units on the axes ("remainTime [s]", "setChangeRate [1/s]", "time [s]");
- a Boolean or a status code that holds for a single sample (a one-call event such as status
  16#7001, or a one-step pulse of an input) is ringed, so that it stays visible on a long run;
- block-specific marks, e.g. LGF_RampCI's table points: a block's scenarios.py may define
  `plot_marks(result) -> {lane name: ([t...], [y...], label)}`.

Needs matplotlib (the Agg backend: files only) and numpy; `md` is an FMPy ModelDescription (of
the FMU, or read from modelDescription/<Block>.xml).
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from tools import blocks

OUTPUT_COLOUR = "tab:blue"
INPUT_COLOUR = "tab:orange"
EVENT_COLOUR = "tab:red"
MARK_COLOUR = "black"


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def is_word(variable) -> bool:
    """A WORD status code (docs/behaviour.md §1.4): shown in hex, as levels."""
    return variable.type == "Integer" and (variable.description or "").startswith("WORD")


def label(variable) -> str:
    return variable.name + (f" [{variable.unit}]" if variable.unit else "")


def shown_outputs(result, md) -> list:
    """The outputs worth a lane: all but subFunctionStatus (always 0 in these FMUs) and an
    `error` that never became TRUE."""
    outputs = [
        v for v in md.modelVariables if v.causality == "output" and v.name in result.dtype.names
    ]
    return [
        v
        for v in outputs
        if v.name != "subFunctionStatus" and not (v.name == "error" and not result["error"].any())
    ]


def input_histories(scenario, md):
    """(changing, held): the inputs the scenario changes during the run as {variable: (times,
    values)}, held until stop_time; and the inputs it only sets at t = 0 as {variable: value}."""
    inputs = {v.name: v for v in md.modelVariables if v.causality == "input"}
    changing, held = {}, {}
    rows = sorted(scenario.inputs, key=lambda row: row[0])
    for name in sorted({n for _, changes in rows for n in changes}, key=list(inputs).index):
        times, values = [], []
        for time, changes in rows:
            if name in changes:
                times.append(time)
                values.append(changes[name])
        if times == [0.0]:  # set once: worth a mention if it is not the start value
            if values[0] != _typed(inputs[name], inputs[name].start):
                held[inputs[name]] = values[0]
            continue
        if times[0] != 0.0:  # the start value holds until the first change
            times.insert(0, 0.0)
            values.insert(0, _typed(inputs[name], inputs[name].start))
        changing[inputs[name]] = (times + [scenario.stop_time], values + values[-1:])
    return changing, held


def _typed(variable, text):
    if variable.type == "Boolean":
        return text in ("true", "1", True)
    return int(text) if variable.type == "Integer" else float(text)


def _shown_value(variable, value) -> str:
    if variable.type == "Boolean":
        return "TRUE" if value else "FALSE"
    if is_word(variable):
        return f"16#{int(value):04X}"
    return f"{value:g}" + (f" {variable.unit}" if variable.unit else "")


def one_call_events(y) -> np.ndarray:
    """Indices of the samples of an output whose value lasts one sample: it differs from both
    neighbours' (the first sample: from the next one's)."""
    y = np.asarray(y, dtype=float)
    if len(y) < 2:
        return np.array([], dtype=int)
    before = np.concatenate(([np.nan], y[:-1]))
    after = np.concatenate((y[1:], [y[-1]]))
    return np.flatnonzero((y != before) & (y != after))


def short_pulses(times, values, step: float) -> np.ndarray:
    """Indices of the changes of an input (times, values held until the next time) that hold
    for at most one communication step before the value changes again."""
    times, values = np.asarray(times, dtype=float), np.asarray(values, dtype=float)
    if len(times) < 3:
        return np.array([], dtype=int)
    held = np.diff(times)  # segment i: from times[i] to times[i + 1]
    value = values[:-1]
    before = np.concatenate(([np.nan], values[:-2]))
    after = values[1:]
    return np.flatnonzero((held <= step * (1 + 1e-9)) & (value != before) & (value != after))


def _block_marks(scenario, result) -> dict:
    try:
        hook = blocks.find(scenario.block).plot_marks
    except KeyError:
        return {}
    return hook(result) if hook else {}


def _lane(ax, variable, t, y, colour, marks=None, step=None):
    """One signal in its own lane, held from each sample to the next: an output sampled at
    every communication point, or (step: the communication step) an input given by its
    changes."""
    y = np.asarray(y)
    if variable.type == "Boolean":
        level = y.astype(float)
        ax.step(t, level, where="post", color=colour, linewidth=1.6)
        ax.fill_between(t, 0, level, step="post", color=colour, alpha=0.15, linewidth=0)
        ax.set_yticks([0, 1])
        ax.set_yticklabels(["FALSE", "TRUE"])
        ax.set_ylim(-0.3, 1.3)
    elif is_word(variable):
        codes = sorted({int(v) for v in y})
        level = np.array([codes.index(int(v)) for v in y], dtype=float)
        ax.step(t, level, where="post", color=colour, linewidth=1.6)
        ax.set_yticks(range(len(codes)))
        ax.set_yticklabels([f"16#{c:04X}" for c in codes])
        ax.set_ylim(-0.5, len(codes) - 0.5)
    else:
        level = y.astype(float)
        ax.step(t, level, where="post", color=colour, linewidth=1.6)
        if variable.type == "Integer":
            from matplotlib.ticker import MaxNLocator

            ax.yaxis.set_major_locator(MaxNLocator(nbins=4, integer=True))
        else:
            ax.locator_params(axis="y", nbins=4)
        ax.margins(y=0.15)
    handles = []
    if variable.type == "Boolean" or is_word(variable):  # states and codes, not a staircase
        events = one_call_events(level) if step is None else short_pulses(t, level, step)
        if len(events):
            handles.append(
                ax.plot(
                    np.asarray(t)[events],
                    level[events],
                    "o",
                    markersize=7,
                    markerfacecolor="none",
                    markeredgecolor=EVENT_COLOUR,
                    markeredgewidth=1.5,
                    label="one call",
                )[0]
            )
    for times, values, text in marks or []:
        handles.append(
            ax.plot(times, values, "D", markersize=4.5, color=MARK_COLOUR, label=text)[0]
        )
    if handles:
        ax.legend(
            handles=handles,
            loc="upper left",
            bbox_to_anchor=(1.005, 1.0),
            fontsize="x-small",
            frameon=False,
            borderaxespad=0.0,
        )
    ax.set_ylabel(label(variable), rotation=0, ha="right", va="center", color=colour)
    ax.grid(True, alpha=0.3)


def plot_run(
    scenario, result, md, path: Path, dpi: int = 90, width: float = 10.0, title: bool = True
) -> None:
    """Draws a simulated scenario into `path` (PNG): its outputs, then its changing inputs."""
    fig = figure(scenario, result, md, width, title)
    fig.savefig(path, dpi=dpi, metadata={"Software": None})
    _pyplot().close(fig)


def figure(scenario, result, md, width: float = 10.0, title: bool = True):
    """The matplotlib figure of plot_run; each lane's axes carry the lane's variable name as
    their label (`ax.get_label()`)."""
    plt = _pyplot()
    outputs = shown_outputs(result, md)
    changing, held = input_histories(scenario, md)
    marks = _block_marks(scenario, result)
    lanes = [(v, OUTPUT_COLOUR) for v in outputs] + [(v, INPUT_COLOUR) for v in changing]
    ratios = [0.55 if v.type == "Boolean" else 1.0 for v, _ in lanes]
    header = 0.75 if title else 0.35
    fig, axes = plt.subplots(
        len(lanes),
        1,
        sharex=True,
        squeeze=False,
        figsize=(width, 1.05 * sum(ratios) + header + 0.45),
        gridspec_kw={"height_ratios": ratios},
    )
    t = result["time"]
    for ax, (variable, colour) in zip(axes[:, 0], lanes):
        ax.set_label(variable.name)
        if colour == OUTPUT_COLOUR:
            _lane(ax, variable, t, result[variable.name], colour, marks.get(variable.name))
        else:
            times, values = changing[variable]
            _lane(ax, variable, times, values, colour, step=scenario.output_interval)
    first_input = len(outputs)
    if changing:
        axes[first_input, 0].set_title("inputs", loc="left", fontsize="small", color=INPUT_COLOUR)
    axes[0, 0].set_title("outputs", loc="left", fontsize="small", color=OUTPUT_COLOUR)
    axes[-1, 0].set_xlabel("time [s]")
    axes[-1, 0].set_xlim(0, scenario.stop_time)
    lines = []
    if title:
        lines.append(scenario.title)
    settings = parameter_settings(scenario.parameters, md)
    settings += [f"{v.name} = {_shown_value(v, value)}" for v, value in held.items()]
    if settings:
        lines.append("held from t = 0: " + ", ".join(settings))
    if lines:
        fig.suptitle("\n".join(lines), fontsize="medium" if title else "small")
    fig.tight_layout()
    return fig


def parameter_settings(parameters: dict, md) -> list[str]:
    """The scenario's parameters as text; the members of a structured array
    (`setpoints[i].outputValue`, `setpoints[i].time`) as one list of tuples, in index order."""
    texts, arrays = [], {}
    for name, value in parameters.items():
        match = re.fullmatch(r"(\w+)\[(\d+)\]\.(\w+)", name)
        if match:
            array, index = match[1], int(match[2])
            arrays.setdefault(array, {}).setdefault(index, []).append(
                _shown_value(_variable(md, name), value)
            )
        else:
            texts.append(f"{name} = {_shown_value(_variable(md, name), value)}")
    for array, entries in arrays.items():
        texts.append(
            f"{array} = " + ", ".join(f"({', '.join(entries[i])})" for i in sorted(entries))
        )
    return texts


def _variable(md, name):
    for v in md.modelVariables:
        if v.name == name:
            return v
    return None


def icon(result, output: str, path: Path) -> None:
    """A 128 x 128 picture of the block's signal: one output over a run (the FMU's model.png)."""
    plt = _pyplot()
    fig = plt.figure(figsize=(1.28, 1.28), dpi=100)
    ax = fig.add_axes([0.08, 0.08, 0.84, 0.84])
    ax.step(
        result["time"], result[output].astype(float), where="post", color=OUTPUT_COLOUR, linewidth=3
    )
    ax.set_xticks([])
    ax.set_yticks([])
    ax.margins(0.06)
    for side in ("top", "right"):
        ax.spines[side].set_visible(False)
    for side in ("left", "bottom"):
        ax.spines[side].set_linewidth(1.5)
    fig.savefig(path, dpi=100, metadata={"Software": None})
    plt.close(fig)


def overview(runs, path: Path, dpi: int = 80) -> None:
    """The README's picture: for each FMU, its first output over its default experiment, i.e.
    dropped into a model with no input connected. runs: [(block, result, md)]."""
    plt = _pyplot()
    fig, axes = plt.subplots(len(runs), 1, squeeze=False, figsize=(9, 1.35 * len(runs) + 0.6))
    for ax, (block, result, md) in zip(axes[:, 0], runs):
        variable = shown_outputs(result, md)[0]
        ax.step(
            result["time"],
            result[variable.name].astype(float),
            where="post",
            color=OUTPUT_COLOUR,
            linewidth=1.8,
        )
        ax.set_title(f"{block}.fmu: {label(variable)}", loc="left", fontsize="medium")
        ax.set_xlim(0, result["time"][-1])
        ax.margins(y=0.15)
        ax.locator_params(axis="y", nbins=3)
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]  (each FMU's default experiment, no input connected)")
    fig.tight_layout()
    fig.savefig(path, dpi=dpi, metadata={"Software": None})
    plt.close(fig)


def interface_of(md) -> tuple:
    """What makes blocks one family: the names and types of their inputs and outputs."""
    return tuple(
        sorted(
            (v.name, v.causality, v.type)
            for v in md.modelVariables
            if v.causality in ("input", "output")
        )
    )


def families(runs, path: Path, dpi: int = 80) -> None:
    """docs/families.png: the blocks that share one interface (e.g. the five signal
    generators), their first output over the default experiment on one time axis per family.
    runs: [(block, result, md)]."""
    groups: dict[tuple, list] = {}
    for run in runs:
        groups.setdefault(interface_of(run[2]), []).append(run)
    shown = [members for members in groups.values() if len(members) > 1]
    if not shown:
        return
    plt = _pyplot()
    fig, axes = plt.subplots(len(shown), 1, squeeze=False, figsize=(9, 2.6 * len(shown) + 0.6))
    for ax, members in zip(axes[:, 0], shown):
        for block, result, md in members:
            variable = shown_outputs(result, md)[0]
            ax.step(
                result["time"],
                result[variable.name].astype(float),
                where="post",
                linewidth=1.6,
                label=block,
            )
        ax.set_ylabel(label(shown_outputs(members[0][1], members[0][2])[0]))
        ax.legend(loc="upper right", fontsize="small", ncol=min(5, len(members)))
        ax.margins(y=0.15)
        ax.grid(True, alpha=0.3)
        ax.set_xlim(0, max(result["time"][-1] for _, result, _ in members))
    axes[-1, 0].set_xlabel("time [s]  (each FMU's default experiment, no input connected)")
    fig.tight_layout()
    fig.savefig(path, dpi=dpi, metadata={"Software": None})
    plt.close(fig)
