"""The package's tests run against the installed lgf_fmus (make test installs it into .venv);
the reference is FMPy's simulate_fmu on the same FMU file, driven from inputs built here."""

import os

import pytest
from hypothesis import HealthCheck, settings

from tests.lgf_blocks import param_id

pytest_plugins = ["pytester"]

# FMPy and Dask speeds depend on the machine and its load: no deadlines (as in tests/conftest.py).
settings.register_profile("lgf", deadline=None, suppress_health_check=[HealthCheck.too_slow])
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "lgf"))


def pytest_make_parametrize_id(config, val, argname):
    """A block or a scenario as a parameter: an id that names the block, as in tests/."""
    return param_id(val)


@pytest.fixture(scope="session")
def cluster_client():
    """A 2-worker LocalCluster on loopback, shared by the tests that need one."""
    from dask.distributed import Client, LocalCluster

    with (
        LocalCluster(
            n_workers=2,
            threads_per_worker=1,
            processes=True,
            host="127.0.0.1",
            dashboard_address="127.0.0.1:0",
        ) as cluster,
        Client(cluster) as client,
    ):
        yield client
