"""The S7 IEC timers of src/iec/timer.h (docs/behaviour.md §1.12), which every block that times
something uses: TON, TOF and TP, each executed once per call of a 100 ms cycle, against hand
traces of the rules (PT taken at the starting edge and kept while the timer runs; a negative PT
counts as 0; ET in whole ms, at most PT; a read of Q or ET between executions updates the timer).
tests/c/iec_timers.c executes the timer."""

import shutil
import subprocess

import pytest

from tests.harness import ROOT

CYCLE_US = 100_000


@pytest.fixture(scope="module")
def driver(tmp_path_factory):
    if not shutil.which("cc"):
        pytest.fail("cc is needed to compile tests/c/iec_timers.c")
    program = tmp_path_factory.mktemp("timers") / "iec_timers"
    subprocess.run(
        ["cc", "-std=c11", "-O1", "-Wall", "-Wextra", "-Wpedantic", "-Werror",
         f"-I{ROOT / 'src'}", str(ROOT / "tests/c/iec_timers.c"), "-o", str(program)],
        check=True, capture_output=True, text=True,
    )  # fmt: skip
    return program


def run(driver, kind, ins, pts):
    """(Q, ET in ms) after each call k (at k · 100 ms) with IN ins[k] and PT pts[k] ms."""
    lines = [f"{kind} {k * CYCLE_US} {int(i)} {pt}" for k, (i, pt) in enumerate(zip(ins, pts))]
    out = subprocess.run([str(driver)], input="\n".join(lines) + "\n", capture_output=True,
                         text=True, check=True).stdout  # fmt: skip
    return [(bool(int(q)), int(et)) for q, et in (line.split() for line in out.splitlines())]


F, T = False, True


def test_ton_q_once_in_has_been_true_for_pt(driver):
    ins = [F, T, T, T, T, F, T]
    expected = [(F, 0), (F, 0), (F, 100), (F, 200), (T, 300), (F, 0), (F, 0)]
    assert run(driver, "TON", ins, [300] * 7) == expected


def test_ton_keeps_the_pt_of_its_rising_edge(driver):
    # PT 300 ms at the edge in call 0; from call 1 on PT 100 ms: the running timer still needs
    # 300 ms, the next start takes 100 ms.
    ins = [T, T, T, T, F, T, T]
    pts = [300, 100, 100, 100, 100, 100, 100]
    expected = [(F, 0), (F, 100), (F, 200), (T, 300), (F, 0), (F, 0), (T, 100)]
    assert run(driver, "TON", ins, pts) == expected


def test_ton_with_pt_of_zero_or_less_at_the_edge_is_q_in_that_call(driver):
    assert run(driver, "TON", [T, T], [-500, 300]) == [(T, 0), (T, 0)]
    assert run(driver, "TON", [T], [0]) == [(T, 0)]


def test_tof_q_while_in_and_for_pt_after_it_falls(driver):
    ins = [F, T, T, F, F, F, F, T, F]
    expected = [(F, 0), (T, 0), (T, 0), (T, 0), (T, 100), (F, 200), (F, 200), (T, 0), (T, 0)]
    assert run(driver, "TOF", ins, [200] * 9) == expected


def test_tof_keeps_the_pt_of_its_falling_edge(driver):
    # PT 200 ms when IN falls in call 1; PT 500 ms from call 2 on does not lengthen it.
    ins = [T, F, F, F, F]
    pts = [200, 200, 500, 500, 500]
    assert run(driver, "TOF", ins, pts) == [(T, 0), (T, 0), (T, 100), (F, 200), (F, 200)]


def test_tp_a_pulse_of_pt_that_ignores_edges_during_it(driver):
    ins = [F, T, F, T, T, T, F, T]
    expected = [(F, 0), (T, 0), (T, 100), (T, 200), (F, 300), (F, 300), (F, 0), (T, 0)]
    assert run(driver, "TP", ins, [300] * 8) == expected


def test_tp_keeps_the_pt_of_its_rising_edge_and_zero_gives_no_pulse(driver):
    assert run(driver, "TP", [T, T, T, F], [200, 900, 900, 900]) == [
        (T, 0), (T, 100), (F, 200), (F, 0)
    ]  # fmt: skip
    assert run(driver, "TP", [T, T], [0, 300]) == [(F, 0), (F, 0)]


def script(driver, lines):
    """(Q, ET) after each line "<kind> <ms> <IN> <PT>"; the kinds QTON, QTOF, QTP read the timer
    at that time without executing it (a read of inst.Q / inst.ET)."""
    text = "".join(f"{kind} {ms * 1000} {int(i)} {pt}\n" for kind, ms, i, pt in lines)
    out = subprocess.run([str(driver)], input=text, capture_output=True, text=True,
                         check=True).stdout  # fmt: skip
    return [(bool(int(q)), int(et)) for q, et in (line.split() for line in out.splitlines())]


def test_a_read_of_ton_q_between_executions_sees_the_time_of_the_read(driver):
    # S7-1200 System Manual V4.2 §8.2: reading Q or ET updates the timer. Started at 0 ms with
    # PT 300 ms: a read at 200 ms gives (F, 200), at 300 ms already (T, 300), with no execution
    # since the start; the reads change nothing the next execution sees.
    lines = [("TON", 0, T, 300), ("QTON", 200, F, 0), ("QTON", 300, F, 0), ("TON", 400, T, 300)]
    assert script(driver, lines) == [(F, 0), (F, 200), (T, 300), (T, 300)]


def test_a_read_of_tof_q_ends_the_delay_at_the_time_of_the_read(driver):
    # IN falls at 100 ms with PT 200 ms: Q until 300 ms. Reads at 250 ms and 300 ms.
    lines = [("TOF", 0, T, 200), ("TOF", 100, F, 200), ("QTOF", 250, F, 0), ("QTOF", 300, F, 0)]
    assert script(driver, lines) == [(T, 0), (T, 0), (T, 150), (F, 200)]


def test_a_read_of_tp_q_ends_the_pulse_at_the_time_of_the_read(driver):
    lines = [("TP", 0, T, 300), ("QTP", 100, F, 0), ("QTP", 300, F, 0), ("TP", 400, F, 300)]
    assert script(driver, lines) == [(T, 0), (T, 100), (F, 300), (F, 0)]


def test_a_timer_never_executed_reads_false(driver):
    assert script(driver, [("QTON", 500, T, 0), ("QTOF", 500, T, 0), ("QTP", 500, T, 0)]) == [
        (F, 0), (F, 0), (F, 0)
    ]  # fmt: skip
