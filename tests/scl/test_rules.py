"""Every rule of docs/scl.md §3 has an ID ([S7-WRAP-1]: a rule of S7; [DEC-DIV-0]: a decision
of ours) and a test that cites it; no test cites an ID that no rule has. A test cites a rule by
its ID in a comment or docstring (`# docs/scl.md rules: [S7-WRAP-1]`), so that a rule without a
test, and a test of a rule since removed, show here (as ironplc's spec-conformance tests)."""

from __future__ import annotations

import re
from pathlib import Path

from tests.scl.driver import ROOT

ID = re.compile(r"\[((?:S7|DEC)-[A-Z0-9]+(?:-[A-Z0-9]+)*)\]")
DOCS = (ROOT / "docs" / "scl.md").read_text(encoding="utf-8")
RULES = DOCS.split("\n## 3 ")[1].split("\n## 4 ")[0]
TESTS = {
    p.name: p.read_text(encoding="utf-8")
    for p in sorted(Path(__file__).parent.glob("test_*.py"))
    if p.name != Path(__file__).name
}


def rule_ids() -> list[str]:
    return ID.findall(RULES)


def cited() -> dict[str, set[str]]:
    """ID -> the test files that cite it."""
    found: dict[str, set[str]] = {}
    for name, text in TESTS.items():
        for rule in ID.findall(text):
            found.setdefault(rule, set()).add(name)
    return found


def test_the_rules_are_in_section_3():
    """An ID stands before its rule, and may stand again where another rule refers to it."""
    assert len(set(rule_ids())) >= 50
    assert set(ID.findall(DOCS)) == set(rule_ids())  # only §3 holds rules


def test_every_rule_is_cited_by_a_test():
    missing = sorted(set(rule_ids()) - set(cited()))
    assert missing == [], f"rules no test cites: {missing}"


def test_no_test_cites_a_rule_that_does_not_exist():
    unknown = {rule: files for rule, files in cited().items() if rule not in rule_ids()}
    assert unknown == {}, f"tests citing rules docs/scl.md §3 does not have: {unknown}"
