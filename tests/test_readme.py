"""Every ```python snippet of the project's Markdown pages (README.md, docs/*.md, each block's
src/blocks/<Block>/README.md, every other `.md` of the repository) runs as a new user would run
it: as a script of its own, from the repository root, with the FMUs of fmus/. It must end
without error and without FMPy's "missing input" warnings, and where a ```text block follows it
(nothing but blank lines between), print exactly that. A snippet preceded by an HTML comment
`<!-- not executed: <reason> -->` (e.g. the OMSimulator script, whose package is not installed
here) is no test here: python/tests/test_plugin.py runs those that need the package. Every
relative link and picture of these pages names a file of the repository."""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

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


def markdown_pages() -> list[Path]:
    """The repository's Markdown files (tracked, or new and not ignored), README.md first."""
    listed = subprocess.run(
        ["git", "ls-files", "--cached", "--others", "--exclude-standard", "*.md"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()
    pages = sorted({ROOT / name for name in listed if (ROOT / name).is_file()})
    return sorted(pages, key=lambda p: p != ROOT / "README.md")


PAGES = markdown_pages()
README = (ROOT / "README.md").read_text(encoding="utf-8")
SNIPPETS = [
    {**s, "page": page.relative_to(ROOT).as_posix()}
    for page in PAGES
    for s in snippets(page.read_text(encoding="utf-8"))
]
EXECUTED = [s for s in SNIPPETS if s["skip"] is None]


def test_the_pages_have_snippets_and_the_chain_example():
    assert {p.relative_to(ROOT).as_posix() for p in PAGES} >= {
        "README.md",
        "docs/importing.md",
        "docs/python.md",
        "src/blocks/LGF_RampCI/README.md",
    }
    assert len(EXECUTED) >= 6
    assert any(
        "LGF_SawTooth.fmu" in s["code"] and "LGF_LimRateOfChangeCI.fmu" in s["code"]
        for s in EXECUTED
    )
    assert all(s["expected"] is not None for s in EXECUTED), (
        "every executed snippet shows its output in a ```text block below it"
    )


@pytest.mark.parametrize(
    "snippet", EXECUTED, ids=[f"{s['page']}:line{s['line']}" for s in EXECUTED]
)
def test_snippet_runs_as_shown(snippet, tmp_path):
    where = f"{snippet['page']} line {snippet['line']}"
    run_as_shown(snippet, where, tmp_path / "snippet.py", ROOT, seconds=120)


def run_as_shown(snippet: dict, where: str, script: Path, cwd: Path, seconds: float) -> None:
    """The snippet as the script of its own `script`, run in cwd: it ends without error and
    without FMPy's "missing input" warnings, and prints exactly its ```text block if it has one
    (python/tests/test_plugin.py runs the package's snippets so too)."""
    script.write_text(snippet["code"], encoding="utf-8")
    run = subprocess.run(
        [sys.executable, str(script)],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=hang_guard(seconds),
        env={**os.environ, "MPLBACKEND": "Agg", "PYTHONDONTWRITEBYTECODE": "1"},
    )
    assert run.returncode == 0, f"{where} fails:\n{run.stderr[-3000:]}"
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


def local_links(text: str) -> list[str]:
    """The relative links and pictures of a Markdown text, outside code, without #anchors."""
    prose = re.sub(r"`[^`\n]*`", "", FENCE.sub("", text))
    targets = re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", prose)
    return [t for t in targets if not re.match(r"\w+:", t)]


def test_the_readme_s_links_and_picture_exist():
    """Every relative link and image of README.md names a file of the repository, and the
    picture at the top is there (written by `make references` from the blocks' typical runs)."""
    local = local_links(README)
    assert "docs/overview.png" in local
    missing = [t for t in local if not (ROOT / t).exists()]
    assert missing == []
    assert (ROOT / "docs" / "overview.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_the_readme_is_a_five_minute_page_linking_every_block_s_page():
    """README.md stays short; its table links the page beside each block."""
    assert README.count("\n") <= 300
    blocks = sorted(p.parent.name for p in (ROOT / "src" / "blocks").glob("*/interface.toml"))
    for block in blocks:
        assert f"](src/blocks/{block}/README.md)" in README, block


@pytest.mark.parametrize("page", PAGES, ids=[p.relative_to(ROOT).as_posix() for p in PAGES])
def test_every_page_s_links_exist(page):
    """Every relative link and picture of a Markdown page names a file, relative to the page."""
    missing = [
        t for t in local_links(page.read_text(encoding="utf-8")) if not (page.parent / t).exists()
    ]
    assert missing == []
