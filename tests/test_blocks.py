"""The blocks of the test suite (tests/lgf_blocks.py: the folders of tests/blocks/) are the blocks
of the C side (the folders of src/blocks/ with an interface.toml, tools/blocks.py), each has its
FMU, and a folder that lacks part of what a block folder holds, or a block's scenarios.py that
lacks part of what it holds, is refused, saying what is missing."""

from pathlib import Path

import pytest

from tests.harness import FMU_DIR, ROOT
from tests.lgf_blocks import MODULES, BlockFolderError, blocks, discover, names
from tools import blocks as build_blocks


def test_the_blocks_are_the_blocks_of_the_c_side():
    c_blocks = {p.parent.name for p in (ROOT / "src" / "blocks").glob("*/interface.toml")}
    python_blocks = set(names())
    assert python_blocks == c_blocks, (
        f"in tests/blocks/ but without src/blocks/<Block>/interface.toml: "
        f"{sorted(python_blocks - c_blocks)}; in src/blocks/ but without tests/blocks/<Block>/: "
        f"{sorted(c_blocks - python_blocks)}"
    )


@pytest.mark.parametrize("block", names())
def test_every_block_has_its_fmu(block):
    assert (FMU_DIR / f"{block}.fmu").is_file(), f"fmus/{block}.fmu is missing: run `make build`"


@pytest.mark.parametrize("module", MODULES)
def test_a_folder_without_one_of_the_modules_is_refused(tmp_path, module):
    folder = tmp_path / "LGF_New"
    folder.mkdir()
    for name in ("__init__", *MODULES):
        if name != module:
            (folder / f"{name}.py").write_text("")
    with pytest.raises(BlockFolderError, match=rf"LGF_New/ lacks {module}\.py"):
        discover(tmp_path, package="nowhere")


def test_an_empty_blocks_folder_is_refused(tmp_path):
    (tmp_path / "__pycache__").mkdir()
    with pytest.raises(BlockFolderError, match="no block folder"):
        discover(tmp_path, package="nowhere")


SCENARIOS_PY = """from tools.scenario import Scenario
SCENARIOS = [Scenario(name="new_table", block="LGF_New", title="t", stop_time=1.0,
                      parameters={"numberOfSetpoints": 2}),
             Scenario(name="new_plain", block="LGF_New", title="t", stop_time=1.0)]
"""


def build_block(root: Path, package: str, scenarios_py: str | None) -> Path:
    """A folder like src/blocks/ with the one block LGF_New, in a package of its own (so that
    no module is cached), on the import path."""
    directory = root / package
    folder = directory / "LGF_New"
    folder.mkdir(parents=True)
    (directory / "__init__.py").write_text("")
    (folder / "interface.toml").write_text("")
    if scenarios_py is not None:
        (folder / "scenarios.py").write_text(scenarios_py)
    return directory


@pytest.mark.parametrize(
    "line, message",
    [
        ("", "the first scenario 'new_table' sets parameters, so COMPATIBILITY must name"),
        ("COMPATIBILITY = 1", "must define COMPATIBILITY"),
        ("COMPATIBILITY = 'missing'", "'missing', which is not one of SCENARIOS"),
        ("COMPATIBILITY = 'new_table'", "'new_table', which sets parameters"),
    ],
)
def test_the_compatibility_scenario_is_one_without_parameters(tmp_path, monkeypatch, line, message):
    monkeypatch.syspath_prepend(str(tmp_path))
    bad = f"{tmp_path.name}_bad"
    with pytest.raises(BlockFolderError, match=message):
        build_blocks.discover(build_block(tmp_path, bad, SCENARIOS_PY + line + "\n"), bad)
    good = f"{tmp_path.name}_good"
    directory = build_block(tmp_path, good, SCENARIOS_PY + "COMPATIBILITY = 'new_plain'\n")
    [block] = build_blocks.discover(directory, good)
    assert block.compatibility.name == "new_plain"
    assert [s.name for s in block.scenarios] == ["new_table", "new_plain"]


def test_a_scenario_takes_its_block_from_the_folder_and_the_first_is_the_compatibility_one(
    tmp_path, monkeypatch
):
    monkeypatch.syspath_prepend(str(tmp_path))
    package = f"{tmp_path.name}_plain"
    plain = (
        "from tools.scenario import Scenario\n"
        "SCENARIOS = [Scenario(name='new_plain', title='t', stop_time=1.0)]\n"
    )
    [block] = build_blocks.discover(build_block(tmp_path, package, plain), package)
    assert block.compatibility is block.scenarios[0]
    assert block.scenarios[0].block == "LGF_New"
    other = f"{tmp_path.name}_other"
    with pytest.raises(BlockFolderError, match="'new_plain' is not a Scenario of block 'LGF_New'"):
        build_blocks.discover(
            build_block(tmp_path, other, plain.replace("t',", "t', block='X',")), other
        )


def test_a_block_without_scenarios_is_refused(tmp_path, monkeypatch):
    monkeypatch.syspath_prepend(str(tmp_path))
    package = f"{tmp_path.name}_none"
    with pytest.raises(BlockFolderError, match=r"LGF_New/ lacks scenarios\.py"):
        build_blocks.discover(build_block(tmp_path, package, None), package)


def test_a_test_folder_of_no_block_is_refused(tmp_path):
    folder = tmp_path / "LGF_Gone"
    folder.mkdir()
    for name in ("__init__", *MODULES):
        (folder / f"{name}.py").write_text("")
    with pytest.raises(BlockFolderError, match=r"LGF_Gone/ is no block of src/blocks/"):
        discover(tmp_path, package="nowhere")


def test_the_build_and_the_tests_see_the_same_scenarios():
    """The test suite's blocks carry the build's scenarios, the very objects."""
    for block in blocks():
        built = build_blocks.find(block.name)
        assert block.scenarios is built.scenarios and block.compatibility is built.compatibility
        assert block.reference(block.scenarios[0]) == built.reference(block.scenarios[0])
