"""`make dist`: the release zip dist/lgf-fmus-<version>.zip, with the version of VERSION. It
unpacks into one folder, lgf-fmus-<version>/, holding:

    fmi2/<Block>.fmu           every FMI 2.0 FMU of fmus/ (fmi3/ the same for FMI 3.0 FMUs,
                               when built)
    fmi2/<Block>_in.csv        its compatibility information (tools/compat.py): the inputs,
    fmi2/<Block>_ref.csv       the reference result,
    fmi2/<Block>_ref.opt       the experiment's options (FMI cross-check format)
    fmi2/<Block>_README.md     and what they are and how to replay them
    examples/                  the files of the repository's examples/ (chain.py: two FMUs
                               connected, with FMPy alone; its README.md)
    README.md                  what the release holds, how to check it
    LICENSE, CHANGELOG.md      of the repository
    SHA256SUMS                 of every other file (`sha256sum -c SHA256SUMS`)

The compatibility files are the ones inside each FMU (extra/org.fmi-standard.fmi-ls-ref/).
The README lists the binaries of each folder's FMUs: linux64 and win64 for FMI 2.0,
x86_64-linux, x86_64-windows and aarch64-linux for FMI 3.0 (PLATFORMS; the cross-built ones
where `make build` had their cross compilers, which it says otherwise, and so does make dist).
Before anything is packed, every FMU must pass FMPy's validate_fmu, hold its folder's native
binary, no binary of a platform its folder does not list and the same ones as the other FMUs
of its folder; its reference result must be identical to the committed regression reference
(tests/blocks/<Block>/references/), and a replay of the FMU from the files alone must give that
result exactly; CHANGELOG.md must have a section for the version. Any failure stops `make dist`
with the reason.

    python -m release.dist --fmus fmus --out dist
"""

from __future__ import annotations

import argparse
import hashlib
import re
import shutil
import sys
import tempfile
import zipfile
from pathlib import Path

from lgf_fmus.fmuzip import pack  # the zip's bytes depend on its contents only
from tools import ROOT, compat, version

FOLDERS = {"2.0": "fmi2", "3.0": "fmi3"}
EXAMPLES = ROOT / "examples"  # scripts that run on the release's FMUs with FMPy alone
# The platforms of each folder's binaries, in the order the README lists them: the native one,
# then the cross-built ones (FMI 2.0 has no platform name for aarch64 Linux).
PLATFORMS = {
    "fmi2": ("linux64", "win64"),
    "fmi3": ("x86_64-linux", "x86_64-windows", "aarch64-linux"),
}


class DistError(Exception):
    """Something that must not be released; the message says what and what to do."""


def fmi_folder(fmi_version: str) -> str:
    """The release folder of an FMU of that fmiVersion."""
    major = fmi_version.split(".")[0] + ".0"
    if major not in FOLDERS:
        raise DistError(f"fmiVersion {fmi_version!r}: only FMI 2.0 and 3.0 FMUs are released")
    return FOLDERS[major]


def changelog_section(text: str, version_: str) -> str:
    """The CHANGELOG.md section of a version: from its `## [<version>]` heading to the next."""
    match = re.search(rf"^## \[{re.escape(version_)}\][^\n]*\n(.*?)(?=^## |\Z)", text, re.S | re.M)
    if not match or not match.group(1).strip():
        raise DistError(
            f"CHANGELOG.md has no section `## [{version_}] - <date>` for the version "
            f"of VERSION: write what changed, then make dist"
        )
    return match.group(1).strip()


def sha256(path: Path) -> str:
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 16), b""):
            digest.update(chunk)
    return digest.hexdigest()


def platforms(fmu: Path, folder: str) -> tuple[str, ...]:
    """The platforms an FMU of that release folder holds a binary for (binaries/<platform>/),
    in the order of PLATFORMS; DistError for one that is not the folder's."""
    with zipfile.ZipFile(fmu) as z:
        found = {
            parts[1]
            for parts in (n.removeprefix("./").split("/") for n in z.namelist())
            if len(parts) > 2 and parts[0] == "binaries" and parts[2]
        }
    unknown = found - set(PLATFORMS[folder])
    if unknown:
        raise DistError(
            f"{fmu}: binaries for {', '.join(sorted(unknown))}, which the {folder}/ "
            f"FMUs do not carry (only {', '.join(PLATFORMS[folder])}): rebuild it "
            "with make build"
        )
    return tuple(p for p in PLATFORMS[folder] if p in found)


def _print_message(scenario):
    from tools.simulate import Messages

    return Messages(scenario)


def check_fmu(fmu: Path, folder: Path) -> tuple[str, str, tuple[str, ...]]:
    """Validates one FMU, extracts its compatibility files into `folder` and replays them.
    Returns (block, release folder, the platforms of its binaries)."""
    from fmpy import read_model_description
    from fmpy.validation import validate_fmu

    md = read_model_description(str(fmu))
    block = md.coSimulation.modelIdentifier if md.coSimulation else md.modelExchange.modelIdentifier
    target = fmi_folder(md.fmiVersion)
    held = platforms(fmu, target)
    if PLATFORMS[target][0] not in held:
        raise DistError(f"{fmu} has no binaries/{PLATFORMS[target][0]}: rebuild it with make build")
    problems = validate_fmu(str(fmu))
    if problems:
        raise DistError(f"{fmu}: FMPy's validate_fmu finds " + "; ".join(problems))
    inside = f"{compat.LS_REF_FOLDER}/"
    with zipfile.ZipFile(fmu) as z:
        entries = {n.removeprefix("./"): n for n in z.namelist()}
        for name in compat.release_files(block):
            if inside + name not in entries:
                raise DistError(
                    f"{fmu} holds no {inside}{name}: build it with the documentation "
                    "(make build), which writes the compatibility information"
                )
            (folder / name).write_bytes(z.read(entries[inside + name]))
    scenario = compat.scenario_of(block)
    committed = ROOT / "tests" / "blocks" / block / "references" / f"{scenario.name}.csv"
    reference = folder / compat.files(block)["reference"]
    # the FMI 3.0 FMU's files write the Booleans as false/true (tools/compat.py says why)
    if not committed.is_file() or compat.as_fmi(
        committed.read_text(encoding="utf-8"), compat.booleans(md), int(target[-1])
    ) != reference.read_text(encoding="utf-8"):
        raise DistError(
            f"{fmu}: its reference result is not the committed "
            f"{committed.relative_to(ROOT)}: run `make references`, review the diff, "
            "commit it, then make dist"
        )
    replay_dir = Path(tempfile.mkdtemp(prefix="lgf-replay-"))
    try:
        shutil.copy(fmu, replay_dir / fmu.name)
        for name in compat.release_files(block):
            shutil.copy(folder / name, replay_dir / name)
        problems = compat.replay(replay_dir / fmu.name, replay_dir, block, _print_message(scenario))
    finally:
        shutil.rmtree(replay_dir, ignore_errors=True)
    if problems:
        raise DistError(
            f"{fmu}: a replay from its compatibility information differs: " + "; ".join(problems)
        )
    return block, target, held


def example_files() -> list[Path]:
    """The files of examples/ that the release carries: its scripts and pages."""
    found = sorted(p for p in EXAMPLES.iterdir() if p.is_file() and p.suffix in (".py", ".md"))
    if not any(p.name == "chain.py" for p in found):
        raise DistError(f"{EXAMPLES} holds no chain.py: the release's example is missing")
    return found


def readme_text(
    version_: str, released: dict[str, list[str]], notes: str, binaries: dict[str, tuple[str, ...]]
) -> str:
    """The release's README.md; `binaries` holds the platforms of each folder's FMUs."""
    listing = "\n".join(
        f"- `{folder}/` (FMI {folder[-1]}.0, binaries "
        + ", ".join(binaries[folder])
        + "): "
        + ", ".join(f"`{b}.fmu`" for b in blocks)
        for folder, blocks in sorted(released.items())
    )
    return f"""# lgf-fmus {version_}

Siemens LGF PLC function blocks as FMUs that behave like the block on the S7 CPU, call for
call: each FMU holds Co-Simulation and Model Exchange, the binaries listed below, its C
sources and its documentation (`documentation/index.html` inside the FMU). FMI 2.0 has no
platform name for 64-bit ARM Linux (aarch64-linux): take the FMI 3.0 FMUs there.

{listing}

Beside each `<Block>.fmu` lies its compatibility information, as the FMI cross-check rules
ask of an exporter: `<Block>_in.csv` (inputs), `<Block>_ref.csv` (reference result),
`<Block>_ref.opt` (start, stop, communication step) and `<Block>_README.md` (what the
experiment is and how to replay it). The same files are inside each FMU, under
`{compat.LS_REF_FOLDER}/`, described by the manifest of the layered standard FMI-LS-REF.
The CSVs of `fmi2/` write Booleans as 0/1, which FMPy and fmusim read; those of `fmi3/` as
false/true, the only form fmusim reads for FMI 3.0 (FMPy's `read_csv` reads numbers only: the
replay in each FMI 3.0 `_README.md` reads them as 0/1).

Check the download: `sha256sum -c SHA256SUMS` in this folder. Replay an FMU: see its
`<Block>_README.md`; the outputs must be equal to the reference, not just close.

`examples/` holds scripts that run on these FMUs with FMPy alone (`pip install fmpy`), from
this folder: `python examples/chain.py` connects two FMUs, LGF_SawTooth → LGF_LimRateOfChangeCI,
in a co-simulation master of a few lines (`examples/README.md` says what it prints and why).

License: BSD 2-Clause (`LICENSE`). Siemens, SIMATIC, S7 and TIA Portal are trademarks of
Siemens AG; these FMUs are an independent implementation of the blocks' documented behaviour.

## Changes in {version_}

{notes}
"""


def build(fmu_dir: Path, out: Path) -> Path:
    """Checks every FMU of fmu_dir and writes out/lgf-fmus-<version>.zip; returns its path."""
    version_ = version()
    notes = changelog_section((ROOT / "CHANGELOG.md").read_text(encoding="utf-8"), version_)
    fmus = sorted(fmu_dir.rglob("*.fmu"))
    if not fmus:
        raise DistError(f"{fmu_dir} holds no FMU: run `make build` first")
    stage = Path(tempfile.mkdtemp(prefix="lgf-dist-"))
    try:
        released: dict[str, list[str]] = {}
        binaries: dict[str, tuple[str, ...]] = {}
        for fmu in fmus:
            files = Path(tempfile.mkdtemp(dir=stage, prefix=".files-"))
            block, folder, held = check_fmu(fmu, files)
            if binaries.setdefault(folder, held) != held:
                raise DistError(
                    f"{fmu} has binaries for {', '.join(held)}, the other {folder}/ "
                    f"FMUs for {', '.join(binaries[folder])}: rebuild them with "
                    "make build"
                )
            target = stage / folder
            target.mkdir(exist_ok=True)
            if (target / fmu.name).exists():
                raise DistError(f"two FMI {folder[-1]} FMUs named {fmu.name} in {fmu_dir}")
            shutil.copy(fmu, target / fmu.name)
            for name in compat.release_files(block):
                shutil.move(files / name, target / name)
            shutil.rmtree(files)
            released.setdefault(folder, []).append(block)
            print(
                f"{folder}/{fmu.name}: valid, reference replayed exactly, binaries "
                + ", ".join(held)
            )
        shutil.copy(ROOT / "LICENSE", stage / "LICENSE")
        shutil.copy(ROOT / "CHANGELOG.md", stage / "CHANGELOG.md")
        (stage / "examples").mkdir()
        for example in example_files():
            shutil.copy(example, stage / "examples" / example.name)
        for folder, held in sorted(binaries.items()):
            missing = [p for p in PLATFORMS[folder] if p not in held]
            if missing:
                print(
                    f"NOTE: the {folder}/ FMUs have no binaries for {', '.join(missing)} (their "
                    "cross compiler was missing when they were built, see make build)"
                )
        (stage / "README.md").write_text(
            readme_text(version_, released, notes, binaries), encoding="utf-8"
        )
        names = sorted(p.relative_to(stage).as_posix() for p in stage.rglob("*") if p.is_file())
        (stage / "SHA256SUMS").write_text(
            "".join(f"{sha256(stage / n)}  {n}\n" for n in names), encoding="utf-8"
        )
        out.mkdir(parents=True, exist_ok=True)
        archive = out / f"lgf-fmus-{version_}.zip"
        pack(
            {f"{archive.stem}/{n}": (stage / n).read_bytes() for n in names + ["SHA256SUMS"]},
            archive,
            folders=False,
        )
        return archive
    finally:
        shutil.rmtree(stage, ignore_errors=True)


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument(
        "--fmus", default=ROOT / "fmus", type=Path, help="the built FMUs (searched recursively)"
    )
    parser.add_argument("--out", default=ROOT / "dist", type=Path, help="where the zip is written")
    args = parser.parse_args()
    try:
        archive = build(args.fmus, args.out)
    except DistError as e:
        sys.exit(f"make dist: {e}")
    print(f"{archive} ({archive.stat().st_size // 1024} KiB)")


if __name__ == "__main__":
    main()
