"""The release notes say what a release ships (CHANGELOG.md, which `make dist` copies and quotes
in the zip's README): the version of VERSION has its section, and every bundled block and every
command of `python -m lgf_fmus` is named in the section of a released version no later than
VERSION, the one that first shipped it. A block or a command added without a line in the notes
fails here."""

from __future__ import annotations

import re

from tests.harness import ROOT

SECTION = re.compile(r"^## \[(?P<version>[^\]]+)\](?: - (?P<date>\d{4}-\d{2}-\d{2}))?\s*$", re.M)


def version_key(version: str) -> tuple[int, ...]:
    return tuple(int(part) for part in re.match(r"\d+(\.\d+)*", version).group(0).split("."))


def sections() -> dict[str, str]:
    """Each released version's notes by version ([Unreleased] left out)."""
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    heads = list(SECTION.finditer(text))
    notes = {}
    for head, after in zip(heads, heads[1:] + [None]):
        if head["version"] == "Unreleased":
            continue
        assert head["date"], f"release {head['version']} has no date in its heading"
        notes[head["version"]] = text[head.end() : after.start() if after else len(text)]
    return notes


def commands() -> list[str]:
    from lgf_fmus.cli import parser

    sub = next(a for a in parser()._actions if a.__class__.__name__ == "_SubParsersAction")
    return sorted(sub.choices)


def first_named(name: str, notes: dict[str, str]) -> str | None:
    pattern = re.compile(rf"(?<![\w-]){re.escape(name)}(?![\w-])")
    named = [v for v, text in notes.items() if pattern.search(text)]
    return min(named, key=version_key) if named else None


def test_the_version_has_its_section():
    version = (ROOT / "VERSION").read_text(encoding="utf-8").strip()
    assert version in sections(), f"CHANGELOG.md has no `## [{version}] - <date>` section"


def test_every_block_and_command_is_in_the_notes_of_a_release():
    version = (ROOT / "VERSION").read_text(encoding="utf-8").strip()
    notes = sections()
    blocks = sorted(p.parent.name for p in (ROOT / "src" / "blocks").glob("*/interface.toml"))
    assert len(blocks) == 22
    missing, late = [], []
    for name in blocks + [f"lgf_fmus {c}" for c in commands()]:
        first = first_named(name.replace("lgf_fmus ", "python -m lgf_fmus "), notes)
        if first is None and name.startswith("lgf_fmus "):  # also written `lgf-fmus compile`
            first = first_named(name.replace("lgf_fmus ", "lgf-fmus "), notes)
        if first is None:
            missing.append(name)
        elif version_key(first) > version_key(version):
            late.append(f"{name} ({first})")
    assert not missing, f"named in no release's notes: {', '.join(missing)}"
    assert not late, f"first named after VERSION {version}: {', '.join(late)}"


def test_the_check_finds_a_name_missing_from_the_notes():
    notes = {"0.1.0": "- LGF_SawTooth: a sawtooth", "0.2.0": "- `lgf-fmus compile`: SCL"}
    assert first_named("LGF_SawTooth", notes) == "0.1.0"
    assert first_named("LGF_Saw", notes) is None  # whole names only
    assert first_named("lgf-fmus compile", notes) == "0.2.0"
    assert first_named("LGF_RampCI", notes) is None
