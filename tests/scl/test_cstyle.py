"""The generated C reads like ours (docs/scl.md §4): each statement after a comment of its
place in the SCL (`/* file.scl:LINE */`), no `(void)x;` lines (a local the statements never
name is not declared, one they only assign is SCL_UNUSED), no cast of a literal, and laid out by
clang-format in the project's style where it is installed."""

from __future__ import annotations

import re

import pytest

from lgf_fmus import scl
from lgf_fmus.scl import ast as A
from lgf_fmus.scl import cformat, parser
from tests.scl.driver import TWINS
from tests.scl.test_constructs import DATA

PROGRAMS = {p.stem: p.read_text(encoding="utf-8") for p in sorted(TWINS.glob("*.scl"))}
PROGRAMS["Data"] = DATA


@pytest.fixture(scope="module", params=sorted(PROGRAMS))
def program(request, tmp_path_factory):
    """(the SCL file, its text, the generated files) of a program of the tests."""
    name = request.param
    path = tmp_path_factory.mktemp("cstyle") / f"{name}.scl"
    path.write_text(PROGRAMS[name], encoding="utf-8")
    return path, PROGRAMS[name], scl.generate_c([path], name)


def test_each_statement_follows_a_comment_of_its_line(program):
    path, text, files = program
    block_c = files[f"blocks/{path.stem}/block.c"]
    marked = {int(n) for n in re.findall(rf"/\* {re.escape(path.name)}:(\d+) \*/", block_c)}
    statements = {
        n.loc.line
        for unit in parser.parse(text, str(path))
        if isinstance(unit, A.Block)
        for n in A.nodes(unit.body)
        if isinstance(n, A.Stmt) and not isinstance(n, A.Region)
    }
    assert marked == statements


def test_no_void_lines_and_no_cast_of_a_literal(program):
    _, _, files = program
    for name, code in files.items():
        assert not re.search(r"^\s*\(void\)", code, re.M), name
        literal_cast = r"\(\((?:u?int\d+_t|float|double|iec_time|bool)\)-?[0-9.]+[fu]?\)"
        assert re.findall(literal_cast, code) == [], name


@pytest.mark.skipif(cformat.executable() is None, reason="no clang-format installed")
def test_the_c_is_in_the_project_s_style(program):
    _, _, files = program
    c_files = {k: v for k, v in files.items() if k.endswith((".c", ".h"))}
    assert cformat.formatted(c_files) == c_files  # clang-format changes nothing
    for name, code in c_files.items():
        assert max(map(len, code.splitlines())) <= 100, name
