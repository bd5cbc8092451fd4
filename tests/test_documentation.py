"""What an FMU's documentation (documentation/index.html, tools/documentation.py) says to the
person who opens it: each page speaks its own FMI version (the FMI 3.0 page names fmi3DoStep,
fmi3Error, fmi3Int16, never an fmi2 function or type, and the FMI 2.0 page no fmi3 one), and it
names no file the FMU does not contain (no file of this repository, such as a block's
scenarios.py or docs/behaviour.md) and no word of the project's own (the seed, the test suite)."""

from __future__ import annotations

import re
import zipfile
from html.parser import HTMLParser

import pytest

from tests.lgf_blocks import names
from tools.simulate import FMU_DIR

PAGES = [(block, fmi) for block in names() for fmi in (2, 3)]
IDS = [f"{block}-fmi{fmi}" for block, fmi in PAGES]


def fmu(block: str, fmi: int):
    return FMU_DIR / (f"{block}.fmu" if fmi == 2 else f"fmi3/{block}.fmu")


class _Text(HTMLParser):
    """The page as a reader meets it: its text and the targets of its links and pictures
    (the icon, inlined as data, is no file)."""

    def __init__(self):
        super().__init__()
        self.text, self.targets = [], []

    def handle_starttag(self, tag, attrs):
        for name, value in attrs:
            if name in ("href", "src") and value and not value.startswith("data:"):
                self.targets.append(value)

    def handle_data(self, data):
        self.text.append(data)


def read_page(block: str, fmi: int) -> tuple[str, list[str], set[str]]:
    """(text, link targets, the FMU's files and folders) of a block's FMI <fmi>.0 page."""
    with zipfile.ZipFile(fmu(block, fmi)) as z:
        entries = [n.removeprefix("./") for n in z.namelist()]
        page = _Text()
        page.feed(z.read("documentation/index.html").decode("utf-8"))
    contained = set(entries)
    for name in entries:  # and every folder on the way to a file
        parts = name.split("/")
        contained |= {"/".join(parts[:k]) + "/" for k in range(1, len(parts))}
    return " ".join(page.text), page.targets, contained


@pytest.mark.parametrize(("block", "fmi"), PAGES, ids=IDS)
def test_the_page_speaks_its_fmi_version(block, fmi):
    text, _, _ = read_page(block, fmi)
    other = "fmi3" if fmi == 2 else "fmi2"
    assert other not in text, re.findall(rf"\S*{other}\S*", text)
    for name in (f"fmi{fmi}DoStep", f"fmi{fmi}ExitInitializationMode", f"fmi{fmi}Error"):
        assert name in text, name
    if fmi == 3:  # the types of the FMI 3.0 modelDescription
        assert "fmi3Int16" in text and "fmi3UInt16" in text and "fmi3Float64" in text


# A file or folder a page could name: a file name with an extension (fmi-ls-ref.txt,
# core/numerics.h) or a folder (binaries/); not a ratio such as time/cycleTime.
EXTENSIONS = "py|md|c|h|csv|txt|json|xml|png|html"
PATH = re.compile(
    rf"(?<![\w./-])((?:[\w.-]+/)*[\w-]+\.(?:{EXTENSIONS})(?![\w/])|(?:[A-Za-z_][\w.-]*/)+(?![\w/]))"
)
# The project's own words, which mean nothing to the user of an FMU.
PROJECT_WORDS = ("the seed", "test suite", "committed", "demo scenario", "this project")


@pytest.mark.parametrize(("block", "fmi"), PAGES, ids=IDS)
def test_the_page_names_only_files_the_fmu_contains(block, fmi):
    text, targets, contained = read_page(block, fmi)
    named = PATH.findall(text) + targets
    assert "sources/" in named and "typical_run.png" in targets  # the pattern finds them
    for path in named:
        found = [p for p in (path, f"documentation/{path}", f"sources/{path}") if p in contained]
        assert found, f"the page names {path}, which the FMU does not contain"
    for words in PROJECT_WORDS:
        assert words not in text.lower(), words


def test_the_pattern_finds_what_a_page_could_name():
    text = (
        "see src/blocks/X/scenarios.py, docs/behaviour.md and fmi-ls-ref.txt in extra/a.b/; "
        "1/s, time/cycleTime, S7-1200/1500, 3.5 s."
    )
    assert PATH.findall(text) == [
        "src/blocks/X/scenarios.py",
        "docs/behaviour.md",
        "fmi-ls-ref.txt",
        "extra/a.b/",
    ]
