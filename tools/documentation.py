"""Writes the documentation of one block's FMUs at build time (CMake runs it, see
lgf_documentation):

    <out>/documentation/index.html        of the FMI 2.0 FMU: purpose, interface table (FMI 2.0
                                          types and ranges), behaviour, status codes, a typical run
    <out>/documentation/typical_run.png
    <out>/fmi3/documentation/index.html   the same page for the FMI 3.0 FMU (its types and ranges)
    <out>/fmi3/documentation/typical_run.png
    <out>/model.png                       the FMUs' icon: the shape of its typical run

    python -m tools.documentation --block LGF_RampCI --interface build/interface/LGF_RampCI.json \
        --interface3 build/interface/fmi3/LGF_RampCI.json \
        --xml modelDescription/LGF_RampCI.xml --binary build/LGF_RampCI.so \
        --out build/doc/LGF_RampCI

(from the repository's root). The interface table comes from the block's interface table (the
JSON its describe program prints, `json` and `json3`); the prose is src/blocks/<Block>/doc.html
(written from docs/behaviour.md); the typical run is the block's first demo scenario
(src/blocks/<Block>/scenarios.py), simulated with FMPy on the binary just built, so the
documentation needs no test artefact; the plot and the icon are drawn by tools/plots.py, as the
demo's. Needs FMPy, numpy and matplotlib.
"""

from __future__ import annotations

import base64
import html
import json
import re
import shutil
import xml.etree.ElementTree as ET
from pathlib import Path

from fmpy import read_model_description

from tools import blocks, plots, version
from tools.simulate import built_library_parser, simulate_built

ROOT = Path(__file__).resolve().parent.parent


def read_interface(path: Path) -> dict:
    interface = json.loads(path.read_text(encoding="utf-8"))
    for v in interface["variables"]:
        v["start_text"] = start_text(v)
    return interface


def number(value) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):  # the shortest text that reads back as the same number
        return str(int(value)) if value.is_integer() and abs(value) < 1e15 else repr(value)
    return str(value)


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
    out = [
        '<table class="interface">',
        "<tr><th>name</th><th>LGF name</th><th>causality</th><th>type (FMI / IEC)</th>"
        "<th>unit</th><th>start</th><th>range</th><th>value reference</th>"
        "<th>description</th></tr>",
    ]
    for v in rows:
        name = f"<code>{html.escape(v['name'])}{html.escape(v.get('member', ''))}</code>"
        vr = str(v["vr"])
        description = v["description"]
        if v["count"] > 1:
            name += f"<br><small>i = 0 &hellip; {v['count'] - 1}</small>"
            vr = f"{v['vr']} &hellip; {v['vr'] + v['count'] - 1}"
            description = description.replace("{i+1}", "i+1").replace("{i}", "i")
        causality = v["causality"] + (
            f" ({v['variability']})" if v["causality"] == "parameter" else ""
        )
        limits = ""
        if "min" in v or "max" in v:
            limits = (
                f"{number(v['min']) if 'min' in v else '&minus;&infin;'} &hellip; "
                f"{number(v['max']) if 'max' in v else '&infin;'}"
            )
        start = html.escape(v["start_text"]) if v["start_text"] is not None else "(calculated)"
        original = html.escape(v["original"]) if "original" in v else "same"
        out.append(
            f"<tr><td>{name}</td><td>{original}</td><td>{causality}</td>"
            f"<td>{v['type']} / {iec_type(v)}</td><td>{html.escape(v['unit'])}</td><td>{start}</td>"
            f"<td>{limits}</td><td>{vr}</td><td>{html.escape(description)}</td></tr>"
        )
    out.append("</table>")
    return "\n".join(out)


def first_scenario(block: str):
    """The typical run of the documentation: the first of the block's demo scenarios."""
    return blocks.find(block).scenarios[0]


def scenario_table(scenario) -> str:
    def value(v):
        return ("TRUE" if v else "FALSE") if isinstance(v, bool) else repr(v)

    rows = []
    if scenario.parameters:
        settings = ", ".join(
            f"<code>{html.escape(k)}</code> = {value(v)}" for k, v in scenario.parameters.items()
        )
        rows.append(f"<tr><td>parameters</td><td>{settings}</td></tr>")
    for time, changes in sorted(scenario.inputs, key=lambda row: row[0]):
        settings = ", ".join(
            f"<code>{html.escape(k)}</code> = {value(v)}" for k, v in changes.items()
        )
        rows.append(f"<tr><td>t = {time:g} s</td><td>{settings}</td></tr>")
    return '<table class="scenario">' + "\n".join(rows) + "</table>"


# The names of the FMI functions and types the pages speak of, in each version's own words.
FMI_NAMES = {
    2: {
        "enter": "fmi2SetupExperiment",
        "exit": "fmi2ExitInitializationMode",
        "do_step": "fmi2DoStep",
        "error": "fmi2Error",
        "int": "an fmi2Integer in &minus;32768&hellip;32767",
        "word": "an fmi2Integer 0&hellip;65535",
        "real": "an fmi2Real",
    },
    3: {
        "enter": "fmi3EnterInitializationMode",
        "exit": "fmi3ExitInitializationMode",
        "do_step": "fmi3DoStep",
        "error": "fmi3Error",
        "int": "an fmi3Int16 (&minus;32768&hellip;32767)",
        "word": "an fmi3UInt16 (0&hellip;65535)",
        "real": "an fmi3Float64",
    },
}


def call_cycle(fmi: int) -> str:
    """How the FMU calls the block, in the names of FMI <fmi>.0."""
    n = FMI_NAMES[fmi]
    return f"""<p>The FMU is called like the PLC calls the block: once every <code>cycleTime</code>
(parameter, s, default 0.1, held as whole &micro;s). The first call happens in
<code>{n["exit"]}</code> at the start time t0 with the inputs set during
initialization; call k happens at t0&nbsp;+&nbsp;k&middot;cycleTime, computed from an integer
call counter (no drift). <code>{n["do_step"]}(t, h)</code> executes every call whose time lies in
(t,&nbsp;t+h], each with the inputs set before the step (a call within 1e-4&middot;cycleTime,
plus a few ulps, of t+h counts as inside, so a master that computes t0&nbsp;+&nbsp;n&middot;h and
one that adds up its steps both keep every call). The communication step may be any size: with
inputs that change only on the call grid, the outputs are identical bit for bit whatever the step
size; a step that holds no call leaves the outputs as they were. A <code>stopTime</code> defined
in <code>{n["enter"]}</code> is enforced. Inputs are <code>discrete</code>: an importer
holds them between communication points.</p>
<p>Data types follow IEC 61131-3: INT is {n["int"]} and wraps on
overflow as on the PLC; WORD is {n["word"]}; LREAL is {n["real"]} (NaN is
refused); TIME is {n["real"]} in seconds, rounded to whole ms, &plusmn;2147483.647&nbsp;s.</p>
<p>Bad input never crashes the FMU and never changes it: a value out of range or NaN, setting an
output or a fixed parameter after initialization, an unknown value reference, a call in the wrong
state, h&nbsp;&le;&nbsp;0, a step past a defined <code>stopTime</code>, a communication point
that does not match the FMU's time, or a damaged serialized state is answered with
<code>{n["error"]}</code> and one log line naming the function, the variable and the allowed
values. The FMU can get, set and serialize its state.</p>"""


STYLE = """body { font-family: sans-serif; max-width: 75em; margin: 1em auto; padding: 0 1em; \
line-height: 1.4; }
table { border-collapse: collapse; margin: 0.5em 0 1em; }
th, td { border: 1px solid #bbb; padding: 0.2em 0.5em; vertical-align: top; text-align: left; }
th { background: #eee; }
table.interface td:nth-child(8) { white-space: nowrap; }
code { background: #f4f4f4; padding: 0 0.2em; }
img.plot { max-width: 100%; border: 1px solid #ddd; }
.meta { color: #555; font-size: 0.9em; }"""


def read_prose(path: Path) -> str:
    """A prose file without its comments (they speak to the maintainer)."""
    return re.sub(r"<!--.*?-->\n?", "", path.read_text(encoding="utf-8"), flags=re.S)


def family_prose(block: str, prose: str) -> str:
    """The prose of a block that shares its page with a family (the signal generators): the
    family's page, src/iec/<family>.html, with the block's parts, <template id="part">, in
    place of its {{part}}s. Other blocks' prose is their own."""
    parts = dict(re.findall(r'<template id="(\w+)">(.*?)</template>', prose, flags=re.S))
    if "family" not in parts:
        return prose
    page = read_prose(ROOT / "src" / "iec" / parts.pop("family"))
    for name, text in {**parts, "block": block}.items():
        page = page.replace("{{" + name + "}}", text)
    return page


def write(block: str, interfaces: dict[int, Path], xml: Path, binary: Path, out: Path):
    """The page of each FMI version in `interfaces` (2: out/documentation, 3:
    out/fmi3/documentation), from one simulation of the typical run."""
    root = ET.parse(xml).getroot()
    prose_file = ROOT / "src" / "blocks" / block / "doc.html"
    prose = family_prose(block, read_prose(prose_file))

    folders = {2: out / "documentation", 3: out / "fmi3" / "documentation"}
    for fmi in interfaces:
        folders[fmi].mkdir(parents=True, exist_ok=True)
    documentation = folders[min(interfaces)]
    scenario = first_scenario(block)
    result = simulate_built(scenario, xml, binary)
    md = read_model_description(str(xml))
    plots.plot_run(
        scenario, result, md, documentation / "typical_run.png", dpi=80, width=9.0, title=False
    )
    plots.icon(result, plots.shown_outputs(result, md)[0].name, out / "model.png")
    # Inline, as FMI 2.0 and 3.0 keep the icon in different places (model.png, terminalsAndIcons/).
    icon = base64.b64encode((out / "model.png").read_bytes()).decode("ascii")
    for fmi in interfaces:
        if folders[fmi] != documentation:
            shutil.copyfile(documentation / "typical_run.png", folders[fmi] / "typical_run.png")

    # For the user: what ran and where its data are in the FMU, no file of this repository.
    reference = ""
    if scenario is blocks.find(block).compatibility:
        reference = """ This run is also the FMU's reference experiment: its inputs and its result
are in <code>extra/org.fmi-standard.fmi-ls-ref/</code> (see <a href="fmi-ls-ref.txt">\
fmi-ls-ref.txt</a>), to replay in your own tool."""
    typical_run = f"""<p>{html.escape(scenario.title)}. The scenario <code>{scenario.name}</code>:
the settings of the table below, each held until it changes, simulated with FMPy when the FMU
was built, communication step {scenario.output_interval:g}&nbsp;s, <code>cycleTime</code>
0.1&nbsp;s unless set below; outputs are recorded at the end of each step.{reference}</p>
{scenario_table(scenario)}
<p><img class="plot" src="typical_run.png" \
alt="outputs and changing inputs of the scenario {scenario.name} over time"></p>"""
    default = root.find("DefaultExperiment")
    for fmi, interface_json in interfaces.items():
        interface = read_interface(interface_json)
        page = write_page(block, fmi, interface, prose, typical_run, icon, default)
        (folders[fmi] / "index.html").write_text(page, encoding="utf-8")


def write_page(block, fmi, interface, prose, typical_run, icon, default) -> str:
    """The page of the FMI <fmi> FMU: its interface table has that version's types and
    ranges (docs/behaviour.md §1.4, §7)."""
    variables = interface["variables"]
    other = 3 if fmi == 2 else 2
    body = (
        prose.replace("{{interface}}", interface_table(variables))
        .replace("{{call_cycle}}", call_cycle(fmi))
        .replace("{{fmi}}", f"fmi{fmi}")
        .replace("{{typical_run}}", typical_run)
    )
    leftover = re.findall(r"\{\{\w+\}\}", body)
    if leftover:
        raise SystemExit(f"src/blocks/{block}/doc.html: unknown placeholders {leftover}")
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<title>{block} &mdash; LGF block as an FMI {fmi}.0 FMU (co-simulation and Model Exchange)\
</title>
<style>
{STYLE}
</style>
</head>
<body>
<h1><img src="data:image/png;base64,{icon}" alt="" width="64" height="64" \
style="vertical-align: middle"> {block}</h1>
<p>{html.escape(interface["description"])}</p>
<p class="meta">This is the FMI {fmi}.0 FMU (co-simulation and Model Exchange in one file;
the types and ranges below are FMI {fmi}.0's); the same block is also built as an FMI \
{other}.0 FMU, with the same names, value references and behaviour. modelIdentifier \
<code>{block}</code>, GUID and instantiation token
<code>{html.escape(interface["guid"])}</code>. Default experiment:
{default.get("startTime")} &hellip; {default.get("stopTime")} s, step {default.get("stepSize")} s.
The FMU carries binaries (<code>binaries/</code>) and its C sources (<code>sources/</code>,
listed in the modelDescription's <code>SourceFiles</code>) for importers that compile it for
their own platform, and a reference experiment with its result, for a replay in your own tool or
CI (<code>extra/org.fmi-standard.fmi-ls-ref/</code>, layered standard FMI-LS-REF; see
<a href="fmi-ls-ref.txt">fmi-ls-ref.txt</a>). lgf-fmus {version()}.</p>
<p class="meta">Building from <code>sources/</code>: the floating-point contract is in the
sources (<code>core/numerics.h</code>, which the translation unit includes first): every
operation is rounded on its own, as on the S7 CPU, with no fused multiply-add whatever the
compiler's flags, so a build with any optimisation flags (<code>-O3 -march=native</code>,
<code>-mfma</code>, aarch64, Apple silicon) gives the same bits as the binaries.
<code>-ffast-math</code> (<code>-Ofast</code>) is not supported: it, its parts such as
<code>-ffinite-math-only</code>, and x87 excess precision are refused at compile time with an
error that says why (clang's <code>-ffp-contract=fast</code>, which no source can undo, is not
supported either).</p>
{body}
</body>
</html>
"""


def main():
    parser = built_library_parser(__doc__, "folder for documentation/ and model.png")
    parser.add_argument(
        "--interface", required=True, type=Path, help="the JSON of describe_<Block> json"
    )
    parser.add_argument(
        "--interface3", type=Path, help="the JSON of describe_<Block> json3: an FMI 3.0 page too"
    )
    args = parser.parse_args()
    interfaces = {2: args.interface} | ({3: args.interface3} if args.interface3 else {})
    write(args.block, interfaces, args.xml, args.binary, args.out)


if __name__ == "__main__":
    main()
