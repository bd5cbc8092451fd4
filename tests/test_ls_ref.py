"""Every FMU carries its compatibility information (tools/compat.py) under
extra/org.fmi-standard.fmi-ls-ref/, so that an importer's tool or CI can replay it: the layered
standard's manifest names every file of the folder with a role FMI-LS-REF defines; the
experiment file (Experiments Format) points at the stimuli and the reference result; the
stimuli are the compatibility scenario's inputs, written independently here from the scenario;
the reference result is byte for byte the committed regression reference of that scenario; and
a fresh simulation of the FMU from these files alone, read as an FMPy user reads them, equals
the reference result exactly, every column, every row."""

from __future__ import annotations

import csv
import re
import shutil
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import pytest

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
