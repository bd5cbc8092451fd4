"""The command line end to end, as a user runs it: python -m lgf_fmus list | simulate | sweep."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pandas as pd
import pytest
from reference import fmpy_run, identical

import lgf_fmus
from tests.timeouts import hang_guard


def cli(*args, cwd=None, check=True):
    done = subprocess.run(
        [sys.executable, "-m", "lgf_fmus", *map(str, args)],
        cwd=cwd,
        capture_output=True,
        text=True,
        timeout=hang_guard(300),
    )
    if check:
        assert done.returncode == 0, done.stderr
    return done


def test_list(tmp_path):
    out = cli("list").stdout
    assert [line.split()[0] for line in out.splitlines()] == lgf_fmus.blocks()
    block = lgf_fmus.blocks()[0]
    detail = cli("list", "--variables", block).stdout
    for name in lgf_fmus.model(block).outputs + ["cycleTime"]:
        assert name in detail
    # an FMU by its path, as simulate takes it (a copy outside the package, FMI 3.0)
    copy = tmp_path / "Copy.fmu"
    copy.write_bytes(lgf_fmus.fmu_path(block, 3).read_bytes())
    by_path = cli("list", "--variables", copy).stdout.splitlines()
    assert by_path[0] == f"{block}  FMI 3.0  {copy}"
    # the FMI 3.0 types listed by the FMI 2.0 kind that holds them: the same variables
    assert [line.split()[:3] for line in by_path[1:]] == [
        line.split()[:3] for line in detail.splitlines()[1:]
    ]


def test_simulate_csv_and_plot(tmp_path):
    block = lgf_fmus.blocks()[0]
    md = lgf_fmus.model(block)
    name = next(n for n in md.inputs if md.variables[n].type == "Real")
    out, png = tmp_path / "run.csv", tmp_path / "run.png"
    cli(
        "simulate",
        block,
        "--stop-time",
        3,
        "-p",
        "cycleTime=0.01",
        "-i",
        f"{name}=0:0,1:5",
        "--output-interval",
        0.1,
        "--out",
        out,
        "--plot",
        png,
    )
    assert png.stat().st_size > 1000
    result = pd.read_csv(out)
    reference = fmpy_run(block, 3.0, {"cycleTime": 0.01}, {name: [(0.0, 0.0), (1.0, 5.0)]}, 0.1)
    for column, expected in reference.items():
        got = result[column].to_numpy(dtype=np.float64)
        assert identical(expected.astype(np.float64), got), column


def test_simulate_refuses_bad_values():
    block = lgf_fmus.blocks()[0]
    done = cli("simulate", block, "-p", "cycleTime=100", check=False)
    assert done.returncode == 2
    assert "cycleTime = 100.0 is out of range" in done.stderr


def test_sweep_spec(tmp_path):
    block = next(b for b in lgf_fmus.blocks() if "setChangeRate" in lgf_fmus.model(b).inputs)
    spec = tmp_path / "spec.toml"
    spec.write_text(f'''
block = "{block}"
stop_time = 10.0
output_interval = 0.1
outputs = ["delayedValue"]

[parameters]
cycleTime = 0.01

[inputs]
value = [[0.0, 0.0], [1.0, 100.0]]

[runs]
setChangeRate = {{ start = 10.0, stop = 100.0, num = 10 }}
defaultOutValue = [0.0, 1.0]

[reach]
delayedValue = 95.0
''')
    out = tmp_path / "results.parquet"
    done = cli("sweep", spec, "--workers", 1, "--out", out, "--no-progress")
    assert "20 runs, 0 failed" in done.stdout
    result = pd.read_parquet(out)
    expected = lgf_fmus.sweep(
        block,
        {"setChangeRate": np.linspace(10, 100, 10), "defaultOutValue": [0.0, 1.0]},
        10.0,
        ["delayedValue"],
        parameters={"cycleTime": 0.01},
        inputs={"value": [(0.0, 0.0), (1.0, 100.0)]},
        output_interval=0.1,
        reach={"delayedValue": 95.0},
        workers=0,
        progress=False,
    )
    pd.testing.assert_frame_equal(result, expected, check_dtype=False)
    # in process, written as CSV
    cli("sweep", spec, "--workers", 0, "--out", tmp_path / "r.csv", "--no-progress")
    assert len(pd.read_csv(tmp_path / "r.csv")) == 20


def test_sweep_spec_errors_name_the_problem(tmp_path):
    spec = tmp_path / "bad.toml"
    block = lgf_fmus.blocks()[0]
    spec.write_text(f'block = "{block}"\nstop_time = 1.0\n[runs]\ncycleTime = [0.1, -1.0]\n')
    done = cli("sweep", spec, "--workers", 0, check=False)
    assert done.returncode == 2
    assert "run 1: cycleTime = -1.0 is out of range" in done.stderr
    spec.write_text(f'block = "{block}"\nstoptime = 1.0\n[runs]\ncycleTime = [0.1]\n')
    assert "unknown keys stoptime" in cli("sweep", spec, check=False).stderr


def reference_block():
    return next(b for b in lgf_fmus.blocks() if "setChangeRate" in lgf_fmus.model(b).inputs)


def table_block():
    return next(b for b in lgf_fmus.blocks(fmi_version=2) if lgf_fmus.model(b).tables)


SPEC = """block = "BLOCK"
stop_time = 1.0
outputs = ["delayedValue"]
[parameters]
cycleTime = 0.1
[runs]
setChangeRate = [1.0, 2.0]
"""
TOP = 'outputs = ["delayedValue"]'  # top-level keys go after it, before the tables
GRID = "[runs]\nsetChangeRate = [1.0, 2.0]\n"
PARAMETERS = "[parameters]\ncycleTime = 0.1\n"


def top(line):
    """An edit of SPEC: one more top-level key."""
    return [(TOP, f"{TOP}\n{line}")]


# (what, the spec's text or edits [(old, new), ...] of SPEC, what the error line says)
BAD_SPECS = [
    ("broken TOML", "[runs\nx = 1\n", "is not valid TOML: Expected ']'"),
    ("not UTF-8", b'block = "\xff"\n', "is not valid TOML"),
    (
        "parameters a number",
        [(PARAMETERS, "")] + top("parameters = 5"),
        "the spec's parameters must be a table",
    ),
    ("inputs a number", top("inputs = 5"), "the spec's inputs must be a table"),
    ("an input row", top("inputs = { value = [[0.0]] }"), "a row is (time, value)"),
    (
        "an input row a number",
        top("inputs = { value = [0.0, 1.0] }"),
        "a row is (time, value), not 0.0",
    ),
    (
        "a range of text",
        [("[1.0, 2.0]", '{ start = "a", stop = 2.0, num = 3 }')],
        "runs.setChangeRate: a range's start, stop and num",
    ),
    (
        "a negative num",
        [("[1.0, 2.0]", "{ start = 1.0, stop = 2.0, num = -3 }")],
        "runs.setChangeRate: a range's start, stop and num",
    ),
    ("a range without num", [("[1.0, 2.0]", "{ start = 1.0, stop = 2.0 }")], "missing 'num'"),
    ("runs a number", [(GRID, "")] + top("runs = 5"), "the spec's runs must be a table"),
    ("runs a missing CSV", [(GRID, "")] + top('runs = "nowhere.csv"'), "runs: no file"),
    (
        "a threshold of text",
        top('reach = { delayedValue = "high" }'),
        "the threshold 'high' is not a number",
    ),
    ("metrics a number", top("metrics = 5"), "the spec's metrics must be"),
    ("an unknown metric", top('metrics = ["median"]'), "unknown metric 'median'"),
    ("outputs a number", [(TOP, "outputs = 5")], "the spec's outputs must be"),
    ("chunk_size zero", top("chunk_size = 0"), "chunk_size must be"),
    ("stop_time text", [("stop_time = 1.0", 'stop_time = "long"')], "stop_time must be"),
    ("traces text", top('traces = "yes"'), "the spec's traces must be"),
    ("block a number", [('block = "BLOCK"', "block = 5")], "the spec's block must be"),
]


def one_error_line(capsys, argv) -> str:
    """main(argv) as the CLI runs it: exit status 2 and one line `error: ...` on stderr."""
    from lgf_fmus.cli import main

    assert main([str(a) for a in argv]) == 2
    captured = capsys.readouterr()
    lines = captured.err.splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: "), captured.err
    assert captured.out == ""
    return lines[0]


@pytest.mark.parametrize("what, spec, says", BAD_SPECS, ids=[c[0] for c in BAD_SPECS])
def test_a_broken_spec_is_one_error_line(tmp_path, capsys, what, spec, says):
    path = tmp_path / "spec.toml"
    if isinstance(spec, list):
        text = SPEC
        for old, new in spec:
            assert old in text
            text = text.replace(old, new)
        path.write_text(text.replace("BLOCK", reference_block()))
    else:
        path.write_bytes(spec if isinstance(spec, bytes) else spec.encode())
    line = one_error_line(capsys, ["sweep", path, "--workers", 0, "--no-progress"])
    assert says in line


def test_a_missing_spec_is_one_error_line(tmp_path, capsys):
    line = one_error_line(capsys, ["sweep", tmp_path / "nowhere.toml", "--workers", 0])
    assert line.startswith("error: ") and "nowhere.toml" in line and "No such file" in line
    line = one_error_line(capsys, ["sweep", tmp_path, "--workers", 0])
    assert str(tmp_path) in line


BAD_ARGUMENTS = [
    (["-p", "cycleTime=abc"], "-p/--parameter: 'cycleTime=abc': 'abc' is not a number"),
    (["-p", "cycleTime"], "-p/--parameter: 'cycleTime': expected NAME=VALUE"),
    (["-p", "cycleTime="], "'' is not a number"),
    (["-i", "value=0:x"], "-i/--input: 'value=0:x': 'x' is not a number"),
    (["-i", "value=01"], "-i/--input: 'value=01': '01' is not T:V"),
    (["-i", "value=0:1,"], "'' is not T:V"),
    (["-i", "value"], "-i/--input: 'value': expected NAME=T:V,T:V,..."),
    (["--stop-time", "abc"], "--stop-time: invalid float value: 'abc'"),
    (["--workers", "2"], "unrecognized arguments: --workers 2"),
    (["--plot", "run.nope"], "--plot run.nope: matplotlib writes"),
    (["--inputs", "nowhere.csv"], "no file nowhere.csv"),
]


@pytest.mark.parametrize(
    "arguments, says", BAD_ARGUMENTS, ids=[" ".join(a) for a, _ in BAD_ARGUMENTS]
)
def test_bad_simulate_arguments_are_one_error_line(capsys, arguments, says):
    line = one_error_line(capsys, ["simulate", reference_block(), *arguments])
    assert says in line


def test_an_output_file_is_checked_before_the_run(tmp_path, capsys):
    """--out and --plot in a folder that does not exist (none is made), or on a folder: one
    error line before the run, so nothing reaches stdout and nothing is written."""
    block = reference_block()
    missing = tmp_path / "missing"
    for option, name in (("--out", "run.csv"), ("--plot", "run.png")):
        line = one_error_line(capsys, ["simulate", block, option, missing / name])
        assert f"{option} {missing / name}: the folder {missing} does not exist" in line
        line = one_error_line(capsys, ["simulate", block, option, tmp_path])
        assert f"{option} {tmp_path}: a folder, not a file" in line
    assert not missing.exists()


def test_bad_tables_and_commands_are_one_error_line(tmp_path, capsys):
    block = table_block()
    assert "--table: '0:2,100': '100' is not V:T" in one_error_line(
        capsys, ["simulate", block, "--table", "0:2,100"]
    )
    assert "'x' is not a number" in one_error_line(capsys, ["simulate", block, "--table", "0:x"])
    assert "table: no file" in one_error_line(capsys, ["simulate", block, "--table", "no.csv"])
    broken = tmp_path / "broken.csv"
    broken.write_bytes(b'outputValue,time\n\xff\xfe,"1\n')
    assert "broken.csv" in one_error_line(capsys, ["simulate", block, "--table", broken])
    assert "invalid choice: 'simulat'" in one_error_line(capsys, ["simulat", block])
    assert "required: block" in one_error_line(capsys, ["simulate"])
    assert "--workers: invalid int value" in one_error_line(
        capsys, ["sweep", "s.toml", "--workers", "x"]
    )


def test_an_inputs_csv_whose_time_goes_back_is_one_error_line(tmp_path, capsys):
    """Rows out of time order are a mistake in the table, refused like any other malformed CSV
    (equal times are allowed: the last row wins)."""
    block = reference_block()
    table = tmp_path / "back.csv"
    table.write_text("time,value\n0,1\n0.5,2\n0.5,3\n0.3,4\n")
    line = one_error_line(capsys, ["simulate", block, "--inputs", table])
    assert "the time goes back from 0.5 to 0.3 at data row 4" in line
    table.write_text("time,value\n0,1\n0.5,2\n0.5,3\n")
    assert cli("simulate", block, "--inputs", table, check=False).returncode == 0


def test_bad_input_from_the_shell_is_one_error_line(tmp_path):
    """The same through `python -m lgf_fmus`: status 2, one line on stderr, no traceback."""
    block = reference_block()
    broken = tmp_path / "spec.toml"
    broken.write_text("[runs\n")
    for args in (
        ["simulate", block, "-p", "cycleTime=abc"],
        ["simulate", block, "-i", "value=1"],
        ["sweep", tmp_path / "nowhere.toml"],
        ["sweep", broken],
        ["simulate", block, "-p", "cycleTime"],
    ):
        done = cli(*args, check=False)
        assert done.returncode == 2, done.stderr
        assert len(done.stderr.splitlines()) == 1 and done.stderr.startswith("error: "), done.stderr
