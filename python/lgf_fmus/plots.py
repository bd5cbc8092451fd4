"""The one plotting style of lgf-fmus: `python -m lgf_fmus simulate ... --plot run.png` draws
with it, and so do the repository's demo pictures and each FMU's documentation (tools/plots.py),
so that an engineer reads them the same way everywhere:

- a panel of outputs, then a panel of the inputs the run changes, one lane per signal, on one
  time axis; inputs (and parameters) held from the start are listed under the title;
- every signal drawn as steps (held from each sample to the next, as the PLC holds it);
  Booleans as FALSE/TRUE traces;
- status codes (an Integer whose description starts with "WORD" or "DWORD", or one named
  ...status) as evenly spaced levels labelled 16#xxxx, so that 16#7000, 16#7001 and 16#7002
  never lie on top of each other;
- units on the axes ("remainTime [s]", "periode [ms]", "time [s]"); FMI gives an Integer no
  unit attribute, so an Integer's unit is the one its description names ("UDINT: period of the
  signal in ms");
- a Boolean or a status code that holds for a single sample (a one-call event such as status
  16#7001, or a one-step pulse of an input) is ringed, so that it stays visible on a long run.

The variables are FMPy's ModelVariables or lgf_fmus.model(...).variables: anything with name,
type ("Real", "Integer", "Boolean"), causality, start, unit and description. This module needs
only numpy and matplotlib (the Agg backend: files only) and imports nothing else of the package,
so that the repository's build can load it from its file without the package installed.
"""

from __future__ import annotations

import re
import textwrap

import numpy as np

OUTPUT_COLOUR = "tab:blue"
INPUT_COLOUR = "tab:orange"
EVENT_COLOUR = "tab:red"
MARK_COLOUR = "black"

# The units an Integer's description may name ("... in ms"): those of the FMUs' UnitDefinitions.
DESCRIBED_UNITS = ("ms", "s", "1/s")


def pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def is_status(variable) -> bool:
    """A WORD/DWORD status code (docs/behaviour.md §1.4): shown in hex, as levels."""
    if variable.type != "Integer":
        return False
    described = re.match(r"D?WORD\b", variable.description or "")
    return bool(described) or variable.name.lower().endswith("status")


def unit(variable) -> str | None:
    """The variable's unit: its unit attribute, or for an Integer (FMI 2.0 and 3.0 give integers
    no unit attribute) the unit its description names, e.g. "period of the signal in ms"."""
    if getattr(variable, "unit", None):
        return variable.unit
    if variable.type == "Integer":
        named = re.search(
            r"\bin (" + "|".join(map(re.escape, DESCRIBED_UNITS)) + r")(?![\w/])",
            variable.description or "",
        )
        if named:
            return named[1]
    return None


def label(variable) -> str:
    return variable.name + (f" [{unit(variable)}]" if unit(variable) else "")


def typed(variable, value):
    """A start value or a table's value (text, number or Boolean) as the variable's type."""
    if variable.type == "Boolean":
        if isinstance(value, str):
            return value.strip().lower() in ("true", "1")
        return bool(value)
    return int(float(value)) if variable.type == "Integer" else float(value)


def shown_value(variable, value) -> str:
    if variable is None:
        return f"{value}"
    value = typed(variable, value)
    if variable.type == "Boolean":
        return "TRUE" if value else "FALSE"
    if is_status(variable):
        return f"16#{value:04X}"
    return f"{value:g}" + (f" {unit(variable)}" if unit(variable) else "")


def shown_outputs(names, variables: dict, result) -> list:
    """The outputs worth a lane, of `names`: all but subFunctionStatus (always 0 in these FMUs),
    an `error` that never became TRUE and a `status` that stayed 16#0000: a run without an error
    would draw them as flat lines that say nothing."""
    return [
        variables[n]
        for n in names
        if n != "subFunctionStatus"
        and not (n in ("error", "status") and not np.asarray(result[n]).any())
    ]


def input_histories(tables: dict, variables: dict, start: float, stop: float, starts=None):
    """(changing, held) of the inputs that step tables {name: [(time, value), ...]} drive (a time
    None: from the start): those that change during the run as {variable: (times, values)}, each
    value held until the next time, the last until `stop`; and those that keep one value from the
    start as {variable: value} (only if it is not the start value). Before its first row an input
    keeps its start value: `starts`' (e.g. the run's parameters) or the modelDescription's. Rows
    at or after `stop` are left out."""
    starts = starts or {}
    changing, held = {}, {}
    for name, rows in tables.items():
        variable = variables[name]
        before = typed(variable, starts.get(name, variable.start))
        points = {}  # time -> value; of two rows at one time the later holds
        for time, value in rows:
            if time is not None and float(time) >= stop:  # never applied during the run
                continue
            points[start if time is None else max(float(time), start)] = typed(variable, value)
        times, values = [start], [before]
        for time in sorted(points):
            if time == start:
                values[0] = points[time]
            elif points[time] != values[-1]:  # a row that repeats the value changes nothing
                times.append(time)
                values.append(points[time])
        if len(times) == 1:
            if values[0] != before:
                held[variable] = values[0]
            continue
        changing[variable] = (times + [stop], values + values[-1:])
    return changing, held


def parameter_settings(parameters: dict, variables: dict) -> list[str]:
    """Start values as text; the members of a structured array (`setpoints[i].outputValue`,
    `setpoints[i].time`) as one list of tuples, in index order."""
    texts, arrays = [], {}
    for name, value in parameters.items():
        match = re.fullmatch(r"(\w+)\[(\d+)\]\.(\w+)", name)
        text = shown_value(variables.get(name), value)
        if match:
            arrays.setdefault(match[1], {}).setdefault(int(match[2]), []).append(text)
        else:
            texts.append(f"{name} = {text}")
    for array, entries in arrays.items():
        texts.append(
            f"{array} = " + ", ".join(f"({', '.join(entries[i])})" for i in sorted(entries))
        )
    return texts


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


def drawable(y, margin: float = 0.15):
    """(values, y-limits or None) to draw a Real signal with. Values beyond ±1e300
    (StoreMinMax's clearing values ±LREAL max), infinities and NaN would make the axis
    infinite: then the scale is that of the other values, with `margin` of their span, and
    those values are drawn past the axis' edge."""
    level = np.asarray(y, dtype=float)
    finite = level[np.isfinite(level) & (np.abs(level) <= 1e300)]
    if len(finite) == len(level):
        return level, None
    lo, hi = (finite.min(), finite.max()) if len(finite) else (-1.0, 1.0)
    pad = margin * (hi - lo) or max(1.0, margin * abs(hi))
    level = np.clip(np.nan_to_num(level, nan=hi), lo - 10 * pad, hi + 10 * pad)
    return level, (lo - pad, hi + pad)


def lane(ax, variable, t, y, colour, marks=None, step=None):
    """One signal in its own lane, held from each sample to the next: an output sampled at
    every communication point, or (step: the communication step) an input given by its
    changes. marks: [(times, values, legend text)], drawn as diamonds."""
    y = np.asarray(y)
    if variable.type == "Boolean":
        level = y.astype(float)
        ax.step(t, level, where="post", color=colour, linewidth=1.6)
        ax.fill_between(t, 0, level, step="post", color=colour, alpha=0.15, linewidth=0)
        ax.set_yticks([0, 1])
        ax.set_yticklabels(["FALSE", "TRUE"])
        ax.set_ylim(-0.3, 1.3)
    elif is_status(variable):
        codes = sorted({int(v) for v in y})
        level = np.array([codes.index(int(v)) for v in y], dtype=float)
        ax.step(t, level, where="post", color=colour, linewidth=1.6)
        ax.set_yticks(range(len(codes)))
        ax.set_yticklabels([f"16#{c:04X}" for c in codes])
        ax.set_ylim(-0.5, len(codes) - 0.5)
    else:
        level, limits = drawable(y)
        ax.step(t, level, where="post", color=colour, linewidth=1.6)
        if variable.type == "Integer":
            from matplotlib.ticker import MaxNLocator

            ax.yaxis.set_major_locator(MaxNLocator(nbins=4, integer=True))
        else:
            ax.locator_params(axis="y", nbins=4)
        if limits:
            ax.set_ylim(*limits)
        else:
            ax.margins(y=0.15)
    handles = []
    if variable.type == "Boolean" or is_status(variable):  # states and codes, not a staircase
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
    if handles:  # right of the lane, never on the signal
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


def run_figure(
    time,
    outputs,
    inputs=(),
    *,
    step: float,
    span: tuple[float, float],
    lines=(),
    width: float = 10.0,
    small_title: bool = False,
):
    """A run's figure: a lane per output, outputs = [(variable, samples at `time`, marks)], then
    a lane per changing input, inputs = [(variable, times, values held until the next time)];
    `step` the communication step, `span` the time axis, `lines` the text above (the title,
    the values held from the start). Each lane's axes carry the variable's name as their label
    (`ax.get_label()`)."""
    plt = pyplot()
    lanes = [(v, OUTPUT_COLOUR) for v, _, _ in outputs] + [(v, INPUT_COLOUR) for v, _, _ in inputs]
    ratios = [0.55 if v.type == "Boolean" else 1.0 for v, _ in lanes]
    body = 1.05 * sum(ratios) + 0.45  # the lanes and the time axis
    fig, axes = plt.subplots(
        len(lanes),
        1,
        sharex=True,
        squeeze=False,
        figsize=(width, body + 0.35),
        gridspec_kw={"height_ratios": ratios},
    )
    for ax, (variable, samples, marks) in zip(axes[:, 0], outputs):
        ax.set_label(variable.name)
        lane(ax, variable, time, samples, OUTPUT_COLOUR, marks)
    for ax, (variable, times, values) in zip(axes[len(outputs) :, 0], inputs):
        ax.set_label(variable.name)
        lane(ax, variable, times, values, INPUT_COLOUR, step=step)
    if outputs:
        axes[0, 0].set_title("outputs", loc="left", fontsize="small", color=OUTPUT_COLOUR)
    if inputs:
        axes[len(outputs), 0].set_title("inputs", loc="left", fontsize="small", color=INPUT_COLOUR)
    axes[-1, 0].set_xlabel("time [s]")
    axes[-1, 0].set_xlim(*span)
    if lines:
        title = fig.suptitle("\n".join(lines), fontsize="small" if small_title else "medium")
        fit_title(fig)
        fig.set_figheight(body + 0.35 + 0.2 * (title.get_text().count("\n") + 1))
    fig.tight_layout()
    return fig


def fit_title(fig, margin: float = 0.02):
    """Wraps the figure's suptitle at word boundaries until each line fits within the figure's
    width less `margin` on each side (a long list of held values is otherwise cut off at both
    edges); measured with the renderer, so any font and size fits."""
    title = fig._suptitle
    if title is None:
        return
    # a number keeps its unit on its line ("1700 ms", "30 %"): a no-break space, which
    # textwrap does not break at
    text = re.sub(r"(\d) (?=(?:ms|s|%|1/s)(?![\w/]))", "\\1\u00a0", title.get_text())
    paragraphs = text.split("\n")
    room = fig.bbox.width * (1 - 2 * margin)
    renderer = fig.canvas.get_renderer()
    columns = max(len(p) for p in paragraphs)
    while columns > 20:
        title.set_text(
            "\n".join(
                "\n".join(textwrap.wrap(p, columns, break_on_hyphens=False)) for p in paragraphs
            )
        )
        if title.get_window_extent(renderer).width <= room:
            break
        columns = int(columns * 0.9)
