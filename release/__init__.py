"""Releases: the release zip (release/dist.py, `make dist`) of the FMUs and their compatibility
information (release/compat.py: the reference experiment inside each FMU, under
extra/org.fmi-standard.fmi-ls-ref/, and next to it in the release)."""
from __future__ import annotations

from tools import ROOT, version  # noqa: F401 (the release's version: the one line of VERSION)
