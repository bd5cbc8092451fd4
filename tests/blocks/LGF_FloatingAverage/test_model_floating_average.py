"""Hand-traced tests of the FloatingAverage model against the original block's logic, without
any FMU. Calls are numbered from 0, cycle 0.1 s."""

import math

from .model import STATUS_OK, STATUS_WRONG_WINDOW_SIZE, FloatingAverage

INF = math.inf
CYCLE = 100_000


def inp(value=0.0, window=3, cyclic=True, trigger=False, reset=False):
    return {
        "cyclicExecution": cyclic,
        "trigger": trigger,
        "value": value,
        "windowSize": window,
        "reset": reset,
    }


def run(seq):
    b = FloatingAverage(CYCLE)
    return [b.call(k * CYCLE, i) for k, i in enumerate(seq)]


def out(average, reached=False, error=False, status=STATUS_OK):
    return {"average": average, "windowSizeReached": reached, "error": error, "status": status}


def avg(outs):
    return [o["average"] for o in outs]


def test_status_codes():
    assert (STATUS_OK, STATUS_WRONG_WINDOW_SIZE) == (0, 33280)


def test_fill_then_slide():
    # call 0: windowSize 3 differs from the remembered 0: cleared, nothing read (value 99 lost)
    # calls 1-3 fill: 3 -> 3/1 = 3.0; 6 -> 9/2 = 4.5; 9 -> 18/3 = 6.0, window full but
    #   windowSizeReached still FALSE
    # call 4: counter 3 MOD 3 = slot 0 (the 3): 18 + (12 - 3) = 27, / 3 = 9.0, reached TRUE
    # call 5: slot 1 (6): 27 + (0 - 6) = 21 -> 7.0; call 6: slot 2 (9): 21 + (30 - 9) = 42
    #   -> 14.0; call 7: counter 6 MOD 3 = slot 0 (12): 42 + (3 - 12) = 33 -> 11.0
    values = [99.0, 3.0, 6.0, 9.0, 12.0, 0.0, 30.0, 3.0]
    outs = run([inp(v) for v in values])
    assert outs == [
        out(0.0),
        out(3.0),
        out(4.5),
        out(6.0),
        out(9.0, True),
        out(7.0, True),
        out(14.0, True),
        out(11.0, True),
    ]


def test_lreal_and_the_order_of_the_sliding_sum():
    # windowSize 1: call 1 fills 0.1; call 2 slides: 0.1 + (0.2 - 0.1) = 0.2
    # ((0.1 + 0.2) - 0.1 would be 0.20000000000000004)
    outs = run([inp(0.0, 1), inp(0.1, 1), inp(0.2, 1)])
    assert avg(outs) == [0.0, 0.1, 0.2]
    assert (0.1 + 0.2) - 0.1 == 0.20000000000000004
    # a value REAL could not hold: 1e8 then 1.0: 1e8 + (1 - 1e8) = 1.0 in LREAL
    outs = run([inp(0.0, 1), inp(1e8, 1), inp(1.0, 1)])
    assert avg(outs) == [0.0, 1e8, 1.0]
    assert outs[2]["windowSizeReached"] is True
    # 0.1 is not rounded to float32
    assert run([inp(0.0, 2), inp(0.1, 2)])[1]["average"] == 0.1


def test_reset_returns_without_reading_in():
    # windowSize 2: call 1: 4 -> 4.0; call 2: 8 -> 6.0; call 3 reset (value 100): cleared, 0.0,
    # 100 not read; call 4: 10 -> 10.0 (the first of a new window)
    seq = [inp(0.0, 2), inp(4.0, 2), inp(8.0, 2), inp(100.0, 2, reset=True), inp(10.0, 2)]
    assert run(seq) == [out(0.0), out(4.0), out(6.0), out(0.0), out(10.0)]


def test_reset_held_reads_nothing():
    seq = [inp(0.0, 2), inp(4.0, 2)] + [inp(5.0, 2, reset=True)] * 3 + [inp(7.0, 2)]
    assert avg(run(seq)) == [0.0, 4.0, 0.0, 0.0, 0.0, 7.0]


def test_change_of_window_size_returns_without_reading_in():
    # a full window of 2 (reached at call 3), then windowSize 3 at call 4: cleared, 0.0, FALSE,
    # the 50 lost; call 5: 1 -> 1.0
    seq = [inp(0.0, 2), inp(2.0, 2), inp(4.0, 2), inp(6.0, 2), inp(50.0, 3), inp(1.0, 3)]
    assert run(seq) == [out(0.0), out(2.0), out(3.0), out(5.0, True), out(0.0), out(1.0)]


def test_invalid_window_size_errors_one_call_later():
    # call 1: 5 -> 5.0; call 2: windowSize 0 is a change: cleared, no error;
    # calls 3-4: 0 again: error, 16#8200; call 5: 3 is a change: cleared, no error;
    # call 6: 7 -> 7.0
    seq = [inp(0.0), inp(5.0), inp(5.0, 0), inp(5.0, 0), inp(5.0, 0), inp(5.0), inp(7.0)]
    err = out(0.0, False, True, STATUS_WRONG_WINDOW_SIZE)
    assert run(seq) == [out(0.0), out(5.0), out(0.0), err, err, out(0.0), out(7.0)]


def test_invalid_window_size_from_the_first_call():
    err = out(0.0, False, True, STATUS_WRONG_WINDOW_SIZE)
    # 0 equals the remembered start value 0: no change, the error at once
    assert run([inp(1.0, 0), inp(1.0, 0)]) == [err, err]
    # 101, -1, 32767, -32768: a change first, the error from call 1
    for w in (101, -1, 32767, -32768):
        assert run([inp(1.0, w), inp(1.0, w), inp(1.0, w)]) == [out(0.0), err, err]


def test_reset_with_an_invalid_size_is_no_error():
    # the reset branch comes first: no error in a reset call, whatever windowSize is
    err = out(0.0, False, True, STATUS_WRONG_WINDOW_SIZE)
    seq = [inp(1.0, 0), inp(1.0, 0, reset=True), inp(1.0, 0)]
    assert run(seq) == [err, out(0.0), err]


def test_trigger_edges():
    # cyclicExecution FALSE, windowSize 2:
    # call 0: trigger rises with the change of windowSize: the edge is used up, nothing read
    # call 1: trigger held: no edge, 0.0; call 2: FALSE; call 3: rises, 4 -> 4.0;
    # call 4: held: 4.0; call 5: FALSE; call 6: rises, 8 -> 6.0
    t = [True, True, False, True, True, False, True]
    v = [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 8.0]
    outs = run([inp(vv, 2, cyclic=False, trigger=tt) for vv, tt in zip(v, t)])
    assert avg(outs) == [0.0, 0.0, 0.0, 4.0, 4.0, 4.0, 6.0]


def test_cyclic_and_trigger_edge_read_one_value():
    outs = run([inp(0.0, 2), inp(4.0, 2, trigger=True), inp(8.0, 2)])
    assert avg(outs) == [0.0, 4.0, 6.0]


def test_window_size_one_slides_from_the_second_read_in():
    # fill: 5 -> 5.0, FALSE; then each read-in replaces it: TRUE
    outs = run([inp(0.0, 1), inp(5.0, 1), inp(6.0, 1), inp(7.0, 1)])
    assert outs == [out(0.0), out(5.0), out(6.0, True), out(7.0, True)]


def test_window_of_100():
    # values 1 ... 100 at calls 1-100: the mean of 1 ... k while filling; call 100: 50.5, still
    # FALSE; call 101: 101 replaces 1: 5050 + (101 - 1) = 5150 -> 51.5, TRUE
    seq = [inp(0.0, 100)] + [inp(float(k), 100) for k in range(1, 102)]
    outs = run(seq)
    assert outs[100] == out(50.5)
    assert outs[101] == out(51.5, True)


def test_infinity_leaving_the_window_gives_nan_until_a_restart():
    # windowSize 1: Inf -> Inf; then 1: Inf + (1 - Inf) = Inf + -Inf = NaN (positive quiet);
    # NaN stays (NaN + ...); a reset clears it
    seq = [inp(0.0, 1), inp(INF, 1), inp(1.0, 1), inp(2.0, 1), inp(2.0, 1, reset=True)]
    seq.append(inp(3.0, 1))
    outs = run(seq)
    assert outs[1]["average"] == INF
    for o in outs[2:4]:
        assert math.isnan(o["average"]) and math.copysign(1.0, o["average"]) == 1.0
    assert avg(outs)[4:] == [0.0, 3.0]
