"""The pytest plugin (entry point pytest11): an example CI suite, written as a user would, run
with pytester in a pytest of its own; and the README's example test."""
from __future__ import annotations

import re
from pathlib import Path

import lgf_fmus

README = Path(__file__).resolve().parents[2] / "README.md"

SUITE = '''
from lgf_fmus.testing import assert_rate_limited, assert_settles, assert_within


def test_every_bundled_fmu_is_a_file(lgf_block, lgf_fmu, lgf_fmu_paths):
    assert lgf_fmu == lgf_fmu_paths[lgf_block] and lgf_fmu.is_file()


def test_limiter_settles_and_is_limited(lgf_simulate):
    result = lgf_simulate("{block}", 6.0, {{"cycleTime": 0.01, "setChangeRate": 40.0}},
                          inputs={{"value": [(1.0, 100.0)]}}, output_interval=0.01)
    assert_rate_limited(result, "delayedValue", 40.0)
    assert_within(result, "delayedValue", 0.0, 100.0)
    assert_settles(result, "delayedValue", 100.0, within=2.6, tolerance=1e-9, after=1.0)


def test_a_failing_requirement(lgf_simulate):
    result = lgf_simulate("{block}", 3.0, {{"cycleTime": 0.01, "setChangeRate": 40.0}},
                          inputs={{"value": [(1.0, 100.0)]}}, output_interval=0.1)
    assert_settles(result, "delayedValue", 100.0, within=1.0, tolerance=0.5, after=1.0)
'''


def limiter():
    return next(b for b in lgf_fmus.blocks() if "setChangeRate" in lgf_fmus.model(b).inputs)


def test_example_suite(pytester):
    pytester.makepyfile(test_ci=SUITE.format(block=limiter()))
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    result.assert_outcomes(passed=len(lgf_fmus.blocks()) + 1, failed=1)
    result.stdout.fnmatch_lines([
        "*delayedValue did not settle to 100 ± 0.5 within 1 s after t = 1 s: at t = 2 s it is 39.99999999999992 (off by -60)*",
        "*lgf_fmus simulations*",
        "*simulate('*', 3.0, *-> 31 samples, *.csv",
    ])


def test_readme_example_test_passes(pytester):
    """The example test of the README (the block of code after 'CI example'), copied as is."""
    text = README.read_text()
    section = text[text.index("### CI example"):]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    pytester.makepyfile(test_readme=code)
    result = pytester.runpytest_subprocess("-p", "no:cacheprovider")
    outcomes = result.parseoutcomes()
    assert outcomes.get("passed", 0) >= 1 and not outcomes.get("failed"), result.stdout.str()


def readme_examples() -> list[str]:
    """The Python examples of the README's package section, except those marked
    '<!-- not executed' and the CI example (run above by pytester)."""
    text = README.read_text()
    section = text[text.index("## The Python package lgf-fmus"):]
    section = section[:section.index("### CI example")]
    blocks = []
    for match in re.finditer(r"(<!-- not executed[^\n]*\n)?```python\n(.*?)```", section, re.S):
        if not match.group(1):
            blocks.append(match.group(2))
    return blocks


def test_readme_examples_run(tmp_path):
    import os
    import subprocess
    import sys

    from tests.timeouts import hang_guard
    examples = readme_examples()
    assert len(examples) >= 2
    for code in examples:
        done = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True,
                              text=True, env={**os.environ, "MPLBACKEND": "Agg"},
                              timeout=hang_guard(600))
        assert done.returncode == 0, f"{code}\n{done.stderr[-3000:]}"
    assert (tmp_path / "results.parquet").is_file() and (tmp_path / "sweep-t95.png").is_file()
