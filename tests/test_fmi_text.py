"""What the FMI 2.0 text asks, where it is precise (docs/behaviour.md §1.3, §1.7-1.9): stopTime,
fmi2Discard for status kinds the FMU cannot provide, logging categories, the cycleTime messages,
and the serialized state read field by field as the documentation lays it out."""

import math
import struct
from ctypes import byref, c_char_p, c_double, c_int, c_uint

import pytest
from fmpy.fmi2 import fmi2Discard, fmi2Error, fmi2OK, fmi2Warning

from tests.harness import Slave, status_of
from tests.lgf_blocks import find, names

BLOCKS = names()
LIM = "LGF_LimRateOfChangeCI"
DO_STEP_STATUS, PENDING_STATUS, LAST_SUCCESSFUL_TIME, TERMINATED = 0, 1, 2, 3


def slave_until(block, stop_time):
    s = Slave(block, initialize=False)
    s.fmu.setupExperiment(startTime=0.0, stopTime=stop_time)
    s.fmu.enterInitializationMode()
    s.set(find(block).active)
    s.fmu.exitInitializationMode()
    return s


# ---- stopTime (FMI 2.0, 4.2.3 fmi2SetupExperiment) ----


@pytest.mark.parametrize("block", BLOCKS)
def test_a_step_past_the_stop_time_is_refused_and_changes_nothing(block):
    s = slave_until(block, 1.0)
    for _ in range(9):
        s.step(0.1)
    before = s.outputs()
    assert status_of(s.fmu.doStep, s.time, 0.2) == fmi2Error
    assert any(
        "fmi2DoStep" in text and "stopTime" in text
        for status, _, text in s.log
        if status == fmi2Error
    )
    assert s.outputs() == before
    s.step(0.1)  # the step that ends on the stop time (0.1 summed 10 times: a few ulps off)
    assert status_of(s.fmu.doStep, s.time, 1e-3) == fmi2Error
    s.free()


def test_without_a_stop_time_every_step_is_taken():
    s = Slave(LIM, initialize=False)
    s.fmu.setupExperiment(startTime=0.0)
    s.fmu.enterInitializationMode()
    s.fmu.exitInitializationMode()
    assert status_of(s.fmu.doStep, 0.0, 1e6) == fmi2OK
    assert status_of(s.fmu.doStep, 1e6, 0.1) == fmi2OK
    assert s.log == []
    time = c_double()
    assert (
        status_of(s.fmu.fmi2GetRealStatus, s.fmu.component, LAST_SUCCESSFUL_TIME, byref(time))
        == fmi2OK
    )
    assert time.value == 1e6 + 0.1
    # every call of the 0.1 s cycle up to t was executed: call 0 and 10,000,001 more
    calls = {name: at for name, _, at in LIM_FIELDS}["calls"]
    assert struct.unpack_from("<q", serialized(s), HEADER + calls) == (10_000_002,)
    assert s.outputs()["delayedValue"] == 100.0  # the start value of value, long reached
    s.free()


# ---- fmi2Get*Status (FMI 2.0, 4.2.3): fmi2Discard for what the FMU cannot provide ----


def test_status_kinds_the_fmu_cannot_provide_are_discarded():
    s = Slave(LIM)
    s.step(0.1)
    f, c = s.fmu, s.fmu.component
    status, real, integer, boolean, string = c_int(), c_double(), c_int(), c_int(), c_char_p()
    assert status_of(f.fmi2GetRealStatus, c, LAST_SUCCESSFUL_TIME, byref(real)) == fmi2OK
    assert real.value == pytest.approx(0.1, abs=1e-15)
    assert status_of(f.fmi2GetBooleanStatus, c, TERMINATED, byref(boolean)) == fmi2OK
    assert boolean.value == 0
    discarded = [
        status_of(f.fmi2GetStatus, c, DO_STEP_STATUS, byref(status)),
        status_of(f.fmi2GetStatus, c, PENDING_STATUS, byref(status)),
        status_of(f.fmi2GetRealStatus, c, DO_STEP_STATUS, byref(real)),
        status_of(f.fmi2GetIntegerStatus, c, DO_STEP_STATUS, byref(integer)),
        status_of(f.fmi2GetBooleanStatus, c, LAST_SUCCESSFUL_TIME, byref(boolean)),
        status_of(f.fmi2GetStringStatus, c, PENDING_STATUS, byref(string)),
    ]
    assert discarded == [fmi2Discard] * 6
    assert real.value == pytest.approx(0.1, abs=1e-15)  # a discarded call writes nothing
    s.free()


def test_status_functions_in_the_wrong_mode_are_errors():
    s = Slave(LIM, initialize=False)
    value = c_double()
    assert (
        status_of(s.fmu.fmi2GetRealStatus, s.fmu.component, LAST_SUCCESSFUL_TIME, byref(value))
        == fmi2Error
    )
    assert any("fmi2GetRealStatus" in text for _, _, text in s.log)
    s.free()


# ---- logging (FMI 2.0, 2.1.5) ----


def trace_lines(s):
    return [text for status, category, text in s.log if category == "logAll"]


def test_log_all_traces_the_calls_of_each_step_only_when_switched_on():
    s = Slave(LIM)
    s.step(0.3)
    assert trace_lines(s) == []  # loggingOn was false at instantiation
    s.fmu.setDebugLogging(True, [])  # no categories: all of them
    s.step(0.3)
    assert any("fmi2DoStep" in t and "calls 4 to 6" in t for t in trace_lines(s)), trace_lines(s)
    s.fmu.setDebugLogging(False, ["logAll"])  # that category off again
    n = len(s.log)
    s.step(0.3)
    assert s.log[n:] == []
    s.free()


def test_categories_select_what_is_logged_but_errors_always_are():
    s = Slave(LIM)
    s.fmu.setDebugLogging(True, ["logStatusWarning"])  # only that category
    s.step(0.2)
    assert trace_lines(s) == []
    s.fmu.setDebugLogging(False, [])  # everything off
    assert status_of(s.fmu.setReal, [s.vr("delayedValue")], [1.0]) == fmi2Error
    assert any(status == fmi2Error and "delayedValue" in text for status, _, text in s.log)
    assert status_of(s.fmu.setDebugLogging, True, ["logNothing"]) == fmi2Error
    assert any("logNothing" in text for _, _, text in s.log)
    s.free()


def test_a_block_error_code_reaches_an_importer_intact():
    # docs/behaviour.md §1.8: the FMU doubles '#'; the logger reads "##" as '#'.
    s = Slave(LIM, inputs={"setChangeRate": -1.0})
    warnings = [
        (raw, text) for raw, (status, _, text) in zip(s.raw_log, s.log) if status == fmi2Warning
    ]
    assert warnings and "16##8200" in warnings[0][0] and "16#8200" in warnings[0][1]
    s.free()


# ---- cycleTime (docs/behaviour.md §1.1, §1.7) ----


def set_real(s, name, value):
    """The status of fmi2SetReal itself (FMPy's setReal hides a warning)."""
    return s.fmu.fmi2SetReal(s.fmu.component, (c_uint * 1)(s.vr(name)), 1, (c_double * 1)(value))


@pytest.mark.parametrize(
    "block, codes", [(LIM, ["16#8600", "16#8601"]), ("LGF_RampCI", ["16#8400", "16#8200"])]
)
def test_an_invalid_cycle_time_names_the_codes_it_replaces(block, codes):
    s = Slave(block, initialize=False)
    assert status_of(s.fmu.setReal, [s.vr("cycleTime")], [0.0]) == fmi2Error
    text = [t for status, _, t in s.log if status == fmi2Error][-1]
    assert "fmi2SetReal" in text and "cycleTime" in text and all(c in text for c in codes), text
    s.free()


@pytest.mark.parametrize("value, runs_on", [(1.0000004, 1.0), (0.0100004, 0.01), (2.5e-6, 3e-6)])
def test_a_cycle_time_rounded_to_whole_microseconds_is_reported(value, runs_on):
    s = Slave(LIM, initialize=False)
    assert set_real(s, "cycleTime", value) == fmi2Warning
    assert any(
        status == fmi2Warning and "cycleTime" in text and "µs" in text for status, _, text in s.log
    )
    s.fmu.enterInitializationMode()
    assert s.get(["cycleTime"])["cycleTime"] == runs_on
    s.free()


def test_a_whole_microsecond_cycle_time_is_taken_silently():
    s = Slave(LIM, initialize=False)
    for value in (0.1, 0.001, 1e-6, 60.0, 0.123457):
        assert set_real(s, "cycleTime", value) == fmi2OK
    assert s.log == []
    s.free()


# ---- the serialized state, read as docs/behaviour.md §1.9 lays it out ----

HEADER = 104


def fnv1a(data: bytes) -> int:
    h = 0xCBF29CE484222325
    for b in data:
        h = ((h ^ b) * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


def serialized(s) -> bytes:
    state = s.fmu.getFMUstate()
    data = bytes(s.fmu.serializeFMUstate(state))
    s.fmu.freeFMUstate(state)
    return data


# LGF_LimRateOfChangeCI's payload: the clock, then its variables in the order of the table
# (value, setChangeRate, defaultOutValue, enDefaultOutValue, delayedValue, error, status,
# subFunctionStatus), then statPrevOutValue; each little endian at an offset aligned to its size.
LIM_FIELDS = [
    ("mode", "<i", 0),
    ("cycle_us", "<i", 4),
    ("start_time", "<d", 8),
    ("time", "<d", 16),
    ("calls", "<q", 24),
    ("stop_time", "<d", 32),
    ("stop_defined", "<?", 40),
    ("value", "<d", 48),
    ("setChangeRate", "<d", 56),
    ("defaultOutValue", "<d", 64),
    ("enDefaultOutValue", "<?", 72),
    ("delayedValue", "<d", 80),
    ("error", "<?", 88),
    ("status", "<H", 90),
    ("subFunctionStatus", "<H", 92),
    ("statPrevOutValue", "<d", 96),
]


def with_field(data: bytes, offset: int, raw: bytes) -> bytes:
    """The state with raw bytes at a payload offset and a checksum that matches again."""
    b = bytearray(data)
    b[HEADER + offset : HEADER + offset + len(raw)] = raw
    b[88:96] = struct.pack("<Q", fnv1a(bytes(b[HEADER:])))
    return bytes(b)


def test_the_serialized_state_is_written_field_by_field():
    s = Slave(LIM, {"cycleTime": 0.25}, {"value": 10.0, "setChangeRate": 2.0})
    s.step(0.5)
    data = serialized(s)
    assert data[:8] == b"LGF-FMU\0" and struct.unpack_from("<I", data, 8) == (2,)
    assert data[12:44].rstrip(b"\0") == LIM.encode()
    payload = data[HEADER:]
    assert struct.unpack_from("<I", data, 84) == (len(payload),) == (104,)
    assert struct.unpack_from("<Q", data, 88) == (fnv1a(payload),)
    fields = {name: struct.unpack_from(fmt, payload, at)[0] for name, fmt, at in LIM_FIELDS}
    assert fields == {
        "mode": 2,
        "cycle_us": 250000,
        "start_time": 0.0,
        "time": 0.5,
        "calls": 3,
        "stop_time": 0.0,
        "stop_defined": False,
        "value": 10.0,
        "setChangeRate": 2.0,
        "defaultOutValue": 0.0,
        "enDefaultOutValue": False,
        "delayedValue": 1.5,
        "error": False,
        "status": 0,
        "subFunctionStatus": 0,
        "statPrevOutValue": 1.5,
    }
    s.free()


@pytest.mark.parametrize(
    "what, offset, raw, says",
    [
        ("NaN in a Real static", 96, struct.pack("<d", math.nan), "statPrevOutValue"),
        ("Boolean byte 2 in an input", 72, b"\x02", "enDefaultOutValue"),
        ("Boolean byte 0xFF in the clock", 40, b"\xff", "clock"),
        ("a padding byte", 41, b"\x01", "padding"),
        ("NaN in an input", 48, struct.pack("<d", math.nan), "value"),
    ],
)
def test_a_state_no_run_can_produce_is_refused(what, offset, raw, says):
    s = Slave(LIM, inputs={"value": 3.0, "setChangeRate": 1.0})
    s.step(0.1)
    data = serialized(s)
    assert (
        status_of(s.fmu.deSerializeFMUstate, with_field(data, 0, data[HEADER : HEADER + 1]))
        == fmi2OK
    )
    assert status_of(s.fmu.deSerializeFMUstate, with_field(data, offset, raw)) == fmi2Error, what
    text = [t for status, _, t in s.log if status == fmi2Error][-1]
    assert "fmi2DeSerializeFMUstate" in text and says in text, text
    s.free()


def test_a_state_of_another_layout_is_refused():
    s = Slave(LIM)
    data = bytearray(serialized(s))
    data[96] ^= 1  # the layout identity: what a rebuild with other statics would write
    assert status_of(s.fmu.deSerializeFMUstate, bytes(data)) == fmi2Error
    assert "layout" in [t for status, _, t in s.log if status == fmi2Error][-1]
    s.free()
