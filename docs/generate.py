"""Writes the documentation of one FMU at build time (CMake runs it, see add_lgf_fmu):

    <out>/documentation/index.html   purpose, interface table, behaviour, status codes, a typical run
    <out>/documentation/typical_run.png
    <out>/model.png                  the FMU's icon: the shape of its signal

    python docs/generate.py --xml modelDescription/LGF_RampCI.xml --out build/doc/LGF_RampCI

The interface table is read from the block's modelDescription.xml (the authoritative interface);
the prose is docs/blocks/<Block>.html (written from docs/behaviour.md); the plot is the committed
reference result (tests/references) of the block's first demo scenario (demo/scenarios.py), so it
shows what the test suite checks. Needs numpy and matplotlib only.
"""
from __future__ import annotations

import argparse
import html
import re
import sys
import xml.etree.ElementTree as ET
from collections import Counter
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "demo"))
from scenarios import SCENARIOS  # noqa: E402

# Interface names that differ from the original block (docs/behaviour.md §1.5) or do not exist on
# the PLC.
LGF_NAMES = {
    "LGF_LimRateOfChangeCI": {
        "cycleTime": "&mdash; (replaces <code>callOB</code>)",
        "subFunctionStatus": "<code>subfunctionStatus</code>",
    },
    "LGF_SawTooth": {
        "cycleTime": "&mdash; (period of the calling OB)",
        "plcTiming": "&mdash; (FMU only)",
    },
    "LGF_RampCI": {
        "cycleTime": "&mdash; (replaces <code>callOB</code>)",
        "numberOfSetpoints": "&mdash; (size of the <code>setpoints</code> array)",
        "enDefaultOutValue": "<code>enDefaulftOutValue</code>",
        "subFunctionStatus": "<code>subfunctionStatus</code>",
        "setpoints[i].outputValue": "<code>outVal</code> in the seed and older LGF versions",
    },
}

ARRAY_NAME = re.compile(r"^(\w+)\[(\d+)\]\.(\w+)$")


def read_variables(xml: Path) -> tuple[ET.Element, list[dict]]:
    root = ET.parse(xml).getroot()
    variables = []
    for sv in root.find("ModelVariables"):
        type_element = sv[0]
        variables.append({
            "name": sv.get("name"),
            "vr": sv.get("valueReference"),
            "causality": sv.get("causality", "local"),
            "variability": sv.get("variability", "continuous"),
            "description": sv.get("description", ""),
            "type": type_element.tag,
            "unit": type_element.get("unit", ""),
            "start": type_element.get("start"),
            "min": type_element.get("min"),
            "max": type_element.get("max"),
        })
    return root, variables


def iec_type(v: dict) -> str:
    """The PLC type behind an FMI variable (docs/behaviour.md §1.4)."""
    if v["causality"] == "parameter" and not v["name"].startswith("setpoints["):
        return "&mdash;"
    if v["type"] == "Boolean":
        return "BOOL"
    if v["type"] == "Integer":
        return "WORD" if v["min"] == "0" and v["max"] == "65535" else "INT"
    return "TIME" if v["unit"] == "s" else "LREAL"


def group_arrays(variables: list[dict]) -> list[dict]:
    """setpoints[0].time ... setpoints[63].time become one row setpoints[i].time."""
    rows, groups = [], {}
    table_size = next((int(v["start"]) for v in variables if v["name"] == "numberOfSetpoints"), None)
    for v in variables:
        m = ARRAY_NAME.match(v["name"])
        if not m:
            rows.append(dict(v))
            continue
        key = f"{m.group(1)}[i].{m.group(3)}"
        index = int(m.group(2))
        if key not in groups:
            groups[key] = {**v, "name": key, "elements": []}
            rows.append(groups[key])
        text = v["description"].replace(f"point {index + 1}", "point i+1").replace(f"point {index}", "point i")
        groups[key]["elements"].append((index, v["start"], text, v["vr"]))
    for row in groups.values():
        elements = sorted(row["elements"])
        row["description"] = Counter(text for _, _, text, _ in elements).most_common(1)[0][0]
        row["vr"] = f"{elements[0][3]} &hellip; {elements[-1][3]}"
        row["index_range"] = (elements[0][0], elements[-1][0])
        starts = [start for _, start, _, _ in elements]
        # The default table: the first numberOfSetpoints entries, else up to the last non-zero.
        shown = table_size or 1 + max((k for k, s in enumerate(starts) if s not in ("0", None)), default=0)
        row["start"] = ", ".join(starts[:shown])
        if shown < len(starts) and len(set(starts[shown:])) == 1:
            row["start"] += f"; from i = {shown} on: {starts[shown]}"
    return rows


def interface_table(block: str, variables: list[dict]) -> str:
    order = {"parameter": 0, "input": 1, "output": 2}
    rows = sorted(group_arrays(variables), key=lambda v: order.get(v["causality"], 3))
    lgf = LGF_NAMES.get(block, {})
    out = ['<table class="interface">',
           "<tr><th>name</th><th>LGF name</th><th>causality</th><th>type (FMI / IEC)</th>"
           "<th>unit</th><th>start</th><th>range</th><th>value reference</th><th>description</th></tr>"]
    for v in rows:
        name = f"<code>{html.escape(v['name'])}</code>"
        if "index_range" in v:
            lo, hi = v["index_range"]
            name += f"<br><small>i = {lo} &hellip; {hi}</small>"
        causality = v["causality"] + (f" ({v['variability']})" if v["causality"] == "parameter" else "")
        limits = ""
        if v["min"] is not None or v["max"] is not None:
            limits = f"{v['min'] or '&minus;&infin;'} &hellip; {v['max'] or '&infin;'}"
        start = html.escape(v["start"]) if v["start"] is not None else "(calculated)"
        out.append(
            f"<tr><td>{name}</td><td>{lgf.get(v['name'], 'same')}</td><td>{causality}</td>"
            f"<td>{v['type']} / {iec_type(v)}</td><td>{html.escape(v['unit'])}</td><td>{start}</td>"
            f"<td>{limits}</td><td>{v['vr']}</td><td>{html.escape(v['description'])}</td></tr>")
    out.append("</table>")
    return "\n".join(out)


def first_scenario(block: str):
    for scenario in SCENARIOS:
        if scenario.block == block:
            return scenario
    raise SystemExit(f"demo/scenarios.py has no scenario for {block}")


def input_histories(scenario, variables: list[dict]) -> dict[str, tuple[list, list, str]]:
    """Every input the scenario changes: (times, values, FMI type), held until stop_time."""
    by_name = {v["name"]: v for v in variables if v["causality"] == "input"}
    histories = {}
    for name in sorted({n for _, changes in scenario.inputs for n in changes}):
        start = by_name[name]["start"]
        times, values = [0.0], [float({"true": 1, "false": 0}.get(start, start) if start else 0)]
        for time, changes in sorted(scenario.inputs, key=lambda row: row[0]):
            if name in changes:
                times.append(time)
                values.append(float(changes[name]))
        if len(set(values[1:] if times[1:2] == [0.0] else values)) > 1:
            histories[name] = (times + [scenario.stop_time], values + values[-1:], by_name[name]["type"])
    return histories


def plot_typical_run(scenario, variables: list[dict], path: Path) -> list[str]:
    """Outputs of the reference result over time (time outputs share one panel), then the inputs
    the scenario changes: numbers in one panel, Booleans stacked in another."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    csv = ROOT / "tests" / "references" / f"{scenario.name}.csv"
    result = np.genfromtxt(csv, delimiter=",", names=True)
    units = {v["name"]: v["unit"] for v in variables}
    types = {v["name"]: v["type"] for v in variables}
    outputs = [n for n in result.dtype.names[1:]
               if n != "subFunctionStatus" and not (n == "error" and not result[n].any())]
    times = [n for n in outputs if units[n] == "s"]
    panels = [[n] for n in outputs if n not in times]
    if times:
        panels.insert(1, times)
    histories = input_histories(scenario, variables)
    numbers = {n: h for n, h in histories.items() if h[2] != "Boolean"}
    booleans = {n: h for n, h in histories.items() if h[2] == "Boolean"}
    rows = len(panels) + bool(numbers) + bool(booleans)
    fig, axes = plt.subplots(rows, 1, figsize=(9, 1.45 * rows + 0.8), sharex=True, squeeze=False)
    axes = list(axes[:, 0])
    t = result["time"]
    for names in panels:
        ax = axes.pop(0)
        if names == ["status"]:  # codes as evenly spaced levels, labelled in hex
            codes = sorted({int(v) for v in result["status"]})
            ax.step(t, [codes.index(int(v)) for v in result["status"]], where="post")
            ax.set_yticks(range(len(codes)))
            ax.set_yticklabels([f"16#{c:04X}" for c in codes])
            ax.set_ylim(-0.4, len(codes) - 0.6)
        else:
            for name in names:
                ax.step(t, result[name], where="post", label=name)
        if types[names[0]] == "Boolean":
            ax.set_yticks([0, 1])
            ax.set_yticklabels(["FALSE", "TRUE"])
            ax.set_ylim(-0.2, 1.2)
        if len(names) > 1:
            ax.legend(loc="upper right", fontsize="small", ncol=len(names))
            ax.set_ylabel("[s]", rotation=0, ha="right", va="center")
        else:
            ax.set_ylabel(names[0], rotation=0, ha="right", va="center")
        ax.grid(True, alpha=0.3)
    if numbers:
        ax = axes.pop(0)
        for name, (tt, yy, _) in numbers.items():
            ax.step(tt, yy, where="post", label=name, linestyle="--")
        ax.set_ylabel("inputs", rotation=0, ha="right", va="center")
        ax.legend(loc="upper right", fontsize="small", ncol=min(4, len(numbers)))
        ax.grid(True, alpha=0.3)
    if booleans:
        ax = axes.pop(0)
        for k, (name, (tt, yy, _)) in enumerate(booleans.items()):
            ax.step(tt, [1.5 * k + 0.9 * y for y in yy], where="post", linestyle="--")
        ax.set_yticks([1.5 * k + 0.45 for k in range(len(booleans))])
        ax.set_yticklabels(list(booleans))
        ax.grid(True, axis="x", alpha=0.3)
    fig.axes[-1].set_xlabel("time [s]")
    fig.tight_layout()
    fig.savefig(path, dpi=80, metadata={"Software": None})
    plt.close(fig)
    return outputs


def scenario_table(scenario) -> str:
    def value(v):
        return ("TRUE" if v else "FALSE") if isinstance(v, bool) else repr(v)
    rows = []
    if scenario.parameters:
        settings = ", ".join(f"<code>{html.escape(k)}</code> = {value(v)}" for k, v in scenario.parameters.items())
        rows.append(f"<tr><td>parameters</td><td>{settings}</td></tr>")
    for time, changes in sorted(scenario.inputs, key=lambda row: row[0]):
        settings = ", ".join(f"<code>{html.escape(k)}</code> = {value(v)}" for k, v in changes.items())
        rows.append(f"<tr><td>t = {time:g} s</td><td>{settings}</td></tr>")
    return '<table class="scenario">' + "\n".join(rows) + "</table>"


def icon(block: str, path: Path):
    """A 128 x 128 picture of the block's signal shape."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(1.28, 1.28), dpi=100)
    ax = fig.add_axes([0.08, 0.08, 0.84, 0.84])
    color = {"LGF_LimRateOfChangeCI": "#1f77b4", "LGF_SawTooth": "#d62728", "LGF_RampCI": "#2ca02c"}[block]
    if block == "LGF_LimRateOfChangeCI":  # a jump of the input (dashed) becomes a ramp
        ax.step([0, 2, 10], [1, 8, 8], where="post", color="0.55", linestyle="--", linewidth=2)
        ax.plot([0, 2, 5, 10], [1, 1, 8, 8], color=color, linewidth=3.5)
    elif block == "LGF_SawTooth":  # teeth of equal steps that fall back to the start
        t, y = [0], [1]
        for tooth in range(2):
            for step in range(4):
                t += [tooth * 5 + step + 1] * 2
                y += [y[-1], 1 + (step + 1) * 2 if step < 3 else 1]
        t.append(10)
        y.append(y[-1])
        ax.plot(t, y, color=color, linewidth=3)
    else:  # a setpoint profile through table points
        t, y = [0, 2.5, 5.5, 7, 10], [1, 8, 8, 4, 1]
        ax.plot(t, y, color=color, linewidth=3)
        ax.plot(t, y, "o", color=color, markersize=5, markeredgecolor="white")
    ax.set_xlim(-0.5, 10.5)
    ax.set_ylim(0, 9.5)
    ax.set_xticks([])
    ax.set_yticks([])
    for side in ("top", "right"):
        ax.spines[side].set_visible(False)
    for side in ("left", "bottom"):
        ax.spines[side].set_linewidth(1.5)
    fig.savefig(path, dpi=100, metadata={"Software": None})
    plt.close(fig)


CALL_CYCLE = """<p>The FMU is called like the PLC calls the block: once every <code>cycleTime</code>
(parameter, s, default 0.1, held as whole &micro;s). The first call happens in
<code>fmi2ExitInitializationMode</code> at the start time t0 with the inputs set during
initialization; call k happens at t0&nbsp;+&nbsp;k&middot;cycleTime, computed from an integer
call counter (no drift). <code>fmi2DoStep(t, h)</code> executes every call whose time lies in
(t,&nbsp;t+h], each with the inputs set before the step (a call within 1e-4&middot;cycleTime,
plus a few ulps, of t+h counts as inside, so a master that computes t0&nbsp;+&nbsp;n&middot;h and
one that adds up its steps both keep every call). The communication step may be any size: with
inputs that change only on the call grid, the outputs are identical bit for bit whatever the step
size; a step that holds no call leaves the outputs as they were. A <code>stopTime</code> defined
in <code>fmi2SetupExperiment</code> is enforced. Inputs are <code>discrete</code>: an importer
holds them between communication points.</p>
<p>Data types follow IEC 61131-3: INT is an fmi2Integer in &minus;32768&hellip;32767 and wraps on
overflow as on the PLC; WORD is an fmi2Integer 0&hellip;65535; LREAL is an fmi2Real (NaN is
refused); TIME is an fmi2Real in seconds, rounded to whole ms, &plusmn;2147483.647&nbsp;s.</p>
<p>Bad input never crashes the FMU and never changes it: a value out of range or NaN, setting an
output or a fixed parameter after initialization, an unknown value reference, a call in the wrong
state, h&nbsp;&le;&nbsp;0, a step past a defined <code>stopTime</code>, a communication point
that does not match the FMU's time, or a damaged serialized state is answered with
<code>fmi2Error</code> and one log line naming the function, the variable and the allowed
values. The FMU can get, set and serialize its state.</p>"""

STYLE = """body { font-family: sans-serif; max-width: 75em; margin: 1em auto; padding: 0 1em; line-height: 1.4; }
table { border-collapse: collapse; margin: 0.5em 0 1em; }
th, td { border: 1px solid #bbb; padding: 0.2em 0.5em; vertical-align: top; text-align: left; }
th { background: #eee; }
table.interface td:nth-child(8) { white-space: nowrap; }
code { background: #f4f4f4; padding: 0 0.2em; }
img.plot { max-width: 100%; border: 1px solid #ddd; }
.meta { color: #555; font-size: 0.9em; }"""


def write(xml: Path, out: Path):
    root, variables = read_variables(xml)
    block = root.find("CoSimulation").get("modelIdentifier")
    prose_file = ROOT / "docs" / "blocks" / f"{block}.html"
    prose = re.sub(r"<!--.*?-->\n?", "", prose_file.read_text(encoding="utf-8"), flags=re.S)

    documentation = out / "documentation"
    documentation.mkdir(parents=True, exist_ok=True)
    scenario = first_scenario(block)
    plot_typical_run(scenario, variables, documentation / "typical_run.png")
    icon(block, out / "model.png")

    typical_run = f"""<p>{html.escape(scenario.title)}. The demo scenario <code>{scenario.name}</code>
(<code>demo/scenarios.py</code>), simulated with FMPy, communication step
{scenario.output_interval:g}&nbsp;s, default <code>cycleTime</code> 0.1&nbsp;s unless set below;
outputs are recorded at the end of each step. The curves are the committed regression result
<code>tests/references/{scenario.name}.csv</code> that the test suite compares every build with.</p>
{scenario_table(scenario)}
<p><img class="plot" src="typical_run.png" alt="outputs of the scenario {scenario.name} over time"></p>"""

    body = (prose.replace("{{interface}}", interface_table(block, variables))
                 .replace("{{call_cycle}}", CALL_CYCLE)
                 .replace("{{typical_run}}", typical_run))
    leftover = re.findall(r"\{\{\w+\}\}", body)
    if leftover:
        raise SystemExit(f"{prose_file}: unknown placeholders {leftover}")
    default = root.find("DefaultExperiment")
    page = f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{block} &mdash; FMI 2.0 co-simulation FMU</title>
<style>
{STYLE}
</style>
</head>
<body>
<h1><img src="../model.png" alt="" width="64" height="64" style="vertical-align: middle"> {block}</h1>
<p>{html.escape(root.get("description", ""))}</p>
<p class="meta">FMI {root.get("fmiVersion")} co-simulation, modelIdentifier <code>{block}</code>,
GUID <code>{html.escape(root.get("guid", ""))}</code>. Default experiment:
{default.get("startTime")} &hellip; {default.get("stopTime")} s, step {default.get("stepSize")} s.
The FMU carries binaries (<code>binaries/</code>) and its C sources (<code>sources/</code>,
listed in the modelDescription's <code>SourceFiles</code>) for importers that compile it for
their own platform.</p>
{body}
</body>
</html>
"""
    (documentation / "index.html").write_text(page, encoding="utf-8")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--xml", required=True, type=Path, help="modelDescription/<Block>.xml")
    parser.add_argument("--out", required=True, type=Path, help="folder for documentation/ and model.png")
    args = parser.parse_args()
    write(args.xml, args.out)


if __name__ == "__main__":
    main()
