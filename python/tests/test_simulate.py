"""simulate(): the demo scenario of every block equals fmpy.simulate_fmu bit for bit, through
every form of inputs; the FMPy pitfalls are gone; bad names and values are refused."""

from __future__ import annotations

import re
from pathlib import Path

import pandas as pd
import pytest
from reference import assert_same, fmpy_run

import lgf_fmus
from lgf_fmus import LgfValueError, SimulationError, simulate
from tests.lgf_blocks import scenarios

# Some demo scenarios drive a block into its status codes, which the FMU logs as warnings.
pytestmark = pytest.mark.filterwarnings("ignore::lgf_fmus.FMUWarning")

SCENARIOS = scenarios()


def steps_of(scenario) -> dict:
    steps: dict = {}
    for time, changes in scenario.inputs:
        for name, value in changes.items():
            steps.setdefault(name, []).append((time, value))
    return steps


BUILT = Path(__file__).resolve().parents[2] / "fmus"


def test_the_bundled_fmus_are_the_built_ones():
    """Every FMU of the build, FMI 2.0 (fmus/<Block>.fmu) and FMI 3.0 (fmus/fmi3/<Block>.fmu),
    is bundled, the same bytes, and the block list is theirs."""
    built = {2: sorted(BUILT.glob("*.fmu")), 3: sorted(BUILT.glob("fmi3/*.fmu"))}
    assert built[2], "make build first"
    assert lgf_fmus.blocks() == sorted({p.stem for p in built[2] + built[3]})
    for version, paths in built.items():
        assert lgf_fmus.blocks(fmi_version=version) == [p.stem for p in paths]
        for path in paths:
            bundled = lgf_fmus.fmu_path(path.stem, fmi_version=version)
            assert bundled.read_bytes() == path.read_bytes(), bundled
    for block in lgf_fmus.blocks(fmi_version=2):
        assert lgf_fmus.fmu_path(block) == lgf_fmus.fmu_path(block, fmi_version=2)


def test_fmu_path_names_what_exists():
    with pytest.raises(LgfValueError, match="bundled blocks are"):
        lgf_fmus.fmu_path("LGF_NoSuchBlock")
    for block in lgf_fmus.blocks():
        if 3 not in lgf_fmus.fmi_versions(block):
            with pytest.raises(LgfValueError, match="no FMI 3.0 FMU"):
                lgf_fmus.fmu_path(block, fmi_version=3)
        else:
            with pytest.raises(LgfValueError, match="simulate and sweep run FMI 2.0 FMUs"):
                simulate(block, 1.0, fmi_version=3)


@pytest.mark.parametrize("scenario", SCENARIOS)
def test_scenario_equals_fmpy(scenario):
    steps = steps_of(scenario)
    reference = fmpy_run(
        scenario.block, scenario.stop_time, scenario.parameters, steps, scenario.output_interval
    )
    result = simulate(
        scenario.block,
        scenario.stop_time,
        scenario.parameters,
        steps,
        output_interval=scenario.output_interval,
        outputs=[n for n in reference if n != "time"],
    )
    assert_same(reference, result, f"{scenario.name}: ")


@pytest.mark.parametrize("scenario", SCENARIOS[:2])
def test_csv_and_dataframe_inputs_are_the_dict(scenario, tmp_path):
    steps = steps_of(scenario)
    kwargs = dict(output_interval=scenario.output_interval)
    expected = simulate(scenario.block, scenario.stop_time, scenario.parameters, steps, **kwargs)
    # one table with a time column, every input given from the first row on
    frame = simulate(
        scenario.block, scenario.stop_time, scenario.parameters, _wide(scenario, steps), **kwargs
    )
    pd.testing.assert_frame_equal(frame, expected)
    csv = tmp_path / "inputs.csv"
    wide = _wide(scenario, steps)
    wide.astype({c: int for c in wide.columns if wide[c].dtype == bool}).to_csv(csv, index=False)
    from_csv = simulate(scenario.block, scenario.stop_time, scenario.parameters, str(csv), **kwargs)
    pd.testing.assert_frame_equal(from_csv, expected)


def _wide(scenario, steps) -> pd.DataFrame:
    md = lgf_fmus.model(scenario.block)
    times = sorted({0.0} | {t for rows in steps.values() for t, _ in rows})
    columns = {"time": times}
    for name, rows in steps.items():
        v = md.variables[name]
        value, column = scenario.parameters.get(name, v.start), []
        for t in times:
            for time, x in rows:
                if time <= t:
                    value = x
            column.append(value)
        columns[name] = column
    return pd.DataFrame(columns)


@pytest.mark.parametrize("block", lgf_fmus.blocks())
def test_one_row_table_and_no_missing_input_warning(block, capfd):
    """FMPy 0.3.32 crashes on a one-row input array and warns of every input without a column;
    here a one-row table holds its value and nothing is printed."""
    md = lgf_fmus.model(block)
    name = md.inputs[0]
    v = md.variables[name]
    value = (not v.start) if v.type == "Boolean" else v.start
    capfd.readouterr()
    result = simulate(block, 2.0, inputs={name: [(0.0, value)]}, output_interval=0.1)
    assert "missing input" not in capfd.readouterr().out
    reference = fmpy_run(block, 2.0, {}, {name: [(0.0, value)]}, 0.1)
    assert_same(reference, result)


@pytest.mark.parametrize("block", lgf_fmus.blocks())
def test_an_input_keeps_its_start_value_until_its_first_row(block):
    md = lgf_fmus.model(block)
    name = next((n for n in md.inputs if md.variables[n].type == "Real"), None)
    if name is None:
        pytest.skip(f"{block} has no Real input")
    later = simulate(block, 2.0, inputs={name: [(1.0, 7.0)]}, output_interval=0.1)
    explicit = simulate(
        block,
        2.0,
        inputs={name: [(0.0, md.variables[name].start), (1.0, 7.0)]},
        output_interval=0.1,
    )
    pd.testing.assert_frame_equal(later, explicit)


def integer_input(md):
    return next((n for n in md.inputs + md.parameters if md.variables[n].type == "Integer"), None)


# The blocks with an Integer parameter or input (LGF_LimRateOfChangeCI has none).
WITH_INTEGERS = [b for b in lgf_fmus.blocks() if integer_input(lgf_fmus.model(b))]


@pytest.mark.parametrize("block", WITH_INTEGERS)
def test_fractional_values_for_integers_are_refused(block):
    md = lgf_fmus.model(block)
    name = integer_input(md)
    v = md.variables[name]
    with pytest.raises(
        LgfValueError,
        match=rf"{name} = 2\.5 is not allowed.*integer in "
        rf"\[{v.min:.10g}, {v.max:.10g}\]",
    ):
        simulate(block, 1.0, {name: 2.5})
    if name in md.inputs:
        with pytest.raises(LgfValueError, match=rf"inputs\['{name}'\] at t = 0\.5: {name} = 1\.25"):
            simulate(block, 1.0, inputs={name: [(0.5, 1.25)]})
    simulate(block, 1.0, {name: float(max(v.min, 2))})  # an integral float is that integer


@pytest.mark.parametrize("block", lgf_fmus.blocks())
def test_bad_names_and_values_name_the_variable_and_its_range(block):
    md = lgf_fmus.model(block)
    with pytest.raises(
        LgfValueError,
        match=r"no parameter or input 'cycletime' \(did you mean "
        r"cycleTime\?\)",
    ):
        simulate(block, 1.0, {"cycletime": 0.1})
    c = md.variables["cycleTime"]
    with pytest.raises(
        LgfValueError,
        match=rf"cycleTime = 100\.0 is out of range: cycleTime takes "
        rf"a number \(not NaN\) in \[{c.min:.10g}, "
        rf"{c.max:.10g}\] s",
    ):
        simulate(block, 1.0, {"cycleTime": 100.0})
    with pytest.raises(LgfValueError, match="cycleTime = nan"):
        simulate(block, 1.0, {"cycleTime": float("nan")})
    output = md.outputs[0]
    with pytest.raises(
        LgfValueError,
        match=rf"{output} is an output \(discrete\), not a parameter "
        rf"or input; the parameters are",
    ):
        simulate(block, 1.0, {output: 1})
    with pytest.raises(LgfValueError, match="no output 'nothing'"):
        simulate(block, 1.0, outputs=["nothing"])
    boolean = next((n for n in md.inputs if md.variables[n].type == "Boolean"), None)
    if boolean is not None:
        with pytest.raises(
            LgfValueError,
            match=rf"{boolean} = 2 is not allowed: {boolean} takes a "
            rf"Boolean",
        ):
            simulate(block, 1.0, inputs={boolean: [(0.0, 2)]})


@pytest.mark.parametrize("block", lgf_fmus.blocks())
def test_an_fmu_error_raises_with_the_fmu_message(block):
    """At t = 1e12 s a double cannot resolve the call grid of the shortest cycleTime: the FMU
    refuses fmi2ExitInitializationMode (docs/behaviour.md §1.3)."""
    shortest = lgf_fmus.model(block).variables["cycleTime"].min
    with pytest.raises(SimulationError, match="cannot resolve the call grid"):
        simulate(block, 1e12 + 1, {"cycleTime": shortest}, start_time=1e12, output_interval=0.5)


def test_fmu_warnings_become_python_warnings():
    block = lgf_fmus.blocks()[0]
    with pytest.warns(lgf_fmus.FMUWarning, match="cycleTime"):
        simulate(block, 1.0, {"cycleTime": 0.0100004}, output_interval=0.1)


@pytest.mark.parametrize("block", [b for b in lgf_fmus.blocks() if lgf_fmus.model(b).tables])
def test_a_table_of_points_sets_its_entries(block, tmp_path):
    md = lgf_fmus.model(block)
    [table] = md.tables.values()
    rows = [(0.0, 1.0), (50.0, 0.5), (20.0, 0.0)]
    entries = {table.count: len(rows)}
    for i, row in enumerate(rows):
        for field, value in zip(table.fields, row):
            entries[f"{table.name}[{i}].{field}"] = value
    start = next(n for n in md.inputs if md.variables[n].type == "Boolean")
    inputs = {n: [(0.0, True)] for n in md.inputs if n == "start"} or {start: [(0.0, True)]}
    reference = fmpy_run(block, 3.0, entries, inputs, 0.1)
    assert_same(reference, simulate(block, 3.0, inputs=inputs, table=rows, output_interval=0.1))
    csv = tmp_path / "table.csv"
    csv.write_text(",".join(table.fields) + "\n" + "\n".join(",".join(map(str, r)) for r in rows))
    assert_same(reference, simulate(block, 3.0, inputs=inputs, table=csv, output_interval=0.1))
    for key in ("table", table.name):
        assert_same(reference, simulate(block, 3.0, {key: rows}, inputs, output_interval=0.1))
    with pytest.raises(LgfValueError, match=rf"table has 1 rows: {block} takes"):
        simulate(block, 1.0, table=[(1.0, 1.0)])
    time_field = f"{table.name}[1].{table.fields[-1]}"
    if md.variables[time_field].min is not None:
        with pytest.raises(
            LgfValueError,
            match=rf"table row 1: {re.escape(time_field)} = -1.0 is "
            rf"out of range",
        ):
            simulate(block, 1.0, table=[(0.0, 1.0), (1.0, -1.0)])


def test_one_hour_of_one_ms_cycles(lgf_block):
    """The benchmark's long run (make bench times it): 3.6 million calls, a sample a second."""
    md = lgf_fmus.model(lgf_block)
    if md.variables["cycleTime"].min > 0.001:
        pytest.skip("cycleTime 1 ms is out of its range")
    result = simulate(lgf_block, 3600.0, {"cycleTime": 0.001}, output_interval=1.0)
    assert len(result) == 3601
    assert result["time"].iloc[-1] == 3600.0


def test_the_package_version_is_the_repository_s():
    assert lgf_fmus.__version__ == (BUILT.parent / "VERSION").read_text().strip()
