"""lgf_fmus: the Siemens LGF PLC function blocks of this project as FMI FMUs, bundled, with

    blocks()                       the bundled blocks
    fmu_path(block, fmi_version=2) the FMU file of a block
    model(block)                   its variables (names, types, ranges, start values)
    simulate(block, stop_time, parameters, inputs=..., table=...)   one run -> DataFrame
    sweep(block, runs, stop_time, outputs, ...)                     many runs on Dask -> DataFrame

the command line `python -m lgf_fmus` (list, simulate, sweep), a pytest plugin (fixtures
lgf_fmu_paths, lgf_block, lgf_fmu, lgf_simulate) and lgf_fmus.testing (assertions for control
logic).
Every run is simulated by a native runner that drives the FMU's binary through the FMI 2.0 API
with exactly FMPy's master: the results equal fmpy.simulate_fmu bit for bit."""

from ._model import LgfValueError, SimulationError, blocks, fmi_versions, fmu_path, model
from .simulation import FMUWarning, simulate
from .sweeps import METRICS, Trace, sweep

__all__ = [
    "FMUWarning",
    "LgfValueError",
    "METRICS",
    "SimulationError",
    "Trace",
    "blocks",
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
