"""`python -m lgf_fmus simulate ... --plot run.png` in the demo's style (lgf_fmus.plots), read from
the matplotlib figure the command draws: a panel of outputs and one of the inputs the run
changes, units on the axes, status codes as 16#xxxx levels, Booleans (and every signal) as
steps, the start values listed under the title."""

from __future__ import annotations

from types import SimpleNamespace

import pytest

from lgf_fmus import cli, plots


@pytest.fixture
def drawn(monkeypatch, tmp_path):
    """Runs the command line in this process and returns the figure --plot wrote (and its
    file)."""
    figures = []

    def keep(*args, **kwargs):
        figures.append(plot_figure(*args, **kwargs))
        return figures[-1]

    plot_figure = cli.plot_figure
    monkeypatch.setattr(cli, "plot_figure", keep)

    def run(*args):
        png = tmp_path / "run.png"
        argv = ["simulate", *map(str, args), "--out", tmp_path / "run.csv", "--plot", png]
        assert cli.main([str(a) for a in argv]) == 0
        assert png.stat().st_size > 1000
        [fig] = figures[-1:]
        return {ax.get_label(): ax for ax in fig.axes}, fig

    return run


def steps(ax):
    """The lane's signal: its first line, which must be drawn as steps held from each sample."""
    line = ax.get_lines()[0]
    assert line.get_drawstyle() == "steps-post", ax.get_label()
    return list(line.get_xdata()), [float(y) for y in line.get_ydata()]


def ticks(ax) -> list[str]:
    return [t.get_text() for t in ax.get_yticklabels()]


# The README's run: a table of 4 points, started at t = 1 s.
RAMP = ["LGF_RampCI", "--stop-time", 12, "--table", "0:2,100:3,100:2,0:0", "-i", "start=0:0,1:1"]


def test_ramp_outputs_and_inputs_in_panels_with_units_hex_status_and_steps(drawn):
    lanes, fig = drawn(*RAMP)
    outputs = ["outputValue", "actTimeTable", "stepNumber", "remainTime", "totalTime"]
    outputs += ["remainTotalTime", "status"]  # not subFunctionStatus: always 0
    assert list(lanes) == outputs + ["start"]
    assert lanes["outputValue"].get_title(loc="left") == "outputs"
    assert lanes["start"].get_title(loc="left") == "inputs"
    assert [ax.get_title(loc="left") for ax in fig.axes].count("") == len(outputs) - 1
    labels = {name: ax.get_ylabel() for name, ax in lanes.items()}
    assert labels == {
        "outputValue": "outputValue",
        "actTimeTable": "actTimeTable",
        "stepNumber": "stepNumber",
        "remainTime": "remainTime [s]",
        "totalTime": "totalTime [s]",
        "remainTotalTime": "remainTotalTime [s]",
        "status": "status",
        "start": "start",
    }
    assert fig.axes[-1].get_xlabel() == "time [s]"
    # idle 16#7000 until the start, 16#7001 in the start's call, 0 at the end of the curve
    assert ticks(lanes["status"]) == ["16#0000", "16#7000", "16#7001"]
    for name in ("actTimeTable", "start"):
        assert ticks(lanes[name]) == ["FALSE", "TRUE"]
    assert steps(lanes["start"]) == ([0.0, 1.0, 12.0], [0.0, 1.0, 1.0])
    times, values = steps(lanes["actTimeTable"])
    assert set(values) == {0.0, 1.0} and times[0] == 0.0 and times[-1] == 12.0
    for name in outputs:
        steps(lanes[name])
    title = fig._suptitle.get_text().replace("\n", " ").replace("\u00a0", " ")
    assert title.startswith("LGF_RampCI held from t = 0: numberOfSetpoints = 4")
    assert "setpoints = (0, 2 s), (100, 3 s), (100, 2 s), (0, 0 s)" in title


def test_the_period_is_in_ms_and_held_inputs_are_listed(drawn, tmp_path):
    csv = tmp_path / "inputs.csv"
    # amplitude is the same in every row: held, listed; reset changes: a lane
    csv.write_text("time,amplitude,reset\n0,1.5,0\n2,1.5,1\n2.5,1.5,0\n")
    lanes, fig = drawn("LGF_CosinusCI", "--stop-time", 4, "-p", "periode=500", "--inputs", csv)
    assert list(lanes) == ["value", "reset"]  # not status: 16#0000 throughout, nothing to see
    assert steps(lanes["reset"]) == ([0.0, 2.0, 2.5, 4.0], [0.0, 1.0, 0.0, 0.0])
    title = fig._suptitle.get_text().replace("\n", " ").replace("\u00a0", " ")
    assert title == "LGF_CosinusCI held from t = 0: periode = 500 ms, amplitude = 1.5"

    lanes, _ = drawn("LGF_CosinusCI", "--stop-time", 4, "-i", "periode=0:1000,2:500")
    assert lanes["periode"].get_ylabel() == "periode [ms]"
    assert steps(lanes["periode"]) == ([0.0, 2.0, 4.0], [1000.0, 500.0, 500.0])


def test_outputs_asked_for_are_all_shown(drawn):
    lanes, _ = drawn("LGF_CosinusCI", "--outputs", "status,subFunctionStatus")
    assert list(lanes) == ["status", "subFunctionStatus"]
    assert ticks(lanes["subFunctionStatus"]) == ["16#0000"]


def variable(name, type_, description="", unit=None):
    return SimpleNamespace(name=name, type=type_, description=description, unit=unit)


def test_status_codes_and_units_from_the_description():
    assert plots.is_status(variable("status", "Integer", "WORD: 0 = 16#0000 no error"))
    assert plots.is_status(variable("flags", "Integer", "DWORD: bits of an SCL block"))
    assert plots.is_status(variable("status", "Integer"))  # a status without a description
    assert not plots.is_status(variable("stepNumber", "Integer", "INT: number of the point"))
    assert not plots.is_status(variable("status", "Real", "WORD: not an Integer"))
    assert plots.label(variable("periode", "Integer", "UDINT: period in ms; 0 refused")) == (
        "periode [ms]"
    )
    assert plots.label(variable("noOfEdges", "Integer", "number of edges in the time")) == (
        "noOfEdges"
    )
    assert plots.label(variable("rate", "Real", "in ms, but the unit says", "1/s")) == "rate [1/s]"
    assert plots.label(variable("x", "Integer", "count in msec")) == "x"


def test_input_rows_at_or_after_the_stop_time_are_left_out():
    """`-i value=5:1` with --stop-time 2: the row never applies, so value keeps its start value
    (no lane, nothing held); a row before the stop is held to the stop."""
    import lgf_fmus

    variables = lgf_fmus.model("LGF_LimRateOfChangeCI").variables
    start_value = variables["value"].start
    changing, held = plots.input_histories({"value": [(5.0, 1.0)]}, variables, 0.0, 2.0)
    assert changing == {} and held == {}
    changing, held = plots.input_histories(
        {"value": [(1.0, start_value + 3), (2.0, 7.0), (5.0, 9.0)]}, variables, 0.0, 2.0
    )
    [(variable, history)] = changing.items()
    assert variable.name == "value" and held == {}
    assert history == ([0.0, 1.0, 2.0], [start_value, start_value + 3, start_value + 3])


def test_a_lane_keeps_its_scale_when_values_reach_lreal_max():
    """StoreMinMax outputs ±LREAL max (1.7976931348623157e308) in a reset call: the lane is
    scaled to the other values (2 … 5, with 15 % margins), the line leaves it at the edge, and
    nothing overflows (warnings are errors here)."""
    import warnings

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import numpy as np

    variable = SimpleNamespace(type="Real", name="minValue", unit=None, description="")
    figure, ax = plt.subplots()
    values = [1.7976931348623157e308, 3.0, 2.0, -1.7976931348623157e308, 5.0, float("inf")]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        plots.lane(ax, variable, np.arange(6) * 0.1, values, "C0")
        figure.canvas.draw()
    assert ax.get_ylim() == pytest.approx((2.0 - 0.45, 5.0 + 0.45))
    plt.close(figure)
