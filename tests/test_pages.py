"""The generated parts of the Markdown pages (tools/pages.py) are what their source writes today:
each block's src/blocks/<Block>/README.md holds between its interface markers the table its
interface table generates (the same JSON as modelDescription.xml and documentation/index.html),
and python/README.md, the package index page, is docs/python.md with its links made relative to
python/. After a change of an interface table or of docs/python.md: `make descriptions`, review
the diff, commit it. Each block page shows the block's typical run (its first scenario, drawn by
`make references` beside the page), the picture of its FMU's documentation."""

import pytest

from tests.harness import ROOT
from tests.lgf_blocks import find, names
from tools import pages

BUILD = ROOT / "build"


@pytest.mark.parametrize("block", names())
def test_the_block_page_s_interface_table_is_the_generated_one(block):
    page = ROOT / "src" / "blocks" / block / "README.md"
    committed = page.read_text(encoding="utf-8")
    assert committed.count(pages.INTERFACE_START) == 1
    assert committed.count(pages.INTERFACE_END) == 1
    assert pages.block_page(block, BUILD) == committed, (
        f"the interface table of src/blocks/{block}/README.md differs from what its interface "
        "table generates: run `make descriptions` and review the diff"
    )


def test_every_block_has_its_page():
    assert pages.block_names() == sorted(names())


def test_the_table_lists_every_variable_with_both_fmi_types():
    fmi2 = pages.describe("LGF_SinusCI", "json", BUILD)
    table = pages.interface_table(fmi2, pages.describe("LGF_SinusCI", "json3", BUILD))
    rows = table.splitlines()[2:]
    assert len(rows) == len(fmi2["variables"])
    [periode] = [r for r in rows if r.startswith("| `periode` ")]
    assert "Integer / UInt32 (UDINT)" in periode
    assert "1 … 2147483647 (FMI 3.0: 1 … 4294967295)" in periode


def test_a_cell_cannot_end_its_row():
    assert pages.cell("a | b") == "a \\| b"


def test_the_package_index_page_is_docs_python_md():
    text = (ROOT / "docs" / "python.md").read_text(encoding="utf-8")
    generated = pages.package_readme(text)
    assert (ROOT / "python" / "README.md").read_text(encoding="utf-8") == generated, (
        "python/README.md differs from docs/python.md: run `make descriptions` (or "
        "python -m tools.pages)"
    )
    assert "](../docs/behaviour.md)" in generated and "](../README.md)" in generated
    assert pages.package_readme("[x](scl.md) [y](https://a.b/c) [z](#top)").endswith(
        "[x](../docs/scl.md) [y](https://a.b/c) [z](#top)"
    )


@pytest.mark.parametrize("block", names())
def test_the_block_page_shows_its_typical_run(block):
    folder = ROOT / "src" / "blocks" / block
    page = (folder / "README.md").read_text(encoding="utf-8")
    assert "## A typical run\n" in page and "](typical_run.png)" in page
    assert f"`{find(block).scenarios[0].name}`" in page, "the page names the run it shows"
    assert (folder / "typical_run.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", (
        f"src/blocks/{block}/typical_run.png is missing: `make references` draws it"
    )
