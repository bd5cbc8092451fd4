"""The closed loop of examples/tank (docs/scl.md §3.10 - §3.12): the example's PLC program and
plant compiled, run with FMPy for a few seconds beyond the figures below, which are computed by
hand from the program and the plant, not from a run:

- The plant rises by 100 - 20 = 80 mm/s with the valve open, 0.8 mm per 10 ms step. Start is
  pressed at 0 s: OB1 at 0 s sets AUTO, but OB35 (priority 12) ran before it at 0 s, so the valve
  opens with OB35 at 0.1 s and goes out with OB1 at 0.1 s; the plant rises from its step at
  0.1 s on, level(0.1 s + n * 10 ms) = round(0.8 n). It first exceeds setpoint + hysteresis =
  1050 at n = 1314 (1051.2), at 13.24 s; the controller's input takes it at 13.24 s, OB1's image
  at 13.25 s, and the first OB35 after that, at 13.3 s, closes the valve, out with OB1 at 13.3 s:
  the plant rose until 13.3 s, to 0.8 * 1320 = 1056 mm.
- With the setpoint tuned to 1800 (a setpoint of the global DB, a tunable parameter), the level
  first exceeds alarmHigh = 1500 at n = 1876 (1500.8 -> 1501), 18.86 s; OB1 at 18.87 s starts the
  TON, whose Q is TRUE at OB1 at 18.87 + 2 = 20.87 s: the alarm goes out then, and OB35 at 20.9 s
  closes the valve, at 0.8 * 2080 = 1664 mm.
- TankLoop.ssp, run by FMPy's SSP runner, connects the same FMUs the same way: the same levels."""

from __future__ import annotations

import importlib

import numpy as np
import pytest


@pytest.fixture(scope="module")
def tank(tmp_path_factory):
    # examples/ is a namespace package of the repository's root, where the tests run
    module = importlib.import_module("examples.tank.tank")
    module.built = module.build(tmp_path_factory.mktemp("tank"))
    return module


def changes(out, name, rising):
    values = out[name]
    return [
        out["time"][i]
        for i in range(1, len(values))
        if values[i] != values[i - 1] and values[i] == rising
    ]


def test_the_valve_closes_first_at_the_time_computed_by_hand(tank):
    out = tank.run(tank.built, stop=16.0)
    assert changes(out, "valve", True)[0] == pytest.approx(0.1)
    assert changes(out, "valve", False)[0] == pytest.approx(13.3)
    assert max(out["level"]) == 1056
    assert out["mode"][-1] == 1 and not any(out["alarm"])


def test_the_alarm_of_a_tuned_setpoint_at_the_time_computed_by_hand(tank):
    out = tank.run(tank.built, stop=22.0, settings={"Settings.setpoint": 1800})
    assert changes(out, "alarm", True) == [pytest.approx(20.87)]
    assert changes(out, "valve", False) == [pytest.approx(20.9)]
    assert max(out["level"]) == 1664
    assert out["mode"][-1] == 2


def test_the_ssp_runs_the_same_loop(tank):
    ssp = tank.run_ssp(tank.built["ssp"], stop=16.0)
    out = tank.run(tank.built, stop=16.0)
    n = len(out["level"])
    assert np.array_equal(ssp["plant.level"][:n], np.array(out["level"]))


def test_the_program_fmu_runs_in_the_package_s_simulate(tank):
    """issue 27 item 5: a program's FMU is an FMU like the bundled ones for lgf_fmus.simulate.
    Start pressed at 0 s, the level held at 0 mm: OB35 opens the valve at 0.1 s (the figure of
    the first test) and keeps it open; the settings are its tunable parameters."""
    import lgf_fmus

    out = lgf_fmus.simulate(
        str(tank.built["control"]),
        1.0,
        parameters={"Settings.setpoint": 900},
        inputs={"Start": [(0.0, True), (0.05, False)], "Level": 0},
        output_interval=0.01,
    )
    valve = dict(zip(out["time"].round(2), out["Valve"]))
    assert not valve[0.09] and valve[0.1] and valve[1.0]


def test_the_program_fmu_runs_in_a_sweep(tank):
    """issue 27 item 5: a sweep of the program's FMU, each run its own setpoint (a tunable
    parameter of the global DB), Start pressed at 0 s and the Level tag held at 1000 mm: with
    setpoint 900 the level is above 900 + 50, so the valve stays shut; with 1800 it is below
    1800 - 50, so OB35 opens the valve at 0.1 s, as in the first test."""
    import lgf_fmus

    rows = lgf_fmus.sweep(
        str(tank.built["control"]),
        {"Settings.setpoint": [900, 1800]},
        0.5,
        inputs={"Start": [(0.0, True), (0.05, False)], "Level": 1000},
        output_interval=0.01,
        outputs=["Valve"],
        reach={"Valve": 1},
        workers=0,
        progress=False,
    )
    opened = dict(zip(rows["Settings.setpoint"], rows["Valve.reach(1)"]))
    assert rows["ok"].all()
    assert np.isnan(opened[900]) and opened[1800] == pytest.approx(0.1)


def test_the_closed_loop_meets_its_requirements_in_the_pytest_kit(tank):
    """The package's assertions on the loop of the first test: the level first reaches 1051 mm
    at 13.24 s (n = 1314 steps of 0.8 mm after 0.1 s) and never exceeds 1056 mm."""
    import pandas as pd

    from lgf_fmus.testing import assert_reaches, assert_within

    result = pd.DataFrame(tank.run(tank.built, stop=16.0))
    assert_reaches(result, "level", 1051, by=13.24)
    assert_within(result, "level", low=0, high=1056)
    with pytest.raises(AssertionError):
        assert_reaches(result, "level", 1051, by=13.23)
    with pytest.raises(AssertionError):
        assert_within(result, "level", high=1055)
