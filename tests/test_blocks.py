"""The blocks of the test suite (tests/lgf_blocks.py: the folders of tests/blocks/) are the blocks
of the C side (the folders of src/blocks/ with an interface.c), each has its FMU, and a folder
that lacks part of what a block folder holds is refused, saying what is missing."""
import pytest

from tests.harness import FMU_DIR, ROOT
from tests.lgf_blocks import MODULES, BlockFolderError, discover, names


def test_the_blocks_are_the_blocks_of_the_c_side():
    c_blocks = {p.parent.name for p in (ROOT / "src" / "blocks").glob("*/interface.c")}
    python_blocks = set(names())
    assert python_blocks == c_blocks, (
        f"in tests/blocks/ but without src/blocks/<Block>/interface.c: "
        f"{sorted(python_blocks - c_blocks)}; in src/blocks/ but without tests/blocks/<Block>/: "
        f"{sorted(c_blocks - python_blocks)}")


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


SPEC_PY = """from hypothesis import strategies as st
from tests.block_spec import BlockSpec
SPEC = BlockSpec(make_model=None, cycles_us=st.just(100000), parameters=lambda: st.just({}), inputs={})
ACTIVE = {}
ORIGINAL_NAMES = []
"""
SCENARIOS_PY = """from tools.scenario import Scenario
SCENARIOS = [Scenario(name="new_table", block="LGF_New", title="t", stop_time=1.0,
                      parameters={"numberOfSetpoints": 2}),
             Scenario(name="new_plain", block="LGF_New", title="t", stop_time=1.0)]
"""


@pytest.mark.parametrize("line, message", [
    ("", "must define COMPATIBILITY"),
    ("COMPATIBILITY = 'missing'", "'missing', which is not one of SCENARIOS"),
    ("COMPATIBILITY = 'new_table'", "'new_table', which sets parameters"),
])
def test_the_compatibility_scenario_is_one_without_parameters(tmp_path, monkeypatch, line, message):
    def block_folder(name, compatibility_line):
        package = tmp_path / name  # a package of its own per folder: no module cached
        folder = package / "LGF_New"
        folder.mkdir(parents=True)
        (package / "__init__.py").write_text("")
        for module in ("__init__", "model"):
            (folder / f"{module}.py").write_text("")
        (folder / "cross.py").write_text("def script(md):\n    return ''\n")
        (folder / "spec.py").write_text(SPEC_PY)
        (folder / "scenarios.py").write_text(SCENARIOS_PY + compatibility_line + "\n")
        return package

    monkeypatch.syspath_prepend(str(tmp_path))
    with pytest.raises(BlockFolderError, match=message):
        discover(block_folder(f"{tmp_path.name}_bad", line), package=f"{tmp_path.name}_bad")
    good = block_folder(f"{tmp_path.name}_good", "COMPATIBILITY = 'new_plain'")
    [block] = discover(good, package=f"{tmp_path.name}_good")
    assert block.compatibility.name == "new_plain"
