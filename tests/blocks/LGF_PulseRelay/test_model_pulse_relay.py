"""Hand traces of the PulseRelay model against docs/behaviour.md §11 (no FMU): `out` after each
call."""

import pytest

from .model import PulseRelay

F, T = False, True


def run(trigger, set_=None, reset=None):
    n = len(trigger)
    set_ = set_ or [F] * n
    reset = reset or [F] * n
    m = PulseRelay(100_000)
    return [
        m.call(k * 100_000, {"trigger": trigger[k], "set": set_[k], "reset": reset[k]})["out"]
        for k in range(n)
    ]


def test_worked_example_of_11_3():
    # §11.3: call 1 toggles to TRUE, call 3 back; call 4 holds trigger (no edge); call 5 sets;
    # call 6 trigger rises (set held): toggles to FALSE; call 7 reset rises; call 9: all rise,
    # reset wins.
    trigger = [F, T, F, T, T, F, T, T, F, T]
    set_ = [F, F, F, F, F, T, T, F, F, T]
    reset = [F, F, F, F, F, F, F, T, F, T]
    assert run(trigger, set_, reset) == [F, T, T, F, F, T, F, F, F, F]


def test_trigger_true_in_call_0_is_a_rising_edge():
    # §11.3: the edge memories start FALSE: out TRUE from call 0, held trigger does nothing more.
    assert run([T, T, T, T]) == [T, T, T, T]


def test_frequency_divider():
    # §11.3: trigger T, F, T, … gives out T, T, F, F, T, T, …
    assert run([T, F] * 4) == [T, T, F, F, T, T, F, F]


def test_priorities_in_one_call():
    # §11.3: reset wins over set and trigger; set over trigger (whatever out was).
    assert run([T], [T], [T]) == [F]
    assert run([F], [T], [T]) == [F]
    assert run([T], [F], [T]) == [F]
    assert run([T], [T], [F]) == [T]
    # out TRUE before: trigger + set rising together -> TRUE (set after the toggle)
    assert run([T, F, T], [F, F, T], [F, F, F]) == [T, T, T]


def test_only_edges_act_held_levels_do_nothing():
    # §11.3: reset held TRUE does not keep out FALSE: a later trigger edge sets it; falling edges
    # do nothing.
    trigger = [F, F, T, F, T]
    reset = [T, T, T, T, F]
    assert run(trigger, None, reset) == [F, F, T, T, F]
    # set held from call 0: acts once; a trigger edge toggles it off while set is held
    assert run([F, F, T, F], [T, T, T, T]) == [T, T, F, F]
    # set falls and rises again: sets again
    assert run([F, T, F, F], [T, F, F, T]) == [T, F, F, T]


def test_cycle_range():
    with pytest.raises(ValueError):
        PulseRelay(0)
    with pytest.raises(ValueError):
        PulseRelay(60_000_001)
