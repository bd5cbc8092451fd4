"""modelDescription/<Block>.xml is generated from the block's interface table (the interface.c
tools/interface.py writes from src/blocks/<Block>/interface.toml) by its describe program; the
committed file must be what the generator writes today, so the XML and the binary cannot drift
apart. After a change of a table:
`make descriptions`, review the diff, commit it."""

import subprocess
import xml.etree.ElementTree as ET

import pytest

from tests.harness import ROOT, unpacked
from tests.lgf_blocks import names


def describe(block: str, what: str) -> bytes:
    program = ROOT / "build" / f"describe_{block}"
    assert program.is_file(), f"{program.relative_to(ROOT)} is missing: run `make build`"
    return subprocess.run([str(program), what], check=True, capture_output=True).stdout


@pytest.mark.parametrize("block", names())
def test_the_committed_description_is_the_generated_one(block):
    committed = (ROOT / "modelDescription" / f"{block}.xml").read_bytes()
    assert describe(block, "xml") == committed, (
        f"modelDescription/{block}.xml differs from what its interface table generates: "
        "run `make descriptions` and review the diff"
    )


@pytest.mark.parametrize("block", names())
def test_the_description_offers_both_interfaces_from_one_binary(block):
    root = ET.fromstring(describe(block, "xml"))
    me, cs = root.find("ModelExchange"), root.find("CoSimulation")
    assert me is not None and cs is not None
    assert me.get("modelIdentifier") == cs.get("modelIdentifier") == block
    assert root.get("numberOfEventIndicators") == "0"


@pytest.mark.parametrize("block", names())
def test_every_output_depends_on_every_input(block):
    md, _ = unpacked(block)
    index = {v.name: i + 1 for i, v in enumerate(md.modelVariables)}
    inputs = sorted(index[v.name] for v in md.modelVariables if v.causality == "input")
    root = ET.fromstring(describe(block, "xml"))
    outputs = root.find("ModelStructure/Outputs")
    assert len(outputs) == len([v for v in md.modelVariables if v.causality == "output"])
    for unknown in outputs:
        assert [int(i) for i in unknown.get("dependencies").split()] == inputs
        assert unknown.get("dependenciesKind") is None  # "dependent", not a linear factor
