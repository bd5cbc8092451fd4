"""The pytest plugin of lgf_fmus (entry point pytest11, active wherever the package is installed).

Fixtures:
    lgf_fmu_paths   {block: Path} of every bundled FMI 2.0 FMU (session)
    lgf_block       each bundled block in turn: a test that takes it runs once per block
    lgf_fmu         the FMU (Path) of lgf_block
    lgf_simulate    lgf_fmus.simulate, recording each run: when the test fails, its failure
                    text (on the terminal and in the <failure> of --junitxml) ends with a
                    section "lgf_fmus simulations" listing the runs, with a CSV of each result
                    in the test's tmp_path (lgf_simulate_<n>_<block>.csv; for a block given
                    as an FMU file, the file's stem)

    def test_ramp_is_limited(lgf_simulate):
        result = lgf_simulate("LGF_LimRateOfChangeCI", 5.0, {"cycleTime": 0.01},
                              inputs={"value": [(0.0, 0.0), (1.0, 100.0)], "setChangeRate": 40.0})
        assert_rate_limited(result, "delayedValue", 40.0)
"""

from __future__ import annotations

from pathlib import Path

import pytest

_RUNS = pytest.StashKey[list]()


def pytest_generate_tests(metafunc):
    if "lgf_block" in metafunc.fixturenames:
        from . import blocks

        metafunc.parametrize("lgf_block", blocks(fmi_version=2), ids=str)


@pytest.fixture(scope="session")
def lgf_fmu_paths():
    from . import blocks, fmu_path

    return {block: fmu_path(block) for block in blocks(fmi_version=2)}


@pytest.fixture
def lgf_fmu(lgf_block):
    from . import fmu_path

    return fmu_path(lgf_block)


@pytest.fixture
def lgf_simulate(request, tmp_path):
    from . import simulate
    from .cli import csv_text

    runs = request.node.stash.setdefault(_RUNS, [])

    def run(block, *args, **kwargs):
        result = simulate(block, *args, **kwargs)
        # a block given as an FMU file (the rule of lgf_fmus.model) is named by its stem: its
        # path would put the CSV into folders that do not exist
        name = Path(block).stem if str(block).endswith(".fmu") else block
        csv = tmp_path / f"lgf_simulate_{len(runs)}_{name}.csv"
        csv.write_text(csv_text(result))
        described = ", ".join(
            [repr(block), *map(repr, args), *(f"{k}={v!r}" for k, v in kwargs.items())]
        )
        runs.append(f"simulate({described}) -> {len(result)} samples, {csv}")
        return result

    return run


@pytest.hookimpl(wrapper=True)
def pytest_runtest_makereport(item, call):
    report = yield
    runs = item.stash.get(_RUNS, None)
    if runs and report.when == "call" and report.failed:
        # A section of the failure's own text (longrepr), not of report.sections: that text is
        # what the terminal prints and what --junitxml writes into <failure>, which CI systems
        # show as the failure's details; report.sections reach no JUnit XML, and the terminal
        # leaves them out under any --show-capture but "all". A longrepr without sections (a
        # plain string, from another plugin's items) keeps the report section.
        if hasattr(report.longrepr, "addsection"):
            report.longrepr.addsection("lgf_fmus simulations", "\n".join(runs))
        else:
            report.sections.append(("lgf_fmus simulations", "\n".join(runs)))
    return report
