import pytest

from tests import harness


@pytest.fixture(scope="session", autouse=True)
def _unpacked_fmus():
    yield
    harness.cleanup()
    assert harness.MALFORMED_LOG_MESSAGES == [], (
        "log messages with a '#' that is not escaped as '##': "
        f"{harness.MALFORMED_LOG_MESSAGES[:5]}")
