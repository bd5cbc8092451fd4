"""Global DBs a user can tune and instance DBs with their own start values (docs/scl.md §3.9):
a member of a global DB that TIA marks Setpoint ({ S7_SetPoint := 'True'}, as TIA writes the
attribute) is a tunable FMI parameter unless it is not writable from the HMI or the program
writes it; the rest of the DB stays FMI locals; an instance DB's BEGIN values replace its FB's
start values. The expected values are computed by hand from the program below: OB1 runs every
10 ms from 0 s, so at t it has run n = t / 10 ms + 1 times."""

from __future__ import annotations

import pytest

from lgf_fmus import scl
from tests.scl.driver import Instance

SOURCE = """
TYPE "Limits"
VERSION : 0.1
   STRUCT
      low { S7_SetPoint := 'True'} : Real := 1.0;   // lower limit
      high : Real := 9.0;
   END_STRUCT;
END_TYPE

DATA_BLOCK "Settings"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
   VAR
      gain { S7_SetPoint := 'True'} : Real := 2.0;   // the gain
      offset { ExternalWritable := 'False'; S7_SetPoint := 'True'} : Int := 5;
      clamp { S7_SetPoint := 'True'} : Real := 50.0;
      band : "Limits";
      steps { S7_SetPoint := 'True'} : Array[1..2] of Int := [4, 6];
      count : DInt;
      y : Real;
   END_VAR
BEGIN
   gain := 3.0;
END_DATA_BLOCK

FUNCTION_BLOCK "Counter"
   VAR_OUTPUT
      n : Int;
   END_VAR
   VAR
      stepSize { S7_SetPoint := 'True'} : Int := 2;
   END_VAR
BEGIN
    #n := #n + #stepSize;
END_FUNCTION_BLOCK

DATA_BLOCK "Counter_DB"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
NON_RETAIN
"Counter"
BEGIN
   stepSize := 5;
   n := 100;
END_DATA_BLOCK

ORGANIZATION_BLOCK "Main"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    "Settings".count := "Settings".count + 1;
    "Settings".clamp := 100.0;
    "Settings".y := "Settings".gain * DINT_TO_REAL("Settings".count) + "Settings".band.low
        + INT_TO_REAL("Settings".steps[2] + "Settings".offset);
    "Counter_DB"();
END_ORGANIZATION_BLOCK
"""
PROGRAM = 'name = "Tuned"\n[ob.Main]\nnumber = 1\n'

TUNABLE = ["Settings.gain", "Settings.band.low", "Settings.steps[1]", "Settings.steps[2]"]
LOCAL = ["Settings.offset", "Settings.clamp", "Settings.band.high", "Settings.count"]
LOCAL += ["Settings.y", "Counter_DB.n", "Counter_DB.stepSize"]


@pytest.fixture(scope="module", params=[2, 3])
def fmu(request, tmp_path_factory):
    tmp = tmp_path_factory.mktemp("dbs")
    (tmp / "dbs.scl").write_text(SOURCE, encoding="utf-8")
    (tmp / "program.toml").write_text(PROGRAM, encoding="utf-8")
    return scl.compile(
        [tmp / "dbs.scl"],
        fmi=request.param,
        output=tmp / "Tuned.fmu",
        program=tmp / "program.toml",
        werror=True,
        win64=False,
    )  # fmt: skip


# docs/scl.md rules: [S7-DB-SETPOINT] [DEC-DB-SETPOINT-WRITTEN]
def test_setpoints_are_tunable_parameters_the_rest_locals(fmu):
    s = Instance(fmu, {}, {})
    for name in TUNABLE:
        v = s.variables[name]
        assert (v.causality, v.variability) == ("parameter", "tunable"), name
    for name in LOCAL:
        assert s.variables[name].causality == "local", name
    # the BEGIN value of the global DB, the declared ones
    assert s.variables["Settings.gain"].start in ("3.0", "3")
    assert s.variables["Settings.steps[2]"].start == "6"
    s.free()


# docs/scl.md rules: [S7-DB-SETPOINT] [S7-DB-START]
def test_a_setpoint_tuned_in_a_run_and_the_instance_starts(fmu):
    s = Instance(fmu, {"Settings.band.low": 2.0}, {})
    for k in range(5):
        s.fmu.doStep(currentCommunicationPoint=k * 0.01, communicationStepSize=0.01)
    # at 50 ms: n = 6 runs; y = gain 3 * 6 + low 2 + (steps[2] 6 + offset 5) = 31
    values = s.get(["Settings.count", "Settings.y", "Counter_DB.n", "Settings.clamp"])
    # Counter_DB starts at its DB's n = 100 and adds its DB's stepSize 5 (not the FB's 2)
    assert values == {
        "Settings.count": 6,
        "Settings.y": 31.0,
        "Counter_DB.n": 130,
        "Settings.clamp": 100.0,
    }
    s.set({"Settings.gain": 0.5, "Settings.steps[2]": -5})
    for k in range(5, 10):
        s.fmu.doStep(currentCommunicationPoint=k * 0.01, communicationStepSize=0.01)
    # at 100 ms: n = 11; y = 0.5 * 11 + 2 + (-5 + 5) = 7.5
    assert s.get(["Settings.count", "Settings.y", "Counter_DB.n"]) == {
        "Settings.count": 11,
        "Settings.y": 7.5,
        "Counter_DB.n": 155,
    }
    s.free()
