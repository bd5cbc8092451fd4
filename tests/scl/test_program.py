"""A whole PLC program as one FMU (docs/scl.md §3.10): OB100, OB1 and three cyclic-interrupt OBs of
periods 10, 30 and 100 ms with phases, each logging its runs into a global DB. The expected log
is computed here from the schedule's rules (each OB at phase + k * period, those due at one time
by priority, higher first, then by number; the startup OB once, first), not from a run of the
compiler; the FMU must give it for 10 s, in FMI 2.0 and 3.0, for two communication steps, and
in Model Exchange."""

from __future__ import annotations

import pytest

from lgf_fmus import scl
from tests.scl.driver import Instance

# The log: entry i is the i-th OB run, its time in ms * 1000 + its OB number. An OB reads the
# time with RUNTIME and a MEM of 0.0: the simulated time since the first call (§3.6).
SOURCE = """
DATA_BLOCK "Log"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
   VAR
      count : DInt;
      entry : Array[0..3999] of DInt;
      initialCalls : Int;
      startupCalls : Int;
      cycle123 : UDInt;
      phase123 : UDInt;
      ret123 : Int;
      ret1 : Int;
      cycle1 : UDInt;
   END_VAR
BEGIN
END_DATA_BLOCK

FUNCTION "Record" : Void
   VAR_INPUT
      ob : Int;
   END_VAR
   VAR_TEMP
      mem : LReal;
      now : LReal;
   END_VAR
BEGIN
    #now := RUNTIME(#mem);
    "Log".entry["Log".count] := LREAL_TO_DINT(#now * 1000.0) * 1000 + #ob;
    "Log".count := "Log".count + 1;
END_FUNCTION

FUNCTION_BLOCK "Cycles"
   VAR_INPUT
      callOB : OB_CYCLIC;
   END_VAR
   VAR_OUTPUT
      cycle : UDInt;
      phase : UDInt;
      runs : DInt;
   END_VAR
BEGIN
    QRY_CINT(OB_NR := #callOB, CYCLE => #cycle, PHASE => #phase);
    #runs := #runs + 1;
END_FUNCTION_BLOCK

DATA_BLOCK "Cycles_DB"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
"Cycles"
BEGIN
END_DATA_BLOCK

ORGANIZATION_BLOCK "Main"
TITLE = "Main Program Sweep (Cycle)"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
   VAR_INPUT
      Initial_Call : Bool;
      Remanence : Bool;
   END_VAR
BEGIN
    "Record"(ob := 1);
    IF #Initial_Call AND NOT #Remanence THEN
        "Log".initialCalls := "Log".initialCalls + 1;
    END_IF;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Startup"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
   VAR_INPUT
      LostRetentive : Bool;
      LostRTC : Bool;
   END_VAR
BEGIN
    "Record"(ob := 100);
    "Log".startupCalls := "Log".startupCalls + 1;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Fast"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
   VAR_INPUT
      Initial_Call : Bool;
      Event_Count : Int;
   END_VAR
BEGIN
    "Record"(ob := 123);
    IF #Initial_Call AND #Event_Count = 0 THEN
        "Log".initialCalls := "Log".initialCalls + 1;
    END_IF;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Mid"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
   VAR_TEMP
      ret : Int;
   END_VAR
BEGIN
    "Record"(ob := 32);
    "Cycles_DB"(callOB := "Mid"); // an OB's name: its number, 32
    "Log".ret123 := QRY_CINT(OB_NR := "Fast", CYCLE => "Log".cycle123, PHASE => "Log".phase123);
    "Log".ret1 := QRY_CINT(OB_NR := 1, CYCLE => "Log".cycle1);
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Cyclic interrupt"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    "Record"(ob := "Cyclic interrupt"); // 31
END_ORGANIZATION_BLOCK
"""

# Fast and Mid share priority 10 (Mid, OB32, first by number); OB31's 17 is the highest (its
# name TIA's default for a new cyclic OB, whose blank the C cannot hold); OB1's
# cycle (the minimum cycle time) 4 ms; the tick is gcd(4, 10, 30, 100, 2, 12, 22) = 2 ms
PROGRAM = """
name = "Line"
min_cycle_us = 4000

[ob.Main]
number = 1

[ob.Startup]
number = 100

[ob.Fast]
number = 123
class = "cyclic interrupt"
cycle_us = 10000
phase_us = 2000
priority = 10

[ob.Mid]
number = 32
cycle_us = 30000
phase_us = 12000
priority = 10

[ob."Cyclic interrupt"]
number = 31
cycle_us = 100000
phase_us = 22000
priority = 17
"""

STOP_MS = 10_000
ENTRIES = 4000  # the log's length: the core numbers at most 4096 variables (src/core/values.c)


def expected_log() -> list[int]:
    """The runs of 10 s by the schedule's rules, each time in ms * 1000 + the OB's number."""
    cyclic = [  # (number, period ms, phase ms, priority)
        (1, 4, 0, 1),
        (123, 10, 2, 10),
        (32, 30, 12, 10),
        (31, 100, 22, 17),
    ]
    log = [100]  # OB100 once, before every other OB, at 0
    for t in range(0, STOP_MS + 1):
        due = [ob for ob in cyclic if t >= ob[2] and (t - ob[2]) % ob[1] == 0]
        due.sort(key=lambda ob: (-ob[3], ob[0]))
        log += [t * 1000 + ob[0] for ob in due]
    return log


@pytest.fixture(scope="module")
def fmus(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("program")
    source, program = tmp / "line.scl", tmp / "program.toml"
    source.write_text(SOURCE, encoding="utf-8")
    program.write_text(PROGRAM, encoding="utf-8")
    return {
        fmi: scl.compile(
            [source],
            fmi=fmi,
            output=tmp / f"Line{fmi}.fmu",
            program=program,
            werror=True,
            win64=False,
        )  # fmt: skip
        for fmi in (2, 3)
    }


NAMES = ["Log.count", "Log.initialCalls", "Log.startupCalls", "Cycles_DB.cycle"]
NAMES += ["Cycles_DB.phase", "Cycles_DB.runs", "Log.cycle123", "Log.phase123", "Log.ret123"]
NAMES += ["Log.ret1", "Log.cycle1"]


def read(s: Instance) -> dict:
    """The log's variables: the entries in one call of getInteger (getInt32 in FMI 3.0)."""
    values = s.get(NAMES)
    refs = [s.variables[f"Log.entry[{i}]"].valueReference for i in range(ENTRIES)]
    values["entry"] = list(s.fmu.getInt32(refs) if s.fmi3 else s.fmu.getInteger(refs))
    return values


def run(fmu, step_ms: int) -> dict:
    """Co-simulation for 10 s in steps of step_ms; the log at the end."""
    s = Instance(fmu, {}, {})
    for k in range(STOP_MS // step_ms):
        s.fmu.doStep(
            currentCommunicationPoint=k * step_ms / 1000, communicationStepSize=step_ms / 1000
        )
    values = read(s)
    s.free()
    return values


def run_model_exchange(fmu) -> dict:
    """Model Exchange for 10 s, from time event to time event (docs/behaviour.md §1.11): the
    FMU names each next tick; the log at the end."""
    s = Instance(fmu, {}, {}, model_exchange=True)
    update = s.fmu.updateDiscreteStates if s.fmi3 else s.fmu.newDiscreteStates
    *_, next_time = update()
    s.fmu.enterContinuousTimeMode()
    events = 0
    while next_time <= STOP_MS / 1000 + 1e-9:
        s.fmu.setTime(next_time)
        s.fmu.enterEventMode()
        *_, next_time = update()
        s.fmu.enterContinuousTimeMode()
        events += 1
    values = read(s)
    s.free()
    values["events"] = events
    return values


def check(values: dict):
    log = expected_log()
    n = len(log)
    assert values["Log.count"] == n
    assert values["entry"][:n] == log
    assert values["entry"][n:] == [0] * (ENTRIES - n)
    assert values["Log.startupCalls"] == 1
    assert values["Log.initialCalls"] == 2  # Initial_Call in the first run of Main and of Fast
    # QRY_CINT of the OB that OB_NR names (Cycles runs in OB32 with callOB 32), in µs
    assert (values["Cycles_DB.cycle"], values["Cycles_DB.phase"]) == (30_000, 12_000)
    assert values["Cycles_DB.runs"] == sum(entry % 1000 == 32 for entry in log)
    assert (values["Log.cycle123"], values["Log.phase123"], values["Log.ret123"]) == (
        10_000,
        2_000,
        0,
    )
    # OB1 is no cyclic-interrupt OB: 16#8090 "OB does not exist or is of wrong type"
    assert (values["Log.ret1"], values["Log.cycle1"]) == (0x8090 - 0x10000, 0)


# docs/scl.md rules: [S7-OB-CLASS] [S7-OB-START] [S7-SCHED-CYCLIC] [S7-SCHED-ORDER]
# [DEC-SCHED-TIME] [DEC-PROG-TICK] [S7-PROG-QRY-CINT] [DEC-PROG-OB1] [S7-OB-CONSTANT]
@pytest.mark.parametrize("fmi", [2, 3])
def test_every_run_at_its_time_in_its_order_for_any_step(fmus, fmi):
    small, large = run(fmus[fmi], 4), run(fmus[fmi], 625)
    check(small)
    assert small == large


# docs/scl.md rules: [DEC-SCHED-TIME]
@pytest.mark.parametrize("fmi", [2, 3])
def test_model_exchange_runs_the_same_log(fmus, fmi):
    values = run_model_exchange(fmus[fmi])
    assert values.pop("events") == STOP_MS // 2  # a time event per tick of 2 ms after 0
    check(values)


# docs/scl.md rules: [DEC-PROG-TICK]
def test_the_tick_is_fixed_and_the_documentation_lists_the_obs(fmus):
    import zipfile

    with zipfile.ZipFile(fmus[2]) as z:
        xml = z.read("modelDescription.xml").decode()
        page = z.read("documentation/index.html").decode()
    assert 'name="cycleTime"' in xml and 'start="0.002"' in xml
    for row in ("OB100", "OB31", "OB32", "OB123", "OB1<", "<code>Cyclic interrupt</code>"):
        assert row in page
    assert "every 30000 µs from 12000 µs" in page
    s = Instance(fmus[2], {}, {})  # a tick the program does not have is refused
    s.free()
    with pytest.raises(Exception):
        Instance(fmus[2], {"cycleTime": 0.001}, {})
