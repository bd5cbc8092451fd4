"""The table of built-ins (lgf_fmus.scl.builtins, docs/scl.md §1): every entry has its S7
signature, its rule in docs/scl.md §3 and a test program that calls it, so that a new built-in
is its entry, its rule and its tests."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from lgf_fmus.scl import builtins
from tests.scl.driver import ROOT

DOCS = (ROOT / "docs" / "scl.md").read_text(encoding="utf-8")
RULES = DOCS.split("\n## 3 ")[1].split("\n## 4 ")[0]
TESTS = "".join(p.read_text(encoding="utf-8") for p in Path(__file__).parent.rglob("*.py"))
TESTS += "".join(p.read_text(encoding="utf-8") for p in Path(__file__).parent.rglob("*.scl"))
NAMES = sorted(n for n in builtins.REGISTRY if n != "*_TO_*")


@pytest.mark.parametrize("name", NAMES)
def test_a_built_in_has_its_signature_rule_and_test(name):
    entry = builtins.REGISTRY[name]
    assert entry.signatures and all(s.strip() for s in entry.signatures)
    assert re.search(rf"`{name}\b", RULES), f"{name} has no rule in docs/scl.md §3"
    assert re.search(rf"\b{name}\s*\(", TESTS, re.I), f"no test program calls {name}"


def test_the_conversions_are_one_entry():
    assert builtins.lookup("int_to_real") is builtins.REGISTRY["*_TO_*"]
    assert builtins.lookup("Sqr") is builtins.REGISTRY["SQR"]
    assert builtins.lookup("NOTHING") is None
