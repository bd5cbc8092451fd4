"""The cycle watchdog (docs/scl.md §3.4 [DEC-WATCHDOG], §4 maxCycleTime): a PLC call whose loops
run more iterations than maxCycleTime allows (10000 per ms) ends the step with an error naming
the loop's file:line, the instance is then in the error state, and the importer never hangs.
Each FMU runs in a child process under a hang guard, so that a watchdog that failed to stop a
loop fails the test instead of hanging it. The counts are by hand: maxCycleTime 1 ms is a budget
of 10000 iterations a call."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

from tests.scl.driver import ROOT, compile_text
from tests.timeouts import hang_guard

SOURCE = """FUNCTION "Wait" : Void
VAR_INPUT
   stop : Bool;
END_VAR
VAR_TEMP
   n : DInt;
END_VAR
BEGIN
   REPEAT
      #n := #n + 1;
   UNTIL #stop
   END_REPEAT;
END_FUNCTION

FUNCTION_BLOCK "Spin"
VAR_INPUT
   n : DInt := 10;
   hang : Bool;
   hangInFc : Bool;
END_VAR
VAR_OUTPUT
   count : DInt;
END_VAR
VAR_TEMP
   i : DInt;
END_VAR
BEGIN
   #count := 0;
   FOR #i := 1 TO #n DO
      #count := #count + 1;
   END_FOR;
   WHILE #hang DO
      #count := #count - 1;
   END_WHILE;
   IF #hangInFc THEN
      "Wait"(stop := FALSE);
   END_IF;
END_FUNCTION_BLOCK
"""
# the lines of the loops, which the log must name
FOR_LINE, WHILE_LINE, REPEAT_LINE = (
    next(i for i, line in enumerate(SOURCE.splitlines(), 1) if line.strip().startswith(word))
    for word in ("FOR", "WHILE", "REPEAT")
)

# The child: instantiates the FMU with the parameters (its first call, in initialization, with
# the start values: n = 10), then runs one call per change (cycleTime 0.1 s: a step of 0.1 s in
# co-simulation, a time event in Model Exchange) that sees it; prints per call "ok" or "error"
# and count, and after an error whether a further call is refused; then resets.
CHILD = r"""
import json, sys
from pathlib import Path
from fmpy.fmi1 import FMICallException
from tests.scl.driver import Instance
path, me, parameters, changes = json.loads(sys.argv[1])
s = Instance(Path(path), {"cycleTime": 0.1, **parameters}, {}, model_exchange=me)
if me:
    update = s.fmu.updateDiscreteStates if s.fmi3 else s.fmu.newDiscreteStates
    update()  # at t = 0: the first call ran on leaving initialization, none is due
def call(k, change):  # the call at 0.1 (k + 1) s, with the change
    if me:
        s.fmu.enterContinuousTimeMode()
        s.fmu.setTime(0.1 * (k + 1))
        s.fmu.enterEventMode()
        s.set(change)
        update()
    else:
        s.set(change)
        s.fmu.doStep(currentCommunicationPoint=0.1 * k, communicationStepSize=0.1)
rows, after = [], None
for k, change in enumerate(changes):
    try:
        call(k, change)
        rows.append(["ok", s.get(["count"])["count"]])
    except FMICallException:
        rows.append(["error", s.get(["count"])["count"]])
        try:
            call(k + 1, {})
            after = "ran"
        except FMICallException:
            after = "refused"
        s.fmu.reset()
        break
print("\n".join(s.log))
print("RESULT " + json.dumps({"rows": rows, "after": after}))
"""


@pytest.fixture(scope="module", params=[2, 3])
def spin(request, tmp_path_factory):
    return compile_text(tmp_path_factory.mktemp("spin"), SOURCE, "Spin", request.param)


def run(fmu, me, parameters, changes):
    """(the child's result, its output with the FMU's log lines), under a hang guard that a slow
    machine cannot hit: a stopped call takes milliseconds."""
    argument = json.dumps([str(fmu), me, parameters, changes])
    child = subprocess.run(
        [sys.executable, "-c", CHILD, argument],
        capture_output=True,
        text=True,
        cwd=ROOT,
        timeout=hang_guard(120),
    )
    assert child.returncode == 0, child.stderr
    line = next(x for x in child.stdout.splitlines() if x.startswith("RESULT "))
    return json.loads(line[len("RESULT ") :]), child.stdout


@pytest.mark.parametrize("me", [False, True], ids=["cs", "me"])
def test_a_loop_that_never_ends_is_a_time_error(spin, me):
    # docs/scl.md rules: [DEC-WATCHDOG]
    # at the default maxCycleTime of 150 ms: 1500000 iterations of the WHILE, each count - 1
    result, log = run(spin, me, {}, [{"n": 0}, {"hang": True}])
    assert result["rows"] == [["ok", 0], ["error", -1500000]]
    assert f"Spin.scl:{WHILE_LINE} ran out of the call's budget of 1500000 loop iterations" in log
    assert "maxCycleTime 150 ms" in log
    # the error state: no further call, until a reset
    assert result["after"] == "refused"
    assert "in the error state of a failed PLC call" in log


def test_a_loop_just_within_the_budget_runs(spin):
    # docs/scl.md rules: [DEC-WATCHDOG]
    # maxCycleTime 1 ms: 10000 iterations a call, each call its own budget
    result, _ = run(spin, False, {"maxCycleTime": 0.001}, [{"n": 10000}, {}, {"n": 9999}])
    assert result["rows"] == [["ok", 10000], ["ok", 10000], ["ok", 9999]]
    assert result["after"] is None


def test_one_iteration_over_the_budget_stops_the_call(spin):
    # docs/scl.md rules: [DEC-WATCHDOG]
    # the 10001st iteration of the FOR finds no budget left: count holds the 10000 before it
    result, log = run(spin, False, {"maxCycleTime": 0.001}, [{"n": 10001}])
    assert result["rows"] == [["error", 10000]]
    assert f"the loop at Spin.scl:{FOR_LINE} ran out of the call's budget of 10000" in log


def test_the_log_names_the_loop_of_an_fc(spin):
    # docs/scl.md rules: [DEC-WATCHDOG]
    # the FOR runs its 5 iterations, then the FC's REPEAT the 9995 left and stops
    result, log = run(spin, True, {"maxCycleTime": 0.001}, [{"n": 5}, {"hangInFc": True}])
    assert result["rows"] == [["ok", 5], ["error", 5]]
    assert f"Spin.scl:{REPEAT_LINE} ran out of the call's budget of 10000" in log
