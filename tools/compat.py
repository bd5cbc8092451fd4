"""The compatibility information of an FMU: one reference experiment that any importer can
replay, in two forms that hold the same files.

- Inside the FMU, under extra/org.fmi-standard.fmi-ls-ref/ (the layered standard FMI-LS-REF,
  "References", v1.0.0-beta.1): its manifest fmi-ls-manifest.xml names every file with its role;
  <Block>.exp describes the experiment in the Experiments Format (ma-hs-experiments) that
  FMI-LS-REF refers to for experiments, with the stimuli and the reference result.
- Beside the FMU in the release zip (release/dist.py), as the FMI cross-check rules ask of an
  exporter: <Block>_in.csv (the inputs), <Block>_ref.csv (the reference result),
  <Block>_ref.opt (StartTime, StopTime, StepSize, RelTol) and <Block>_README.md.

Booleans: no CSV form is read by both importers that replay such files today. FMPy's read_csv
(fmpy.util) converts every cell with float(), so it reads 0/1 only; fmusim (the Reference FMUs'
simulator, now a project of its own, whose CSV reader is fmi-rs's) reads 0, 1, false and true
for an FMI 2.0 FMU but only false and true for FMI 3.0 (Rust's bool). So the FMI 2.0 FMU's
files write 0/1 (both read them), the FMI 3.0 FMU's false/true (what fmusim reads; every other
cell is the same as in the FMI 2.0 files), and read_csv() below, which replay() uses, reads
both forms; the FMI 3.0 readme's replay converts for FMPy as well.

The experiment is the block's compatibility scenario (the first of
src/blocks/<Block>/scenarios.py, or the one its COMPATIBILITY names), simulated with FMPy as
co-simulation, a communication step of its output interval and every parameter at its start
value. CMake runs this at build time on the library just built (as the documentation's
typical run):

    python -m tools.compat --block LGF_RampCI --xml build/interface/LGF_RampCI.xml \
        --binary build/LGF_RampCI.so --out build/ls-ref/LGF_RampCI

The reference written there is the same simulation as the committed regression reference
tests/blocks/<Block>/references/<scenario>.csv (written by `make references`, whose diff is
reviewed); the test suite and `make dist` require the two to be identical, and replay() checks
that a fresh run of the FMU from these files gives it exactly.
"""

from __future__ import annotations

import shutil
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np

from tools import blocks, version

LS_REF_NAME = "org.fmi-standard.fmi-ls-ref"
LS_REF_VERSION = "1.0.0-beta.1"
LS_REF_DESCRIPTION = "Layered Standard providing information on related files included in an FMU."
LS_MANIFEST_NAMESPACE = "http://fmi-standard.org/fmi-ls-manifest"
LS_REF_FOLDER = f"extra/{LS_REF_NAME}"
MANIFEST = "fmi-ls-manifest.xml"
EXPERIMENTS_TYPE = "application/x-ma-hs-experiments"
RELATIVE_TOLERANCE = 1e-4  # _ref.opt's RelTol: unused, the FMUs have no continuous states
# How the files of an FMI <version> FMU write a Boolean: (false, true); see the docstring
BOOLEANS = {2: ("0", "1"), 3: ("false", "true")}
FMUSIM = "[fmusim](https://github.com/modelica/fmusim)"


def files(block: str) -> dict[str, str]:
    """The file names of a block's compatibility information, by kind."""
    return {
        "inputs": f"{block}_in.csv",
        "reference": f"{block}_ref.csv",
        "options": f"{block}_ref.opt",
        "readme": f"{block}_README.md",
        "experiments": f"{block}.exp",
        "manifest": MANIFEST,
    }


def release_files(block: str) -> list[str]:
    """The files that lie beside <Block>.fmu in the release (the cross-check set)."""
    names = files(block)
    return [names[k] for k in ("inputs", "reference", "options", "readme")]


def scenario_of(block: str):
    """The block's compatibility scenario (src/blocks/<Block>/scenarios.py: the first or
    COMPATIBILITY; one without parameters, which tools/blocks.py checks)."""
    return blocks.find(block).compatibility


def options_text(scenario) -> str:
    """<Block>_ref.opt, in the FMI cross-check format FMPy's read_ref_opt_file reads."""
    return (
        f"StartTime, 0.0\nStopTime, {float(scenario.stop_time)!r}\n"
        f"StepSize, {float(scenario.output_interval)!r}\nRelTol, {RELATIVE_TOLERANCE!r}\n"
    )


def _xml(root: ET.Element) -> bytes:
    ET.indent(root, space="  ")
    return b'<?xml version="1.0" encoding="UTF-8"?>\n' + ET.tostring(root, encoding="utf-8") + b"\n"


def experiments_xml(block: str, scenario) -> bytes:
    names = files(block)
    root = ET.Element(
        "Experiments",
        name=f"{block} compatibility",
        description=f"The reference experiment of {block} (lgf-fmus {version()}): "
        "co-simulation, every parameter at its start value",
    )
    experiment = ET.SubElement(
        root,
        "Experiment",
        name=scenario.name,
        description=f"{scenario.title}. Co-simulation with a communication step of "
        f"{scenario.output_interval:g} s; outputs recorded at the end of every step",
        startTime="0.0",
        stopTime=repr(float(scenario.stop_time)),
        tolerance=repr(RELATIVE_TOLERANCE),
        stepSize=repr(float(scenario.output_interval)),
    )
    ET.SubElement(experiment, "Stimuli", source=names["inputs"], type="text/csv")
    ET.SubElement(experiment, "References", source=names["reference"], type="text/csv")
    return _xml(root)


def manifest_xml(block: str, scenario) -> bytes:
    """extra/org.fmi-standard.fmi-ls-ref/fmi-ls-manifest.xml: every file of the folder with its
    role (FMI-LS-REF, "Related Files")."""
    ET.register_namespace("fmi-ls", LS_MANIFEST_NAMESPACE)
    ns = f"{{{LS_MANIFEST_NAMESPACE}}}"
    root = ET.Element(
        "fmiReferences",
        {
            f"{ns}fmi-ls-name": LS_REF_NAME,
            f"{ns}fmi-ls-version": LS_REF_VERSION,
            f"{ns}fmi-ls-description": LS_REF_DESCRIPTION,
        },
    )
    names = files(block)
    related = [
        (
            EXPERIMENTS_TYPE,
            names["experiments"],
            "experiment",
            f"The reference experiment {scenario.name}: stimuli, reference result, times",
        ),
        (
            "text/csv",
            names["inputs"],
            "other",
            f"Stimuli of {scenario.name}: every input, one row per change, held until the next row",
        ),
        (
            "text/csv",
            names["reference"],
            "result",
            f"Reference result of {scenario.name}: every output at every communication point",
        ),
        (
            "text/plain",
            names["options"],
            "configuration",
            f"Options of {scenario.name} in the FMI cross-check format (StartTime, StopTime, "
            "StepSize, RelTol)",
        ),
        (
            "text/markdown",
            names["readme"],
            "document",
            "How the reference result was produced and how to replay it",
        ),
    ]
    for mime, source, role, description in related:
        ET.SubElement(root, "Related", type=mime, source=source, role=role, description=description)
    return _xml(root)


def readme_text(block: str, scenario, md, fmi: int = 2) -> str:
    """The readme of the FMI <fmi> FMU's compatibility information (the same experiment and
    result for both versions)."""
    names = files(block)
    inputs = [v.name for v in md.modelVariables if v.causality == "input"]
    outputs = [v.name for v in md.modelVariables if v.causality == "output"]
    deliberate = (
        f"\nThe FMU logs one warning in this experiment, on purpose: {scenario.expected_warning}.\n"
        if scenario.expected_warning
        else ""
    )
    if fmi == 2:
        booleans = f"Booleans are written 0/1, which FMPy and {FMUSIM} read."
        reader = "from fmpy.util import read_csv, read_ref_opt_file\n"
    else:
        booleans = (
            f"Booleans are written false/true, the form {FMUSIM} reads for\n"
            "  FMI 3.0 (it refuses 0/1 there); FMPy's `read_csv` reads numbers only, so the\n"
            "  replay below reads them as 0/1."
        )
        reader = FMPY_READER
    return f"""# {block}: compatibility information (lgf-fmus {version()})

A reference experiment of `{block}.fmu` that any FMI importer can replay, as the FMI
cross-check rules and the layered standard FMI-LS-REF describe. The same files are inside the
FMU, under `{LS_REF_FOLDER}/`, with the layered standard's manifest `{MANIFEST}` and the
experiment description `{names["experiments"]}` (Experiments Format, ma-hs-experiments).

| file | what it holds |
|---|---|
| `{names["inputs"]}` | the inputs: `time` and every input ({", ".join(inputs)}), one row per \
change; each value holds until the next row |
| `{names["reference"]}` | the reference result: `time` and every output ({", ".join(outputs)}) \
at every communication point |
| `{names["options"]}` | `StartTime`, `StopTime`, `StepSize` (the communication step) and \
`RelTol` (unused: no continuous states) |
| `{names["readme"]}` | this file |

## The experiment

`{scenario.name}`: {scenario.title}.

- FMI {fmi}.0 **Co-Simulation**, start time 0 s, stop time {scenario.stop_time:g} s, a
  communication step of {scenario.output_interval:g} s (the default `cycleTime`, one PLC call
  per step). Every parameter keeps its start value.
- Inputs are discrete: the values of the row at time t are set at communication point t and
  reach the PLC calls in (t, t + h]. Outputs are recorded at the end of every step.
- {booleans}
  Reals are written with the digits that read back bit for bit, and the times of
  `{names["reference"]}` are the communication points n·h as doubles (so
  0.30000000000000004 is 3 × 0.1).
{deliberate}
Produced with FMPy on the FMU's linux64 binary, at build time. The project's test suite and
`make dist` require this result to be identical to the committed regression reference
(`tests/blocks/{block}/references/{scenario.name}.csv`, regenerated only by `make references`
and reviewed), which the suite also checks against an independent Python model of the block;
`make dist` replayed the FMU from these files before packing it.

## Replay

With [FMPy](https://github.com/CATIA-Systems/FMPy), in the folder of these files:

```python
import numpy as np
from fmpy import simulate_fmu
{reader}
options = read_ref_opt_file("{names["options"]}")
reference = read_csv("{names["reference"]}")
result = simulate_fmu("{block}.fmu", start_time=options["StartTime"],
                      stop_time=options["StopTime"], output_interval=options["StepSize"],
                      input=read_csv("{names["inputs"]}"), output=list(reference.dtype.names[1:]))
for name in reference.dtype.names:
    assert np.array_equal(result[name], reference[name]), name
print(f"{{len(reference)}} rows replayed: every output identical to the reference")
```

Any other importer: simulate as co-simulation with the communication step `StepSize`, set
each input to the value of the latest row at or before the communication point, and compare
every output at every communication point. The outputs are discrete and deterministic, so
they must be equal, not just close. Through Model Exchange, an input that changes at a PLC
call's time reaches that call instead of the next one (see the project's README), so compare
co-simulation results only.
"""


# The FMI 3.0 readme's reader: FMPy's read_csv with false/true read as 0/1 (the same as read_csv
# below, in the readme's own few lines)
FMPY_READER = '''from fmpy.util import read_ref_opt_file


def read_csv(name):
    """The CSV as fmpy.util.read_csv reads it, with the Booleans false/true as 0/1."""
    with open(name) as f:
        names, *rows = [line.rstrip("\\n").split(",") for line in f]
    value = {"false": 0.0, "true": 1.0}
    return np.array([tuple(float(value.get(c, c)) for c in row) for row in rows],
                    dtype=[(n, np.float64) for n in names])

'''


def write_csv(array, path: Path):
    from tools.simulate import write_csv as write

    write(array, path, exact_times=True)


def booleans(md) -> set[str]:
    """The names of the Boolean variables of a modelDescription (FMPy's)."""
    return {v.name for v in md.modelVariables if v.type == "Boolean"}


def as_fmi(text: str, names: set[str], fmi: int) -> str:
    """A CSV of these files (`time,<names>` and a row per line, in either form) with the
    Booleans of the columns `names` written as the FMI <fmi> files write them (BOOLEANS);
    every other cell unchanged, byte for byte."""
    false, true = BOOLEANS[fmi]
    literal = {"0": false, "false": false, "1": true, "true": true}
    lines = text.splitlines()
    header = lines[0].split(",")
    columns = [i for i, name in enumerate(header) if name.strip('"') in names]
    out = [lines[0]]
    for line in lines[1:]:
        cells = line.split(",")
        for i in columns:
            if cells[i] not in literal:
                raise ValueError(f"{header[i]}: {cells[i]!r} is no Boolean")
            cells[i] = literal[cells[i]]
        out.append(",".join(cells))
    return "\n".join(out) + "\n"


def read_csv(path) -> np.ndarray:
    """A CSV of these files as fmpy.util.read_csv reads it (a structured array, every column
    float64), in either form: false/true (the FMI 3.0 files) read as 0/1."""
    with open(path) as f:
        names, *rows = [line.rstrip("\n").split(",") for line in f]
    value = {"false": 0.0, "true": 1.0}
    return np.array(
        [tuple(float(value.get(c, c)) for c in row) for row in rows],
        dtype=[(name.strip('"'), np.float64) for name in names],
    )


def write(block: str, xml: Path, binary: Path, out: Path, out3: Path | None = None) -> None:
    """Writes the compatibility information of a block into `out`, simulating its compatibility
    scenario on `binary` (the library just built) with `xml` (its modelDescription.xml); and,
    with `out3`, what the FMI 3.0 FMU's copy has of its own there: its readme, and its _in.csv
    and _ref.csv with the Booleans as false/true (the other files are the same)."""
    from fmpy import read_model_description

    from tools.scenario import input_defaults
    from tools.simulate import simulate_built

    scenario = scenario_of(block)
    md = read_model_description(str(xml))
    names = files(block)
    if out.exists():
        shutil.rmtree(out)
    out.mkdir(parents=True)
    result = simulate_built(scenario, xml, binary)
    write_csv(result, out / names["reference"])
    write_csv(scenario.input_signals(input_defaults(md)), out / names["inputs"])
    (out / names["options"]).write_text(options_text(scenario), encoding="utf-8")
    (out / names["readme"]).write_text(readme_text(block, scenario, md), encoding="utf-8")
    if out3 is not None:
        if out3.exists():
            shutil.rmtree(out3)
        out3.mkdir(parents=True)
        (out3 / names["readme"]).write_text(readme_text(block, scenario, md, 3), encoding="utf-8")
        for kind in ("inputs", "reference"):
            text = (out / names[kind]).read_text(encoding="utf-8")
            (out3 / names[kind]).write_text(as_fmi(text, booleans(md), 3), encoding="utf-8")
    (out / names["experiments"]).write_bytes(experiments_xml(block, scenario))
    (out / names["manifest"]).write_bytes(manifest_xml(block, scenario))


def replay(fmu: Path, folder: Path, block: str, messages=None) -> list[str]:
    """Simulates `fmu` from the compatibility information in `folder` (its _in.csv and
    _ref.opt, read as an FMPy user reads them, the FMI 3.0 files' false/true as 0/1) and
    compares every column of the result with _ref.csv exactly. Returns the differences found
    (empty: identical). `messages`, a callable (status, message), receives the FMU's log
    messages (default: FMPy prints them)."""
    from fmpy import simulate_fmu
    from fmpy.util import read_ref_opt_file

    names = files(block)
    options = read_ref_opt_file(str(folder / names["options"]))
    reference = read_csv(str(folder / names["reference"]))
    inputs = read_csv(str(folder / names["inputs"]))
    kwargs = dict(
        start_time=options["StartTime"],
        stop_time=options["StopTime"],
        output_interval=options["StepSize"],
        input=inputs,
        output=list(reference.dtype.names[1:]),
    )
    if messages is None:
        result = simulate_fmu(str(fmu), **kwargs)
    else:
        from tools.simulate import forwarding_messages

        with forwarding_messages(messages):
            result = simulate_fmu(str(fmu), **kwargs)
    if len(result) != len(reference):
        return [f"{block}: {len(result)} rows, the reference has {len(reference)}"]
    problems = []
    for name in reference.dtype.names:
        differ = np.flatnonzero(result[name].astype(float) != reference[name])
        if len(differ):
            i = differ[0]
            problems.append(
                f"{block}: {name} differs in {len(differ)} rows, first at t = "
                f"{reference['time'][i]!r}: {result[name][i]!r} instead of {reference[name][i]!r}"
            )
    return problems


def main():
    from tools.simulate import built_library_parser

    parser = built_library_parser(__doc__, "folder to write the files into")
    parser.add_argument(
        "--out3", type=Path, help="folder for the FMI 3.0 FMU's readme, _in.csv and _ref.csv"
    )
    args = parser.parse_args()
    write(args.block, args.xml, args.binary, args.out, args.out3)


if __name__ == "__main__":
    main()
