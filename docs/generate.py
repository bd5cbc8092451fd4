"""Writes the documentation of one FMU at build time (CMake runs it, see add_lgf_fmu):

    <out>/documentation/index.html   purpose, interface table, behaviour, status codes, a typical run
    <out>/documentation/typical_run.png
    <out>/model.png                  the FMU's icon: the shape of its typical run

    python -m docs.generate --block LGF_RampCI --interface build/interface/LGF_RampCI.json \
        --xml modelDescription/LGF_RampCI.xml --binary build/LGF_RampCI.so --out build/doc/LGF_RampCI

(from the repository's root). The interface table comes from the block's interface table (the
JSON its describe program prints); the prose is src/blocks/<Block>/doc.html (written from
docs/behaviour.md); the typical run is the block's first demo scenario
(tests/blocks/<Block>/scenarios.py), simulated with FMPy on the binary just built, so the
documentation needs no test artefact. Needs FMPy, numpy and matplotlib.
"""
from __future__ import annotations

import argparse
import html
import importlib
import json
import re
import shutil
import tempfile
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import numpy as np

from demo.run_demo import simulate

ROOT = Path(__file__).resolve().parent.parent


def read_interface(path: Path) -> dict:
    interface = json.loads(path.read_text(encoding="utf-8"))
    for v in interface["variables"]:
        v["start_text"] = start_text(v)
    return interface


def number(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    return f"{value:g}" if isinstance(value, float) else str(value)


def start_text(v: dict) -> str | None:
    """The start value; for an array the values of the used entries, then the rest if equal."""
    starts = v.get("start")
    if starts is None:
        return None
    if v["count"] == 1:
        return number(starts[0])
    shown = 1 + max((k for k, s in enumerate(starts) if s != 0), default=0)
    text = ", ".join(number(s) for s in starts[:shown])
    if shown < len(starts) and len(set(starts[shown:])) == 1:
        text += f"; from i = {shown} on: {number(starts[shown])}"
    return text


def iec_type(v: dict) -> str:
    """The PLC type behind an FMI variable (docs/behaviour.md §1.4); FMU parameters have none."""
    if v["causality"] == "parameter" and v["count"] == 1:
        return "&mdash;"
    return v["iec"]


def interface_table(variables: list[dict]) -> str:
    order = {"parameter": 0, "input": 1, "output": 2}
    rows = sorted(variables, key=lambda v: order.get(v["causality"], 3))
    out = ['<table class="interface">',
           "<tr><th>name</th><th>LGF name</th><th>causality</th><th>type (FMI / IEC)</th>"
           "<th>unit</th><th>start</th><th>range</th><th>value reference</th><th>description</th></tr>"]
    for v in rows:
        name = f"<code>{html.escape(v['name'])}{html.escape(v.get('member', ''))}</code>"
        vr = str(v["vr"])
        description = v["description"]
        if v["count"] > 1:
            name += f"<br><small>i = 0 &hellip; {v['count'] - 1}</small>"
            vr = f"{v['vr']} &hellip; {v['vr'] + v['count'] - 1}"
            description = description.replace("{i+1}", "i+1").replace("{i}", "i")
        causality = v["causality"] + (f" ({v['variability']})" if v["causality"] == "parameter" else "")
        limits = ""
        if "min" in v or "max" in v:
            limits = f"{number(v['min']) if 'min' in v else '&minus;&infin;'} &hellip; " \
                     f"{number(v['max']) if 'max' in v else '&infin;'}"
        start = html.escape(v["start_text"]) if v["start_text"] is not None else "(calculated)"
        original = html.escape(v["original"]) if "original" in v else "same"
        out.append(
            f"<tr><td>{name}</td><td>{original}</td><td>{causality}</td>"
            f"<td>{v['type']} / {iec_type(v)}</td><td>{html.escape(v['unit'])}</td><td>{start}</td>"
            f"<td>{limits}</td><td>{vr}</td><td>{html.escape(description)}</td></tr>")
    out.append("</table>")
    return "\n".join(out)


def first_scenario(block: str):
    """The typical run of the documentation: the first of the block's demo scenarios."""
    return importlib.import_module(f"tests.blocks.{block}.scenarios").SCENARIOS[0]


def simulate_built(scenario, xml: Path, binary: Path):
    """The scenario on the binary just built: packed with its modelDescription.xml into a
    temporary FMU (documentation and sources are not needed to simulate)."""
    platform = {".so": "linux64", ".dll": "win64", ".dylib": "darwin64"}[binary.suffix]
    folder = Path(tempfile.mkdtemp(prefix="lgf-doc-"))
    try:
        with zipfile.ZipFile(folder / f"{scenario.block}.fmu", "w") as fmu:
            fmu.write(xml, "modelDescription.xml")
            fmu.write(binary, f"binaries/{platform}/{scenario.block}{binary.suffix}")
        result, _, _ = simulate(scenario, folder)
        return result
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def input_histories(scenario, variables: list[dict]) -> dict[str, tuple[list, list, str]]:
    """Every input the scenario changes: (times, values, FMI type), held until stop_time."""
    by_name = {v["name"]: v for v in variables if v["causality"] == "input"}
    histories = {}
    for name in sorted({n for _, changes in scenario.inputs for n in changes}):
        times, values = [0.0], [float(by_name[name]["start"][0])]
        for time, changes in sorted(scenario.inputs, key=lambda row: row[0]):
            if name in changes:
                times.append(time)
                values.append(float(changes[name]))
        if len(set(values[1:] if times[1:2] == [0.0] else values)) > 1:
            histories[name] = (times + [scenario.stop_time], values + values[-1:], by_name[name]["type"])
    return histories


def plot_typical_run(scenario, result, variables: list[dict], path: Path) -> list[str]:
    """Outputs of the run over time (time outputs share one panel), then the inputs the
    scenario changes: numbers in one panel, Booleans stacked in another."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

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
                ax.step(t, result[name].astype(float), where="post", label=name)
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


def icon(result, output: str, path: Path):
    """A 128 x 128 picture of the block's signal: its first output over the typical run."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(1.28, 1.28), dpi=100)
    ax = fig.add_axes([0.08, 0.08, 0.84, 0.84])
    ax.step(result["time"], result[output].astype(float), where="post", color="#1f77b4", linewidth=3)
    ax.set_xticks([])
    ax.set_yticks([])
    ax.margins(0.06)
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


def write(block: str, interface_json: Path, xml: Path, binary: Path, out: Path):
    interface = read_interface(interface_json)
    variables = interface["variables"]
    root = ET.parse(xml).getroot()
    prose_file = ROOT / "src" / "blocks" / block / "doc.html"
    prose = re.sub(r"<!--.*?-->\n?", "", prose_file.read_text(encoding="utf-8"), flags=re.S)

    documentation = out / "documentation"
    documentation.mkdir(parents=True, exist_ok=True)
    scenario = first_scenario(block)
    result = simulate_built(scenario, xml, binary)
    outputs = plot_typical_run(scenario, result, variables, documentation / "typical_run.png")
    icon(result, outputs[0], out / "model.png")

    typical_run = f"""<p>{html.escape(scenario.title)}. The demo scenario <code>{scenario.name}</code>
(<code>tests/blocks/{block}/scenarios.py</code>), simulated with FMPy when the FMU was built,
communication step {scenario.output_interval:g}&nbsp;s, default <code>cycleTime</code>
0.1&nbsp;s unless set below; outputs are recorded at the end of each step. The test suite
compares every build with the committed result of this run.</p>
{scenario_table(scenario)}
<p><img class="plot" src="typical_run.png" alt="outputs of the scenario {scenario.name} over time"></p>"""

    body = (prose.replace("{{interface}}", interface_table(variables))
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
<p>{html.escape(interface["description"])}</p>
<p class="meta">FMI {root.get("fmiVersion")} co-simulation, modelIdentifier <code>{block}</code>,
GUID <code>{html.escape(interface["guid"])}</code>. Default experiment:
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
    parser.add_argument("--block", required=True, help="the modelIdentifier")
    parser.add_argument("--interface", required=True, type=Path, help="the JSON of describe_<Block> json")
    parser.add_argument("--xml", required=True, type=Path, help="modelDescription/<Block>.xml")
    parser.add_argument("--binary", required=True, type=Path, help="the FMU's library just built")
    parser.add_argument("--out", required=True, type=Path, help="folder for documentation/ and model.png")
    args = parser.parse_args()
    write(args.block, args.interface, args.xml, args.binary, args.out)


if __name__ == "__main__":
    main()
