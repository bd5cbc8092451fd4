"""The FMI 3.0 FMUs (fmus/fmi3/<Block>.fmu, docs/behaviour.md §7): built from the same block code
and interface table as the FMI 2.0 FMUs, with INT as Int16 and WORD as UInt16. They validate,
hold binaries for x86_64-linux (and the cross-built x86_64-windows and aarch64-linux),
declare the same interface, and give outputs bit-identical to the FMI 2.0 FMU in every demo
scenario, in Co-Simulation and in Model Exchange; misuse is refused; states round-trip; the
sources rebuild with FMPy."""

from __future__ import annotations

import html
import re
import shutil
import xml.etree.ElementTree as ET
import zipfile
from ctypes import c_double
from pathlib import Path

import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy.fmi3 import FMU3Model, FMU3Slave, fmi3Error, fmi3ValueReference
from fmpy.validation import validate_fmu

from tests.harness import (
    FMU_DIR,
    ROOT,
    Slave,
    binaries,
    built_platforms,
    fmu_path,
    model_exchange_run,
    status_of,
)
from tests.lgf_blocks import find, names, scenarios
from tests.rebuild import FMPY, by_block
from tools.simulate import simulate

FMI3_DIR = FMU_DIR / "fmi3"


# The FMI 3.0 type of each PLC integer (docs/behaviour.md §7).
FMI3_INTEGERS = {
    "UDINT": "UInt32",
    "DWORD": "UInt32",
    "DINT": "Int32",
    "UINT": "UInt16",
    "SINT": "Int8",
    "USINT": "UInt8",
    "BYTE": "UInt8",
}


# FMI 2.0 type and the IEC type of its description (REAL:, UDINT:, DINT:) -> FMI 3.0 type; an
# Integer whose description names no such type is an INT, or a WORD when its range is 0 to 65535.
def fmi3_type(type2: str, attributes: dict) -> str:
    iec = attributes.get("description", "").split(":")[0]
    if type2 == "Real":
        return "Float32" if iec == "REAL" else "Float64"
    if type2 == "Integer":
        if iec in FMI3_INTEGERS:
            return FMI3_INTEGERS[iec]
        return (
            "UInt16"
            if (attributes.get("min"), attributes.get("max")) == ("0", "65535")
            else "Int16"
        )
    return "Boolean"


def fmi3_path(block: str) -> Path:
    return fmu_path(block, FMI3_DIR)


@pytest.mark.parametrize("block", names())
def test_validates(block):
    assert validate_fmu(str(fmi3_path(block))) == []


@pytest.mark.parametrize("block", names())
def test_binaries(block):
    """x86_64-linux, and x86_64-windows and aarch64-linux where their cross compilers are
    installed (tests/test_aarch64.py checks the aarch64 one)."""
    suffix = {"x86_64-linux": ".so", "x86_64-windows": ".dll", "aarch64-linux": ".so"}
    assert binaries(fmi3_path(block)) == {
        p: [f"{block}{suffix[p]}"] for p in built_platforms("fmi3")
    }


@pytest.mark.parametrize("block", names())
def test_the_icon_is_where_fmi3_keeps_it(block):
    with zipfile.ZipFile(fmi3_path(block)) as z:
        files = set(z.namelist())
    assert "terminalsAndIcons/icon.png" in files and "model.png" not in files


def variables(block: str, version: int) -> dict[str, tuple[str, dict]]:
    """name -> (type element, attributes) of a committed modelDescription, FMI 2.0 or 3.0."""
    folder = ROOT / "modelDescription" / ("fmi3" if version == 3 else "")
    root = ET.parse(folder / f"{block}.xml").getroot()
    if version == 2:
        return {
            sv.get("name"): (sv[0].tag, {**sv.attrib, **sv[0].attrib})
            for sv in root.find("ModelVariables")
        }
    return {
        v.get("name"): (v.tag, dict(v.attrib))
        for v in root.find("ModelVariables")
        if v.get("causality") != "independent"
    }


@pytest.mark.parametrize("block", names())
def test_the_interface_is_the_fmi2_interface(block):
    md3 = read_model_description(str(fmi3_path(block)))
    assert md3.fmiVersion == "3.0" and md3.modelExchange and md3.coSimulation
    assert md3.instantiationToken == read_model_description(str(fmu_path(block))).guid
    v2, v3 = variables(block, 2), variables(block, 3)
    assert list(v2) == list(v3)
    for name, (type2, a2) in v2.items():
        type3, a3 = v3[name]
        keys = (
            "valueReference",
            "causality",
            "variability",
            "initial",
            "description",
            "unit",
            "min",
            "start",
        )
        assert {k: a3.get(k) for k in keys} == {k: a2.get(k) for k in keys}, name
        assert type3 == fmi3_type(type2, a2), name
        if type3 == "UInt32":  # FMI 2.0's Integer stops at 2147483647, FMI 3.0's UInt32 does not
            assert (a2["max"], a3["max"]) == ("2147483647", "4294967295"), name
        else:
            assert a3.get("max") == a2.get("max"), name
    assert [v.name for v in md3.modelVariables if v.causality == "independent"] == ["time"]


@pytest.mark.parametrize("block", names())
def test_the_committed_fmi3_description_is_the_generated_one(block):
    with zipfile.ZipFile(fmi3_path(block)) as fmu:
        packed = fmu.read("modelDescription.xml")
    assert packed == (ROOT / "modelDescription" / "fmi3" / f"{block}.xml").read_bytes(), (
        "run `make descriptions` and review the diff"
    )


def compare(result, expected, outputs):
    assert np.array_equal(result["time"], expected["time"])
    for name in outputs:
        assert result[name].tolist() == expected[name].tolist(), name
        if expected[name].dtype.kind == "f":  # Reals bit for bit (a Float32 widened exactly)
            assert (
                result[name].astype(np.float64).tobytes()
                == expected[name].astype(np.float64).tobytes()
            ), name


@pytest.mark.parametrize("scenario", scenarios())
def test_co_simulation_equals_fmi2(scenario):
    expected, outputs, _ = simulate(scenario, FMU_DIR)
    result, _, _ = simulate(scenario, FMI3_DIR)
    compare(result, expected, outputs)


@pytest.mark.parametrize("scenario", scenarios())
def test_model_exchange_equals_fmi2_co_simulation(scenario):
    md = read_model_description(str(fmu_path(scenario.block)))
    expected, outputs, _ = simulate(scenario, FMU_DIR)
    compare(model_exchange_run(fmi3_path(scenario.block), scenario, md, outputs), expected, outputs)


class Instance:
    """One FMI 3.0 instance through FMPy, its log kept."""

    def __init__(self, block, model_exchange=False):
        md = read_model_description(str(fmi3_path(block)))
        self.directory = extract(str(fmi3_path(block)))
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        kind = FMU3Model if model_exchange else FMU3Slave
        interface = md.modelExchange if model_exchange else md.coSimulation
        self.fmu = kind(
            guid=md.instantiationToken,
            unzipDirectory=self.directory,
            modelIdentifier=interface.modelIdentifier,
            instanceName="test",
        )
        self.log = []
        self.fmu.instantiate(
            logMessage=lambda env, status, category, message: self.log.append(
                (status, message.decode())
            )
        )

    def free(self):
        self.fmu.freeInstance()
        shutil.rmtree(self.directory, ignore_errors=True)


@pytest.mark.parametrize("block", names())
def test_misuse_is_refused(block):
    s = Instance(block)
    f, c = s.fmu, s.fmu.component
    f.enterInitializationMode(startTime=0.0, stopTime=1.0)
    assert status_of(f.setFloat64, [s.vr["cycleTime"]], [0.0]) == fmi3Error
    f.exitInitializationMode()
    f.doStep(0.0, 0.5)
    assert status_of(f.doStep, 0.5, 1.0) == fmi3Error  # past the stop time
    assert status_of(f.setFloat64, [s.vr["cycleTime"]], [0.2]) == fmi3Error  # fixed
    assert status_of(f.setInt16, [s.vr["cycleTime"]], [1]) == fmi3Error  # a Float64
    vr, values = (fmi3ValueReference * 1)(s.vr["cycleTime"]), (c_double * 2)()
    assert status_of(f.fmi3GetFloat64, c, vr, 1, values, 2) == fmi3Error  # nValues
    assert status_of(f.updateDiscreteStates) == fmi3Error  # a Model Exchange function
    messages = [m for status, m in s.log if status == fmi3Error]
    assert len(messages) >= 5 and all(m.startswith("fmi3") for m in messages), messages
    assert any("16##" in m for _, m in s.log) is False  # FMI 3.0 messages are not escaped
    s.free()


def test_an_int16_parameter_out_of_range_is_refused():
    s = Instance("LGF_RampCI")
    assert status_of(s.fmu.setInt16, [s.vr["numberOfSetpoints"]], [100]) == fmi3Error
    assert any("numberOfSetpoints" in m and "2 to 64" in m for _, m in s.log)
    s.free()


@pytest.mark.parametrize("block", names())
def test_state_round_trip_replays_bit_for_bit(block):
    s = Instance(block)
    f = s.fmu
    variables = {v.name: v for v in read_model_description(s.directory).modelVariables}

    def setter(name):
        return getattr(f, f"set{variables[name].type}")

    def outputs():
        return [
            getattr(f, f"get{v.type}")([v.valueReference])[0]
            for v in variables.values()
            if v.causality == "output"
        ]

    f.enterInitializationMode(startTime=0.0)
    for name, value in find(block).active.items():
        setter(name)([s.vr[name]], [value])
    f.exitInitializationMode()
    for k in range(5):
        f.doStep(k * 0.1, 0.1)
    data = f.serializeFMUState(f.getFMUState())
    base = {**{n: v.start for n, v in variables.items() if v.causality == "input"}}
    base.update(find(block).active)

    def step(k):
        """Inputs that move (Booleans toggle every third step, Reals but times rise within
        their range), one step, and
        the outputs after it (doStep returns FMPy's tuple of its flags)."""
        for name, value in base.items():
            v = variables[name]
            if v.type == "Boolean":
                setter(name)([s.vr[name]], [(k // 3) % 2 == 0])
            elif v.type.startswith("Float") and getattr(v, "unit", None) != "s":  # not a TIME
                x = float(value) + k
                if v.max is not None:
                    x = min(x, float(v.max))
                setter(name)([s.vr[name]], [x])
        f.doStep(k * 0.1, 0.1)
        return outputs()

    run = [step(k) for k in range(5, 15)]
    assert len({repr(row) for row in run}) > 1, "the outputs never change: the test could not fail"
    state = f.deserializeFMUState(data)
    f.setFMUState(state)
    again = [step(k) for k in range(5, 15)]
    assert repr(run) == repr(again)
    s.free()


@pytest.mark.parametrize("scenario", scenarios())
def test_rebuilt_from_sources_simulates_identically(scenario, rebuilt):
    """FMPy's build from sources/ alone (tests/test_sources_build.py: and without a warning)."""
    built = by_block(rebuilt, FMPY, 3)[scenario.block]
    if built.failure:
        pytest.fail(built.failure)
    expected, outputs, _ = simulate(scenario, FMI3_DIR)
    result, _, _ = simulate(scenario, built.folder)
    compare(result, expected, outputs)


def test_a_udint_refused_names_the_range_its_fmi_version_declares():
    """periode is a UDINT: 1 ... 4294967295 as an FMI 3.0 UInt32, 1 ... 2147483647 as an FMI 2.0
    Integer, and each refusal names the range of its own modelDescription."""
    s = Instance("LGF_SinusCI")
    assert status_of(s.fmu.setUInt32, [s.vr["periode"]], [0]) == fmi3Error
    assert any("periode = 0 " in m and "(1 to 4294967295)" in m for _, m in s.log), s.log
    s.free()
    s2 = Slave("LGF_SinusCI", initialize=False)
    with pytest.raises(Exception):
        s2.set({"periode": 0})
    assert any("periode = 0 " in text and "(1 to 2147483647)" in text for _, _, text in s2.log), (
        s2.log
    )


def interface_rows(page: str) -> dict:
    """The documentation's interface table: name -> (FMI type, range text)."""
    rows = re.findall(
        r"<tr><td><code>([^<]+)</code>.*?</td><td>.*?</td><td>.*?</td><td>(\w+) / .*?</td>"
        r"<td>.*?</td><td>.*?</td><td>(.*?)</td>",
        page,
    )
    return {
        html.unescape(name): (fmi_type, html.unescape(limits)) for name, fmi_type, limits in rows
    }


@pytest.mark.parametrize("block", names())
def test_each_fmi_version_documents_its_own_types_and_ranges(block):
    """The FMI 2.0 and the FMI 3.0 FMU each carry the page of their own version: the interface
    table's types and ranges are those of the modelDescription beside it."""
    for path in (fmu_path(block), fmi3_path(block)):
        with zipfile.ZipFile(path) as z:
            page = z.read("documentation/index.html").decode("utf-8")
        md = read_model_description(str(path))
        version = md.fmiVersion[0]
        assert f"as an FMI {version}.0 FMU" in page, path
        rows = interface_rows(page)
        scalars = [v for v in md.modelVariables if "[" not in v.name and v.name != "time"]
        assert scalars and all(v.name in rows for v in scalars), (path, sorted(rows))
        for v in scalars:
            fmi_type, limits = rows[v.name]
            assert fmi_type == v.type, (path, v.name)
            if v.type != "Boolean" and v.max is not None and v.min is not None:
                assert limits == f"{v.min} … {v.max}", (path, v.name, limits)


def test_a_boolean_set_in_continuous_time_mode_waits_for_the_next_call():
    """docs/behaviour.md §1.11: FMI 3.0 too takes a discrete input set in continuous-time mode
    (OMSimulator does it), says so once, and the next call reads it. LGF_PulseRelay toggles its
    output at a rising edge of `trigger` (§11)."""
    s = Instance("LGF_PulseRelay", model_exchange=True)
    f = s.fmu
    f.enterInitializationMode(startTime=0.0)
    f.exitInitializationMode()
    f.updateDiscreteStates()
    f.enterContinuousTimeMode()
    f.setTime(0.05)
    f.setBoolean([s.vr["trigger"]], [True])
    f.setBoolean([s.vr["trigger"]], [True])
    assert f.getBoolean([s.vr["out"]]) == [False]  # not before the next call
    f.setTime(0.1)
    f.enterEventMode()
    f.updateDiscreteStates()  # call 1 reads the edge
    assert f.getBoolean([s.vr["out"]]) == [True]
    told = [m for _, m in s.log if "continuous-time mode" in m]
    assert len(told) == 1 and told[0].startswith("fmi3SetBoolean"), told
    s.free()
