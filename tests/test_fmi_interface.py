"""The shared FMI layer, for every block: the FMU validates, the binary agrees with its
modelDescription.xml, and every misuse of docs/behaviour.md §1.7 is refused with fmi2Error, a log
sentence naming the function and the variable, and no effect on what follows."""

import math
from ctypes import byref

import pytest
from fmpy.fmi2 import FMU2Slave, fmi2Error, fmi2OK, fmi2Warning
from fmpy.validation import validate_fmu

from tests.harness import Slave, fmu_path, status_of, unpacked
from tests.lgf_blocks import find, names

BLOCKS = names()
STEPS = 25


def active_slave(block, **kwargs):
    return Slave(block, inputs=find(block).active, **kwargs)


def run(slave, steps=STEPS, h=0.1):
    return [slave.step(h) for _ in range(steps)]


def reference_run(block):
    s = active_slave(block)
    rows = run(s)
    s.free()
    return rows


def errors(slave):
    return [text for status, _, text in slave.log if status == fmi2Error]


@pytest.mark.parametrize("block", BLOCKS)
def test_validates(block):
    assert validate_fmu(str(fmu_path(block))) == []


@pytest.mark.parametrize("block", BLOCKS)
def test_binary_agrees_with_xml(block):
    """Every variable of the XML: its value reference answers with its type and its start value,
    outputs cannot be set, and the XML's min/max are the limits the binary enforces."""
    md, _ = unpacked(block)
    s = Slave(block, initialize=False)
    s.fmu.setupExperiment(startTime=0.0)
    s.fmu.enterInitializationMode()
    getters = {"Real": s.fmu.getReal, "Integer": s.fmu.getInteger, "Boolean": s.fmu.getBoolean}
    setters = {"Real": s.fmu.setReal, "Integer": s.fmu.setInteger, "Boolean": s.fmu.setBoolean}
    for v in md.modelVariables:
        value = getters[v.type]([v.valueReference])[0]
        if v.start is not None:
            start = {"Real": float, "Integer": int, "Boolean": lambda x: x in ("true", "1", True)}[
                v.type
            ](v.start)
            assert value == start, v.name
        for other, getter in getters.items():
            if other != v.type:
                assert status_of(getter, [v.valueReference]) == fmi2Error, (v.name, other)
        if v.causality == "output":
            assert status_of(setters[v.type], [v.valueReference], [value]) == fmi2Error, v.name
            continue
        if v.type in ("Real", "Integer") and v.min is not None:
            step = 1 if v.type == "Integer" else 1e-3 * max(1.0, abs(float(v.min)))
            low = (int if v.type == "Integer" else float)(v.min)
            assert status_of(setters[v.type], [v.valueReference], [low - step]) == fmi2Error, v.name
            assert status_of(setters[v.type], [v.valueReference], [value]) in (fmi2OK, fmi2Warning)
        if v.type in ("Real", "Integer") and v.max is not None:
            step = 1 if v.type == "Integer" else 1e-3 * max(1.0, abs(float(v.max)))
            high = (int if v.type == "Integer" else float)(v.max)
            assert status_of(setters[v.type], [v.valueReference], [high + step]) == fmi2Error, (
                v.name
            )
    known = {v.valueReference for v in md.modelVariables}
    for vr in (max(known) + 1, 4000000000):
        assert vr not in known
        for getter in getters.values():
            assert status_of(getter, [vr]) == fmi2Error
    assert any("unknown value reference" in text for text in errors(s))
    s.fmu.exitInitializationMode()
    s.free()


def misuses(block):
    """(label, function of a slave in step mode returning the FMI status) for every misuse."""
    md, _ = unpacked(block)
    cases = []
    for v in md.modelVariables:
        vr = [v.valueReference]
        if v.causality == "output":
            setter = {"Real": "setReal", "Integer": "setInteger", "Boolean": "setBoolean"}[v.type]
            cases.append(
                (
                    f"set output {v.name}",
                    lambda s, setter=setter, vr=vr: status_of(getattr(s.fmu, setter), vr, [1]),
                )
            )
            continue
        if v.variability == "fixed":
            setter = {"Real": "setReal", "Integer": "setInteger", "Boolean": "setBoolean"}[v.type]
            value = {"Real": float, "Integer": int, "Boolean": lambda x: x == "true"}[v.type](
                v.start
            )
            cases.append(
                (
                    f"set fixed {v.name} after init",
                    lambda s, setter=setter, vr=vr, value=value: status_of(
                        getattr(s.fmu, setter), vr, [value]
                    ),
                )
            )
        if v.type == "Real":
            cases.append(
                (f"NaN into {v.name}", lambda s, vr=vr: status_of(s.fmu.setReal, vr, [math.nan]))
            )
        if v.type == "Integer" and v.variability != "fixed":
            # past the range: 40000 for an INT, 0 for a UDINT period (1 … 2147483647)
            bad = int(v.max) + 1 if int(v.max) < 2**31 - 1 else int(v.min) - 1
            cases.append(
                (
                    f"{bad} into {v.name}",
                    lambda s, vr=vr, bad=bad: status_of(s.fmu.setInteger, vr, [bad]),
                )
            )
        if v.type == "Real" and v.unit == "s" and v.variability != "fixed":
            cases.append(
                (
                    f"TIME beyond range into {v.name}",
                    lambda s, vr=vr: status_of(s.fmu.setReal, vr, [3e6]),
                )
            )
    unknown = max(v.valueReference for v in md.modelVariables) + 1
    cases += [
        ("unknown value reference", lambda s: status_of(s.fmu.setReal, [unknown], [0.0])),
        ("Integer setter on a Real", lambda s: status_of(s.fmu.setInteger, [0], [1])),
        ("doStep h = 0", lambda s: status_of(s.fmu.doStep, s.time, 0.0)),
        ("doStep h < 0", lambda s: status_of(s.fmu.doStep, s.time, -0.1)),
        ("doStep h = NaN", lambda s: status_of(s.fmu.doStep, s.time, math.nan)),
        ("doStep from the wrong time", lambda s: status_of(s.fmu.doStep, s.time + 0.05, 0.1)),
        ("doStep from the past", lambda s: status_of(s.fmu.doStep, s.time - 0.1, 0.1)),
        ("setupExperiment in step mode", lambda s: status_of(s.fmu.setupExperiment, None, 0.0)),
        (
            "enterInitializationMode in step mode",
            lambda s: status_of(s.fmu.enterInitializationMode),
        ),
        ("exitInitializationMode in step mode", lambda s: status_of(s.fmu.exitInitializationMode)),
        ("cancelStep", lambda s: status_of(s.fmu.cancelStep)),
        ("setString", lambda s: status_of(s.fmu.setString, [0], ["x"])),
        ("unknown log category", lambda s: status_of(s.fmu.setDebugLogging, True, ["logNothing"])),
        ("deserialize garbage", lambda s: status_of(s.fmu.deSerializeFMUstate, b"\x00" * 64)),
    ]
    return cases


@pytest.mark.parametrize("block", BLOCKS)
def test_every_misuse_is_refused_and_changes_nothing(block):
    expected = reference_run(block)
    for label, misuse in misuses(block):
        s = active_slave(block)
        rows = run(s, 5)
        before = len(s.log)
        assert misuse(s) == fmi2Error, label
        new = [text for status, _, text in s.log[before:] if status == fmi2Error]
        assert len(new) == 1, (label, s.log[before:])
        assert new[0].startswith("fmi2"), (label, new[0])  # names the function
        rows += run(s, STEPS - 5)
        assert rows == expected, label
        s.free()


@pytest.mark.parametrize("block", BLOCKS)
def test_a_rejected_multi_set_applies_none_of_its_values(block):
    md, _ = unpacked(block)
    reals = [v for v in md.modelVariables if v.type == "Real" and v.causality == "input"]
    if not reals:
        pytest.skip("no Real input")
    expected = reference_run(block)
    s = active_slave(block)
    first = reals[0]
    got = status_of(s.fmu.setReal, [first.valueReference, first.valueReference], [12.5, math.nan])
    assert got == fmi2Error
    assert run(s) == expected


@pytest.mark.parametrize("block", BLOCKS)
def test_calls_in_the_wrong_state(block):
    s = Slave(block, initialize=False)
    assert status_of(s.fmu.doStep, 0.0, 0.1) == fmi2Error  # before initialization
    assert status_of(s.fmu.getReal, [0]) == fmi2Error  # no get before init mode
    assert status_of(s.fmu.terminate) == fmi2Error
    assert status_of(s.fmu.exitInitializationMode) == fmi2Error
    assert any("must not be called in instantiated" in t for t in errors(s))
    s.fmu.setupExperiment(startTime=0.0)
    s.fmu.enterInitializationMode()
    s.fmu.exitInitializationMode()
    s.fmu.terminate()
    assert status_of(s.fmu.doStep, 0.0, 0.1) == fmi2Error  # after terminate
    assert status_of(s.fmu.setReal, [0], [0.1]) == fmi2Error
    assert status_of(s.fmu.getReal, [0]) == fmi2OK  # get is fine when terminated
    s.fmu.reset()  # back to instantiated
    s.fmu.setupExperiment(startTime=0.0)
    s.fmu.enterInitializationMode()
    s.fmu.exitInitializationMode()
    s.free()


@pytest.mark.parametrize("block", BLOCKS)
def test_wrong_guid_and_unknown_fmu_type_are_refused(block):
    md, directory = unpacked(block)
    wrong = FMU2Slave(
        guid="{00000000-0000-0000-0000-000000000000}",
        unzipDirectory=directory,
        modelIdentifier=md.coSimulation.modelIdentifier,
        instanceName="wrong",
    )
    probe = Slave(block, initialize=False)
    # fmi2Instantiate returns NULL; FMPy says so with an Exception of its own, no subclass
    with pytest.raises(Exception, match="^Failed to instantiate model$") as refused:
        wrong.instantiate(callbacks=probe.callbacks)
    assert refused.type is Exception and wrong.component is None
    assert errors(probe) == [
        "fmi2Instantiate: fmuGUID does not match the guid of this FMU's "
        f"modelDescription.xml ({block})."
    ]
    other = probe.fmu.fmi2Instantiate(
        b"other", 2, md.guid.encode(), b"", byref(probe.callbacks), 0, 0
    )
    assert other is None
    assert errors(probe)[1:] == [
        f"fmi2Instantiate: fmuType must be fmi2ModelExchange or fmi2CoSimulation ({block})."
    ]
    probe.free()


@pytest.mark.parametrize("block", BLOCKS)
def test_restored_state_replays_bit_for_bit(block):
    s = active_slave(block)
    run(s, 7)
    state = s.fmu.getFMUstate()
    t = s.time
    first = run(s, 15)
    s.fmu.setFMUstate(state)
    s.time = t
    assert run(s, 15) == first
    s.fmu.freeFMUstate(state)
    s.free()


@pytest.mark.parametrize("block", BLOCKS)
def test_serialized_state_continues_in_a_fresh_instance(block):
    s = active_slave(block)
    run(s, 9)
    state = s.fmu.getFMUstate()
    data = bytes(s.fmu.serializeFMUstate(state))
    s.fmu.freeFMUstate(state)
    t = s.time
    expected = run(s, 12)

    fresh = Slave(block)  # default inputs: everything must come from the state
    restored = fresh.fmu.deSerializeFMUstate(data)
    fresh.fmu.setFMUstate(restored)
    fresh.fmu.freeFMUstate(restored)
    fresh.time = t
    assert run(fresh, 12) == expected
    s.free()
    fresh.free()


def _flip(data, index):
    damaged = bytearray(data)
    damaged[index] ^= 0x01
    return bytes(damaged)


@pytest.mark.parametrize("block", BLOCKS)
def test_damaged_or_foreign_state_is_refused(block):
    s = active_slave(block)
    state = s.fmu.getFMUstate()
    data = bytes(s.fmu.serializeFMUstate(state))
    bad = {
        "truncated": data[:-1],
        "padded": data + b"\x00",
        "empty": b"",
        "magic": _flip(data, 0),
        "version": _flip(data, 8),
        "block name": _flip(data, 12),
        "guid": _flip(data, 50),
        "payload": _flip(data, len(data) - 3),
    }
    for other in BLOCKS:
        if other != block:
            o = active_slave(other)
            ostate = o.fmu.getFMUstate()
            bad[f"state of {other}"] = bytes(o.fmu.serializeFMUstate(ostate))
            o.fmu.freeFMUstate(ostate)
            o.free()
    expected = run(active_slave(block), 5)
    for label, blob in bad.items():
        before = len(s.log)
        assert status_of(s.fmu.deSerializeFMUstate, blob) == fmi2Error, label
        assert any("fmi2DeSerializeFMUstate" in t for _, _, t in s.log[before:]), label
    s.fmu.freeFMUstate(state)
    assert run(s, 5) == expected
    s.free()


@pytest.mark.parametrize("block", BLOCKS)
def test_instances_do_not_interfere(block):
    expected = reference_run(block)
    a, b = active_slave(block, instance_name="a"), Slave(block, instance_name="b")
    rows = []
    for _ in range(STEPS):
        rows.append(a.step(0.1))
        b.set({k: v for k, v in find(block).active.items() if isinstance(v, bool)} or {})
        b.step(0.1)
    assert rows == expected
    a.free()
    b.free()
