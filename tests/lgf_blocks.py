"""The blocks: the folders of tests/blocks/, one per block, named by the FMU's modelIdentifier.
Every generic suite, the demo and the benchmark take the blocks from `blocks()`; adding a block
means adding its folder (and its C side in src/blocks/<Block>/), nothing here.

A block folder tests/blocks/<Block>/ holds:

    __init__.py      makes it the package tests.blocks.<Block>
    model.py         the independent Python model (from docs/behaviour.md, never from the C)
    spec.py          SPEC: its BlockSpec (tests/block_spec.py) for the property tests;
                     ACTIVE: inputs under which the block visibly works (generic interface tests);
                     ORIGINAL_NAMES: names of the original block the documentation must mention
    scenarios.py     SCENARIOS: its demo scenarios (tools.scenario.Scenario, block = <Block>),
                     at least one; the first one is the typical run of the documentation;
                     COMPATIBILITY: the name of the one (without parameters) whose inputs and
                     reference result are the FMU's compatibility information (release/compat.py);
                     optionally plot_marks(result), marks for the plots (demo/plots.py)
    cross.py         script(md) -> str: its fixed scenario for tests/cross/scenario_runner.c
    references/      <scenario>.csv per scenario (written by `make references`)
    test_*.py        its own hand-traced tests

A folder that lacks one of these modules or names makes blocks() raise BlockFolderError, saying
what is missing. Folders whose name starts with '_' or '.' (such as __pycache__) are not blocks.
"""
from __future__ import annotations

import functools
import importlib
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Callable

from tests.block_spec import BlockSpec
from tools.scenario import Scenario

ROOT = Path(__file__).resolve().parent.parent
BLOCKS_DIR = ROOT / "tests" / "blocks"
PACKAGE = "tests.blocks"
MODULES = ("model", "spec", "scenarios", "cross")


class BlockFolderError(Exception):
    """A folder of tests/blocks/ that does not hold what a block folder must hold."""


@dataclass(frozen=True)
class Block:
    name: str                      # the folder's name: the FMU's modelIdentifier
    folder: Path
    model: ModuleType              # model.py
    spec: BlockSpec                # spec.SPEC
    active: dict                   # spec.ACTIVE
    original_names: list[str]      # spec.ORIGINAL_NAMES
    scenarios: list[Scenario]      # scenarios.SCENARIOS
    compatibility: Scenario        # the scenario named by scenarios.COMPATIBILITY
    script: Callable[[object], str]  # cross.script

    def reference(self, scenario: Scenario) -> Path:
        """The committed reference result of one of the block's scenarios."""
        return self.folder / "references" / f"{scenario.name}.csv"


def _shown(folder: Path) -> str:
    return str(folder.relative_to(ROOT) if folder.is_relative_to(ROOT) else folder)


def _attribute(folder: Path, module: ModuleType, name: str, check: Callable[[object], bool],
               what: str):
    value = getattr(module, name, None)
    if not check(value):
        raise BlockFolderError(f"{_shown(folder)}/{module.__name__.rsplit('.', 1)[-1]}.py must "
                               f"define {name}: {what}")
    return value


def _is(kind):
    return lambda value: isinstance(value, kind)


def _block(folder: Path, package: str) -> Block:
    shown = _shown(folder)
    files = ("__init__.py", *(f"{m}.py" for m in MODULES))
    missing = [f for f in files if not (folder / f).is_file()]
    if missing:
        raise BlockFolderError(f"{shown}/ lacks {', '.join(missing)}: a block folder holds "
                               f"{', '.join(files)} (see tests/lgf_blocks.py)")
    modules = {m: importlib.import_module(f"{package}.{folder.name}.{m}") for m in MODULES}
    spec, scenarios, cross = modules["spec"], modules["scenarios"], modules["cross"]
    block = Block(
        name=folder.name,
        folder=folder,
        model=modules["model"],
        spec=_attribute(folder, spec, "SPEC", _is(BlockSpec), "the block's BlockSpec"),
        active=_attribute(folder, spec, "ACTIVE", _is(dict),
                          "a dict of inputs under which the block visibly works"),
        original_names=_attribute(folder, spec, "ORIGINAL_NAMES", _is(list),
                                  "a list of names of the original the documentation must mention"),
        scenarios=_attribute(folder, scenarios, "SCENARIOS", _is(list),
                             "a list of the block's demo scenarios"),
        compatibility=_compatibility(folder, scenarios),
        script=_attribute(folder, cross, "script", callable,
                          "a function script(md) -> str, the block's cross scenario"),
    )
    if not block.scenarios:
        raise BlockFolderError(f"{shown}/scenarios.py: SCENARIOS is empty; a block has at "
                               "least one scenario")
    for scenario in block.scenarios:
        if not isinstance(scenario, Scenario) or scenario.block != block.name:
            raise BlockFolderError(f"{shown}/scenarios.py: {getattr(scenario, 'name', scenario)!r} "
                                   f"is not a Scenario of block {block.name!r}")
    return block


def _compatibility(folder: Path, module: ModuleType) -> Scenario:
    """The scenario of the FMU's compatibility information: one of SCENARIOS, named by
    COMPATIBILITY, without parameters (the FMI cross-check format carries inputs only)."""
    name = _attribute(folder, module, "COMPATIBILITY", _is(str),
                      "the name of the scenario of the FMU's compatibility information")
    found = [s for s in getattr(module, "SCENARIOS", None) or [] if getattr(s, "name", None) == name]
    if not found:
        raise BlockFolderError(f"{_shown(folder)}/scenarios.py: COMPATIBILITY names {name!r}, "
                               "which is not one of SCENARIOS")
    if found[0].parameters:
        raise BlockFolderError(f"{_shown(folder)}/scenarios.py: COMPATIBILITY names {name!r}, "
                               "which sets parameters; the compatibility information carries "
                               "inputs only, so its scenario runs on the parameters' start values")
    return found[0]


def discover(directory: Path = BLOCKS_DIR, package: str = PACKAGE) -> list[Block]:
    """The blocks of `directory` (the package `package`), sorted by name; BlockFolderError for
    a folder that is not a complete block folder, or for no block at all."""
    folders = sorted(p for p in directory.iterdir()
                     if p.is_dir() and not p.name.startswith(("_", ".")))
    if not folders:
        raise BlockFolderError(f"{directory} holds no block folder")
    found = [_block(folder, package) for folder in folders]
    names = [s.name for b in found for s in b.scenarios]
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise BlockFolderError(f"scenario names used twice: {repeated} (a scenario's name is "
                               "the name of its reference CSV and of the demo's output)")
    return found


@functools.cache
def _blocks() -> tuple[Block, ...]:
    return tuple(discover())


def blocks() -> list[Block]:
    """Every block of tests/blocks/, sorted by name."""
    return list(_blocks())


def names() -> list[str]:
    """The names (modelIdentifiers) of every block."""
    return [b.name for b in blocks()]


def find(name: str) -> Block:
    """The block of that name."""
    for b in blocks():
        if b.name == name:
            return b
    raise KeyError(f"no block folder tests/blocks/{name}/")


def scenarios() -> list[Scenario]:
    """Every block's demo scenarios, block by block."""
    return [s for b in blocks() for s in b.scenarios]
