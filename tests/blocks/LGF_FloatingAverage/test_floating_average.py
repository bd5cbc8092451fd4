"""LGF_FloatingAverage against the rules of docs/behaviour.md §15, with hand-computed
expectations (the arithmetic in the comments; REAL values are float32, f32() below)."""

import math
import struct

import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of

BLOCK = "LGF_FloatingAverage"
WRONG_WINDOW_SIZE = 0x8200
CYCLE = 0.1


def f32(x: float) -> float:
    """The float32 nearest to x, as a double (what a REAL holds)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def run(calls: list[dict], **start) -> list[dict]:
    """Outputs of calls 0, 1, ...: calls[0] (with start) is set during initialization and reaches
    call 0, calls[k] is set before the step that executes call k (docs/behaviour.md §1.3)."""
    s = Slave(BLOCK, {"cycleTime": CYCLE}, {**start, **calls[0]})
    rows = [s.outputs()]
    for changes in calls[1:]:
        s.set(changes)
        rows.append(s.step(CYCLE))
    s.free()
    return rows


def column(rows, name):
    return [row[name] for row in rows]


def test_worked_example_fills_then_slides():
    # §15.3: window 3, values 3, 6, 9, 12, 0. Filling: 3/1 = 3, (3+6)/2 = 4.5, (9+9)/3 = 6;
    # sliding: (18 + 12) - 3 = 27, /3 = 9; (27 + 0) - 6 = 21, /3 = 7.
    rows = run(
        [{"value": 3.0}, {"value": 6.0}, {"value": 9.0}, {"value": 12.0}, {"value": 0.0}],
        cyclicExecution=True,
        windowSize=3,
    )
    assert column(rows, "average") == [3.0, 4.5, 6.0, 9.0, 7.0]
    assert column(rows, "windowSizeReached") == [False, False, True, True, True]
    assert {(r["error"], r["status"]) for r in rows} == {(False, 0)}


def test_start_values_read_one_per_call_into_a_window_of_ten():
    # §15.1: cyclicExecution true, value 1.0, windowSize 10: average 1.0 from call 0, the
    # window full with the tenth value (call 9, t = 0.9 s).
    s = Slave(BLOCK)
    rows = [s.outputs()] + [s.step(CYCLE) for _ in range(11)]
    s.free()
    assert column(rows, "average") == [1.0] * 12
    assert column(rows, "windowSizeReached") == [False] * 9 + [True] * 3


def test_a_hundred_values_fill_the_largest_window():
    # §15.2: values 1, 2, ..., 100 in a window of 100: after k values the mean is (k+1)/2 (the
    # sums k(k+1)/2 <= 5050 are exact in float32); the 100th fills the window (mean 50.5); the
    # 101st (101) replaces 1: (5050 + 101) - 1 = 5150, /100 = 51.5.
    rows = run([{"value": float(k)} for k in range(1, 102)], cyclicExecution=True, windowSize=100)
    assert column(rows, "average")[:3] == [1.0, 1.5, 2.0]
    assert rows[99]["average"] == 50.5 and rows[99]["windowSizeReached"]
    assert not rows[98]["windowSizeReached"]
    assert rows[100]["average"] == 51.5


def test_trigger_reads_at_rising_edges_only():
    # §15.2 steps 1 and 4: cyclicExecution FALSE; trigger TRUE in call 0 (an edge: the memory
    # starts FALSE), held in call 1 (no edge), FALSE in 2, TRUE in 3 (edge), 4 held.
    # Window 2: call 0 reads 10 -> 10; call 3 reads 40 -> (10 + 40)/2 = 25.
    rows = run(
        [
            {"trigger": True, "value": 10.0},
            {"value": 20.0},
            {"trigger": False, "value": 30.0},
            {"trigger": True, "value": 40.0},
            {"value": 50.0},
        ],
        cyclicExecution=False,
        windowSize=2,
    )
    assert column(rows, "average") == [10.0, 10.0, 10.0, 25.0, 25.0]
    assert column(rows, "windowSizeReached") == [False, False, False, True, True]


def test_no_read_in_holds_the_outputs():
    # §15.3: with neither cyclicExecution nor an edge, nothing is read: the outputs hold.
    rows = run(
        [{"value": 4.0}, {"cyclicExecution": False, "value": 100.0}, {"value": -7.0}],
        cyclicExecution=True,
        windowSize=5,
    )
    assert column(rows, "average") == [4.0, 4.0, 4.0]


def test_cyclic_execution_and_a_trigger_edge_read_one_value():
    # §15.5: both together read one value, not two: window 2, values 2 then 4 -> 2, 3.
    rows = run(
        [{"trigger": True, "value": 2.0}, {"trigger": False}, {"trigger": True, "value": 4.0}],
        cyclicExecution=True,
        windowSize=2,
    )
    # call 1 reads 2 again (cyclic): (2 + 2)/2 = 2; call 2: (4 + 4) - 2 = 6, /2 = 3
    assert column(rows, "average") == [2.0, 2.0, 3.0]


def test_trigger_held_when_cyclic_execution_falls_is_no_edge():
    # §15.5: the edge memory follows trigger in every call, also while cyclicExecution is TRUE.
    rows = run(
        [{"trigger": True, "value": 1.0}, {"cyclicExecution": False, "value": 9.0}],
        cyclicExecution=True,
        windowSize=3,
    )
    assert column(rows, "average") == [1.0, 1.0]


@pytest.mark.parametrize("size", [0, -1, 101, 32767, -32768])
def test_invalid_window_size_is_status_8200_and_reads_nothing(size):
    # §15.2 step 3, §15.4: the change to the invalid size restarts the window (average 0.0,
    # windowSizeReached FALSE), then error TRUE, status 16#8200, nothing read in.
    s = Slave(BLOCK, {"cycleTime": CYCLE}, {"value": 6.0, "windowSize": 1})
    assert s.outputs() == {
        "average": 6.0,
        "windowSizeReached": True,
        "error": False,
        "status": 0,
    }
    s.set({"windowSize": size})
    want = {"average": 0.0, "windowSizeReached": False, "error": True, "status": WRONG_WINDOW_SIZE}
    assert s.step(CYCLE) == want
    assert s.step(CYCLE) == want
    assert any("16#8200" in text and cat == "logStatusWarning" for _, cat, text in s.log)
    # back to a valid size: a restart, then a fresh window
    s.set({"windowSize": 2, "value": 8.0})
    assert s.step(CYCLE) == {
        "average": 8.0,
        "windowSizeReached": False,
        "error": False,
        "status": 0,
    }
    s.free()


def test_invalid_window_size_from_the_first_call():
    rows = run([{"windowSize": 0}, {}], value=5.0)
    assert (
        rows
        == [
            {"average": 0.0, "windowSizeReached": False, "error": True, "status": WRONG_WINDOW_SIZE}
        ]
        * 2
    )


def test_a_new_window_size_restarts_the_window():
    # §15.2 step 2: window 3 with 3, 6, 9 (mean 6); windowSize 4 in call 3 restarts: 12/1 = 12.
    rows = run(
        [{"value": 3.0}, {"value": 6.0}, {"value": 9.0}, {"value": 12.0, "windowSize": 4}],
        cyclicExecution=True,
        windowSize=3,
    )
    assert column(rows, "average") == [3.0, 4.5, 6.0, 12.0]
    assert column(rows, "windowSizeReached") == [False, False, True, False]


def test_reset_is_a_level_and_the_reset_call_still_reads():
    # §15.5: reset held with cyclicExecution: a window of one in each call (average = value).
    rows = run(
        [
            {"value": 2.0},
            {"value": 4.0},
            {"reset": True, "value": 10.0},
            {"value": 20.0},
            {"reset": False, "value": 40.0},
        ],
        cyclicExecution=True,
        windowSize=3,
    )
    # 2; (2+4)/2 = 3; reset: 10; reset: 20; then (20 + 40)/2 = 30
    assert column(rows, "average") == [2.0, 3.0, 10.0, 20.0, 30.0]


def test_reset_without_a_read_in_outputs_zero():
    rows = run(
        [{"value": 2.0}, {"cyclicExecution": False, "reset": True}, {"reset": False}],
        cyclicExecution=True,
        windowSize=1,
    )
    assert column(rows, "average") == [2.0, 0.0, 0.0]
    assert column(rows, "windowSizeReached") == [True, False, False]


def test_values_are_float32():
    # §15.1: 0.1 is stored as the float32 0.100000001490116...; (x + x)/2 and ((x+x)+x)/3 give
    # it back exactly. 1/3 as a REAL: 0.3333333432674408.
    rows = run(
        [{"value": 0.1}, {}, {}, {"value": 1.0 / 3.0, "windowSize": 1}], cyclicExecution=True
    )
    assert column(rows, "average") == [f32(0.1)] * 3 + [0.3333333432674408]
    assert rows[0]["average"] == 0.10000000149011612


def test_the_running_sum_keeps_its_rounding():
    # §15.3: window 1: 1e8 -> 1e8; then (1e8 + 1) - 1e8 = 0 (1e8 + 1 rounds to 1e8 in float32),
    # and from then (0 + 1) - 1 = 0: average 0.0 while value is 1.0, until a restart.
    rows = run(
        [{"value": 1e8}, {"value": 1.0}, {}, {}, {"reset": True}, {"reset": False}],
        cyclicExecution=True,
        windowSize=1,
    )
    assert column(rows, "average") == [1e8, 0.0, 0.0, 0.0, 1.0, 1.0]


def test_the_sliding_sum_adds_before_it_subtracts():
    # §15.2 step 4: (sum + value) - oldest, in this order. Window 2: 1e8, then 1: sum
    # 1e8 + 1 = 1e8, mean 5e7; then 1 replaces 1e8: (1e8 + 1) - 1e8 = 0, mean 0 (the other
    # order, (1e8 - 1e8) + 1, would give 0.5).
    rows = run([{"value": 1e8}, {"value": 1.0}, {}, {}], cyclicExecution=True, windowSize=2)
    assert column(rows, "average") == [1e8, 5e7, 0.0, 0.0]


def test_infinity_and_the_nan_it_leaves():
    # §15.3: +Inf makes the sum +Inf; when it leaves a window of 2, Inf - Inf = NaN, which stays
    # until a restart. The NaN is got as the positive quiet NaN (§1.4).
    s = Slave(BLOCK, {"cycleTime": CYCLE}, {"cyclicExecution": True, "windowSize": 2, "value": 1.0})
    s.set({"value": math.inf})
    assert s.step(CYCLE)["average"] == math.inf  # (1 + Inf)/2
    s.set({"value": 3.0})
    assert s.step(CYCLE)["average"] == math.inf  # (1 + Inf + 3) - 1
    got = s.step(CYCLE)["average"]  # (Inf + 3) - Inf
    assert math.isnan(got) and math.copysign(1.0, got) == 1.0
    assert math.isnan(s.step(CYCLE)["average"])
    s.set({"reset": True})
    assert s.step(CYCLE)["average"] == 3.0
    s.free()


def test_overflow_of_the_float32_sum():
    # 3e38 + 3e38 overflows float32 to +Inf.
    rows = run([{"value": 3e38}, {}], cyclicExecution=True, windowSize=2)
    assert rows[0]["average"] == f32(3e38)
    assert rows[1]["average"] == math.inf


def test_nan_and_out_of_range_values_are_refused():
    s = Slave(BLOCK, {"cycleTime": CYCLE}, {"value": 2.0})
    assert status_of(s.fmu.setReal, [s.vr("value")], [math.nan]) == fmi2Error
    assert status_of(s.fmu.setReal, [s.vr("value")], [1e39]) == fmi2Error  # beyond float32
    assert status_of(s.fmu.setInteger, [s.vr("windowSize")], [40000]) == fmi2Error  # INT range
    assert s.step(CYCLE)["average"] == 2.0  # nothing was applied
    s.free()
