"""The demo's pictures (demo/run_demo.py, `make demo`) and each FMU's documentation
(tools/documentation.py: its typical run and its icon), drawn in the one style of the package's
plotting module, python/lgf_fmus/plots.py, which `python -m lgf_fmus simulate --plot` uses too
(what the pictures show is described there). Here: a scenario's run in that style, with
block-specific marks, e.g. LGF_RampCI's table points (a block's scenarios.py may define
`plot_marks(result) -> {lane name: ([t...], [y...], label)}`); the overview of every block's
typical run (the README's picture and the demo's), and the families of blocks that share one
interface; the FMU's icon.

The build imports the package lgf_fmus of this tree (CMakeLists.txt puts python/ on its
PYTHONPATH). `md` is an FMPy ModelDescription (of the FMU, or read from
modelDescription/<Block>.xml).
"""

from __future__ import annotations

from pathlib import Path

from lgf_fmus import plots as style
from tools import blocks

OUTPUT_COLOUR, is_status, label = style.OUTPUT_COLOUR, style.is_status, style.label


def _variables(md) -> dict:
    return {v.name: v for v in md.modelVariables}


def shown_outputs(result, md) -> list:
    """The outputs worth a lane (style.shown_outputs), in the modelDescription's order."""
    names = [
        v.name
        for v in md.modelVariables
        if v.causality == "output" and v.name in result.dtype.names
    ]
    return style.shown_outputs(names, _variables(md), result)


def input_histories(scenario, md):
    """(changing, held) of the scenario's inputs (style.input_histories): its rows of changes
    [(time, {name: value})] as one step table per input."""
    tables: dict[str, list] = {}
    for time, changes in sorted(scenario.inputs, key=lambda row: row[0]):
        for name, value in changes.items():
            tables.setdefault(name, []).append((time, value))
    inputs = [v.name for v in md.modelVariables if v.causality == "input"]
    tables = {name: tables[name] for name in inputs if name in tables}
    return style.input_histories(tables, _variables(md), 0.0, scenario.stop_time)


def _block_marks(scenario, result) -> dict:
    try:
        hook = blocks.find(scenario.block).plot_marks
    except KeyError:
        return {}
    return hook(result) if hook else {}


def plot_run(
    scenario, result, md, path: Path, dpi: int = 90, width: float = 10.0, title: bool = True
) -> None:
    """Draws a simulated scenario into `path` (PNG): its outputs, then its changing inputs."""
    fig = figure(scenario, result, md, width, title)
    fig.savefig(path, dpi=dpi, metadata={"Software": None})
    style.pyplot().close(fig)


def figure(scenario, result, md, width: float = 10.0, title: bool = True):
    """The matplotlib figure of plot_run (style.run_figure)."""
    changing, held = input_histories(scenario, md)
    marks = _block_marks(scenario, result)
    outputs = [(v, result[v.name], marks.get(v.name)) for v in shown_outputs(result, md)]
    inputs = [(v, times, values) for v, (times, values) in changing.items()]
    lines = [scenario.title] if title else []
    settings = style.parameter_settings(scenario.parameters, _variables(md))
    settings += [f"{v.name} = {style.shown_value(v, value)}" for v, value in held.items()]
    if settings:
        lines.append("held from t = 0: " + ", ".join(settings))
    return style.run_figure(
        result["time"],
        outputs,
        inputs,
        step=scenario.output_interval,
        span=(0.0, scenario.stop_time),
        lines=lines,
        width=width,
        small_title=not title,
    )


def icon(result, output: str, path: Path) -> None:
    """A 128 x 128 picture of the block's signal: one output over a run (the FMU's model.png)."""
    plt = style.pyplot()
    fig = plt.figure(figsize=(1.28, 1.28), dpi=100)
    ax = fig.add_axes([0.08, 0.08, 0.84, 0.84])
    level, limits = style.drawable(result[output], margin=0.06)
    ax.step(result["time"], level, where="post", color=OUTPUT_COLOUR, linewidth=3)
    ax.set_xticks([])
    ax.set_yticks([])
    ax.margins(0.06)
    if limits:
        ax.set_ylim(*limits)
    for side in ("top", "right"):
        ax.spines[side].set_visible(False)
    for side in ("left", "bottom"):
        ax.spines[side].set_linewidth(1.5)
    fig.savefig(path, dpi=100, metadata={"Software": None})
    plt.close(fig)


def main_input(scenario, md):
    """The input the overview draws beside a block's output: of the inputs the scenario
    changes, the first number (a value, a frequency), else the first Boolean; None if it
    changes none."""
    changing, _ = input_histories(scenario, md)
    numbers = [v for v in changing if v.type != "Boolean"]
    shown = (numbers or list(changing))[:1]
    return (shown[0], *changing[shown[0]]) if shown else None


def overview(runs, path: Path, dpi: int = 80) -> None:
    """The README's picture and the demo's overview: for each block, its typical run (the first
    of its scenarios, as its documentation draws it): its first output, and the main input the
    run changes on an axis of its own. runs: [(scenario, result, md)]."""
    fig = overview_figure(runs)
    fig.savefig(path, dpi=dpi, metadata={"Software": None})
    style.pyplot().close(fig)


def overview_figure(runs):
    """The matplotlib figure of overview(): one panel per run, the output's axes labelled with
    the block's name, their twin (the input's) with the input's."""
    plt = style.pyplot()
    fig, axes = plt.subplots(len(runs), 1, squeeze=False, figsize=(9, 1.5 * len(runs) + 0.6))
    for ax, (scenario, result, md) in zip(axes[:, 0], runs):
        ax.set_label(scenario.block)
        variable = shown_outputs(result, md)[0]
        drawn = main_input(scenario, md)
        if drawn:  # behind the output, on its own scale at the right
            v, times, values = drawn
            twin = ax.twinx()
            twin.set_label(v.name)
            level = [float(x) for x in values]
            twin.step(times, level, where="post", color=style.INPUT_COLOUR, linewidth=1.2)
            if v.type == "Boolean":
                twin.set_yticks([0, 1])
                twin.set_yticklabels(["FALSE", "TRUE"])
                twin.set_ylim(-0.3, 1.3)
            else:
                twin.margins(y=0.15)
                twin.locator_params(axis="y", nbins=3)
            twin.set_ylabel(label(v), color=style.INPUT_COLOUR, fontsize="small")
            twin.tick_params(axis="y", colors=style.INPUT_COLOUR, labelsize="small")
            ax.set_zorder(twin.get_zorder() + 1)
            ax.patch.set_visible(False)
        level, limits = style.drawable(result[variable.name])
        ax.step(result["time"], level, where="post", color=OUTPUT_COLOUR, linewidth=1.8)
        ax.set_title(f"{scenario.block}.fmu: {scenario.name}", loc="left", fontsize="medium")
        ax.set_ylabel(label(variable), color=OUTPUT_COLOUR, fontsize="small")
        ax.set_xlim(0, scenario.stop_time)
        ax.margins(y=0.15)
        if limits:
            ax.set_ylim(*limits)
        if variable.type == "Boolean":
            ax.set_yticks([0, 1])
            ax.set_yticklabels(["FALSE", "TRUE"])
            ax.set_ylim(-0.3, 1.3)
        else:
            ax.locator_params(axis="y", nbins=3)
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel(
        "time [s]  (each block's typical run: an output in blue, an input it changes in orange)"
    )
    fig.tight_layout()
    return fig


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
    """docs/families.png: the blocks that share one interface (e.g. the signal
    generators), their first output over the default experiment on one time axis per family.
    runs: [(block, result, md)]."""
    fig = families_figure(runs)
    if fig is not None:
        fig.savefig(path, dpi=dpi, metadata={"Software": None})
        style.pyplot().close(fig)


def families_figure(runs):
    """The matplotlib figure of families(), None if no two blocks share an interface."""
    groups: dict[tuple, list] = {}
    for run in runs:
        groups.setdefault(interface_of(run[2]), []).append(run)
    shown = [members for members in groups.values() if len(members) > 1]
    if not shown:
        return None
    plt = style.pyplot()
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
        # beside the axes: inside, it covered the waves, which fill the whole time axis
        ax.legend(
            loc="upper left",
            bbox_to_anchor=(1.01, 1.0),
            fontsize="small",
            frameon=False,
            borderaxespad=0.0,
        )
        ax.margins(y=0.15)
        ax.grid(True, alpha=0.3)
        ax.set_xlim(0, max(result["time"][-1] for _, result, _ in members))
    axes[-1, 0].set_xlabel("time [s]  (each FMU's default experiment, no input connected)")
    fig.tight_layout()
    return fig
