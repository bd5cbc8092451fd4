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
