"""Drives any FMU file, a compiled one or a hand-written one, through FMPy's FMI 2.0 and 3.0 APIs
as tests/harness.py drives the bundled FMUs: co-simulation with the communication points an
importer computes (docs/behaviour.md §1.3), Model Exchange event by event at the call times
(§1.11). Variables by name, so that a compiled twin and its hand-written block are compared
name by name."""

from __future__ import annotations

import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

import pytest
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Model, FMU2Slave
from fmpy.fmi3 import FMU3Model, FMU3Slave

from lgf_fmus import scl
from lgf_fmus.scl import SclError
from tests.harness import callbacks_for, forget
from tests.timeouts import hang_guard

ROOT = Path(__file__).resolve().parents[2]
TWINS = Path(__file__).resolve().parent / "twins"


_unpacked: dict[str, tuple] = {}


def unpacked(fmu: Path):
    """(unzip directory, model description) of an FMU, extracted once per session."""
    key = str(fmu)
    if key not in _unpacked:
        directory = extract(key, tempfile.mkdtemp(prefix="lgf-scl-test-"))
        _unpacked[key] = (directory, read_model_description(directory))
    return _unpacked[key]


def cleanup():
    for directory, _ in _unpacked.values():
        shutil.rmtree(directory, ignore_errors=True)
    _unpacked.clear()


class Instance:
    def __init__(self, fmu: Path, parameters: dict, inputs: dict, model_exchange=False):
        self.directory, self.md = unpacked(fmu)
        self.fmi3 = self.md.fmiVersion.startswith("3")
        self.variables = {v.name: v for v in self.md.modelVariables}
        self.output_names = [v.name for v in self.md.modelVariables if v.causality == "output"]
        if self.fmi3:
            kind = FMU3Model if model_exchange else FMU3Slave
            identifier = (
                self.md.modelExchange if model_exchange else self.md.coSimulation
            ).modelIdentifier
        else:
            kind = FMU2Model if model_exchange else FMU2Slave
            identifier = (
                self.md.modelExchange if model_exchange else self.md.coSimulation
            ).modelIdentifier
        self.fmu = kind(
            guid=self.md.guid,
            unzipDirectory=self.directory,
            modelIdentifier=identifier,
            instanceName="scl",
        )
        self.log: list[str] = []  # every message the FMU logs, as its text
        if self.fmi3:
            self.fmu.instantiate(logMessage=lambda env, status, category, text: self._log(text))
        else:  # the process's one FMI 2.0 logger, which dispatches to each instance's _log
            self.callbacks = callbacks_for(self)
            self.fmu.instantiate(callbacks=self.callbacks)
        if self.fmi3:
            self.fmu.enterInitializationMode(startTime=0.0)
        else:
            self.fmu.setupExperiment(startTime=0.0)
            self.fmu.enterInitializationMode()
        self.set({**parameters, **inputs})
        self.fmu.exitInitializationMode()

    def _log(self, *record) -> None:  # (text) of FMI 3.0, (status, category, text) of 2.0
        self.log.append(record[-1].decode("utf-8"))

    def set(self, values: dict):
        for name, value in values.items():
            v = self.variables[name]
            vr = [v.valueReference]
            if v.type in ("Real", "Float64"):
                self.fmu.setReal(vr, [float(value)]) if not self.fmi3 else self.fmu.setFloat64(
                    vr, [float(value)]
                )
            elif v.type == "Float32":
                self.fmu.setFloat32(vr, [float(value)])
            elif v.type == "Integer":
                self.fmu.setInteger(vr, [int(value)])
            elif v.type == "Boolean":
                self.fmu.setBoolean(vr, [bool(value)])
            elif v.type == "String":  # a STRING or WSTRING (docs/scl.md §3.1)
                self.fmu.setString(vr, [value])
            else:  # FMI 3.0 integers: Int16, UInt16, Int32, UInt32, ...
                getattr(self.fmu, "set" + v.type)(vr, [int(value)])

    def get(self, names) -> dict:
        result = {}
        for name in names:
            v = self.variables[name]
            vr = [v.valueReference]
            if v.type == "Real":
                result[name] = self.fmu.getReal(vr)[0]
            elif v.type == "Integer":
                result[name] = self.fmu.getInteger(vr)[0]
            elif v.type == "Boolean":
                result[name] = bool(self.fmu.getBoolean(vr)[0])
            elif v.type == "String":  # FMPy gives FMI 2.0's as the bytes of UTF-8
                text = self.fmu.getString(vr)[0]
                result[name] = text.decode("utf-8") if isinstance(text, bytes) else text
            else:
                result[name] = getattr(self.fmu, "get" + v.type)(vr)[0]
        return result

    def outputs(self) -> dict:
        return self.get(self.output_names)

    def free(self):
        self.fmu.terminate()
        self.fmu.freeInstance()
        if not self.fmi3:
            forget(self)


def run_cs(fmu: Path, cycle_us: int, parameters: dict, initial: dict, steps, names=None):
    """Outputs after initialization and after every step of (h in µs, input changes)."""
    s = Instance(fmu, {"cycleTime": cycle_us / 1e6, **parameters}, initial)
    names = names or s.output_names
    rows = [s.get(names)]
    elapsed = 0
    for h_us, changes in steps:
        s.set(changes)
        t, end = elapsed / 1e6, (elapsed + h_us) / 1e6
        s.fmu.doStep(currentCommunicationPoint=t, communicationStepSize=end - t)
        elapsed += h_us
        rows.append(s.get(names))
    s.free()
    return rows


def run_me(fmu: Path, cycle_us: int, parameters: dict, per_call: list[dict], names=None):
    """Model Exchange (FMI 2.0 or 3.0): outputs after each call k, which sees per_call[k]."""
    s = Instance(fmu, {"cycleTime": cycle_us / 1e6, **parameters}, per_call[0], model_exchange=True)
    update = s.fmu.updateDiscreteStates if s.fmi3 else s.fmu.newDiscreteStates
    names = names or s.output_names
    rows = [s.get(names)]
    *_, next_time = update()
    s.fmu.enterContinuousTimeMode()
    for inputs in per_call[1:]:
        s.fmu.setTime(next_time)
        s.fmu.enterEventMode()
        s.set(inputs)
        *_, next_time = update()
        rows.append(s.get(names))
        s.fmu.enterContinuousTimeMode()
    s.free()
    return rows


def calls(fmu: Path, per_call: list[dict], cycle_us=100_000, outputs=None) -> list[dict]:
    """The outputs after each call k, which sees per_call[k] (co-simulation, h = cycleTime)."""
    steps = [(cycle_us, inputs) for inputs in per_call[1:]]
    return run_cs(fmu, cycle_us, {}, per_call[0], steps, names=outputs)


def once(fmu: Path, inputs: dict) -> dict:
    """The outputs of the first call, which sees inputs."""
    return calls(fmu, [inputs])[0]


def hand_written(block: str, fmi: int = 2) -> Path:
    path = ROOT / "fmus" / ("" if fmi == 2 else "fmi3") / f"{block}.fmu"
    assert path.exists(), f"{path} is missing: run `make -o .venv/.installed build`"
    return path


def compile_text(tmp: Path, text: str, block: str, fmi: int = 2, **options) -> Path:
    """An SCL text of a test, compiled as the user's would be (with -Werror: a warning of the
    C compiler on generated C is a defect), without the win64 binary that nothing here runs
    (tests/scl/test_win64.py runs one); options as scl.compile takes them."""
    source = tmp / f"{block}.scl"
    source.write_text(text, encoding="utf-8")
    return scl.compile(
        [source],
        block=block,
        fmi=fmi,
        output=tmp / f"{block}_fmi{fmi}.fmu",
        werror=True,
        win64=False,
        aarch64=False,
        **options,
    )


def compiled(text: str, block: str):
    """A fixture of a module's tests: the SCL text compiled once (compile_text) for them all."""

    @pytest.fixture(scope="module")
    def fmu(tmp_path_factory):
        return compile_text(tmp_path_factory.mktemp(block), text, block)

    return fmu


def refusal(tmp: Path, text: str, block: str = "Fb", name: str = "fb.scl", **options) -> SclError:
    """The error of an SCL text of a test that the compiler must refuse, written as the file
    `name` (scl.generate_c: the refusals come before any C); options as generate_c takes them."""
    source = tmp / name
    source.write_text(text, encoding="utf-8")
    with pytest.raises(SclError) as caught:
        scl.generate_c([source], block=block, **options)
    return caught.value


def compile_command(*args, cwd=None) -> subprocess.CompletedProcess:
    """`python -m lgf_fmus compile ARGS` as a user runs it, its output as text."""
    return subprocess.run(
        [sys.executable, "-m", "lgf_fmus", "compile", *map(str, args)],
        capture_output=True,
        text=True,
        cwd=cwd,
        timeout=hang_guard(120),
    )
