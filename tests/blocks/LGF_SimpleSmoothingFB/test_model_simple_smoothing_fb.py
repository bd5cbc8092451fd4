"""Hand-traced tests of the SimpleSmoothingFB model against the original block's logic, without
any FMU. Calls are numbered from 0, cycle 0.1 s."""

import math

from tests.models.history import (
    STATUS_FIRST_CALL,
    STATUS_NO_CALL,
    STATUS_NOT_ENOUGH_VALUES,
    STATUS_SUBSEQUENT_CALL,
)

from .model import SimpleSmoothingFB

INF = math.inf
CYCLE = 100_000
N, F, S, E = STATUS_NO_CALL, STATUS_FIRST_CALL, STATUS_SUBSEQUENT_CALL, STATUS_NOT_ENOUGH_VALUES


def inp(value=0.0, insert=False, enable=True):
    return {"enable": enable, "insert": insert, "value": value}


def run(seq):
    b = SimpleSmoothingFB(CYCLE)
    return [b.call(k * CYCLE, i) for k, i in enumerate(seq)]


def sv(outs):
    return [o["smoothedValue"] for o in outs]


def st(outs):
    return [o["status"] for o in outs]


def inserts(values, first=None):
    """enable TRUE from call 0; one rising edge of insert in every second call from call 1."""
    seq = [first or inp()]
    for v in values:
        seq += [inp(v, insert=True), inp(v)]
    return seq


def test_status_codes_as_integers():
    assert (N, F, S, E) == (28672, 28673, 28674, 28688)


def test_first_smoothed_value_at_the_fourth_read_in():
    # call 0: enable edge -> 16#7001, 0.0
    # call 1: 3 in, [0, 0, 3], count 0 -> 1, 16#7010; call 3: 6 in, count 2, 16#7010
    # call 5: 9 in, [3, 6, 9], count 2 <= 2 -> 3, still 16#7010 and 0.0
    # call 7: 12 in, [6, 9, 12], count 3 > 2: (6 + 9 + 12) / 3 = 9.0, 16#7002
    outs = run(inserts([3.0, 6.0, 9.0, 12.0]))
    assert st(outs) == [F, E, E, E, E, E, E, S, S]
    assert sv(outs) == [0.0] * 7 + [9.0, 9.0]
    assert outs[5] == {"smoothedValue": 0.0, "error": False, "status": 0x7010}
    assert outs[7] == {"smoothedValue": 9.0, "error": False, "status": 0x7002}


def test_later_read_ins_smooth_the_last_three():
    # the 5th read-in 15: [9, 12, 15] -> 12.0; the count stays 3
    outs = run(inserts([3.0, 6.0, 9.0, 12.0, 15.0]))
    assert sv(outs)[9] == 12.0 and st(outs)[9] == S


def test_enable_edge_and_insert_edge_in_one_call_start_only():
    # call 0: enable and insert rise together, value 5: the start only (16#7001), 5 is lost;
    # call 1: insert still TRUE: no edge, 16#7001; call 2: insert FALSE;
    # call 3: insert rises, 7 in: count 1, 16#7010
    seq = [inp(5.0, insert=True), inp(5.0, insert=True), inp(7.0), inp(7.0, insert=True)]
    outs = run(seq)
    assert st(outs) == [F, F, F, E]
    assert sv(outs) == [0.0] * 4


def test_enable_edge_later_with_insert_edge():
    # call 0 disabled; call 1 enable and insert rise: start only; calls 2-7: read-ins
    # 1, 2, 3, 4 at calls 3, 5, 7, 9 -> (2 + 3 + 4) / 3 = 3.0 at call 9
    seq = [inp(enable=False), inp(100.0, insert=True), inp(100.0)]
    for v in (1.0, 2.0, 3.0, 4.0):
        seq += [inp(v, insert=True), inp(v)]
    outs = run(seq)
    assert st(outs)[:3] == [N, F, F]
    assert st(outs)[3:9] == [E] * 6
    assert outs[9] == {"smoothedValue": 3.0, "error": False, "status": S}


def test_rounding_order():
    # ((0.1 + 0.2) + 0.3) / 3.0 = 0.6000000000000001 / 3 = 0.20000000000000004
    outs = run(inserts([9.0, 0.1, 0.2, 0.3]))
    assert sv(outs)[7] == 0.20000000000000004 == ((0.1 + 0.2) + 0.3) / 3.0


def test_disable_outputs_zero_and_re_enable_starts_afresh():
    # after a smoothed 9.0, enable FALSE: 0.0 / 16#7000 at once; enable again: 16#7001 and
    # four new read-ins needed (the old values are cleared)
    seq = inserts([3.0, 6.0, 9.0, 12.0]) + [inp(enable=False), inp()]
    seq += [inp(v, insert=b) for v in (1.0, 2.0, 4.0, 8.0) for b in (True, False)]
    outs = run(seq)
    assert outs[9] == {"smoothedValue": 0.0, "error": False, "status": N}
    assert st(outs)[10] == F
    assert st(outs)[11:17] == [E] * 6 and sv(outs)[11:17] == [0.0] * 6
    assert outs[17] == {"smoothedValue": (2.0 + 4.0 + 8.0) / 3.0, "error": False, "status": S}


def test_insert_edges_while_disabled_are_not_read_but_update_the_memory():
    # call 0 disabled with insert TRUE; call 1 enable rises, insert held TRUE: start, no edge;
    # call 2 insert held: nothing
    outs = run([inp(1.0, insert=True, enable=False), inp(1.0, insert=True), inp(1.0, insert=True)])
    assert st(outs) == [N, F, F]


def test_held_status_without_edges():
    outs = run(inserts([3.0]) + [inp(), inp()])
    assert st(outs) == [F, E, E, E, E]


def test_opposite_infinities_give_the_positive_nan():
    # read-ins 0, Inf, -Inf, 1: (Inf + -Inf) + 1 = NaN, got as the positive quiet NaN;
    # three read-ins later (2, 3, 4) the NaN is gone: (2 + 3 + 4) / 3 = 3.0
    outs = run(inserts([0.0, INF, -INF, 1.0, 2.0, 3.0, 4.0]))
    o = outs[7]["smoothedValue"]
    assert math.isnan(o) and math.copysign(1.0, o) == 1.0
    assert outs[13]["smoothedValue"] == 3.0


def test_error_is_never_set():
    assert not any(o["error"] for o in run(inserts([1.0, 2.0, 3.0, 4.0])))
