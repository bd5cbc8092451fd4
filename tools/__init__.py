"""What the build runs besides CMake and the compiler, and what the demo, the release, the
benchmarks and the tests share with it: the Python package `tools` (the shell scripts beside it
are make's). It imports neither the test suite nor Hypothesis, so that the FMUs and the wheel of
the package lgf-fmus build from a tree without tests/ (tests/test_tools.py checks it).

    blocks.py         the blocks (src/blocks/<Block>/) and their scenarios (scenarios.py there)
    interface.py      each block's interface.c, from its interface.toml (CMake runs it)
    scenario.py       the Scenario type of every block's scenarios
    simulate.py       a scenario simulated with FMPy, on a built FMU or a library just built; CSV
    plots.py          the demo's pictures and each FMU's documentation plot, in the style of the
                      package's plotting module python/lgf_fmus/plots.py (lgf_fmus.plots)
    documentation.py  each FMU's documentation/ and icon (the build runs it)
    compat.py         each FMU's compatibility information (the build runs it; its replay)

Needs FMPy and numpy, and matplotlib and the package lgf_fmus for the plots (the build and make
put python/ on PYTHONPATH; the tests take the installed package). Run from the repository's root
(python -m tools.<module>), which puts the root on the import path as the test suite's settings
do.
"""

from __future__ import annotations

from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
VERSION_FILE = ROOT / "VERSION"


def version() -> str:
    """The version of the FMUs, of the release and of the Python package: the one line of
    VERSION."""
    text = VERSION_FILE.read_text(encoding="utf-8").strip()
    if not text or len(text.splitlines()) != 1:
        raise ValueError(f"{VERSION_FILE} must hold one line, the version (e.g. 0.1.0)")
    return text
