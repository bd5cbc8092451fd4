"""Tests of the LGF_RampCI reference model against traces computed by hand from
docs/behaviour.md §4.

Every expected row below was worked out on paper from §4.3 (not produced by the model).
Interpolated outputs are given as the exact 4.2 c) expression `ip(prev, target, remainTime_ms, Ts)`
(bit-exact) and checked against the round hand value as well.
"""

import math

import pytest

from src.blocks.LGF_RampCI.table import table

from .model import RampCI

# Worked example table of §4.5: (0.0, 0.3 s), (30.0, 0.2 s), (30.0, 0.25 s), (0.0, 0 s).
WORKED = table((0.0, 0.3), (30.0, 0.2), (30.0, 0.25), (0.0, 0.0))


def ip(prev, target, rt_ms, ts_ms):
    """§4.3 c), same operations in the same order, for rest times up to 2^24 ms, where
    REAL(rt_ms) and REAL(ts_ms) are exact (beyond 2^24 ms: the tests at the end of this file)."""
    assert 0 < rt_ms <= 2**24 and 0 < ts_ms <= 60_000
    return prev + (target - prev) / float(rt_ms) * float(ts_ms)


class Drv:
    """Calls the model once per cycle with all inputs (defaults: everything 0/FALSE)."""

    DEFAULTS = dict(
        defaultOutValue=0.0,
        contStepNbr=0,
        contStepTime=0.0,
        enDefaultOutValue=False,
        start=False,
        hold=False,
        cyclicOP=False,
        updateTime=False,
        reset=False,
    )

    def __init__(self, cycle_us=100_000, params=None):
        self.m = RampCI(cycle_us, params)
        self.cycle_us = cycle_us
        self.k = 0

    def __call__(self, **kw):
        inputs = dict(self.DEFAULTS)
        inputs["continue"] = kw.pop("cont", False)
        inputs.update(kw)
        out = self.m.call(self.k * self.cycle_us, inputs)
        self.k += 1
        assert set(out) == {
            "outputValue",
            "actTimeTable",
            "stepNumber",
            "remainTime",
            "totalTime",
            "remainTotalTime",
            "error",
            "status",
            "subFunctionStatus",
        }
        assert out["error"] is False and out["subFunctionStatus"] == 0
        return out


def check(out, y=None, act=None, step=None, rt=None, tt=None, rtt=None, st=None, approx=None):
    """Compare the given fields exactly (times in s are exact ms/1000)."""
    if y is not None:
        assert out["outputValue"] == y, out
    if approx is not None:
        assert out["outputValue"] == pytest.approx(approx, abs=1e-9), out
    for key, exp in (
        ("actTimeTable", act),
        ("stepNumber", step),
        ("remainTime", rt),
        ("totalTime", tt),
        ("remainTotalTime", rtt),
        ("status", st),
    ):
        if exp is not None:
            assert out[key] == exp, (key, out)


# Rows of the §4.5 table: (start, output, approx, act, step, rt, tt, rtt, status).
y02 = ip(0.0, 30.0, 300, 100)
y03 = ip(y02, 30.0, 200, 100)
y07 = ip(30.0, 0.0, 250, 100)
y08 = ip(y07, 0.0, 150, 100)
WORKED_ROWS = [
    (False, 0.0, 0, False, 0, 0.0, 0.0, 0.0, 0x7000),  # t = 0.0
    (True, 0.0, 0, True, 1, 0.3, 0.75, 0.75, 0x7001),  # t = 0.1
    (True, y02, 10, True, 1, 0.2, 0.75, 0.65, 0x7000),  # t = 0.2
    (True, y03, 20, True, 1, 0.1, 0.75, 0.55, 0x7000),  # t = 0.3
    (True, 30.0, 30, True, 2, 0.2, 0.75, 0.45, 0x7000),  # t = 0.4
    (True, 30.0, 30, True, 2, 0.1, 0.75, 0.35, 0x7000),  # t = 0.5
    (True, 30.0, 30, True, 3, 0.25, 0.75, 0.25, 0x7000),  # t = 0.6
    (True, y07, 18, True, 3, 0.15, 0.75, 0.15, 0x7000),  # t = 0.7
    (True, y08, 6, True, 3, 0.05, 0.75, 0.05, 0x7000),  # t = 0.8
    (True, 0.0, 0, False, 3, 0.0, 0.75, 0.0, 0x0000),  # t = 0.9
    (True, 0.0, 0, False, 3, 0.0, 0.75, 0.0, 0x0000),  # t = 1.0 ("and later")
    (True, 0.0, 0, False, 3, 0.0, 0.75, 0.0, 0x0000),  # t = 1.1
]


def check_row(out, row):
    _, y, approx, act, step, rt, tt, rtt, st = row
    check(out, y=y, approx=approx, act=act, step=step, rt=rt, tt=tt, rtt=rtt, st=st)


def test_worked_example_4_3():
    d = Drv(100_000, WORKED)
    for row in WORKED_ROWS:
        check_row(d(start=row[0]), row)


def test_continue_without_hold_has_no_effect():
    d = Drv(100_000, WORKED)
    for row in WORKED_ROWS:
        check_row(d(start=row[0], cont=True, contStepNbr=3, contStepTime=0.4), row)


def test_status_after_end_and_idle():
    d = Drv(100_000, WORKED)
    for row in WORKED_ROWS:
        d(start=row[0])
    # start FALSE after a non-cyclic end: idle, 0x7000, time outputs keep their values.
    check(d(start=False), y=0.0, act=False, step=3, rt=0.0, tt=0.75, rtt=0.0, st=0x7000)
    # next start edge runs the table again
    check(d(start=True), y=0.0, act=True, step=1, rt=0.3, tt=0.75, rtt=0.75, st=0x7001)
    check(d(start=True), y=y02, st=0x7000)


def test_reset_blocks_until_next_start_edge():
    d = Drv(100_000, WORKED)
    check(d(start=True), y=0.0, act=True, step=1, rt=0.3, tt=0.75, rtt=0.75, st=0x7001)
    check(d(start=True), y=y02, act=True, step=1, rt=0.2, rtt=0.65, st=0x7000)
    # reset edge: status 0, output 0, step 0, remainTime 0, totals recomputed, blocked
    check(d(start=True, reset=True), y=0.0, act=False, step=0, rt=0.0, tt=0.75, rtt=0.75, st=0)
    # reset held: no edge, still blocked, idle status
    check(d(start=True, reset=True), y=0.0, act=False, step=0, rt=0.0, tt=0.75, rtt=0.75, st=0x7000)
    # held start does not restart
    for _ in range(3):
        check(d(start=True), y=0.0, act=False, step=0, rt=0.0, tt=0.75, rtt=0.75, st=0x7000)
    check(d(start=False), y=0.0, act=False, step=0, rt=0.0, st=0x7000)
    # next rising edge of start: fresh run from point 0
    check(d(start=True), y=0.0, act=True, step=1, rt=0.3, tt=0.75, rtt=0.75, st=0x7001)
    check(d(start=True), y=y02, act=True, step=1, rt=0.2, rtt=0.65, st=0x7000)


def test_reset_edge_while_idle_and_with_default_value():
    d = Drv(100_000, WORKED)
    # reset at the first call: totals computed; enDefaultOutValue (step 5) overrides the 0.0
    check(
        d(reset=True, enDefaultOutValue=True, defaultOutValue=7.0),
        y=7.0,
        act=False,
        step=0,
        rt=0.0,
        tt=0.75,
        rtt=0.75,
        st=0,
    )
    check(d(), y=0.0, act=False, tt=0.75, st=0x7000)


def test_start_and_reset_edge_in_same_call_stays_blocked():
    # 4.2 order: step 1 clears "blocked", step 2 sets it again.
    d = Drv(100_000, WORKED)
    check(d(start=True, reset=True), y=0.0, act=False, step=0, rt=0.0, tt=0.75, rtt=0.75, st=0)
    check(d(start=True), y=0.0, act=False, step=0, st=0x7000)


def test_start_false_mid_run_gives_zero_and_restart_on_edge():
    d = Drv(100_000, WORKED)
    d(start=True)
    check(d(start=True), y=y02, rt=0.2, rtt=0.65)
    for _ in range(2):
        check(d(start=False), y=0.0, act=False, step=1, rt=0.2, tt=0.75, rtt=0.65, st=0x7000)
    check(d(start=True), y=0.0, act=True, step=1, rt=0.3, tt=0.75, rtt=0.75, st=0x7001)
    check(d(start=True), y=y02, act=True, step=1, rt=0.2, rtt=0.65)


def test_default_out_value_time_runs_underneath():
    d = Drv(100_000, WORKED)
    d(start=True)  # a): rt 300, rtt 750
    check(
        d(start=True, enDefaultOutValue=True, defaultOutValue=50.0),
        y=50.0,
        act=False,
        step=1,
        rt=0.2,
        rtt=0.65,
        st=0x7000,
    )  # c) underneath
    check(
        d(start=True, enDefaultOutValue=True, defaultOutValue=50.0),
        y=50.0,
        act=False,
        step=1,
        rt=0.1,
        rtt=0.55,
    )  # c) from prev = 50
    # released: remainTime 100 = Ts -> d) snaps onto point 1
    check(d(start=True), y=30.0, act=True, step=2, rt=0.2, rtt=0.45)


def test_default_out_value_release_ramps_from_default():
    d = Drv(100_000, WORKED)
    d(start=True)
    check(d(start=True, enDefaultOutValue=True, defaultOutValue=50.0), y=50.0, act=False, rt=0.2)
    # ramp from 50 to target 30 in the remaining 200 ms; actTimeTable stays FALSE until d)
    check(
        d(start=True), y=ip(50.0, 30.0, 200, 100), approx=40.0, act=False, step=1, rt=0.1, rtt=0.55
    )
    check(d(start=True), y=30.0, act=True, step=2, rt=0.2, rtt=0.45)


def test_default_out_value_while_idle():
    d = Drv(100_000, WORKED)
    check(d(enDefaultOutValue=True, defaultOutValue=-3.5), y=-3.5, act=False, step=0, st=0x7000)
    check(d(), y=0.0, act=False)


def test_hold_after_default_uses_default_as_previous_output():
    d = Drv(100_000, WORKED)
    d(start=True)
    check(d(start=True, enDefaultOutValue=True, defaultOutValue=50.0), y=50.0, rt=0.2)
    check(d(start=True, hold=True), y=50.0, act=False, rt=0.2, rtt=0.65)


def test_hold_freezes_and_extends_run():
    d = Drv(100_000, WORKED)
    d(start=True)
    check(d(start=True), y=y02, act=True, step=1, rt=0.2, rtt=0.65)
    for _ in range(2):  # 0.2 s hold: output and times frozen
        check(
            d(start=True, hold=True), y=y02, act=False, step=1, rt=0.2, tt=0.75, rtt=0.65, st=0x7000
        )
    check(d(start=True), y=ip(y02, 30.0, 200, 100), approx=20, act=False, step=1, rt=0.1, rtt=0.55)
    check(d(start=True), y=30.0, act=True, step=2, rt=0.2, rtt=0.45)
    check(d(start=True), y=30.0, act=True, step=2, rt=0.1, rtt=0.35)
    check(d(start=True), y=30.0, act=True, step=3, rt=0.25, rtt=0.25)
    check(d(start=True), y=y07, approx=18, step=3, rt=0.15, rtt=0.15)
    check(d(start=True), y=y08, approx=6, step=3, rt=0.05, rtt=0.05, st=0x7000)
    # the end arrives 2 calls (= the hold time) later than in the worked example
    check(d(start=True), y=0.0, act=False, step=3, rt=0.0, tt=0.75, rtt=0.0, st=0)
    assert d.k == 11  # worked example with start at call 0 ends at call 8; +2 hold calls


def test_hold_continue_to_last_point():
    d = Drv(100_000, WORKED)
    d(start=True)
    d(start=True)  # y02, rt 200
    # hold + continue: target point 3 (0.0) in 0.4 s; rtt = 400 + time[3] (0)
    for _ in range(2):
        check(
            d(start=True, hold=True, cont=True, contStepNbr=3, contStepTime=0.4),
            y=y02,
            act=False,
            step=3,
            rt=0.4,
            tt=0.75,
            rtt=0.4,
            st=0x7000,
        )
    y1 = ip(y02, 0.0, 400, 100)
    y2 = ip(y1, 0.0, 300, 100)
    y3 = ip(y2, 0.0, 200, 100)
    check(
        d(start=True, cont=True, contStepNbr=3, contStepTime=0.4),
        y=y1,
        approx=7.5,
        act=False,
        step=3,
        rt=0.3,
        rtt=0.3,
    )
    check(d(start=True), y=y2, approx=5.0, step=3, rt=0.2, rtt=0.2)
    check(d(start=True), y=y3, approx=2.5, step=3, rt=0.1, rtt=0.1)
    check(d(start=True), y=0.0, act=False, step=3, rt=0.0, rtt=0.0, st=0)


def test_hold_continue_recomputed_every_call_then_runs_on():
    d = Drv(100_000, WORKED)
    d(start=True)
    d(start=True)  # y02 = 10, rt 200
    # target point 1 (30.0) in 0.2 s: rtt = 200 + 200 + 250 + 0
    check(
        d(start=True, hold=True, cont=True, contStepNbr=1, contStepTime=0.2),
        y=y02,
        act=False,
        step=1,
        rt=0.2,
        rtt=0.65,
    )
    # contStepTime changed while held: recomputed -> 500 + 450
    check(
        d(start=True, hold=True, cont=True, contStepNbr=1, contStepTime=0.5),
        y=y02,
        act=False,
        step=1,
        rt=0.5,
        rtt=0.95,
    )
    # hold without continue keeps what continue set
    check(d(start=True, hold=True), y=y02, step=1, rt=0.5, rtt=0.95)
    ya = ip(y02, 30.0, 500, 100)
    check(d(start=True), y=ya, approx=14.0, step=1, rt=0.4, rtt=0.85)
    yb = ip(ya, 30.0, 400, 100)
    check(d(start=True), y=yb, approx=18.0, step=1, rt=0.3, rtt=0.75)
    yc = ip(yb, 30.0, 300, 100)
    check(d(start=True), y=yc, approx=22.0, step=1, rt=0.2, rtt=0.65)
    check(d(start=True), y=ip(yc, 30.0, 200, 100), approx=26.0, step=1, rt=0.1, rtt=0.55)
    check(d(start=True), y=30.0, act=True, step=2, rt=0.2, rtt=0.45)


def test_hold_continue_to_point_zero():
    d = Drv(100_000, WORKED)
    d(start=True)
    d(start=True)
    # target point 0 (0.0) in 0.1 s; rtt = 100 + 750
    check(
        d(start=True, hold=True, cont=True, contStepNbr=0, contStepTime=0.1),
        y=y02,
        step=0,
        rt=0.1,
        rtt=0.85,
    )
    # remainTime 100 = Ts: d) snaps onto point 0 and heads for point 1
    check(d(start=True), y=0.0, act=True, step=1, rt=0.3, rtt=0.75)
    check(d(start=True), y=y02, step=1, rt=0.2, rtt=0.65)


def test_cyclic_operation_wraps_without_interpolation():
    d = Drv(100_000, table((0.0, 0.2), (20.0, 0.1), (10.0, 0.0)))
    for first in (True, False):
        check(
            d(start=True, cyclicOP=True),
            y=0.0,
            act=True,
            step=1,
            rt=0.2,
            tt=0.3,
            rtt=0.3,
            st=0x7001 if first else 0x7000,
        )
        check(
            d(start=True, cyclicOP=True),
            y=ip(0.0, 20.0, 200, 100),
            approx=10.0,
            act=True,
            step=1,
            rt=0.1,
            rtt=0.2,
            st=0x7000,
        )
        check(d(start=True, cyclicOP=True), y=20.0, act=True, step=2, rt=0.1, rtt=0.1, st=0x7000)
        # wrap call: last point's value, status 0x7002, remainTime/remainTotalTime 0
        check(
            d(start=True, cyclicOP=True),
            y=10.0,
            act=True,
            step=2,
            rt=0.0,
            tt=0.3,
            rtt=0.0,
            st=0x7002,
        )
        # loop: next call jumps to point 0 (10 -> 0, no interpolation), status 0x7000
    d(start=True)  # a) point 0
    d(start=True)  # c) 10
    check(d(start=True), y=20.0, step=2)  # d)
    check(d(start=True), y=10.0, act=False, rt=0.0, rtt=0.0, st=0)  # e) without cyclicOP
    check(d(start=True, cyclicOP=True), y=10.0, act=False, st=0x7002)  # still at the end: wraps
    check(d(start=True, cyclicOP=True), y=0.0, act=True, step=1, rt=0.2, rtt=0.3, st=0x7000)


def test_update_time_after_table_change():
    d = Drv(100_000, WORKED)
    check(d(start=True), tt=0.75, rtt=0.75)
    check(d(start=True), y=y02, rt=0.2, rtt=0.65)
    d.m.set("setpoints[1].time", 0.5)
    d.m.set("setpoints[2].outputValue", 40.0)
    # no edge: totalTime unchanged; the table itself is read live
    check(d(start=True), y=y03, step=1, rt=0.1, tt=0.75, rtt=0.55)
    # updateTime edge: d) snaps to point 1, rt := time[1] = 500, target 40;
    # then tt = 300+500+250+0, rtt = 500 + time[2] + time[3] = 750
    check(d(start=True, updateTime=True), y=30.0, act=True, step=2, rt=0.5, tt=1.05, rtt=0.75)
    # held updateTime: no edge
    check(
        d(start=True, updateTime=True),
        y=ip(30.0, 40.0, 500, 100),
        approx=32.0,
        step=2,
        rt=0.4,
        tt=1.05,
        rtt=0.65,
    )
    check(d(start=True), rt=0.3, tt=1.05, rtt=0.55)


def test_update_time_while_idle_and_start_recomputes_total():
    d = Drv(100_000, WORKED)
    d.m.set("setpoints[0].time", 1.0)
    check(d(updateTime=True), y=0.0, act=False, step=0, rt=0.0, tt=1.45, rtt=1.45, st=0x7000)
    d.m.set("setpoints[3].time", 0.05)  # last point's time is counted in totalTime
    check(d(), tt=1.45, rtt=1.45)
    check(d(start=True), y=0.0, act=True, step=1, rt=1.0, tt=1.5, rtt=1.5, st=0x7001)


@pytest.mark.parametrize(
    "cycle_ms,t_ms",
    [(100, 100), (100, 150), (100, 250), (100, 300), (100, 301), (100, 1000), (7, 50), (1, 3)],
)
def test_segment_takes_ceil_t_over_ts_calls(cycle_ms, t_ms):
    d = Drv(cycle_ms * 1000, table((0.0, t_ms / 1000), (100.0, 0.0)))
    check(d(start=True), y=0.0, st=0x7001)
    calls = 0
    while True:
        out = d(start=True)
        calls += 1
        if out["outputValue"] == 100.0:
            break
        assert out["outputValue"] < 100.0 and calls < 10_000
    assert calls == math.ceil(t_ms / cycle_ms)
    check(out, y=100.0, act=False, rt=0.0, rtt=0.0, st=0)


def test_cycle_of_1_5_ms_runs_with_ts_1_ms():
    d = Drv(1500, table((0.0, 0.005), (10.0, 0.0)))
    check(d(start=True), y=0.0, step=1, rt=0.005, tt=0.005, rtt=0.005, st=0x7001)
    y = 0.0
    for rt in (5, 4, 3, 2):  # Ts = 1 ms, not 1.5 ms
        y = ip(y, 10.0, rt, 1)
        check(d(start=True), y=y, approx=2.0 * (6 - rt), rt=(rt - 1) / 1000, rtt=(rt - 1) / 1000)
    check(d(start=True), y=10.0, act=False, rt=0.0, rtt=0.0, st=0)


def test_cycle_time_limits():
    with pytest.raises(ValueError):
        RampCI(999)
    with pytest.raises(ValueError):
        RampCI(60_000_001)
    RampCI(1000)
    RampCI(60_000_000)


def test_default_table():
    d = Drv(100_000)
    check(d(start=True), y=0.0, act=True, step=1, rt=5.0, tt=20.0, rtt=20.0, st=0x7001)
    check(d(start=True), y=ip(0.0, 100.0, 5000, 100), approx=2.0, rt=4.9, rtt=19.9)


def test_remain_total_time_goes_negative_with_short_segments():
    d = Drv(100_000, table((0.0, 0.05), (10.0, 0.05), (20.0, 0.05), (30.0, 0.0)))
    check(d(start=True), y=0.0, step=1, rt=0.05, tt=0.15, rtt=0.15)
    check(d(start=True), y=10.0, step=2, rt=0.05, rtt=0.05)
    check(d(start=True), y=20.0, step=3, rt=0.05, rtt=-0.05)
    check(d(start=True), y=30.0, step=3, rt=0.0, rtt=0.0, st=0)


def test_sums_saturate():
    big = 2147483.647
    d = Drv(100_000, table((0.0, big), (1.0, big), (2.0, 0.0)))
    check(d(start=True), rt=big, tt=big, rtt=big)
    check(d(start=True), rt=2147483.547, tt=big, rtt=2147483.547)
    check(d(start=True, updateTime=True), rt=2147483.447, tt=big, rtt=big)
    # hold + continue: contStepTime + sum also saturates
    check(d(start=True, hold=True, cont=True, contStepNbr=1, contStepTime=10.0), rtt=big)


def test_setpoint_times_are_rounded_to_ms():
    # §1.4 (the shared TIME helper itself: tests/test_iec.py): 0.2504 s is 250 ms, 0.2505 s 251 ms
    d = Drv(100_000, table((0.0, 0.2504), (1.0, 0.0)))
    check(d(start=True), rt=0.25)
    d = Drv(100_000, table((0.0, 0.2505), (1.0, 0.0)))
    check(d(start=True), rt=0.251)


def test_invalid_parameters_rejected_and_not_applied():
    m = RampCI(100_000, WORKED)
    for name, value in (
        ("numberOfSetpoints", 1),
        ("numberOfSetpoints", 65),
        ("setpoints[0].time", -0.001),
        ("setpoints[0].time", float("nan")),
        ("setpoints[0].outputValue", float("nan")),
    ):
        with pytest.raises(ValueError):
            m.set(name, value)
    with pytest.raises(KeyError):
        m.set("setpoints[64].time", 1.0)
    d = Drv(100_000, WORKED)
    d.m = m
    check(d(start=True), y=0.0, rt=0.3, tt=0.75)


# docs/behaviour.md §4.3 c): output := prev + (target - prev) / REAL(remainTime_ms) * REAL(Ts), the
# rest time and the cycle rounded to float32 (REAL), the arithmetic in double (LREAL), evaluated
# in that order. float32 holds every integer up to 2^24 = 16777216 ms (about 4.66 h); from 2^24
# to 2^25 its spacing is 2, and ties go to the even significand: REAL(16777217) = 16777216
# (between 2^24 and 2^24 + 2), REAL(16777219) = 16777220 (between 2^24 + 2 and 2^24 + 4).
# Ts <= 60000 ms is always exact.
def test_rest_time_above_2_24_ms_is_rounded_to_real():
    # Ts = 1 ms, one segment of 2^24 + 1 ms = 16777.217 s from 0.0 to 16777216.0.
    d = Drv(1000, table((0.0, 16777.217), (16777216.0, 0.0)))
    check(
        d(start=True), y=0.0, act=True, step=1, rt=16777.217, tt=16777.217, rtt=16777.217, st=0x7001
    )
    # call 1: 0.0 + (16777216.0 - 0.0) / REAL(16777217) * REAL(1) = 16777216 / 16777216 * 1 = 1.0
    # (with the rest time unrounded it would be 16777216/16777217 = 0.99999994..., not 1.0)
    check(d(start=True), y=1.0, act=True, step=1, rt=16777.216, rtt=16777.216, st=0x7000)
    # call 2: rest 16777216 ms is exact: 1.0 + 16777215.0 / 16777216.0 * 1.0
    # = 1 + (1 - 2^-24) = 2 - 2^-24 (exact in double)
    check(d(start=True), y=2.0 - 2.0**-24, rt=16777.215, rtt=16777.215)
    check(d(start=True), y=ip(2.0 - 2.0**-24, 16777216.0, 16777215, 1), rt=16777.214)


def test_rest_time_above_2_24_ms_rounds_half_to_even_upwards():
    # Ts = 1 ms, segment of 2^24 + 3 ms = 16777.219 s from 0.0 to 16777220.0:
    # call 1: 16777220.0 / REAL(16777219) * 1.0 = 16777220 / 16777220 = 1.0
    d = Drv(1000, table((0.0, 16777.219), (16777220.0, 0.0)))
    check(d(start=True), y=0.0, rt=16777.219, st=0x7001)
    check(d(start=True), y=1.0, rt=16777.218, st=0x7000)


def test_rest_time_above_2_24_ms_with_a_60_s_cycle():
    # Ts = 60000 ms (REAL exact), segment of 2^24 + 1 ms from 0.0 to 3.0:
    # call 1: 0.0 + 3.0 / REAL(16777217) * REAL(60000) = 3 / 2^24 * 60000 = 180000 / 2^24
    # = 0.0107288360595703125 (3 * 2^-24 and 180000 * 2^-24 are exact in double); the unrounded
    # rest time would give 3 / 16777217 * 60000, which is smaller.
    d = Drv(60_000_000, table((0.0, 16777.217), (3.0, 0.0)))
    check(d(start=True), y=0.0, rt=16777.217, st=0x7001)
    check(d(start=True), y=0.0107288360595703125, rt=16717.217, rtt=16717.217, st=0x7000)
