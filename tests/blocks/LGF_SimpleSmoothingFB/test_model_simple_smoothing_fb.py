"""Hand-traced tests of the SimpleSmoothingFB model (docs/behaviour.md §16), without any FMU."""

import math

from .model import (
    STATUS_FIRST_CALL,
    STATUS_NO_CALL,
    STATUS_NOT_ENOUGH_VALUES,
    STATUS_SUBSEQUENT_CALL,
    SimpleSmoothingFB,
)

INF = math.inf


def inp(value=0.0, insert=False, enable=True):
    return {"enable": enable, "insert": insert, "value": value}


def run(seq, cycle_us=100_000):
    b = SimpleSmoothingFB(cycle_us)
    return [b.call(k * cycle_us, i) for k, i in enumerate(seq)]


def sv(outs):
    return [o["smoothedValue"] for o in outs]


def st(outs):
    return [o["status"] for o in outs]


def test_status_codes_as_integers():
    assert (STATUS_NO_CALL, STATUS_FIRST_CALL, STATUS_SUBSEQUENT_CALL) == (28672, 28673, 28674)
    assert STATUS_NOT_ENOUGH_VALUES == 28688


def test_worked_example():
    # §16.4: insert rising in calls 1, 3, 5, 7 with values 3, 6, 9, 12
    seq = [inp()] + [
        inp(v, insert=ins)
        for v, ins in [(3.0, True), (3.0, False), (6.0, True), (6.0, False), (9.0, True),
                       (9.0, False), (12.0, True), (12.0, False)]
    ]  # fmt: skip
    outs = run(seq)
    assert st(outs) == [0x7001] + [0x7010] * 4 + [0x7002] * 4
    # call 5: ((3 + 6) + 9)/3 = 6; call 7: ((6 + 9) + 12)/3 = 9
    assert sv(outs) == [0.0] * 5 + [6.0, 6.0, 9.0, 9.0]
    assert all(o["error"] is False for o in outs)


def test_start_values_without_signal():
    # §16.1: enable TRUE, insert FALSE: 16#7001 and 0.0 forever
    outs = run([inp()] * 4)
    assert st(outs) == [0x7001] * 4 and sv(outs) == [0.0] * 4


def test_rounding_order():
    # §16.4: (0.1 + 0.2) + 0.3 = 0.6000000000000001, / 3 = 0.20000000000000004
    seq = [inp(0.1, True), inp(0.1), inp(0.2, True), inp(0.2), inp(0.3, True)]
    assert sv(run(seq))[-1] == 0.20000000000000004
    assert (0.1 + 0.2) + 0.3 == 0.6000000000000001


def test_insert_with_enable_edge_is_read_in():
    # §16.4: insert TRUE in the first call with enable rising: read in -> 16#7010
    outs = run([inp(5.0, True)])
    assert st(outs) == [0x7010]


def test_held_insert_while_enable_rises_is_no_edge():
    # §16.2 step 1: insert held TRUE while enable is FALSE, then enable rises: no read-in
    outs = run([inp(1.0, True, enable=False), inp(1.0, True), inp(1.0, False), inp(2.0, True)])
    assert st(outs) == [0x7000, 0x7001, 0x7001, 0x7010]


def test_disable_gives_zero_and_7000_and_buffer_cleared_at_next_enable():
    seq = [inp(3.0, True), inp(), inp(6.0, True), inp(), inp(9.0, True)]  # 6.0, 16#7002
    seq += [inp(enable=False), inp(enable=False)]
    seq += [inp(12.0, True), inp(), inp(15.0, True), inp(), inp(18.0, True)]
    outs = run(seq)
    assert sv(outs)[4] == 6.0 and st(outs)[4] == 0x7002
    assert sv(outs)[5:7] == [0.0, 0.0] and st(outs)[5:7] == [0x7000, 0x7000]
    # enable rises with insert rising (call 7): buffer cleared, 12 read in -> 16#7010
    assert st(outs)[7:11] == [0x7010] * 4
    assert sv(outs)[11] == 15.0  # (12 + 15 + 18)/3, not with the old values


def test_status_held_between_read_ins():
    # §16.3: no insert edge: smoothedValue and status hold
    seq = [inp(1.0, True), inp(), inp(2.0, True), inp(), inp(3.0, True), inp(), inp(), inp()]
    outs = run(seq)
    assert st(outs)[4:] == [0x7002] * 4 and sv(outs)[4:] == [2.0] * 4


def test_count_stops_at_three():
    # §16.5: statCount stops at 3 (no wrap): 40000 read-ins
    b = SimpleSmoothingFB(1000)
    for k in range(40000):
        b.call(2 * k * 1000, inp(float(k), True))
        b.call((2 * k + 1) * 1000, inp(float(k), False))
    assert b.statCount == 3
    # last three values 39997, 39998, 39999: (39997 + 39998 + 39999)/3 = 39998
    assert b.smoothedValue == 39998.0 and b.statStatus == 0x7002


def test_infinities_nan_then_gone():
    # §16.4: +Inf and -Inf among the three: NaN (positive quiet); three values later gone
    vals = [INF, -INF, 1.0, 1.0, 1.0, 1.0]
    seq = []
    for v in vals:
        seq += [inp(v, True), inp(v)]
    outs = run(seq)
    s = sv(outs)
    assert math.isnan(s[4]) and math.copysign(1.0, s[4]) == 1.0  # (Inf + -Inf) + 1
    assert s[6] == -INF  # ((-Inf + 1) + 1) / 3 = -Inf
    assert s[8] == 1.0 and s[10] == 1.0  # ((1 + 1) + 1) / 3: the NaN is gone


def test_infinity_alone_is_infinite():
    seq = [inp(1.0, True), inp(), inp(2.0, True), inp(), inp(INF, True)]
    assert sv(run(seq))[-1] == INF
