"""The SCL tests run against this checkout's compiler: while the package installed in .venv
(make package) predates lgf_fmus.scl, its import path is extended by python/lgf_fmus of this
tree (lgf_fmus itself is already imported by then, as pytest loads its plugin first)."""

from pathlib import Path

import pytest

import lgf_fmus

SOURCE = Path(__file__).resolve().parents[2] / "python" / "lgf_fmus"
if not (Path(lgf_fmus.__file__).parent / "scl").is_dir():
    lgf_fmus.__path__.insert(0, str(SOURCE))


@pytest.fixture(scope="session", autouse=True)
def _unpacked_fmus():
    yield
    from tests.scl import driver

    driver.cleanup()
