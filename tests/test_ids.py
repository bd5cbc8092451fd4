"""`pytest -k <Block>` selects every test of a block: the id of every test whose parameters
name a block (a Block, a Scenario, or a block's name) holds that name as a whole part (ids are
split at '-'). The suites are collected in a subprocess (`pytest --collect-only`) with
IdRecorder as a plugin, so the check sees every test, whatever this run selected."""

from __future__ import annotations

import json
import re
import subprocess
import sys

import pytest

from tests.harness import ROOT
from tests.lgf_blocks import Block, blocks, names, param_id
from tests.timeouts import hang_guard
from tools.scenario import Scenario


def named_blocks(value) -> set[str]:
    """The blocks a parameter value names."""
    if isinstance(value, Block):
        return {value.name}
    if isinstance(value, Scenario):
        return {value.block}
    if isinstance(value, str) and value in names():
        return {value}
    return set()


class IdRecorder:
    """A pytest plugin: writes, for every collected test with parameters, its node id, its
    parameter id and the blocks and scenarios its parameters name, as JSON to `path`."""

    def __init__(self, path):
        self.path = path

    def pytest_collection_finish(self, session):
        rows = []
        for item in session.items:
            spec = getattr(item, "callspec", None)
            if spec is None:
                continue
            values = list(spec.params.values())
            rows.append(
                {
                    "nodeid": item.nodeid,
                    "id": spec.id,
                    "blocks": sorted(set().union(*map(named_blocks, values))),
                    "scenarios": [f"{v.block}-{v.name}" for v in values if isinstance(v, Scenario)],
                }
            )
        with open(self.path, "w", encoding="utf-8") as file:
            json.dump(rows, file)


COLLECT = (
    "import sys, pytest\n"
    "from tests.test_ids import IdRecorder\n"
    "sys.exit(pytest.main(['--collect-only', '-q', '-p', 'no:cacheprovider', sys.argv[2]],"
    " plugins=[IdRecorder(sys.argv[1])]))\n"
)


def collected(suite: str, tmp_path) -> list[dict]:
    out = tmp_path / "ids.json"
    run = subprocess.run(
        [sys.executable, "-c", COLLECT, str(out), suite],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=hang_guard(300),
    )
    assert run.returncode == 0, f"collecting {suite} fails:\n{run.stdout}\n{run.stderr}"
    return json.loads(out.read_text(encoding="utf-8"))


def parts(test_id: str) -> set[str]:
    return set(re.split(r"[-\[\]]", test_id))


def test_param_id_names_the_block():
    block = blocks()[0]
    scenario = block.scenarios[0]
    assert param_id(block) == block.name
    assert param_id(scenario) == f"{block.name}-{scenario.name}"
    assert param_id(block.name) is None and param_id(0.1) is None


try:  # the package lgf-fmus importable, installed or on PYTHONPATH
    import lgf_fmus  # noqa: F401

    PACKAGE = True
except ImportError:
    PACKAGE = False


@pytest.mark.parametrize(
    "suite",
    [
        "tests",
        pytest.param(
            "python/tests",
            marks=pytest.mark.skipif(
                not PACKAGE,
                reason="python/tests needs the package lgf-fmus installed (make package)",
            ),
        ),
    ],
)
def test_every_test_of_a_block_has_the_block_in_its_id(suite, tmp_path):
    rows = collected(suite, tmp_path)
    of_blocks = [r for r in rows if r["blocks"]]
    assert of_blocks, f"no test of {suite} takes a block or a scenario"
    missing = [r["nodeid"] for r in of_blocks if not set(r["blocks"]) <= parts(r["id"])]
    assert missing == [], f"tests whose id does not name their block: {missing}"
    # every scenario parameter is "<Block>-<scenario>" in the id
    unnamed = [r["nodeid"] for r in rows for s in r["scenarios"] if s not in r["id"]]
    assert unnamed == [], unnamed
    if suite == "tests":  # each block, and each of its scenarios, has tests that name it
        ids = {r["id"] for r in of_blocks}
        for block in blocks():
            assert any(block.name in parts(i) for i in ids), block.name
            for scenario in block.scenarios:
                assert any(param_id(scenario) in i for i in ids), param_id(scenario)
