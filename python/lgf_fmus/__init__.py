"""lgf_fmus: the Siemens LGF PLC function blocks of this project as FMI FMUs, bundled, with

    blocks()                       the bundled blocks
    fmu_path(block, fmi_version=2) the FMU file of a block
    model(block)                   its variables (names, types, ranges, start values)
    simulate(block, stop_time, parameters, inputs=..., table=...)   one run -> DataFrame
    sweep(block, runs, stop_time, outputs, ...)                     many runs on Dask -> DataFrame
    compile(sources, block=..., fmi=2, output=...)   an SCL function block -> an FMU (docs/scl.md)

the command line `python -m lgf_fmus` (list, simulate, sweep, compile), a pytest plugin (fixtures
lgf_fmu_paths, lgf_block, lgf_fmu, lgf_simulate) and lgf_fmus.testing (assertions for control
logic).
Every run is simulated by a native runner that drives the FMU's binary through the FMI 2.0 API
with exactly FMPy's master: the results equal fmpy.simulate_fmu bit for bit."""

from ._model import LgfValueError, SimulationError, blocks, fmi_versions, fmu_path, model
from .simulation import FMUWarning, simulate
from .sweeps import METRICS, Trace, sweep


def compile(
    sources,
    block: str | None = None,
    fmi: int = 2,
    output=None,
    *,
    program=None,
    tags=None,
    win64=None,
    aarch64=None,
    iec_check=False,
    auto_eno=False,
):
    """Compiles the FUNCTION_BLOCK `block` of SCL sources (a path or a list of paths, as TIA
    Portal exports them) into an FMU, FMI 2.0 (Co-Simulation and Model Exchange) or 3.0, written
    to output (default <block>.fmu); returns its path. With program (a program.toml) instead of
    block, the whole PLC program as one FMU: its OBs on their cycles, tags its PLC tag table
    (TIA's .xlsx export or a CSV of its columns; docs/scl.md §3.10-§3.12).
    The FMU carries a binary for this platform and, where mingw-w64 is installed (win64=None)
    or required (True), one for win64; False leaves that out; aarch64 likewise for an
    aarch64-linux binary of an FMI 3.0 FMU (Debian's cross compiler gcc-aarch64-linux-gnu).
    iec_check=True compiles as TIA Portal with the blocks' "IEC check" on: only the implicit
    conversions towards a type that holds every value (off, TIA's default, also those between
    integers and bit strings); auto_eno=True as with their "Set ENO automatically" on (a REAL
    operation with no finite result sets ENO FALSE, docs/scl.md §3.4). A source it refuses
    raises lgf_fmus.scl.SclError, "file:line:col: message" (docs/scl.md)."""
    from .scl import compile as compile_scl

    return compile_scl(
        sources,
        block=block,
        fmi=fmi,
        output=output,
        program=program,
        tags=tags,
        win64=win64,
        aarch64=aarch64,
        iec_check=iec_check,
        auto_eno=auto_eno,
    )


__all__ = [
    "FMUWarning",
    "LgfValueError",
    "METRICS",
    "SimulationError",
    "Trace",
    "blocks",
    "compile",
    "fmi_versions",
    "fmu_path",
    "model",
    "simulate",
    "sweep",
]
try:
    from importlib.metadata import version as _version

    __version__ = _version("lgf-fmus")  # the repository's VERSION
except Exception:  # not installed as a distribution
    __version__ = "unknown"
