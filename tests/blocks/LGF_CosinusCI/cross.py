"""The fixed scenario of LGF_CosinusCI for tests/cross/scenario_runner.c (tests/test_win64.py,
tests/test_aarch64.py), the one of every signal generator (tests/signal_generators.py)."""

from tests.signal_generators import cross_script


def script(md) -> str:
    return cross_script(md, "cosinus_ci")
