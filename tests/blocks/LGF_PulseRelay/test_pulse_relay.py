"""LGF_PulseRelay against the rules of docs/behaviour.md §11, with hand-computed expectations
(each trace is worked out from §11.2 in the comments, never taken from the FMU)."""

import pytest
from fmpy.fmi2 import fmi2Error

from tests.harness import Slave, status_of

BLOCK = "LGF_PulseRelay"
F, T = False, True


def relay(cycle=0.1, **inputs):
    return Slave(BLOCK, {"cycleTime": cycle}, {"trigger": F, "set": F, "reset": F, **inputs})


def run(rows, cycle=0.1):
    """out after call 0 (inputs rows[0], set in initialization) and after one step of one
    cycle per further row (the inputs set before the step reach the call at its end)."""
    s = relay(cycle, **dict(zip(("trigger", "set", "reset"), rows[0])))
    outs = [s.get(["out"])["out"]]
    for trigger, set_, reset in rows[1:]:
        s.set({"trigger": trigger, "set": set_, "reset": reset})
        outs.append(s.step(cycle)["out"])
    s.free()
    return outs


def test_worked_example():
    # docs/behaviour.md §11.3, calls 0 ... 9 (trigger, set, reset):
    # 0 FFF: nothing, F | 1 T: edge, toggle F->T | 2 F: T | 3 T: edge, T->F | 4 T held: F
    # 5 set rises: T | 6 trigger rises (toggle T->F), set held: F | 7 reset rises: F
    # 8 nothing: F | 9 all three rise: toggle F->T, set T, reset F: F
    rows = [
        (F, F, F),
        (T, F, F),
        (F, F, F),
        (T, F, F),
        (T, F, F),
        (F, T, F),
        (T, T, F),
        (T, F, T),
        (F, F, F),
        (T, T, T),
    ]
    assert run(rows) == [F, T, T, F, F, T, F, F, F, F]


def test_an_input_true_in_the_first_call_is_a_rising_edge():
    # §11.3: the edge memories start FALSE, so call 0 (in fmi2ExitInitializationMode) toggles.
    assert run([(T, F, F), (T, F, F), (T, F, F)]) == [T, T, T]
    # set TRUE in call 0 sets; reset TRUE in call 0 on a FALSE state leaves it FALSE
    assert run([(F, T, F), (F, T, F)]) == [T, T]
    assert run([(T, F, T), (T, F, T)]) == [F, F]  # toggle to T, then reset: F


def test_frequency_divider():
    # trigger T, F, T, F, ...: edges in calls 0, 2, 4, 6, ... toggle: T T F F T T F F
    rows = [(k % 2 == 0, F, F) for k in range(8)]
    assert run(rows) == [T, T, F, F, T, T, F, F]
    # a slower clock, TRUE for two calls, FALSE for two: edges at 0, 4, 8 -> period of 8 calls
    rows = [(k % 4 < 2, F, F) for k in range(12)]
    assert run(rows) == [T] * 4 + [F] * 4 + [T] * 4


def test_only_rising_edges_act():
    # trigger held TRUE acts once; its falling edge does nothing
    assert run([(F, F, F), (T, F, F), (T, F, F), (F, F, F), (F, F, F)]) == [F, T, T, T, T]
    # set held: once; after a toggle to FALSE it does not set again while held
    assert run([(F, T, F), (T, T, F), (F, T, F), (T, T, F)]) == [T, F, F, T]
    # call 1 toggles T->F (set held); call 3 toggles F->T


def test_reset_held_does_not_block_trigger_or_set():
    # reset rises in call 1 (F); held, it acts no more: trigger in call 2 toggles to T, then set
    # rising in call 4 keeps T, trigger rising in call 6 toggles to F
    rows = [(F, F, F), (F, F, T), (T, F, T), (F, F, T), (F, T, T), (F, T, T), (T, T, T)]
    assert run(rows) == [F, F, T, T, T, T, F]


@pytest.mark.parametrize(
    "state_before, rising, expected",
    [
        # (out before, which inputs rise together, out after) per §11.2 steps 1-3
        (F, ("trigger", "set"), T),  # toggle to T, set T
        (T, ("trigger", "set"), T),  # toggle to F, set T: set beats trigger
        (F, ("trigger", "reset"), F),  # toggle to T, reset F
        (T, ("trigger", "reset"), F),  # toggle to F, reset F
        (F, ("set", "reset"), F),  # reset beats set
        (T, ("set", "reset"), F),
        (F, ("trigger", "set", "reset"), F),
        (T, ("trigger", "set", "reset"), F),
    ],
)
def test_priority_of_edges_in_one_call(state_before, rising, expected):
    s = relay(set=state_before)  # call 0: set TRUE gives out TRUE, FALSE leaves it FALSE
    s.set({"trigger": F, "set": F, "reset": F})
    assert s.step(0.1)["out"] == state_before
    s.set({name: True for name in rising})
    assert s.step(0.1)["out"] == expected
    s.free()


def test_a_step_of_several_calls_sees_one_edge():
    # §1.3: every call of a step sees the same inputs, so trigger TRUE over a step of 3 cycles
    # rises in its first call only: out F -> T once, not T, F, T.
    s = relay()
    s.set({"trigger": T})
    assert s.step(0.3)["out"] == T
    s.set({"trigger": F})
    s.step(0.2)
    s.set({"trigger": T})
    assert s.step(0.4)["out"] == F  # the next edge toggles back
    s.free()


def test_a_state_replays_the_same_outputs():
    s = relay(cycle=0.01)
    pattern = [k % 3 == 0 for k in range(30)]
    for k in range(5):
        s.set({"trigger": pattern[k]})
        s.step(0.01)

    def run():
        s.set({"trigger": pattern[4], "set": F, "reset": F})  # the inputs as they were saved
        outs = []
        for k in range(5, 30):
            s.set({"trigger": pattern[k], "set": k == 17, "reset": k == 23})
            outs.append(s.step(0.01)["out"])
        return outs

    first, again = s.replayed(run)
    assert again == first
    # By hand: calls 1 ... 5 see trigger T F F T F: toggles in calls 1 and 4, so F when saved.
    # From step k = 5 on, trigger rises at k = 6, 9, ..., 27 (k % 3 == 0), set rises at k = 17,
    # reset at k = 23: T at 6, F at 9, T at 12, F at 15, set T at 17, toggle F at 18, T at 21,
    # reset F at 23, T at 24, F at 27.
    expected = [F] + [T] * 3 + [F] * 3 + [T] * 3 + [F] * 2 + [T] + [F] * 3 + [T] * 2 + [F]
    expected += [T] * 3 + [F] * 3
    assert first == expected
    s.free()


@pytest.mark.parametrize("cycle", [0.0, -0.1, 60.5])
def test_cycle_time_outside_its_range_is_refused(cycle):
    s = Slave(BLOCK, initialize=False)
    s.fmu.setupExperiment(startTime=0.0)
    s.fmu.enterInitializationMode()
    assert status_of(s.fmu.setReal, [s.vr("cycleTime")], [cycle]) == fmi2Error
    assert any("cycleTime" in text for _, _, text in s.log)
    s.free()


def test_setting_the_output_is_refused():
    s = relay()
    assert status_of(s.fmu.setBoolean, [s.vr("out")], [True]) == fmi2Error
    assert s.get(["out"])["out"] == F
    s.free()
