"""Every FMU carries its compatibility information (tools/compat.py) under
extra/org.fmi-standard.fmi-ls-ref/, so that an importer's tool or CI can replay it: the layered
standard's manifest names every file of the folder with a role FMI-LS-REF defines; the
experiment file (Experiments Format) points at the stimuli and the reference result; the
stimuli are the compatibility scenario's inputs, written independently here from the scenario;
the reference result is byte for byte the committed regression reference of that scenario; and
a fresh simulation of the FMU from these files alone, read as an FMPy user reads them, equals
the reference result exactly, every column, every row. The FMI 2.0 FMU's files are what FMPy and
fmusim read for FMI 2.0; the FMI 3.0 FMU's are the same with the Booleans as false/true, what
fmusim reads for FMI 3.0, and replay the same."""

from __future__ import annotations

import csv
import re
import shutil
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import numpy as np
import pytest
from fmpy import read_model_description
from fmpy.util import read_csv

from tests.harness import FMU_DIR, fmu_path, unpacked
from tests.lgf_blocks import blocks
from tools import compat, version

BLOCKS = blocks()
IDS = [b.name for b in BLOCKS]
NS = "{http://fmi-standard.org/fmi-ls-manifest}"
# FMI-LS-REF, "Related Files": the roles it defines (a role may add sub-roles: experiment/...)
ROLES = {
    "document",
    "requirement",
    "specification",
    "model",
    "parameter",
    "system",
    "testcase",
    "experiment",
    "result",
    "method",
    "rationale",
    "report",
    "request",
    "delivery",
    "configuration",
    "signature",
    "serialized-state",
    "meta-data",
    "other",
}


def folder(block) -> Path:
    _, directory = unpacked(block.name)
    return Path(directory) / "extra" / "org.fmi-standard.fmi-ls-ref"


@pytest.mark.parametrize("block", BLOCKS, ids=IDS)
def test_the_manifest_names_every_file_of_the_folder_with_its_role(block):
    root = ET.parse(folder(block) / "fmi-ls-manifest.xml").getroot()
    assert root.tag == "fmiReferences"
    assert root.get(f"{NS}fmi-ls-name") == "org.fmi-standard.fmi-ls-ref"
    assert root.get(f"{NS}fmi-ls-version") == "1.0.0-beta.1"
    assert root.get(f"{NS}fmi-ls-description")
    related = {r.get("source"): r for r in root.findall("Related")}
    present = {p.name for p in folder(block).iterdir()} - {"fmi-ls-manifest.xml"}
    assert set(related) == present
    for source, r in related.items():
        assert r.get("role").split("/")[0] in ROLES, source
        assert r.get("type") and r.get("description"), source
    roles = {r.get("role"): source for source, r in related.items()}
    assert roles["result"] == f"{block.name}_ref.csv"
    assert roles["experiment"] == f"{block.name}.exp"


@pytest.mark.parametrize("block", BLOCKS, ids=IDS)
def test_the_experiment_file_points_at_the_stimuli_and_the_reference(block):
    root = ET.parse(folder(block) / f"{block.name}.exp").getroot()
    assert root.tag == "Experiments" and root.get("name")
    [experiment] = root.findall("Experiment")
    scenario = block.compatibility
    assert experiment.get("name") == scenario.name
    assert float(experiment.get("startTime")) == 0.0
    assert float(experiment.get("stopTime")) == scenario.stop_time
    assert float(experiment.get("stepSize")) == scenario.output_interval
    assert experiment.find("Stimuli").get("source") == f"{block.name}_in.csv"
    assert experiment.find("References").get("source") == f"{block.name}_ref.csv"
    options = (folder(block) / f"{block.name}_ref.opt").read_text().splitlines()
    assert options == [
        "StartTime, 0.0",
        f"StopTime, {scenario.stop_time!r}",
        f"StepSize, {scenario.output_interval!r}",
        "RelTol, 0.0001",
    ]


def expected_inputs(block) -> list[dict]:
    """The scenario's inputs as rows, from its changes over the modelDescription's start values."""
    md, _ = unpacked(block.name)
    convert = {
        "Real": float,
        "Integer": int,
        "Boolean": lambda text: 1.0 if text == "true" else 0.0,
    }
    current = {
        v.name: float(convert[v.type](v.start)) for v in md.modelVariables if v.causality == "input"
    }
    rows = []
    for time, changes in sorted(block.compatibility.inputs, key=lambda row: row[0]):
        current.update({k: float(v) for k, v in changes.items()})
        rows.append({"time": float(time), **current})
    rows.append({**rows[-1], "time": float(block.compatibility.stop_time)})
    return rows


@pytest.mark.parametrize("block", BLOCKS, ids=IDS)
def test_the_stimuli_are_the_scenario_s_inputs(block):
    with open(folder(block) / f"{block.name}_in.csv") as f:
        rows = [{k: float(v) for k, v in row.items()} for row in csv.DictReader(f)]
    assert rows == expected_inputs(block)


@pytest.mark.parametrize("block", BLOCKS, ids=IDS)
def test_the_reference_is_the_committed_regression_reference(block):
    assert (folder(block) / f"{block.name}_ref.csv").read_bytes() == block.reference(
        block.compatibility
    ).read_bytes(), (
        "the FMU's reference result differs from the committed one: run `make references`, review"
    )


@pytest.mark.parametrize("block", BLOCKS, ids=IDS)
def test_a_replay_from_the_files_alone_equals_the_reference_exactly(block):
    assert (
        compat.replay(fmu_path(block.name), folder(block), block.name, messages=lambda s, m: None)
        == []
    )


@pytest.mark.parametrize("block", BLOCKS, ids=IDS)
def test_the_readme_says_what_it_is_and_is_the_documentation_s_fmi_ls_ref_txt(block):
    readme = (folder(block) / f"{block.name}_README.md").read_text()
    assert f"lgf-fmus {version()}" in readme and block.compatibility.name in readme
    _, directory = unpacked(block.name)
    documentation = Path(directory) / "documentation"
    assert (documentation / "fmi-ls-ref.txt").read_text() == readme
    assert 'href="fmi-ls-ref.txt"' in (documentation / "index.html").read_text()


def test_the_replay_finds_a_difference(tmp_path):
    """The comparison is not vacuous: one changed value of the reference is reported."""
    block = BLOCKS[0]
    for name in compat.release_files(block.name):
        (tmp_path / name).write_bytes((folder(block) / name).read_bytes())
    reference = tmp_path / f"{block.name}_ref.csv"
    lines = reference.read_text().splitlines()
    cells = lines[5].split(",")
    cells[1] = repr(float(cells[1]) + 1.0)
    lines[5] = ",".join(cells)
    reference.write_text("\n".join(lines) + "\n")
    [problem] = compat.replay(
        fmu_path(block.name), tmp_path, block.name, messages=lambda s, m: None
    )
    assert "differs in 1 rows" in problem


@pytest.mark.parametrize("fmi", [2, 3])
@pytest.mark.parametrize("block", BLOCKS, ids=IDS)
def test_the_readme_s_replay_runs_as_shown_and_says_so(block, fmi, tmp_path, monkeypatch, capsys):
    """Each FMU's readme names its own FMI version, and its Python replay, run in a folder of
    the FMU and its compatibility files (as the release lays them out), prints its result."""
    fmu = fmu_path(block.name) if fmi == 2 else fmu_path(block.name, FMU_DIR / "fmi3")
    with zipfile.ZipFile(fmu) as z:
        for name in compat.release_files(block.name):
            (tmp_path / name).write_bytes(z.read(f"extra/org.fmi-standard.fmi-ls-ref/{name}"))
    shutil.copy(fmu, tmp_path / f"{block.name}.fmu")
    readme = (tmp_path / f"{block.name}_README.md").read_text()
    assert f"FMI {fmi}.0 **Co-Simulation**" in readme
    code = re.search(r"```python\n(.*?)```", readme, re.S).group(1)
    monkeypatch.chdir(tmp_path)
    exec(compile(code, f"{block.name}_README.md", "exec"), {})
    assert "every output identical to the reference" in capsys.readouterr().out


# What the importers that replay these files read, from their sources. FMPy's read_csv
# (fmpy/util.py) converts every cell with float(). fmusim (0.8, the simulator that left the
# Reference FMUs for a project of its own) reads --input-file and --reference-file with the
# read_csv of fmi-rs: a Boolean is parse_boolean's "true", "1", "false" or "0" for FMI 2.0
# (sim/fmi2/mod.rs) but Rust's bool::from_str, "true" or "false" only, for FMI 3.0
# (sim/fmi3/mod.rs, parse_variable_value); an integer Rust's integer parse (a sign and digits),
# a float Rust's f64 parse; the cells are not trimmed (csv::Reader's default).
FMUSIM_BOOLEANS = {2: {"0", "1", "false", "true"}, 3: {"false", "true"}}
INTEGER = re.compile(r"[+-]?[0-9]+")
FLOAT = re.compile(
    r"[+-]?([0-9]+\.?[0-9]*|\.[0-9]+)([eE][+-]?[0-9]+)?|[+-]?(inf|infinity|nan)", re.I
)
FLOATS = {"Real", "Float32", "Float64"}
INTEGERS = {"Integer", "Enumeration", "Int8", "UInt8", "Int16", "UInt16", "Int32", "UInt32"}
INTEGERS |= {"Int64", "UInt64"}
KINDS = ("inputs", "reference")


def fmi3_files(block, tmp_path) -> tuple[Path, object]:
    """The FMI 3.0 FMU's compatibility files in tmp_path, and its model description."""
    fmu = fmu_path(block.name, FMU_DIR / "fmi3")
    with zipfile.ZipFile(fmu) as z:
        for name in compat.release_files(block.name):
            (tmp_path / name).write_bytes(z.read(f"extra/org.fmi-standard.fmi-ls-ref/{name}"))
    return tmp_path, read_model_description(str(fmu))


def fmusim_refuses(path: Path, md, fmi: int) -> list[str]:
    """The cells of a CSV that fmusim's reader refuses for an FMU of that model description."""
    types = {v.name: v.type for v in md.modelVariables}
    header, *rows = [line.split(",") for line in path.read_text().splitlines()]
    refused = [f"{name}: no variable" for name in header[1:] if name not in types]
    for row in rows:
        if not FLOAT.fullmatch(row[0]):
            refused.append(f"time {row[0]!r}")
        for name, cell in zip(header[1:], row[1:]):
            kind = types.get(name)
            if kind == "Boolean":
                good = cell in FMUSIM_BOOLEANS[fmi]
            elif kind in INTEGERS:
                good = bool(INTEGER.fullmatch(cell))
            else:
                good = kind in FLOATS and bool(FLOAT.fullmatch(cell))
            if not good:
                refused.append(f"{name} ({kind}) {cell!r}")
    return refused


@pytest.mark.parametrize("block", BLOCKS, ids=IDS)
def test_fmusim_and_fmpy_read_the_fmi2_files(block):
    """The FMI 2.0 FMU's _in.csv and _ref.csv: fmusim reads every cell for FMI 2.0, FMPy's
    read_csv reads them, and so does our replay's reader (compat.read_csv), to the same array."""
    md, _ = unpacked(block.name)
    for kind in KINDS:
        path = folder(block) / compat.files(block.name)[kind]
        assert fmusim_refuses(path, md, 2) == [], path.name
        fmpy = read_csv(str(path))  # raises for a cell that is no number
        ours = compat.read_csv(path)
        assert ours.dtype == fmpy.dtype and np.array_equal(ours, fmpy), path.name


@pytest.mark.parametrize("block", BLOCKS, ids=IDS)
def test_the_fmi3_files_are_the_fmi2_files_with_the_booleans_false_true(block, tmp_path):
    """Each cell of the FMI 3.0 FMU's _in.csv and _ref.csv is the FMI 2.0 FMU's, a Boolean's
    0/1 written false/true: fmusim reads them for FMI 3.0, our replay reads them as FMPy reads
    the FMI 2.0 files."""
    files, md = fmi3_files(block, tmp_path)
    booleans = {v.name for v in md.modelVariables if v.type == "Boolean"}
    as_fmi3 = {"0": "false", "1": "true"}
    for kind in KINDS:
        name = compat.files(block.name)[kind]
        fmi2 = [line.split(",") for line in (folder(block) / name).read_text().splitlines()]
        fmi3 = [line.split(",") for line in (files / name).read_text().splitlines()]
        header = fmi2[0]
        expected = [header] + [
            [as_fmi3[c] if h in booleans else c for h, c in zip(header, row)] for row in fmi2[1:]
        ]
        assert fmi3 == expected, name
        assert fmusim_refuses(files / name, md, 3) == [], name
        assert np.array_equal(compat.read_csv(files / name), read_csv(str(folder(block) / name)))
        if booleans & set(header):
            with pytest.raises(ValueError):  # FMPy reads numbers only: our replay converts
                read_csv(str(files / name))


@pytest.mark.parametrize("block", BLOCKS, ids=IDS)
def test_a_replay_of_the_fmi3_fmu_from_its_own_files_equals_the_reference(block, tmp_path):
    files, _ = fmi3_files(block, tmp_path)
    fmu = fmu_path(block.name, FMU_DIR / "fmi3")
    assert compat.replay(fmu, files, block.name, messages=lambda s, m: None) == []


def test_fmusim_s_rules_refuse_what_fmusim_refuses(tmp_path):
    """The rules above are not vacuous: 0/1 for an FMI 3.0 Boolean, a fraction for an integer,
    a blank around a number are refused; the forms of Python's repr are read."""
    block = next(b for b in BLOCKS if b.name == "LGF_LimRateOfChangeCI")
    md, _ = unpacked(block.name)  # enDefaultOutValue: Boolean, value: Real
    path = tmp_path / "in.csv"
    path.write_text("time,enDefaultOutValue,value\n0.0,1,1e-05\n0.5,true,-inf\n1.0,false,nan\n")
    assert fmusim_refuses(path, md, 2) == []
    assert fmusim_refuses(path, md, 3) == ["enDefaultOutValue (Boolean) '1'"]
    path.write_text("time,enDefaultOutValue,value\n0.0,true, 1.0\n")
    assert fmusim_refuses(path, md, 3) == ["value (Real) ' 1.0'"]
    path.write_text("time,status\n0.0,1.0\n")
    assert fmusim_refuses(path, md, 2) == ["status (Integer) '1.0'"]
