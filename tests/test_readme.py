"""Every ```python snippet of README.md runs as a new user would run it: as a script of its own,
from the repository root, with the FMUs of fmus/. It must end without error and without FMPy's
"missing input" warnings, and where a ```text block follows it (nothing but blank lines
between), print exactly that. A snippet preceded by an HTML comment
`<!-- not executed: <reason> -->` (e.g. the OMSimulator script, whose package is not installed
here) is no test here: python/tests/test_plugin.py runs those that need the package."""

from __future__ import annotations

import os
import re
import subprocess
import sys

import pytest

from tests.harness import ROOT
from tests.timeouts import hang_guard

FENCE = re.compile(r"^```(\w*)\n(.*?)^```\n", re.S | re.M)
SKIP = re.compile(r"<!--\s*not executed:\s*(.*?)\s*-->\s*\Z", re.S)


def snippets(text: str) -> list[dict]:
    """The python blocks of a Markdown text: code, expected output (or None), skip reason (or
    None) and line number."""
    blocks = list(FENCE.finditer(text))
    found = []
    for i, block in enumerate(blocks):
        if block.group(1) != "python":
            continue
        following = blocks[i + 1] if i + 1 < len(blocks) else None
        expected = None
        if (
            following
            and following.group(1) == "text"
            and not text[block.end() : following.start()].strip()
        ):
            expected = following.group(2)
        before = text[blocks[i - 1].end() if i else 0 : block.start()]
        skip = SKIP.search(before)
        found.append(
            {
                "code": block.group(2),
                "expected": expected,
                "skip": skip.group(1) if skip else None,
                "line": text.count("\n", 0, block.start()) + 1,
            }
        )
    return found


README = (ROOT / "README.md").read_text(encoding="utf-8")
SNIPPETS = snippets(README)
EXECUTED = [s for s in SNIPPETS if s["skip"] is None]


def test_the_readme_has_snippets_and_the_chain_example():
    assert len(SNIPPETS) >= 4
    assert any(
        "LGF_SawTooth.fmu" in s["code"] and "LGF_LimRateOfChangeCI.fmu" in s["code"]
        for s in SNIPPETS
        if s["skip"] is None
    )
    assert all(s["expected"] is not None for s in SNIPPETS if s["skip"] is None), (
        "every executed snippet shows its output in a ```text block below it"
    )


@pytest.mark.parametrize("snippet", EXECUTED, ids=[f"line{s['line']}" for s in EXECUTED])
def test_readme_snippet_runs_as_shown(snippet, tmp_path):
    script = tmp_path / "snippet.py"
    script.write_text(snippet["code"], encoding="utf-8")
    run = subprocess.run(
        [sys.executable, str(script)],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=hang_guard(120),
        env={**os.environ, "MPLBACKEND": "Agg", "PYTHONDONTWRITEBYTECODE": "1"},
    )
    where = f"README.md line {snippet['line']}"
    assert run.returncode == 0, f"{where} fails:\n{run.stderr}"
    assert "missing input" not in run.stdout + run.stderr, f"{where}: FMPy warns\n{run.stdout}"
    if snippet["expected"] is not None:
        assert run.stdout == snippet["expected"], f"{where} prints\n{run.stdout}"


def test_snippets_are_found_and_the_skip_comment_is_honoured():
    text = (
        "<!-- not executed: needs X -->\n```python\nimport X\n```\n\n"
        "```python\nprint(1)\n```\n\n```text\n1\n```\n"
    )
    first, second = snippets(text)
    assert first["skip"] == "needs X" and first["expected"] is None
    assert second["skip"] is None and second["expected"] == "1\n"


def test_the_readme_s_links_and_picture_exist():
    """Every relative link and image of README.md names a file of the repository, and the
    picture at the top is there (written by `make references` from the FMUs' default runs)."""
    prose = re.sub(r"`[^`\n]*`", "", FENCE.sub("", README))  # links outside code
    targets = re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", prose)
    local = [t for t in targets if not re.match(r"\w+://", t)]
    assert "docs/overview.png" in local
    missing = [t for t in local if not (ROOT / t).exists()]
    assert missing == []
    assert (ROOT / "docs" / "overview.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
