import os

import pytest
from hypothesis import HealthCheck, settings

from tests import harness, lgf_blocks, rebuild
from tests.cross.wine import wine_runners  # noqa: F401 (the fixture of the win64 tests)

# The FMUs are driven through FMPy, whose speed depends on the machine and its load: no
# Hypothesis deadline and no health check on slow data generation, for every test (a test's
# own @settings still sets its max_examples). HYPOTHESIS_PROFILE=default gives Hypothesis's own.
settings.register_profile("lgf", deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "lgf"))


def pytest_make_parametrize_id(config, val, argname):
    """A block or a scenario as a parameter: an id that names the block (lgf_blocks.param_id),
    so that `pytest -k <Block>` selects the test. tests/test_ids.py checks every test."""
    return lgf_blocks.param_id(val)


@pytest.fixture(scope="session", autouse=True)
def _unpacked_fmus():
    yield
    harness.cleanup()
    assert harness.MALFORMED_LOG_MESSAGES == [], (
        f"log messages with a '#' that is not escaped as '##': {harness.MALFORMED_LOG_MESSAGES[:5]}"
    )


@pytest.fixture(scope="session")
def rebuilt(tmp_path_factory):
    """FMUs rebuilt from their sources/ alone (tests/rebuild.py), each (builder, FMU) once per
    session: rebuilt(builders, fmus)[builder, fmu]."""
    return rebuild.Rebuilds(tmp_path_factory.mktemp("rebuilt"))
