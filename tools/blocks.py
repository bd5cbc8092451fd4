"""The blocks and their scenarios, as the build sees them. A block is a folder of src/blocks/
with an interface.toml (as CMakeLists.txt finds them), named by the FMU's modelIdentifier; its
scenarios are product data beside its C, in src/blocks/<Block>/scenarios.py:

    SCENARIOS      its demo scenarios (tools.scenario.Scenario, whose block is <Block>: left out,
                   it is filled in), at least one; the first one is the typical run of the FMU's
                   documentation, and each has its reference result in
                   tests/blocks/<Block>/references/<name>.csv
    COMPATIBILITY  optionally, the name of the one whose inputs and reference result are the
                   FMU's compatibility information (tools/compat.py: <Block>_in.csv,
                   <Block>_ref.csv and <Block>_ref.opt inside the FMU and in the release), if not
                   the first; it sets no parameters, as the FMI cross-check format carries only
                   inputs, so it runs on the FMU's parameter start values
    plot_marks     optionally plot_marks(result) -> {lane: ([t...], [y...], label)}, marks for
                   the plots (tools/plots.py), as LGF_RampCI's table points
    STEADY_DEFAULT optionally, why the default experiment (start values, no input connected)
                   cannot move any output: a block that maps inputs to outputs (an FC, a
                   characteristic curve) or acts only on input edges; without it some output
                   must move (tests/test_default_experiment.py)

A block's scenarios.py is the module src.blocks.<Block>.scenarios: src/, src/blocks/ and each
block's folder are namespace packages (no __init__.py among the C files) under the repository's
root, where the build and the tests run, and a scenarios.py imports its neighbours relatively
(LGF_RampCI's table.py). The committed reference result of each scenario is in
tests/blocks/<Block>/references/ (`make references`); the test suite's own view of a block, with
its model and property tests, is tests/lgf_blocks.py, which takes the scenarios from here.

A block whose scenarios.py is missing or incomplete makes blocks() raise BlockFolderError,
saying what is missing.
"""

from __future__ import annotations

import functools
import importlib
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Callable

from tools import ROOT
from tools.scenario import Scenario

BLOCKS_DIR = ROOT / "src" / "blocks"
REFERENCES_DIR = ROOT / "tests" / "blocks"
# The package of BLOCKS_DIR: src.blocks.<Block> is the folder src/blocks/<Block>/.
PACKAGE = "src.blocks"


class BlockFolderError(Exception):
    """A block folder that does not hold what it must hold."""


@dataclass(frozen=True)
class Block:
    name: str  # the folder's name: the FMU's modelIdentifier
    folder: Path  # src/blocks/<Block>/
    scenarios: list[Scenario]  # scenarios.SCENARIOS
    compatibility: Scenario  # the scenario scenarios.COMPATIBILITY names, or the first
    plot_marks: Callable | None  # scenarios.plot_marks, if it defines one
    steady_default: str | None = None  # scenarios.STEADY_DEFAULT, if it defines one

    def reference(self, scenario: Scenario) -> Path:
        """The committed reference result of one of the block's scenarios."""
        return REFERENCES_DIR / self.name / "references" / f"{scenario.name}.csv"


def shown(folder: Path) -> str:
    """A folder as messages name it: relative to the repository's root when inside it."""
    return str(folder.relative_to(ROOT) if folder.is_relative_to(ROOT) else folder)


def attribute(
    folder: Path, module: ModuleType, name: str, check: Callable[[object], bool], what: str
):
    """module.name if check(it) holds, else BlockFolderError saying what it must be."""
    value = getattr(module, name, None)
    if not check(value):
        raise BlockFolderError(
            f"{shown(folder)}/{module.__name__.rsplit('.', 1)[-1]}.py must define {name}: {what}"
        )
    return value


def _block(folder: Path, package: str) -> Block:
    if not (folder / "scenarios.py").is_file():
        raise BlockFolderError(
            f"{shown(folder)}/ lacks scenarios.py: a block's scenarios (see tools/blocks.py)"
        )
    module = importlib.import_module(f"{package}.{folder.name}.scenarios")
    scenarios = attribute(
        folder,
        module,
        "SCENARIOS",
        lambda v: isinstance(v, list),
        "a list of the block's demo scenarios",
    )
    if not scenarios:
        raise BlockFolderError(
            f"{shown(folder)}/scenarios.py: SCENARIOS is empty; a block has at least one scenario"
        )
    for scenario in scenarios:
        if not isinstance(scenario, Scenario) or scenario.block not in ("", folder.name):
            raise BlockFolderError(
                f"{shown(folder)}/scenarios.py: "
                f"{getattr(scenario, 'name', scenario)!r} is not a Scenario "
                f"of block {folder.name!r}"
            )
        scenario.block = folder.name
    return Block(
        name=folder.name,
        folder=folder,
        scenarios=scenarios,
        compatibility=_compatibility(folder, module),
        plot_marks=getattr(module, "plot_marks", None),
        steady_default=getattr(module, "STEADY_DEFAULT", None),
    )


def _compatibility(folder: Path, module: ModuleType) -> Scenario:
    """The scenario of the FMU's compatibility information: the one of SCENARIOS that
    COMPATIBILITY names, else the first, without parameters (the FMI cross-check format carries
    inputs only)."""
    if not hasattr(module, "COMPATIBILITY"):
        first = module.SCENARIOS[0]
        if first.parameters:
            raise BlockFolderError(
                f"{shown(folder)}/scenarios.py: the first scenario {first.name!r} sets "
                "parameters, so COMPATIBILITY must name one that does not: the compatibility "
                "information carries inputs only"
            )
        return first
    name = attribute(
        folder,
        module,
        "COMPATIBILITY",
        lambda v: isinstance(v, str),
        "the name of the scenario of the FMU's compatibility information",
    )
    found = [s for s in module.SCENARIOS if s.name == name]
    if not found:
        raise BlockFolderError(
            f"{shown(folder)}/scenarios.py: COMPATIBILITY names {name!r}, "
            "which is not one of SCENARIOS"
        )
    if found[0].parameters:
        raise BlockFolderError(
            f"{shown(folder)}/scenarios.py: COMPATIBILITY names {name!r}, "
            "which sets parameters; the compatibility information carries "
            "inputs only, so its scenario runs on the parameters' start values"
        )
    return found[0]


def discover(directory: Path = BLOCKS_DIR, package: str = PACKAGE) -> list[Block]:
    """The blocks of `directory` (whose folders are the packages `package`.<Block>), sorted by
    name; BlockFolderError for a block without complete scenarios, or for no block at all."""
    folders = sorted(p.parent for p in directory.glob("*/interface.toml"))
    if not folders:
        raise BlockFolderError(f"{shown(directory)} holds no block (<Block>/interface.toml)")
    found = [_block(folder, package) for folder in folders]
    names = [s.name for b in found for s in b.scenarios]
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise BlockFolderError(
            f"scenario names used twice: {repeated} (a scenario's name is "
            "the name of its reference CSV and of the demo's output)"
        )
    return found


class Registry:
    """The one registry of blocks: the blocks discover() finds, found once, sorted by name; the
    test suite's (tests/lgf_blocks.py) is one too, over its own folders."""

    def __init__(self, discover: Callable[[], list], where: str):
        self._discover, self._where = discover, where  # where: a block's folder, "{}" its name

    @functools.cached_property
    def _found(self) -> tuple:
        return tuple(self._discover())

    def blocks(self) -> list:
        """Every block, sorted by name."""
        return list(self._found)

    def names(self) -> list[str]:
        """The names (modelIdentifiers) of every block."""
        return [b.name for b in self._found]

    def find(self, name: str):
        """The block of that name."""
        for b in self._found:
            if b.name == name:
                return b
        raise KeyError(f"no block {self._where.format(name)}")

    def scenarios(self) -> list[Scenario]:
        """Every block's demo scenarios, block by block."""
        return [s for b in self._found for s in b.scenarios]


REGISTRY = Registry(discover, "src/blocks/{}/ (with an interface.toml)")
blocks, names, find, scenarios = REGISTRY.blocks, REGISTRY.names, REGISTRY.find, REGISTRY.scenarios
