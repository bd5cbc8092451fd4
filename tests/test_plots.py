"""The plots an engineer reads (tools/plots.py in the style of python/lgf_fmus/plots.py: the
demo's and the FMU documentation's), on every demo scenario: one lane per shown output and per
input the scenario changes, in that order; Booleans as FALSE/TRUE; status codes as evenly spaced
levels, one per code, labelled 16#xxxx (16#7000, 16#7001 and 16#7002 never on top of each
other); units on the axes (an Integer's from its description: periode [ms]); one-call events
ringed; LGF_RampCI's table points marked; no title cut off at the figure's edges; the families'
legend beside the waves, not on them. A block's default picture (its documentation's typical run
and the overview of the README and of `make demo`: its first scenario) draws no flat line: every
output it draws moves, beside the inputs the run changes."""

from __future__ import annotations

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu

from tests.harness import FMU_DIR
from tests.lgf_blocks import blocks, scenarios
from tools import plots
from tools.simulate import simulate

SCENARIOS = scenarios()
BLOCKS = blocks()


@pytest.fixture(scope="module")
def figures():
    drawn = {}
    for scenario in SCENARIOS:
        result, _, md = simulate(scenario, FMU_DIR, echo=False)
        drawn[scenario.name] = (scenario, result, md, plots.figure(scenario, result, md))
    yield drawn
    import matplotlib.pyplot as plt

    plt.close("all")


# The Integers with a unit: FMI gives an Integer no unit attribute, the description names it
# (docs/behaviour.md §1.4: UDINT, a period in ms).
INTEGER_UNITS = {"periode": "ms"}


def lanes(fig) -> dict:
    return {ax.get_label(): ax for ax in fig.axes}


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_one_lane_per_output_and_changing_input(figures, scenario):
    _, result, md, fig = figures[scenario.name]
    changing, _ = plots.input_histories(scenario, md)
    expected = [v.name for v in plots.shown_outputs(result, md)] + [v.name for v in changing]
    assert [ax.get_label() for ax in fig.axes] == expected
    assert "subFunctionStatus" not in expected
    for name in {n for t, changes in scenario.inputs if t > 0 for n in changes}:
        assert name in expected, f"{name} changes during the run but has no lane"
    assert fig.axes[-1].get_xlabel() == "time [s]"


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_booleans_codes_and_units_are_labelled(figures, scenario):
    _, result, md, fig = figures[scenario.name]
    variables = {v.name: v for v in md.modelVariables}
    for name, ax in lanes(fig).items():
        v = variables[name]
        ticks = [t.get_text() for t in ax.get_yticklabels()]
        if v.type == "Boolean":
            assert ticks == ["FALSE", "TRUE"], name
        elif plots.is_status(v):
            codes = sorted({int(c) for c in result[name]})
            assert ticks == [f"16#{c:04X}" for c in codes], name
            assert list(ax.get_yticks()) == list(range(len(codes))), "one level per code"
        unit = v.unit or INTEGER_UNITS.get(name)
        assert ax.get_ylabel() == name + (f" [{unit}]" if unit else "")


def test_ramp_status_codes_lie_on_separate_levels_and_one_call_events_are_ringed(figures):
    _, result, _, fig = figures["ramp_hold_cyclic"]
    status = lanes(fig)["status"]
    assert [t.get_text() for t in status.get_yticklabels()] == [
        "16#0000",
        "16#7000",
        "16#7001",
        "16#7002",
    ]
    [rings] = [line for line in status.get_lines() if line.get_label() == "one call"]
    ringed = set(np.round(rings.get_xdata(), 6))
    one_call = {
        round(float(t), 6)
        for t, s in zip(result["time"], result["status"])
        if s in (0x7001, 0x7002)
    }
    assert one_call and one_call <= ringed


def test_ramp_table_points_are_marked_where_the_output_sits_on_a_point(figures):
    scenario, result, _, fig = figures["ramp_hold_cyclic"]
    [marks] = [
        line
        for line in lanes(fig)["outputValue"].get_lines()
        if line.get_label() == "table point reached"
    ]
    points = {
        scenario.parameters[f"setpoints[{i}].outputValue"]
        for i in range(scenario.parameters["numberOfSetpoints"])
    }
    assert len(marks.get_xdata()) >= 10
    assert set(marks.get_ydata()) <= points


def test_short_input_pulses_and_one_sample_values_are_found():
    assert list(plots.style.one_call_events([0, 0, 1, 0, 0, 2, 2])) == [2]
    assert list(plots.style.one_call_events([5, 0, 0])) == [0]
    # an input TRUE from 1.0 to 1.1 s (one step of 0.1 s), then FALSE until 5 s
    assert list(plots.style.short_pulses([0.0, 1.0, 1.1, 5.0], [0, 1, 0, 0], 0.1)) == [1]
    assert list(plots.style.short_pulses([0.0, 1.0, 2.0, 5.0], [0, 1, 0, 0], 0.1)) == []


def test_the_signal_generators_period_is_labelled_in_ms(figures):
    *_, fig = figures["cosinus_ci"]
    assert lanes(fig)["periode"].get_ylabel() == "periode [ms]"
    assert lanes(fig)["phaseShift"].get_ylabel() == "phaseShift [ms]"


def within(extent, fig) -> bool:
    return 0 <= extent.x0 and extent.x1 <= fig.bbox.width and extent.y1 <= fig.bbox.height


@pytest.mark.parametrize("name", ["cosinus_ci", "rectangle_ci_phase_beyond_half"])
def test_no_title_is_clipped(figures, name):
    *_, fig = figures[name]
    fig.set_dpi(90)  # as plot_run writes it: text is measured as drawn
    fig.canvas.draw()
    title = fig._suptitle
    assert title is not None and title.get_text().startswith(figures[name][0].title.split()[0])
    assert within(title.get_window_extent(), fig), title.get_text()
    for ax in fig.axes:
        assert within(ax.yaxis.label.get_window_extent(), fig), ax.get_ylabel()


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_every_title_fits_the_figure(figures, scenario):
    *_, fig = figures[scenario.name]
    fig.set_dpi(90)
    fig.canvas.draw()
    if fig._suptitle is not None:
        assert within(fig._suptitle.get_window_extent(), fig), scenario.name


def test_the_families_legend_lies_beside_the_waves():
    runs = []
    for block in ["LGF_SinusCI", "LGF_CosinusCI", "LGF_RectangleCI", "LGF_Frequency"]:
        fmu = str(FMU_DIR / f"{block}.fmu")
        runs.append((block, simulate_fmu(fmu), read_model_description(fmu)))
    fig = plots.families_figure(runs)
    fig.set_dpi(80)  # as families() writes it
    fig.canvas.draw()
    [ax] = fig.axes  # one family: the three signal generators; LGF_Frequency has no kin
    legend = ax.get_legend()
    assert [t.get_text() for t in legend.get_texts()] == [
        "LGF_SinusCI",
        "LGF_CosinusCI",
        "LGF_RectangleCI",
    ]
    box, area = legend.get_window_extent(), ax.get_window_extent()
    assert box.x0 >= area.x1, "the legend overlaps the axes, where the waves are"
    assert within(box, fig)


@pytest.mark.parametrize("block", BLOCKS, ids=[b.name for b in BLOCKS])
def test_the_typical_run_draws_no_flat_line(figures, block):
    scenario, result, md, fig = figures[block.scenarios[0].name]
    drawn = [v.name for v in plots.shown_outputs(result, md)]
    flat = [name for name in drawn if len(np.unique(result[name])) == 1]
    assert not flat, f"{scenario.name}, the default picture, draws {flat} as a flat line"
    changing, _ = plots.input_histories(scenario, md)
    assert changing, f"{scenario.name} changes no input: its picture would show no cause"
    hidden = {v.name for v in md.modelVariables if v.causality == "output"} - set(drawn)
    assert hidden <= {"error", "status", "subFunctionStatus"}, "only quiet diagnostics are hidden"


def test_the_overview_draws_each_block_s_typical_run_with_an_input(figures):
    runs = [figures[b.scenarios[0].name][:3] for b in BLOCKS]
    fig = plots.overview_figure(runs)
    panels = [ax for ax in fig.axes if ax.get_label() in {b.name for b in BLOCKS}]
    assert [ax.get_label() for ax in panels] == [b.name for b in BLOCKS]
    for ax, (scenario, result, md) in zip(panels, runs):
        [line] = ax.get_lines()
        assert len(np.unique(line.get_ydata())) > 1, f"{scenario.block}: a flat line"
        assert ax.get_title(loc="left") == f"{scenario.block}.fmu: {scenario.name}"
    inputs = [ax for ax in fig.axes if ax not in panels]
    assert len(inputs) == len(panels), "each panel draws an input beside its output"
    for ax, (scenario, _, md) in zip(inputs, runs):
        assert ax.get_label() == plots.main_input(scenario, md)[0].name
        assert len(ax.get_lines()) == 1
    assert plots.main_input(figures["store_min_max"][0], figures["store_min_max"][2])[0].name == (
        "value"
    ), "a number rather than a Boolean (reset)"
