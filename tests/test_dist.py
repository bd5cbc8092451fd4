"""The release zip (`make dist`, release/dist.py), checked as a user who downloads it would:
unpacked, every checksum of SHA256SUMS verified, every FMU validated and replayed from the
compatibility information beside it (read with FMPy's own readers, compared exactly, every
column of every row), LICENSE and CHANGELOG.md present, the examples run from it, the binaries
of each folder's FMUs listed in its README (FMI 2.0: linux64, win64; FMI 3.0: x86_64-linux,
x86_64-windows, aarch64-linux; the cross-built ones where their cross compilers are installed).
A dist refuses an FMU whose reference result is not the committed one, one with a binary its
folder does not carry, and a version without a CHANGELOG.md section."""

from __future__ import annotations

import hashlib
import shutil
import zipfile

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu
from fmpy.util import read_csv, read_ref_opt_file
from fmpy.validation import validate_fmu

from release import dist
from tests.harness import FMU_DIR, binaries, built_platforms
from tests.lgf_blocks import names
from tests.test_examples import check_run, run_example
from tools import ROOT, compat, version

BLOCKS = names()


@pytest.fixture(scope="module")
def unpacked_release(tmp_path_factory):
    out = tmp_path_factory.mktemp("dist")
    archive = dist.build(FMU_DIR, out)
    assert archive == out / f"lgf-fmus-{version()}.zip"
    folder = tmp_path_factory.mktemp("unpacked")
    with zipfile.ZipFile(archive) as z:
        assert z.testzip() is None
        z.extractall(folder)
        top = f"lgf-fmus-{version()}/"
        assert all(n.startswith(top) for n in z.namelist()), "one top-level folder"
        listed = [n.removeprefix(top) for n in z.namelist()]
    # The same FMUs give the same zip, byte for byte (every entry has one time stamp).
    again = tmp_path_factory.mktemp("again")
    assert dist.build(FMU_DIR, again).read_bytes() == archive.read_bytes()
    return folder / top, listed


def test_the_zip_holds_every_fmu_with_its_compatibility_information(unpacked_release):
    _, listed = unpacked_release
    per_block = {
        f"{version}/{b}{suffix}"
        for version in ("fmi2", "fmi3")
        for b in BLOCKS
        for suffix in (".fmu", "_in.csv", "_ref.csv", "_ref.opt", "_README.md")
    }
    examples = {"examples/chain.py", "examples/README.md"}
    assert set(listed) == per_block | examples | {
        "SHA256SUMS",
        "LICENSE",
        "CHANGELOG.md",
        "README.md",
    }


def test_the_chain_example_runs_from_the_unpacked_zip_with_fmpy_alone(unpacked_release, tmp_path):
    """examples/chain.py, run from the release's folder as its README says (isolated: nothing
    of the repository on the path), connects the release's FMI 2.0 FMUs and prints what
    examples/README.md shows; the release's README names it."""
    folder, _ = unpacked_release
    release = tmp_path / folder.name  # a copy far from the repository
    shutil.copytree(folder, release)
    check_run(run_example("examples/chain.py", release))
    assert "python examples/chain.py" in (release / "README.md").read_text()
    assert (release / "examples" / "README.md").read_bytes() == (
        ROOT / "examples" / "README.md"
    ).read_bytes()


def test_every_checksum_verifies(unpacked_release):
    folder, listed = unpacked_release
    lines = (folder / "SHA256SUMS").read_text().splitlines()
    sums = dict(reversed(line.split("  ", 1)) for line in lines)
    assert sorted(sums) == sorted(n for n in listed if n != "SHA256SUMS")
    for name, digest in sums.items():
        assert hashlib.sha256((folder / name).read_bytes()).hexdigest() == digest, name


def test_license_and_changelog(unpacked_release):
    folder, _ = unpacked_release
    license_text = (folder / "LICENSE").read_text()
    assert (
        license_text.startswith("BSD 2-Clause License")
        and "Redistributions in binary form" in license_text
    )
    assert license_text == (ROOT / "LICENSE").read_text()
    changelog = (folder / "CHANGELOG.md").read_text()
    assert f"## [{version()}] - " in changelog
    assert f"lgf-fmus {version()}" in (folder / "README.md").read_text()


@pytest.mark.parametrize("block", BLOCKS)
def test_every_fmu_is_the_built_one_and_valid(unpacked_release, block):
    folder, _ = unpacked_release
    fmu = folder / "fmi2" / f"{block}.fmu"
    assert fmu.read_bytes() == (FMU_DIR / f"{block}.fmu").read_bytes()
    assert validate_fmu(str(fmu)) == []


@pytest.mark.parametrize("fmi", ["fmi2", "fmi3"])
@pytest.mark.parametrize("block", BLOCKS)
def test_every_fmu_replays_its_reference_exactly(unpacked_release, block, fmi):
    """FMI 2.0 read by FMPy's read_csv; FMI 3.0, whose Booleans are false/true, which FMPy's
    reader refuses, by the replay's (tools/compat.py)."""
    folder = unpacked_release[0] / fmi
    read = read_csv if fmi == "fmi2" else compat.read_csv
    options = read_ref_opt_file(str(folder / f"{block}_ref.opt"))
    reference = read(str(folder / f"{block}_ref.csv"))
    result = simulate_fmu(
        str(folder / f"{block}.fmu"),
        start_time=options["StartTime"],
        stop_time=options["StopTime"],
        output_interval=options["StepSize"],
        input=read(str(folder / f"{block}_in.csv")),
        output=list(reference.dtype.names[1:]),
    )
    assert len(result) == len(reference)
    for name in reference.dtype.names:
        assert np.array_equal(result[name], reference[name]), name
    md = read_model_description(str(folder / f"{block}.fmu"))
    assert set(reference.dtype.names[1:]) == {u.variable.name for u in md.outputs}


@pytest.mark.parametrize("folder", ["fmi2", "fmi3"])
def test_every_fmu_holds_the_binaries_the_readme_lists(unpacked_release, folder):
    root = unpacked_release[0]
    expected = built_platforms(folder)
    for block in BLOCKS:
        assert (
            tuple(
                p for p in dist.PLATFORMS[folder] if p in binaries(root / folder / f"{block}.fmu")
            )
            == expected
        ), block
    listed = f"- `{folder}/` (FMI {folder[-1]}.0, binaries {', '.join(expected)}): "
    assert listed in (root / "README.md").read_text()


def test_the_readme_lists_the_platforms_of_a_complete_build():
    text = dist.readme_text("1.2.3", {"fmi2": ["A"], "fmi3": ["A"]}, "notes", dist.PLATFORMS)
    assert "- `fmi2/` (FMI 2.0, binaries linux64, win64): `A.fmu`" in text
    assert (
        "- `fmi3/` (FMI 3.0, binaries x86_64-linux, x86_64-windows, aarch64-linux): `A.fmu`" in text
    )
    assert dist.PLATFORMS["fmi2"] == ("linux64", "win64")  # FMI 2.0 names no aarch64 platform


def test_an_fmi2_fmu_with_an_aarch64_binary_is_refused(tmp_path):
    block = BLOCKS[0]
    fmu = tmp_path / f"{block}.fmu"
    shutil.copy(FMU_DIR / f"{block}.fmu", fmu)
    with zipfile.ZipFile(fmu, "a") as z:
        z.writestr(f"binaries/aarch64-linux/{block}.so", b"")
    with pytest.raises(dist.DistError, match="aarch64-linux, which the fmi2/ FMUs do not carry"):
        dist.platforms(fmu, "fmi2")
    assert dist.platforms(FMU_DIR / "fmi3" / f"{block}.fmu", "fmi3") == built_platforms("fmi3")


def test_the_release_folder_follows_the_fmi_version():
    assert dist.fmi_folder("2.0") == "fmi2" and dist.fmi_folder("3.0") == "fmi3"
    with pytest.raises(dist.DistError):
        dist.fmi_folder("1.0")


def test_a_version_without_a_changelog_section_is_refused():
    text = (ROOT / "CHANGELOG.md").read_text()
    assert dist.changelog_section(text, version())
    with pytest.raises(dist.DistError, match="no section"):
        dist.changelog_section(text, "99.0.0")


def test_an_fmu_whose_reference_is_not_the_committed_one_is_refused(tmp_path):
    block = BLOCKS[0]
    fmus = tmp_path / "fmus"
    fmus.mkdir()
    inside = f"extra/org.fmi-standard.fmi-ls-ref/{block}_ref.csv"
    with (
        zipfile.ZipFile(FMU_DIR / f"{block}.fmu") as source,
        zipfile.ZipFile(fmus / f"{block}.fmu", "w") as target,
    ):
        for info in source.infolist():
            data = source.read(info)
            if info.filename.removeprefix("./") == inside:
                data = data.replace(b"\n0.0,", b"\n0.0,1", 1)
            target.writestr(info, data)
    with pytest.raises(dist.DistError, match="not the committed"):
        dist.build(fmus, tmp_path / "dist")
    assert not (tmp_path / "dist").exists()
    shutil.rmtree(fmus)


def test_a_release_without_its_example_is_refused(tmp_path, monkeypatch):
    monkeypatch.setattr(dist, "EXAMPLES", tmp_path)
    (tmp_path / "README.md").write_text("# Examples\n")
    with pytest.raises(dist.DistError, match="no chain.py"):
        dist.example_files()
    monkeypatch.undo()
    assert [p.name for p in dist.example_files()] == ["README.md", "chain.py"]
