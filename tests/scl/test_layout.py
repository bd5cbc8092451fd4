"""The compiler's layout (docs/scl.md §1): no file of it over 600 lines, and what the checks find
kept in declared fields, never looked up by hasattr on the tree."""

from __future__ import annotations

from pathlib import Path

import pytest

from lgf_fmus import scl

PACKAGE = Path(scl.__file__).parent
FILES = sorted(PACKAGE.glob("*.py"))


@pytest.mark.parametrize("path", FILES, ids=[p.name for p in FILES])
def test_no_file_of_the_compiler_is_over_600_lines(path):
    assert len(path.read_text(encoding="utf-8").splitlines()) <= 600


def test_nothing_dispatches_on_attributes_hung_on_the_tree():
    for path in FILES:
        assert "hasattr(" not in path.read_text(encoding="utf-8"), path.name
