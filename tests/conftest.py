import pytest

import harness


@pytest.fixture(scope="session", autouse=True)
def _unpacked_fmus():
    yield
    harness.cleanup()
