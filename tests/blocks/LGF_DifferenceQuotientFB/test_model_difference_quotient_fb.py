"""Hand-traced tests of the DifferenceQuotientFB model (docs/behaviour.md §17), without any FMU."""

import math

import pytest

from .model import STATUS_DELTA_T, DifferenceQuotientFB

INF = math.inf


def inp(value=0.0, insert=False, enable=True, deltaT=1.0):
    return {"enable": enable, "insert": insert, "value": value, "deltaT": deltaT}


def read_ins(values, deltaT=1.0, enable_first=True):
    """One rising edge of insert per value (insert FALSE in the call between)."""
    seq = []
    for v in values:
        dt = deltaT(v) if callable(deltaT) else deltaT
        seq += [inp(v, True, deltaT=dt), inp(v, False, deltaT=dt)]
    return seq


def run(seq, cycle_us=100_000):
    b = DifferenceQuotientFB(cycle_us)
    return [b.call(k * cycle_us, i) for k, i in enumerate(seq)]


def after_read_ins(outs):
    """Outputs of the calls that had the rising edge of insert (even indices)."""
    return outs[0::2]


def test_worked_example():
    # §17.4: deltaT 0.5, values 1, 2, 4, 8, 16, 32:
    # (((1 - 8*2) + 8*8) - 16) / (12*0.5) = 33/6 = 5.5; (((2 - 32) + 128) - 32)/6 = 11.0
    outs = after_read_ins(run(read_ins([1.0, 2.0, 4.0, 8.0, 16.0, 32.0], deltaT=0.5)))
    assert [o["status"] for o in outs] == [0x7010] * 4 + [0x7002] * 2
    assert [o["derivatedValue"] for o in outs] == [0.0] * 4 + [5.5, 11.0]
    assert all(o["error"] is False for o in outs)


def test_linear_samples_give_slope():
    # §17.4: y = t: 0..4, deltaT 1: (((0 - 8) + 24) - 4) / 12 = 1.0
    outs = after_read_ins(run(read_ins([0.0, 1.0, 2.0, 3.0, 4.0])))
    assert outs[-1]["derivatedValue"] == 1.0 and outs[-1]["status"] == 0x7002


def test_order_of_arithmetic():
    # §17.2 step 3: ((y0 - 8*y1) + 8*y3) - y4, / (12*deltaT); values 0.1, 0.3, x, 0.7, 0.2,
    # deltaT 0.1: computed step by step in doubles
    vals = [0.1, 0.3, 123.0, 0.7, 0.2]
    num = ((0.1 - 8.0 * 0.3) + 8.0 * 0.7) - 0.2
    den = 12.0 * 0.1
    outs = after_read_ins(run(read_ins(vals, deltaT=0.1)))
    assert outs[-1]["derivatedValue"] == num / den
    # the middle sample has weight 0
    vals[2] = -1e9
    assert after_read_ins(run(read_ins(vals, deltaT=0.1)))[-1]["derivatedValue"] == num / den


def test_start_and_no_signal():
    # §17.1: enable TRUE, insert FALSE: 16#7001 and 0.0
    outs = run([inp()] * 3)
    assert [(o["derivatedValue"], o["status"], o["error"]) for o in outs] == [
        (0.0, 0x7001, False)
    ] * 3


@pytest.mark.parametrize("zero", [0.0, -0.0])
def test_delta_t_zero_error_not_latched(zero):
    # §17.2 step 3 / §17.3: fifth read-in with deltaT 0: 16#8200, error, derivative kept (0.0);
    # sixth with deltaT 1: derivative from the five values then in the buffer
    seq = read_ins([0.0, 1.0, 2.0, 3.0], deltaT=zero)  # deltaT 0 with < 5 values: 16#7010
    seq += [inp(4.0, True, deltaT=zero), inp(4.0, False, deltaT=zero)]
    seq += [inp(5.0, True, deltaT=1.0)]
    outs = run(seq)
    assert [o["status"] for o in outs[:8]] == [0x7010] * 8
    assert outs[8]["status"] == STATUS_DELTA_T == 33280 and outs[8]["error"] is True
    assert outs[8]["derivatedValue"] == 0.0 and outs[9]["status"] == 0x8200  # held
    # buffer 1, 2, 3, 4, 5: (((1 - 16) + 32) - 5)/12 = 1.0
    assert outs[10] == {"derivatedValue": 1.0, "error": False, "status": 0x7002}


def test_delta_t_zero_keeps_last_derivative():
    # §17.5: after 16#8200 derivatedValue keeps the last derivative
    seq = read_ins([0.0, 1.0, 2.0, 3.0, 4.0]) + [inp(5.0, True, deltaT=0.0)]
    outs = run(seq)
    assert outs[-1] == {"derivatedValue": 1.0, "error": True, "status": 0x8200}


def test_delta_t_looked_at_only_when_due():
    # §17.2 step 3: deltaT 0 between read-ins changes nothing
    seq = read_ins([0.0, 1.0, 2.0, 3.0, 4.0]) + [inp(4.0, False, deltaT=0.0)]
    assert run(seq)[-1] == {"derivatedValue": 1.0, "error": False, "status": 0x7002}


def test_negative_and_infinite_delta_t():
    # §17.4: negative deltaT flips the sign; infinite deltaT gives 0.0 (16 / Inf); tiny overflows
    assert (
        after_read_ins(run(read_ins([0.0, 1, 2, 3, 4], deltaT=-1.0)))[-1]["derivatedValue"] == -1.0
    )
    o = after_read_ins(run(read_ins([0.0, 1, 2, 3, 4], deltaT=INF)))[-1]
    assert o["derivatedValue"] == 0.0 and o["status"] == 0x7002
    o = after_read_ins(run(read_ins([0.0, 1, 2, 3, 4], deltaT=1e-320)))[-1]
    assert o["derivatedValue"] == INF


def test_nan_results_are_positive_quiet():
    # §17.4: Inf numerator / Inf den = NaN; Inf - Inf in the numerator = NaN
    o = after_read_ins(run(read_ins([INF, 0.0, 0.0, 0.0, 0.0], deltaT=INF)))[-1]
    assert math.isnan(o["derivatedValue"]) and math.copysign(1.0, o["derivatedValue"]) == 1.0
    o = after_read_ins(run(read_ins([INF, 0.0, 0.0, INF, 0.0])))[-1]  # Inf + 8*Inf = Inf
    assert o["derivatedValue"] == INF
    o = after_read_ins(run(read_ins([INF, 0.0, 0.0, 0.0, INF])))[-1]  # Inf - Inf
    assert math.isnan(o["derivatedValue"]) and math.copysign(1.0, o["derivatedValue"]) == 1.0


def test_disable_and_re_enable():
    # §17.2 steps 2, 4: disabled: 0.0, 16#7000; enable rising clears the buffer: 16#7001
    seq = read_ins([0.0, 1, 2, 3, 4]) + [inp(enable=False), inp(), inp(7.0, True)]
    outs = run(seq)
    assert outs[10] == {"derivatedValue": 0.0, "error": False, "status": 0x7000}
    assert outs[11] == {"derivatedValue": 0.0, "error": False, "status": 0x7001}
    assert outs[12]["status"] == 0x7010  # one value in the cleared buffer


def test_insert_with_enable_edge_is_read_in():
    # §17.4: a rising insert in the call of the rising enable: read in -> 16#7010
    assert run([inp(enable=False), inp(1.0, True)])[1]["status"] == 0x7010


def test_count_stops_at_five():
    b = DifferenceQuotientFB(1000)
    k = 0
    for i in range(33000):
        b.call(k * 1000, inp(float(i), True))
        b.call((k + 1) * 1000, inp(float(i), False))
        k += 2
    assert b.statCount == 5 and b.derivatedValue == 1.0 and b.statStatus == 0x7002
