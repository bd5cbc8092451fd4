"""Hand-traced tests of the DifferenceQuotientFB model against the original block's logic,
without any FMU. Calls are numbered from 0, cycle 0.1 s."""

import math

from tests.models.history import (
    STATUS_FIRST_CALL,
    STATUS_NO_CALL,
    STATUS_NOT_ENOUGH_VALUES,
    STATUS_SUBSEQUENT_CALL,
)

from .model import STATUS_DELTA_T, DifferenceQuotientFB

INF = math.inf
CYCLE = 100_000
N, F, S, E, D = (
    STATUS_NO_CALL,
    STATUS_FIRST_CALL,
    STATUS_SUBSEQUENT_CALL,
    STATUS_NOT_ENOUGH_VALUES,
    STATUS_DELTA_T,
)


def inp(value=0.0, insert=False, enable=True, dt=0.1):
    return {"enable": enable, "insert": insert, "value": value, "deltaT": dt}


def run(seq):
    b = DifferenceQuotientFB(CYCLE)
    return [b.call(k * CYCLE, i) for k, i in enumerate(seq)]


def inserts(values, dt=0.1):
    """enable TRUE from call 0; one rising edge of insert in every second call from call 1;
    dt a number or one per value."""
    dts = dt if isinstance(dt, list) else [dt] * len(values)
    seq = [inp(dt=dts[0])]
    for v, d in zip(values, dts):
        seq += [inp(v, insert=True, dt=d), inp(v, dt=d)]
    return seq


def st(outs):
    return [o["status"] for o in outs]


def dv(outs):
    return [o["derivatedValue"] for o in outs]


def test_status_codes_as_integers():
    assert (N, F, S, E, D) == (28672, 28673, 28674, 28688, 33280)


def test_first_derivative_at_the_sixth_read_in_in_the_original_order():
    # read-ins 1 ... 6 at calls 1, 3, ..., 11, deltaT 0.1: read-ins 1-5 count 0 -> 5, 16#7010;
    # the 6th: [2, 3, 4, 5, 6]: ((2 - 8*3) + 8*5) - 6 = 12; 1.0 / (12.0 * 0.1) =
    # 1.0 / 1.2000000000000002 = 0.8333333333333333; * 12 = 10.0
    # (12 / 1.2000000000000002 would be 9.999999999999998)
    outs = run(inserts([1.0, 2.0, 3.0, 4.0, 5.0, 6.0]))
    assert st(outs) == [F] + [E] * 10 + [S, S]
    assert dv(outs) == [0.0] * 11 + [10.0, 10.0]
    assert (1.0 / (12.0 * 0.1)) * 12.0 == 10.0 and 12.0 / (12.0 * 0.1) == 9.999999999999998


def test_middle_value_has_weight_zero():
    # read-ins 9, 0, 0, 100, 0, 0: at the 6th the last five are [0, 0, 100, 0, 0], and 100
    # (the middle sample) is not in the bracket: 0 -> 0.0
    outs = run(inserts([9.0, 0.0, 0.0, 100.0, 0.0, 0.0], dt=1.0))
    assert outs[11] == {"derivatedValue": 0.0, "error": False, "status": S}


def test_delta_t_zero_is_looked_at_only_when_a_derivative_is_due():
    # deltaT 0 for read-ins 1-5: no error (16#7010); 6th with 0.0: 16#8200, error, value kept
    # (0.0); 7th with -0.0: 16#8200 again; 8th with 0.1: [4, 5, 6, 7, 8]: (4 - 40 + 56 - 8) =
    # 12 -> 10.0
    dts = [0.0] * 6 + [-0.0, 0.1]
    outs = run(inserts([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0], dt=dts))
    assert st(outs)[1:11] == [E] * 10
    assert outs[11] == {"derivatedValue": 0.0, "error": True, "status": D}
    assert outs[13] == {"derivatedValue": 0.0, "error": True, "status": D}
    assert outs[15] == {"derivatedValue": 10.0, "error": False, "status": S}


def test_delta_t_zero_keeps_the_last_derivative():
    dts = [0.1] * 6 + [0.0]
    outs = run(inserts([1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 100.0], dt=dts))
    assert outs[11]["derivatedValue"] == 10.0
    assert outs[13] == {"derivatedValue": 10.0, "error": True, "status": D}


def test_enable_edge_and_insert_edge_in_one_call_start_only():
    # call 0: enable and insert rise together: start only; call 1 insert held: no edge
    outs = run([inp(5.0, insert=True), inp(5.0, insert=True), inp(5.0), inp(6.0, insert=True)])
    assert st(outs) == [F, F, F, E]


def test_disable_outputs_zero_and_re_enable_needs_six_new_values():
    seq = inserts([1.0, 2.0, 3.0, 4.0, 5.0, 6.0]) + [inp(enable=False), inp()]
    seq += [inp(v, insert=b) for v in (0.0, 0.0, 0.0, 0.0, 0.0, 3.0) for b in (True, False)]
    outs = run(seq)
    assert outs[13] == {"derivatedValue": 0.0, "error": False, "status": N}
    assert st(outs)[14] == F
    assert st(outs)[15:25] == [E] * 10
    # [0, 0, 0, 0, 3]: (0 - 0 + 0) - 3 = -3; 0.8333333333333333 * -3 = -2.5
    assert outs[25] == {"derivatedValue": (1.0 / (12.0 * 0.1)) * -3.0, "error": False, "status": S}
    assert outs[25]["derivatedValue"] == -2.5


def test_infinite_delta_t_and_infinite_values():
    # deltaT +Inf: 12 * Inf = Inf, 1 / Inf = 0.0, * 12 = 0.0
    outs = run(inserts([1.0, 2.0, 3.0, 4.0, 5.0, 6.0], dt=INF))
    assert outs[11] == {"derivatedValue": 0.0, "error": False, "status": S}
    # an infinite value with deltaT Inf: 0.0 * -Inf = NaN, the positive quiet NaN
    outs = run(inserts([1.0, 2.0, 3.0, 4.0, 5.0, INF], dt=INF))
    o = outs[11]["derivatedValue"]
    assert math.isnan(o) and math.copysign(1.0, o) == 1.0
    # deltaT 1: the bracket (2 - 24 + 40) - Inf = -Inf; (1/12) * -Inf = -Inf
    outs = run(inserts([1.0, 2.0, 3.0, 4.0, 5.0, INF], dt=1.0))
    assert outs[11]["derivatedValue"] == -INF
