"""The native runner (_lgf_runner, built from python/runner/runner.c) through ctypes: a Plan says
what every run of a batch sets and records, `run_batch` runs many runs into numpy buffers.

Each process (a Dask worker, or the caller for simulate) extracts an FMU once and keeps one
instance per thread, which the runner resets with fmi2Reset between runs."""

from __future__ import annotations

import atexit
import ctypes
import math
import shutil
import tempfile
import threading
import zipfile
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ._model import (
    LgfValueError,
    Model,
    file_key,
    settable_after_instantiation,
    settable_in_initialization,
)

_LIBRARY = None
_lock = threading.Lock()
MESSAGE_SIZE = 2048
RUN_OK, RUN_WARNING, RUN_FAILED = 0, 1, 2


class _Plan(ctypes.Structure):
    _fields_ = [
        ("start_time", ctypes.c_double),
        ("stop_time", ctypes.c_double),
        ("output_interval", ctypes.c_double),
        ("tolerance_defined", ctypes.c_int),
        ("tolerance", ctypes.c_double),
        ("can_handle_variable_step_size", ctypes.c_int),
        ("n_start", ctypes.c_int),
        ("start_vr", ctypes.c_void_p),
        ("start_type", ctypes.c_void_p),
        ("start_phase", ctypes.c_void_p),
        ("n_inputs", ctypes.c_int),
        ("input_vr", ctypes.c_void_p),
        ("input_type", ctypes.c_void_p),
        ("n_outputs", ctypes.c_int),
        ("output_vr", ctypes.c_void_p),
        ("output_type", ctypes.c_void_p),
        ("max_samples", ctypes.c_int),
        ("message_size", ctypes.c_int),
    ]


def _library():
    global _LIBRARY
    if _LIBRARY is None:
        candidates = sorted(Path(__file__).resolve().parent.glob("_lgf_runner*"))
        if not candidates:
            raise RuntimeError(
                "the native runner _lgf_runner is not installed with lgf_fmus "
                "(install the package with pip, which builds it)"
            )
        lib = ctypes.CDLL(str(candidates[0]))
        lib.lgf_runner_open.restype = ctypes.c_void_p
        lib.lgf_runner_open.argtypes = [
            ctypes.c_char_p,
            ctypes.c_char_p,
            ctypes.c_char_p,
            ctypes.c_char_p,
            ctypes.c_char_p,
            ctypes.c_size_t,
        ]
        lib.lgf_runner_close.argtypes = [ctypes.c_void_p]
        lib.lgf_runner_run.restype = ctypes.c_int
        lib.lgf_runner_run.argtypes = [ctypes.c_void_p, ctypes.POINTER(_Plan), ctypes.c_int] + [
            ctypes.c_void_p
        ] * 9
        _LIBRARY = lib
    return _LIBRARY


@dataclass
class Plan:
    """What every run of a sweep (or the one run of simulate) shares."""

    start_names: list[str]  # in the order FMPy sets them
    start_phase: np.ndarray
    input_names: list[str]
    output_names: list[str]
    start_time: float
    stop_time: float
    output_interval: float
    tolerance: float | None
    can_handle_variable_step_size: bool
    start_vr: np.ndarray
    start_type: np.ndarray
    input_vr: np.ndarray
    input_type: np.ndarray
    output_vr: np.ndarray
    output_type: np.ndarray
    output_kinds: list[str]

    @classmethod
    def make(
        cls,
        model: Model,
        start_names,
        input_names,
        output_names,
        start_time,
        stop_time,
        output_interval,
    ) -> "Plan":
        names = set(start_names)
        # FMPy's apply_start_values: first those settable after instantiation, then in
        # initialization mode those that are left, each time in modelDescription order.
        first = [
            v for n, v in model.variables.items() if n in names and settable_after_instantiation(v)
        ]
        second = [
            v
            for n, v in model.variables.items()
            if n in names and not settable_after_instantiation(v) and settable_in_initialization(v)
        ]
        left = names - {v.name for v in first + second}
        if left:
            raise LgfValueError(
                f"{model.identifier}: {', '.join(sorted(left))} cannot be set "
                "before the simulation starts"
            )
        starts = first + second
        inputs = [model.variables[n] for n in input_names]
        outputs = [model.variables[n] for n in output_names]
        if len(inputs) > 64:
            raise LgfValueError("at most 64 inputs can be driven by tables")
        u32 = lambda vs: np.array([v.vr for v in vs], dtype=np.uint32)
        i32 = lambda vs: np.array([v.type_code for v in vs], dtype=np.int32)
        return cls(
            start_names=[v.name for v in starts],
            start_phase=np.array([0] * len(first) + [1] * len(second), dtype=np.int32),
            input_names=[v.name for v in inputs],
            output_names=[v.name for v in outputs],
            start_time=float(start_time),
            stop_time=float(stop_time),
            output_interval=float(output_interval),
            tolerance=model.tolerance,
            can_handle_variable_step_size=model.can_handle_variable_step_size,
            start_vr=u32(starts),
            start_type=i32(starts),
            input_vr=u32(inputs),
            input_type=i32(inputs),
            output_vr=u32(outputs),
            output_type=i32(outputs),
            output_kinds=[v.type for v in outputs],
        )

    def max_samples(self, max_rows: int) -> int:
        grid = (self.stop_time - self.start_time) / self.output_interval
        return int(math.ceil(grid)) + max_rows + 4

    def _struct(self, max_samples: int) -> _Plan:
        ptr = lambda a: a.ctypes.data if a.size else None
        return _Plan(
            self.start_time,
            self.stop_time,
            self.output_interval,
            int(self.tolerance is not None),
            self.tolerance or 0.0,
            int(self.can_handle_variable_step_size),
            len(self.start_names),
            ptr(self.start_vr),
            ptr(self.start_type),
            ptr(self.start_phase),
            len(self.input_names),
            ptr(self.input_vr),
            ptr(self.input_type),
            len(self.output_names),
            ptr(self.output_vr),
            ptr(self.output_type),
            max_samples,
            MESSAGE_SIZE,
        )


@dataclass
class Batch:
    """The results of n runs: times[run, sample], samples[run, sample, output], n_samples[run],
    status[run] (RUN_OK, RUN_WARNING, RUN_FAILED) and each run's message."""

    times: np.ndarray
    samples: np.ndarray
    n_samples: np.ndarray
    status: np.ndarray
    messages: list[str]


class _Runner:
    """One FMU's binary, loaded once, with one instance (made by the first run)."""

    def __init__(self, model: Model, directory: Path):
        self.model = model
        binary = directory / "binaries" / _platform() / (model.identifier + _suffix())
        if not binary.is_file():
            raise LgfValueError(f"{model.path.name} has no binary for {_platform()}")
        message = ctypes.create_string_buffer(1024)
        self.handle = _library().lgf_runner_open(
            str(binary).encode(),
            model.identifier.encode(),
            model.guid.encode(),
            (directory / "resources").as_uri().encode(),
            message,
            len(message),
        )
        if not self.handle:
            raise RuntimeError(message.value.decode(errors="replace"))

    def close(self):
        if self.handle:
            _library().lgf_runner_close(self.handle)
            self.handle = None

    def run(
        self,
        plan: Plan,
        start_values: np.ndarray,
        rows_begin: np.ndarray,
        input_times: np.ndarray,
        input_values: np.ndarray,
    ) -> Batch:
        n = start_values.shape[0]
        max_rows = int(np.max(np.diff(rows_begin))) if n else 0
        max_samples = plan.max_samples(max_rows)
        start_values = np.ascontiguousarray(start_values, dtype=np.float64)
        rows_begin = np.ascontiguousarray(rows_begin, dtype=np.int64)
        input_times = np.ascontiguousarray(input_times, dtype=np.float64)
        input_values = np.ascontiguousarray(input_values, dtype=np.float64)
        times = np.empty((n, max_samples))
        samples = np.empty((n, max_samples, len(plan.output_names)))
        n_samples = np.zeros(n, dtype=np.int32)
        status = np.zeros(n, dtype=np.int32)
        messages = np.empty(n * MESSAGE_SIZE, dtype=np.uint8)  # the runner ends each with 0
        struct = plan._struct(max_samples)
        ptr = lambda a: a.ctypes.data if a.size else None
        result = _library().lgf_runner_run(
            self.handle,
            ctypes.byref(struct),
            n,
            ptr(start_values),
            ptr(rows_begin),
            ptr(input_times),
            ptr(input_values),
            ptr(times),
            ptr(samples),
            ptr(n_samples),
            ptr(status),
            ptr(messages),
        )
        if result < 0:
            raise RuntimeError("the native runner could not run the plan (out of memory?)")
        text = [""] * n
        for i in np.flatnonzero(status != RUN_OK):
            raw = messages[i * MESSAGE_SIZE : (i + 1) * MESSAGE_SIZE].tobytes()
            text[i] = raw.split(b"\0", 1)[0].decode(errors="replace")
        return Batch(times, samples, n_samples, status, text)


def _platform() -> str:
    import platform
    import sys

    machine = platform.machine().lower()
    bits = "64" if machine in ("x86_64", "amd64", "aarch64", "arm64") else "32"
    if sys.platform.startswith("linux"):
        return "linux" + bits
    if sys.platform == "darwin":
        return "darwin" + bits
    return "win" + bits


def _suffix() -> str:
    import sys

    if sys.platform.startswith("linux"):
        return ".so"
    return ".dylib" if sys.platform == "darwin" else ".dll"


# ---- per process: FMUs extracted once, per thread: one runner per FMU ------------------------

_extracted: dict[tuple, Path] = {}
_local = threading.local()
_temp_root: list[Path] = []


def _cleanup():
    for directory in _temp_root:
        shutil.rmtree(directory, ignore_errors=True)


atexit.register(_cleanup)


def _directory(model: Model) -> Path:
    key = file_key(model.path)
    with _lock:
        if key not in _extracted:
            if not _temp_root:
                _temp_root.append(Path(tempfile.mkdtemp(prefix="lgf-fmus-")))
            target = _temp_root[0] / f"{len(_extracted)}-{model.identifier}"
            with zipfile.ZipFile(model.path) as archive:
                archive.extractall(target)
            _extracted[key] = target
        return _extracted[key]


def runner(model: Model) -> _Runner:
    """This thread's runner of the FMU (its binary loaded and extracted once per process, and
    again once the file has changed)."""
    runners = getattr(_local, "runners", None)
    if runners is None:
        runners = _local.runners = {}
    key = file_key(model.path)
    if key not in runners:
        for older in [k for k in runners if k[0] == key[0]]:  # the FMU rebuilt at its path
            runners.pop(older).close()
        runners[key] = _Runner(model, _directory(model))
    return runners[key]
