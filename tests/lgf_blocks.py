"""The blocks of the test suite: the folders of tests/blocks/, one per block, named by the FMU's
modelIdentifier. Every generic suite takes the blocks from `blocks()`; adding a block means
adding its folder (and its C side and scenarios in src/blocks/<Block>/), nothing here.

A block folder tests/blocks/<Block>/ holds:

    __init__.py      makes it the package tests.blocks.<Block>
    model.py         the independent Python model (from docs/behaviour.md, never from the C)
    spec.py          SPEC: its BlockSpec (tests/block_spec.py) for the property tests;
                     ACTIVE: inputs under which the block visibly works (generic interface tests);
                     ORIGINAL_NAMES: names of the original block the documentation must mention
    cross.py         script(md) -> str: its fixed scenario for tests/cross/scenario_runner.c
    references/      <scenario>.csv per scenario (written by `make references`)
    test_*.py        its own hand-traced tests

Its scenarios (SCENARIOS, COMPATIBILITY) are the build's: src/blocks/<Block>/scenarios.py, as
tools/blocks.py lists them. A folder that lacks one of these modules or names, or that is no
block of src/blocks/, makes blocks() raise BlockFolderError, saying what is missing. Folders
whose name starts with '_' or '.' (such as __pycache__) are not blocks.
"""

from __future__ import annotations

import importlib
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Callable

from tests.block_spec import BlockSpec
from tools import ROOT
from tools import blocks as build_blocks
from tools.blocks import BlockFolderError, attribute, shown
from tools.scenario import Scenario

BLOCKS_DIR = ROOT / "tests" / "blocks"
PACKAGE = "tests.blocks"
MODULES = ("model", "spec", "cross")


@dataclass(frozen=True)
class Block:
    name: str  # the folder's name: the FMU's modelIdentifier
    folder: Path
    model: ModuleType  # model.py
    spec: BlockSpec  # spec.SPEC
    active: dict  # spec.ACTIVE
    original_names: list[str]  # spec.ORIGINAL_NAMES
    scenarios: list[Scenario]  # src/blocks/<Block>/scenarios.py: SCENARIOS
    compatibility: Scenario  # the first scenario, or the one its COMPATIBILITY names
    script: Callable[[object], str]  # cross.script
    steady_default: str | None = None  # its scenarios.py's STEADY_DEFAULT

    def reference(self, scenario: Scenario) -> Path:
        """The committed reference result of one of the block's scenarios."""
        return self.folder / "references" / f"{scenario.name}.csv"


def _is(kind):
    return lambda value: isinstance(value, kind)


def _block(folder: Path, package: str, product: dict[str, build_blocks.Block]) -> Block:
    files = ("__init__.py", *(f"{m}.py" for m in MODULES))
    missing = [f for f in files if not (folder / f).is_file()]
    if missing:
        raise BlockFolderError(
            f"{shown(folder)}/ lacks {', '.join(missing)}: a block folder holds "
            f"{', '.join(files)} (see tests/lgf_blocks.py)"
        )
    if folder.name not in product:
        raise BlockFolderError(
            f"{shown(folder)}/ is no block of src/blocks/ (with interface.toml and scenarios.py)"
        )
    modules = {m: importlib.import_module(f"{package}.{folder.name}.{m}") for m in MODULES}
    spec, cross = modules["spec"], modules["cross"]
    built = product[folder.name]
    return Block(
        name=folder.name,
        folder=folder,
        model=modules["model"],
        spec=attribute(folder, spec, "SPEC", _is(BlockSpec), "the block's BlockSpec"),
        active=attribute(
            folder,
            spec,
            "ACTIVE",
            _is(dict),
            "a dict of inputs under which the block visibly works",
        ),
        original_names=attribute(
            folder,
            spec,
            "ORIGINAL_NAMES",
            _is(list),
            "a list of names of the original the documentation must mention",
        ),
        scenarios=built.scenarios,
        compatibility=built.compatibility,
        script=attribute(
            folder,
            cross,
            "script",
            callable,
            "a function script(md) -> str, the block's cross scenario",
        ),
        steady_default=built.steady_default,
    )


def discover(
    directory: Path = BLOCKS_DIR,
    package: str = PACKAGE,
    product: list[build_blocks.Block] | None = None,
) -> list[Block]:
    """The blocks of `directory` (the package `package`), sorted by name, with the scenarios of
    `product` (default: the blocks of src/blocks/); BlockFolderError for a folder that is not a
    complete block folder, or for no block at all."""
    folders = sorted(
        p for p in directory.iterdir() if p.is_dir() and not p.name.startswith(("_", "."))
    )
    if not folders:
        raise BlockFolderError(f"{directory} holds no block folder")
    built = {b.name: b for b in (build_blocks.blocks() if product is None else product)}
    return [_block(folder, package, built) for folder in folders]


REGISTRY = build_blocks.Registry(discover, "folder tests/blocks/{}/")
blocks, names, find, scenarios = REGISTRY.blocks, REGISTRY.names, REGISTRY.find, REGISTRY.scenarios


def param_id(value) -> str | None:
    """The test id of a parameter that belongs to a block: it names the block, so that
    `pytest -k <Block>` selects every test of the block. A Block gives its name, a Scenario
    "<Block>-<scenario>"; any other value None (pytest's own id). The hooks
    pytest_make_parametrize_id of tests/conftest.py and python/tests/conftest.py use it."""
    if isinstance(value, Block):
        return value.name
    if isinstance(value, Scenario):
        return f"{value.block}-{value.name}"
    return None
