"""The package tools is what the build runs (tools/__init__.py): it, every block's scenarios and
the build's steps run with `tests` and `hypothesis` unimportable, so that the FMUs and the wheel
build from a tree without tests/ and without Hypothesis."""

from __future__ import annotations

import os
import pkgutil
import subprocess
import sys
import textwrap

import pytest

from tests.harness import ROOT
from tests.timeouts import hang_guard
from tools import blocks

# Run first in each child: any import of tests or hypothesis (or of a module under them) fails.
REFUSE = textwrap.dedent("""\
    import importlib.abc, sys

    class Refuse(importlib.abc.MetaPathFinder):
        def find_spec(self, name, path=None, target=None):
            if name.partition(".")[0] in ("tests", "hypothesis"):
                raise ImportError(f"the build must not import {name}")

    sys.meta_path.insert(0, Refuse())
    """)
MODULES = sorted(m.name for m in pkgutil.iter_modules([str(ROOT / "tools")]))


def run(code: str, *args: str) -> subprocess.CompletedProcess:
    """Python code run in a child from the repository's root, as CMake runs the build's steps
    (LGF_PYTHON: the package lgf_fmus of python/), with tests and hypothesis unimportable."""
    env = {
        **os.environ,
        "PYTHONDONTWRITEBYTECODE": "1",
        "MPLBACKEND": "Agg",
        "PYTHONPATH": str(ROOT / "python"),
    }
    return subprocess.run(
        [sys.executable, "-c", REFUSE + code, *args],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=hang_guard(120),
    )


def test_the_refusal_works():
    child = run("import tests.harness")
    assert child.returncode != 0 and "the build must not import tests" in child.stderr


def test_the_package_and_every_blocks_scenarios_import_neither_tests_nor_hypothesis():
    assert {"blocks", "compat", "documentation", "plots", "scenario", "simulate"} <= set(MODULES)
    child = run(
        textwrap.dedent(f"""
        import importlib, sys
        for name in {MODULES!r}:
            importlib.import_module("tools." + name)
        from tools.blocks import scenarios
        print(len(scenarios()), "scenarios")
        assert not [m for m in sys.modules if m.partition(".")[0] in ("tests", "hypothesis")]
        # the package's plots, imported as a package: the tree's, not an installed one
        import lgf_fmus.plots
        assert lgf_fmus.plots.__file__ == {str(ROOT / "python" / "lgf_fmus" / "plots.py")!r}
        """)
    )
    assert child.returncode == 0, child.stderr
    assert f"{len(blocks.scenarios())} scenarios" in child.stdout


@pytest.mark.parametrize("module", ["documentation", "compat"])
def test_the_build_steps_run_without_tests_and_hypothesis(tmp_path, module):
    """The steps CMake runs for LGF_RampCI (its scenarios import table.py, its plots mark the
    table points), on the library and interface of `make build`."""
    block, build = "LGF_RampCI", ROOT / "build"
    arguments = [
        "--block",
        block,
        "--xml",
        str(build / "interface" / "fmi2" / f"{block}.xml"),
        "--binary",
        str(build / "fmi2" / f"{block}.so"),
        "--out",
        str(tmp_path / "out"),
    ]
    if module == "documentation":
        arguments += ["--interface", str(build / "interface" / f"{block}.json")]
    for path in arguments[3::2]:
        if path.startswith(str(build)):
            assert os.path.exists(path), f"{path} is missing: run `make build` first"
    child = run(f"import tools.{module}; tools.{module}.main()", *arguments)
    assert child.returncode == 0, child.stderr
    written = {p.name for p in (tmp_path / "out").rglob("*") if p.is_file()}
    expected = {"index.html", "model.png"} if module == "documentation" else {f"{block}_ref.csv"}
    assert expected <= written
