"""The command line end to end, as a user runs it: python -m lgf_fmus list | simulate | sweep."""

from __future__ import annotations

import subprocess
import sys

import numpy as np
import pandas as pd
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


def test_list():
    out = cli("list").stdout
    assert [line.split()[0] for line in out.splitlines()] == lgf_fmus.blocks()
    block = lgf_fmus.blocks()[0]
    detail = cli("list", "--variables", block).stdout
    for name in lgf_fmus.model(block).outputs + ["cycleTime"]:
        assert name in detail


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
        assert identical(expected.astype(np.float64), result[column].to_numpy(dtype=np.float64)), (
            column
        )


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
