"""The pytest plugin (entry point pytest11): an example CI suite, written as a user would, run
with pytester in a pytest of its own; and the package page's example test (docs/python.md)."""

from __future__ import annotations

from pathlib import Path

import lgf_fmus

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "docs" / "python.md"  # the package's page; python/README.md is a copy of it

SUITE = """
from lgf_fmus.testing import assert_rate_limited, assert_settles, assert_within


def test_every_bundled_fmu_is_a_file(lgf_block, lgf_fmu, lgf_fmu_paths):
    assert lgf_fmu == lgf_fmu_paths[lgf_block] and lgf_fmu.is_file()


def test_limiter_settles_and_is_limited(lgf_simulate):
    result = lgf_simulate("{block}", 6.0, {{"cycleTime": 0.01, "setChangeRate": 40.0}},
                          inputs={{"value": [(0.0, 0.0), (1.0, 100.0)]}}, output_interval=0.01)
    assert_rate_limited(result, "delayedValue", 40.0)
    assert_within(result, "delayedValue", 0.0, 100.0)
    assert_settles(result, "delayedValue", 100.0, within=2.6, tolerance=1e-9, after=1.0)


def test_a_failing_requirement(lgf_simulate):
    result = lgf_simulate("{block}", 3.0, {{"cycleTime": 0.01, "setChangeRate": 40.0}},
                          inputs={{"value": [(0.0, 0.0), (1.0, 100.0)]}}, output_interval=0.1)
    assert_settles(result, "delayedValue", 100.0, within=1.0, tolerance=0.5, after=1.0)
"""


def limiter():
    return next(b for b in lgf_fmus.blocks() if "setChangeRate" in lgf_fmus.model(b).inputs)


def test_example_suite(pytester):
    pytester.makepyfile(test_ci=SUITE.format(block=limiter()))
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    result.assert_outcomes(passed=len(lgf_fmus.blocks()) + 1, failed=1)
    result.stdout.fnmatch_lines(
        [
            "*delayedValue did not settle to 100 ± 0.5 within 1 s after t = 1 s: at t = 2 s it is "
            "39.99999999999992 (off by -60)*",
            "*lgf_fmus simulations*",
            "*simulate('*', 3.0, *-> 31 samples, *.csv",
        ]
    )


FAILURES = """
import pandas as pd

from lgf_fmus.testing import assert_rate_limited, assert_reaches, assert_settles, assert_within

RESULT = pd.DataFrame({"time": [0.0, 1.0, 2.0], "y": [0.0, 10.0, 20.0]})


def test_settles():
    assert_settles(RESULT, "y", 0.0, within=1.0, tolerance=0.1)


def test_within():
    assert_within(RESULT, "y", high=5.0)


def test_rate_limited():
    assert_rate_limited(RESULT, "y", 1.0)


def test_reaches():
    assert_reaches(RESULT, "y", 50.0, by=2.0)


def test_unknown_signal():
    assert_within(RESULT, "z", 0.0)
"""

# A result that raises when read: lgf_fmus.testing fails on it with a RuntimeError, a fault that
# keeps its frames (only failed requirements and refused arguments hide them).
FAULT = """
from lgf_fmus.testing import assert_within


class Broken:
    # a result whose columns cannot be read: an error that no check of an argument makes
    columns = ["time", "y"]

    def __getitem__(self, name):
        raise RuntimeError("broken column " + name)


def test_a_broken_result():
    assert_within(Broken(), "y", 0.0)
"""


def library_source_in(output: str, inner: str) -> list[str]:
    """The lines of the output that are lines of lgf_fmus.testing's source (pytest prints a
    frame's source indented, the failing line marked with '>'), leaving out lines that the
    inner test file has too and lines too short to tell apart."""
    import inspect

    import lgf_fmus.testing

    source = {line.strip() for line in inspect.getsource(lgf_fmus.testing).splitlines()}
    source -= {line.strip() for line in inner.splitlines()}
    return [
        line
        for line in output.splitlines()
        if len(line.strip()) >= 8 and line.lstrip(">").strip() in source
    ]


def test_a_failing_assertion_shows_no_library_source(pytester):
    pytester.makepyfile(test_failures=FAILURES)
    result = pytester.runpytest_inprocess("-p", "no:cacheprovider")
    result.assert_outcomes(failed=5)
    output = result.stdout.str()
    assert not library_source_in(output, FAILURES), output
    assert "lgf_fmus/testing.py" not in output, output
    # the test's own line and the message remain
    result.stdout.fnmatch_lines(
        [
            '>*assert_settles(RESULT, "y", 0.0, within=1.0, tolerance=0.1)',
            "E*AssertionError: y did not settle to 0 ± 0.1 within 1 s after t = 0 s*",
            "E*AssertionError: y leaves [[]-inf, 5]: at t = 1 s it is 10*",
            "E*AssertionError: y changes faster than 1/s from t = 0 s (0) to t = 1 s (10)*",
            "E*AssertionError: y does not rise to 50 by t = 2 s*it never does",
            "E*ValueError: assert_within: the result has no signal 'z'; it has y",
        ],
        consecutive=False,
    )

    # the check above finds the library's source where pytest shows it: with --full-trace,
    # which ignores __tracebackhide__
    full = pytester.runpytest_inprocess("-p", "no:cacheprovider", "--full-trace")
    full.assert_outcomes(failed=5)
    assert library_source_in(full.stdout.str(), FAILURES)


def test_a_fault_of_the_library_keeps_its_frames(pytester):
    pytester.makepyfile(test_fault=FAULT)
    result = pytester.runpytest_inprocess("-p", "no:cacheprovider")
    result.assert_outcomes(failed=1)
    output = result.stdout.str()
    assert "RuntimeError: broken column" in output and "lgf_fmus/testing.py" in output, output
    assert library_source_in(output, FAULT), output


RUNS = """
from lgf_fmus.testing import assert_reaches


def test_two_runs_then_a_failure(lgf_simulate):
    step = {{"value": [(0.0, 0.0), (1.0, 100.0)]}}
    slow = lgf_simulate("{block}", 3.0, {{"setChangeRate": 10.0}}, inputs=step)
    fast = lgf_simulate("{block}", 2.0, {{"setChangeRate": 40.0}}, inputs=step)
    assert_reaches(fast, "delayedValue", 100.0, by=2.0)


def test_a_run_that_passes(lgf_simulate):
    lgf_simulate("{block}", 1.0)
"""


def test_the_runs_of_a_failed_test_reach_the_junit_xml(pytester):
    """The runs are a section of the failure's text: in the <failure> element of --junitxml
    (what CI systems show) and, once, on the terminal, even with --show-capture=no."""
    import re
    import xml.etree.ElementTree as ET

    pytester.makepyfile(test_runs=RUNS.format(block=limiter()))
    result = pytester.runpytest_inprocess(
        "-p", "no:cacheprovider", "--junitxml=report.xml", "--show-capture=no"
    )
    result.assert_outcomes(passed=1, failed=1)
    assert result.stdout.str().count("lgf_fmus simulations") == 1, result.stdout.str()

    cases = {c.get("name"): c for c in ET.parse(pytester.path / "report.xml").iter("testcase")}
    assert cases["test_a_run_that_passes"].find("failure") is None
    failure = cases["test_two_runs_then_a_failure"].find("failure")
    assert "delayedValue does not rise to 100 by t = 2 s" in failure.get("message")
    text = failure.text
    assert text.count("lgf_fmus simulations") == 1, text
    section = text[text.index("lgf_fmus simulations") :]
    runs = re.findall(
        r"^simulate\('(\w+)', ([\d.]+), .*\) -> (\d+) samples, (.+\.csv)$", section, re.M
    )
    # at the default cycleTime, 0.1 s: samples at t = 0, 0.1, ..., stop time
    assert [r[:3] for r in runs] == [(limiter(), "3.0", "31"), (limiter(), "2.0", "21")], section
    assert "'setChangeRate': 10.0" in section.splitlines()[1]
    for *_, samples, csv in runs:
        assert len(Path(csv).read_text().splitlines()) == 1 + int(samples), csv


def test_lgf_simulate_names_the_csv_after_the_fmu_file(lgf_simulate, tmp_path):
    """A block given as the path of an FMU file (a compiled one, a copy) names its CSV by the
    file's stem, as str or Path; a bundled block by its name."""
    import shutil

    block = limiter()
    copy = tmp_path / "elsewhere" / "my_limiter.fmu"
    copy.parent.mkdir()
    shutil.copyfile(lgf_fmus.fmu_path(block), copy)
    lgf_simulate(str(copy), 1.0)
    lgf_simulate(copy, 0.5)
    lgf_simulate(block, 0.2)
    csvs = sorted(p.name for p in tmp_path.glob("lgf_simulate_*"))
    assert csvs == [
        "lgf_simulate_0_my_limiter.csv",
        "lgf_simulate_1_my_limiter.csv",
        f"lgf_simulate_2_{block}.csv",
    ]
    # a header and a sample every cycleTime (0.1 s) from t = 0 to the stop time
    assert [len((tmp_path / c).read_text().splitlines()) for c in csvs] == [12, 7, 4]


def test_the_test_extra_brings_a_pytest_range_holding_the_pin():
    """The installed package's extra `test` requires a range of pytest (not an exact pin, which
    would replace a user's own pytest) that holds the version requirements.txt pins, and both
    READMEs say how to install it."""
    from importlib.metadata import requires

    from packaging.requirements import Requirement

    root = ROOT
    [pin] = [
        line.split("#")[0].strip()
        for line in (root / "requirements.txt").read_text().splitlines()
        if line.startswith("pytest==")
    ]
    extra = [Requirement(r.split(";")[0]) for r in requires("lgf-fmus") if 'extra == "test"' in r]
    assert [r.name for r in extra] == ["pytest"]
    assert not any(s.operator in ("==", "===") for s in extra[0].specifier), extra
    assert extra[0].specifier.contains(pin.split("==")[1])
    assert not extra[0].specifier.contains("10.0")  # the next major version may break the plugin
    assert 'pip install ".[test]"' in README.read_text(encoding="utf-8")
    assert 'pip install "lgf-fmus[test]"' in (root / "python" / "README.md").read_text()


def package_snippets() -> list[dict]:
    """The README's Python snippets that need the package (tests/test_readme.py skips them, as
    the project's suite runs before make package installs it): those marked as run here."""
    from tests.test_readme import snippets

    found = [
        s
        for s in snippets(README.read_text(encoding="utf-8"))
        if s["skip"] and "python/tests/test_plugin.py" in s["skip"]
    ]
    assert len(found) >= 3
    return found


def test_readme_ci_example_passes(pytester):
    """The README's CI example, copied as a user would, run by pytest with the plugin."""
    [code] = [s["code"] for s in package_snippets() if "pytester" in s["skip"]]
    pytester.makepyfile(test_readme=code)
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    outcomes = result.parseoutcomes()
    assert outcomes.get("passed", 0) == 1 + len(lgf_fmus.blocks(fmi_version=2)), result.stdout.str()
    assert not outcomes.get("failed"), result.stdout.str()


def test_readme_examples_run_as_shown(tmp_path):
    """The README's simulate and sweep examples, each a script of its own run in an empty
    folder: they end without error and print exactly the text block below them."""
    from tests.test_readme import run_as_shown

    scripts = [s for s in package_snippets() if "pytester" not in s["skip"]]
    for snippet in scripts:
        where = f"docs/python.md line {snippet['line']}"
        assert snippet["expected"] is not None, f"{where}: no text block shows its output"
        run_as_shown(snippet, where, tmp_path / f"line{snippet['line']}.py", tmp_path, seconds=600)
    assert (tmp_path / "results.parquet").is_file() and (tmp_path / "sweep-t95.png").is_file()
