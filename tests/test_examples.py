"""examples/: the scripts the release zip carries (release/dist.py; tests/test_dist.py runs them
from the unpacked zip). Each imports nothing but the standard library and FMPy, and prints what
its page, examples/README.md, shows; chain.py is the chain example of docs/importing.md ("Two
FMUs chained"), the same code but for where it finds the FMUs."""

from __future__ import annotations

import ast
import os
import re
import subprocess
import sys

from tests.harness import ROOT
from tests.timeouts import hang_guard

EXAMPLES = ROOT / "examples"
STANDARD = {"sys", "pathlib"}


def shown_output(page: str, heading: str) -> str:
    """The first ```text block after `heading` on a page: what the example prints."""
    text = (ROOT / page).read_text(encoding="utf-8")
    after = text[text.index(heading) :]
    return re.search(r"^```text\n(.*?)^```\n", after, re.S | re.M)[1]


def documented_chain() -> str:
    text = (ROOT / "docs" / "importing.md").read_text(encoding="utf-8")
    after = text[text.index("### Two FMUs chained") :]
    return re.search(r"^```python\n(.*?)^```\n", after, re.S | re.M)[1]


def imported(tree: ast.Module) -> set[str]:
    names = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names |= {a.name.partition(".")[0] for a in node.names}
        elif isinstance(node, ast.ImportFrom):
            names.add(node.module.partition(".")[0])
    return names


def run_example(script, cwd, *arguments) -> subprocess.CompletedProcess:
    """A script run as a user runs it: isolated (no PYTHONPATH, no user site, not the
    repository's folder on the path); -X importtime lists every module it imports on stderr."""
    return subprocess.run(
        [sys.executable, "-I", "-X", "importtime", str(script), *arguments],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=hang_guard(120),
        env={k: v for k, v in os.environ.items() if not k.startswith("PYTHON")},
    )


def check_run(run: subprocess.CompletedProcess):
    assert run.returncode == 0, run.stderr
    assert run.stdout == shown_output("examples/README.md", "## chain.py")
    loaded = {
        line.rpartition("|")[2].strip().partition(".")[0]
        for line in run.stderr.splitlines()
        if line.startswith("import time:")
    }
    assert "fmpy" in loaded and not loaded & {"lgf_fmus", "tools", "tests", "release"}, loaded


def test_the_examples_import_the_standard_library_and_fmpy_only():
    scripts = sorted(EXAMPLES.glob("*.py"))
    assert [p.name for p in scripts] == ["chain.py"]
    for script in scripts:
        assert imported(ast.parse(script.read_text(encoding="utf-8"))) <= STANDARD | {"fmpy"}


def test_chain_is_the_documented_chain_example():
    """The same statements as the snippet of docs/importing.md (layout and comments aside),
    the snippet's "fmus/<Block>.fmu" being chain.py's fmu("<Block>"), after chain.py's own
    lines that find the FMUs; and the two pages show the same output."""
    tree = ast.parse((EXAMPLES / "chain.py").read_text(encoding="utf-8"))
    own = {"HERE", "FOLDERS", "fmu"}

    def is_own(node) -> bool:
        if isinstance(node, (ast.Import, ast.ImportFrom)):
            return imported(ast.Module(body=[node], type_ignores=[])) <= STANDARD
        if isinstance(node, ast.Assign):
            return all(isinstance(t, ast.Name) and t.id in own for t in node.targets)
        if isinstance(node, ast.FunctionDef):
            return node.name in own
        return isinstance(node, ast.Expr) and isinstance(node.value, ast.Constant)  # docstring

    body = [node for node in tree.body if not is_own(node)]
    snippet = re.sub(r'"fmus/(\w+)\.fmu"', r'fmu("\1")', documented_chain())
    expected = ast.parse(snippet).body
    assert [ast.dump(n) for n in body] == [ast.dump(n) for n in expected]
    assert shown_output("examples/README.md", "## chain.py") == shown_output(
        "docs/importing.md", "### Two FMUs chained"
    )


def test_chain_runs_in_the_repository_on_the_built_fmus(tmp_path):
    """From any folder: without an argument it takes the repository's fmus/ (no fmi2/ there);
    with one, the FMUs of that folder."""
    check_run(run_example(EXAMPLES / "chain.py", tmp_path))
    check_run(run_example(EXAMPLES / "chain.py", tmp_path, str(ROOT / "fmus")))
    missing = run_example(EXAMPLES / "chain.py", tmp_path, str(tmp_path))
    assert missing.returncode == 1 and "LGF_SawTooth.fmu is in none of" in missing.stderr
