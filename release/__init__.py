"""Releases: the compatibility information of every FMU (release/compat.py: the reference
experiment inside each FMU, under extra/org.fmi-standard.fmi-ls-ref/, and next to it in the
release) and the release zip (release/dist.py, `make dist`)."""
from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
VERSION_FILE = ROOT / "VERSION"


def version() -> str:
    """The version of the FMUs and of the Python package: the one line of VERSION."""
    text = VERSION_FILE.read_text(encoding="utf-8").strip()
    if not text or len(text.splitlines()) != 1:
        raise ValueError(f"{VERSION_FILE} must hold one line, the version (e.g. 0.1.0)")
    return text
