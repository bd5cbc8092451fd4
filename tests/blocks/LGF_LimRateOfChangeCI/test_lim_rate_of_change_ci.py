"""LGF_LimRateOfChangeCI against the rules of docs/behaviour.md §3, with hand-computed
expectations."""

import pytest

from tests.harness import Slave

BLOCK = "LGF_LimRateOfChangeCI"
NEGATIVE_RATE = 0x8200


def slave(cycle=0.1, **inputs):
    return Slave(BLOCK, {"cycleTime": cycle}, inputs)


def delayed(s):
    return s.get(["delayedValue"])["delayedValue"]


@pytest.mark.parametrize("cycle, per_call", [(1.0, 10.0), (0.1, 1.0), (0.01, 0.1)])
def test_seed_example_rate_10_per_second(cycle, per_call):
    # Seed 001: setChangeRate 10.0 at 1 s / 100 ms / 10 ms moves 10.0 / 1.0 / 0.1 per call,
    # starting from 0.0 at the first call (in fmi2ExitInitializationMode).
    s = slave(cycle, value=1000.0, setChangeRate=10.0)
    values = [delayed(s)] + [s.step(cycle)["delayedValue"] for _ in range(5)]
    assert values == pytest.approx([per_call * n for n in range(1, 7)], rel=1e-12)
    if cycle >= 0.1:  # 10·cycle is exact in binary for these two, so the sums are exact too
        assert values == [per_call * n for n in range(1, 7)]


def test_lands_exactly_on_target_and_stays():
    s = slave(1.0, value=25.0, setChangeRate=10.0)
    assert [delayed(s)] + [s.step(1.0)["delayedValue"] for _ in range(4)] == [
        10.0,
        20.0,
        25.0,
        25.0,
        25.0,
    ]


def test_falls_with_the_same_rate():
    s = slave(1.0, value=-15.0, setChangeRate=10.0)
    assert [delayed(s)] + [s.step(1.0)["delayedValue"] for _ in range(3)] == [
        -10.0,
        -15.0,
        -15.0,
        -15.0,
    ]


def test_rate_zero_freezes_output():
    s = slave(1.0, value=50.0, setChangeRate=10.0)
    s.step(1.0)
    s.set({"setChangeRate": 0.0})
    assert [s.step(1.0)["delayedValue"] for _ in range(3)] == [20.0, 20.0, 20.0]


def test_negative_rate_is_status_8200_with_output_frozen_and_recovers():
    s = slave(1.0, value=100.0, setChangeRate=10.0)
    s.step(1.0)  # 20.0
    s.set({"setChangeRate": -1.0, "value": -100.0})
    out = s.step(1.0)
    assert out == {
        "delayedValue": 20.0,
        "error": True,
        "status": NEGATIVE_RATE,
        "subFunctionStatus": 0,
    }
    assert s.step(1.0)["delayedValue"] == 20.0
    # the change of status is logged as a warning naming the code
    assert any("16#8200" in text and category == "logStatusWarning" for _, category, text in s.log)
    assert any("16##8200" in raw for raw in s.raw_log)  # as sent: '#' escaped (FMI 2.0, 2.1.5)
    s.set({"setChangeRate": 5.0})
    out = s.step(1.0)
    assert out == {"delayedValue": 15.0, "error": False, "status": 0, "subFunctionStatus": 0}


def test_negative_rate_wins_over_default_value():
    s = slave(1.0, value=0.0, setChangeRate=-2.0, defaultOutValue=7.0, enDefaultOutValue=True)
    assert s.outputs() == {
        "delayedValue": 0.0,
        "error": True,
        "status": NEGATIVE_RATE,
        "subFunctionStatus": 0,
    }


def test_default_value_jumps_then_ramps_back_to_value():
    s = slave(1.0, value=10.0, setChangeRate=10.0)
    assert delayed(s) == 10.0
    s.set({"defaultOutValue": 42.0, "enDefaultOutValue": True})
    assert s.step(1.0)["delayedValue"] == 42.0  # a jump, whatever the rate
    s.set({"value": 60.0})
    assert s.step(1.0)["delayedValue"] == 42.0  # still pre-assigned
    s.set({"enDefaultOutValue": False, "value": 10.0})
    assert [s.step(1.0)["delayedValue"] for _ in range(5)] == [32.0, 22.0, 12.0, 10.0, 10.0]


def test_infinite_inputs_follow_ieee():
    s = slave(1.0, value=float("inf"), setChangeRate=10.0)
    assert delayed(s) == 10.0
    s.set({"setChangeRate": float("inf")})
    assert s.step(1.0)["delayedValue"] == float("inf")


def test_input_set_before_a_step_is_used_by_every_call_of_that_step():
    s = slave(0.1, value=100.0, setChangeRate=10.0)  # first call: 1.0
    out = s.step(0.5)  # calls at 0.1 ... 0.5
    assert out["delayedValue"] == pytest.approx(6.0)
    s.set({"value": 0.0})
    assert s.step(0.05)["delayedValue"] == pytest.approx(6.0)  # no call in (0.5, 0.55]
    assert s.step(0.05)["delayedValue"] == pytest.approx(5.0)  # the call at 0.6


def test_start_values_show_a_ramp_with_no_inputs_set():
    # docs/behaviour.md §3.1, decision on start values: value 100.0 at 20.0 per second, so with
    # nothing set delayedValue rises by 2.0 per call of 0.1 s from the first call (t = 0) and
    # lands on 100.0 in call 49 (t = 4.9 s).
    s = Slave(BLOCK)
    assert s.get(["value", "setChangeRate"]) == {"value": 100.0, "setChangeRate": 20.0}
    values = [delayed(s)] + [s.step(0.1)["delayedValue"] for _ in range(60)]
    assert values == [min(2.0 * (k + 1), 100.0) for k in range(61)]
    assert values.index(100.0) == 49
