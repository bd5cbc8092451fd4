"""The SCL compiler's tests import the package lgf_fmus as installed (`make package`, which
`make pytest` runs first): one import, no path of the checkout. Where the installed compiler
differs from the checkout's python/lgf_fmus/scl, every test here errors naming the files,
instead of testing a stale compiler."""

from __future__ import annotations

from pathlib import Path

import pytest

from lgf_fmus import scl

INSTALLED = Path(scl.__file__).resolve().parent
CHECKOUT = Path(__file__).resolve().parents[2] / "python" / "lgf_fmus" / "scl"


def stale() -> list[str]:
    """The files of the checkout's compiler the installed one does not have as they are."""
    if INSTALLED == CHECKOUT or not CHECKOUT.is_dir():
        return []  # the checkout's own package on the path, or no checkout
    return [
        p.name
        for p in sorted(CHECKOUT.glob("*.py")) + [CHECKOUT / "scl.lark"]
        if not (INSTALLED / p.name).exists() or (INSTALLED / p.name).read_bytes() != p.read_bytes()
    ]


@pytest.fixture(scope="session", autouse=True)
def _installed_compiler_is_the_checkout_s():
    files = stale()
    if files:
        pytest.fail(
            f"the installed lgf_fmus.scl differs from the checkout's ({', '.join(files)}): "
            "run `make package`",
            pytrace=False,
        )


@pytest.fixture(scope="session", autouse=True)
def _unpacked_fmus():
    yield
    from tests.scl import driver

    driver.cleanup()
