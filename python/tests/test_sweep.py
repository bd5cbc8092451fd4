"""sweep(): every run of random sweeps of every block equals fmpy.simulate_fmu bit for bit
(traces and metrics); the 2-worker LocalCluster gives the in-process result; failing runs are
rows with their parameters and the FMU's message; bad names and values are refused first."""

from __future__ import annotations

import re
import time

import numpy as np
import pandas as pd
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from reference import fmpy_run, identical

import lgf_fmus
from lgf_fmus import LgfValueError, simulate, sweep
from tests.lgf_blocks import blocks

BLOCKS = {b.name: b for b in blocks()}

# FMPy's event search subtracts neighbouring input values: inf - inf warns (the reference's).
pytestmark = pytest.mark.filterwarnings(
    "ignore:invalid value encountered in subtract:RuntimeWarning"
)


@st.composite
def sweeps(draw, block):
    """A sweep of 2-5 runs: a common cycle, step and stop time, and per run the block's spec's
    parameters and step tables of some inputs (rows on and off the output grid)."""
    spec = BLOCKS[block].spec
    cycle = draw(spec.cycles_us) / 1e6
    interval = cycle * draw(st.sampled_from([1, 1, 2, 3]))
    steps = draw(st.integers(3, 40))
    stop = steps * interval
    runs = []
    for _ in range(draw(st.integers(2, 5))):
        run = dict(draw(spec.parameters()))
        for name in draw(st.lists(st.sampled_from(sorted(spec.inputs)), unique=True, max_size=3)):
            rows = []
            for _ in range(draw(st.integers(1, 4))):
                time = draw(
                    st.one_of(
                        st.integers(0, steps).map(lambda k: k * interval),
                        st.floats(0, stop, allow_nan=False),
                    )
                )
                rows.append((time, draw(spec.inputs[name])))
            run[name] = rows
        runs.append(run)
    return cycle, interval, stop, runs


def same_extreme(y, got, arg) -> bool:
    """The metric is the first sample at which the output is smallest (largest), bit for bit:
    so -0.0 where that sample is -0.0 (numpy's own min/max may answer either zero)."""
    return identical(np.float64(y[arg(y)]), np.float64(got))


def check_against_fmpy(block, cycle, interval, stop, runs, result):
    outputs = lgf_fmus.model(block).outputs
    for i, run in enumerate(runs):
        row = result.iloc[i]
        parameters = {
            "cycleTime": cycle,
            **{k: v for k, v in run.items() if not isinstance(v, list)},
        }
        steps = {k: v for k, v in run.items() if isinstance(v, list)}
        reference = fmpy_run(block, stop, parameters, steps, interval, outputs)
        assert row["ok"], row["message"]
        for name, expected in reference.items():
            assert identical(expected, row[name]), f"run {i}: {name}"
        for name in outputs:
            y = reference[name]
            assert identical(np.float64(y[-1]), np.float64(row[f"{name}.final"])), (
                f"run {i}: {name}.final"
            )
            assert same_extreme(y, row[f"{name}.min"], np.argmin), f"run {i}: {name}.min"
            assert same_extreme(y, row[f"{name}.max"], np.argmax), f"run {i}: {name}.max"


@pytest.mark.parametrize("block", sorted(BLOCKS))
@settings(max_examples=8)
@given(data=st.data())
def test_random_sweeps_equal_fmpy(block, data):
    cycle, interval, stop, runs = data.draw(sweeps(block))
    result = sweep(
        block,
        runs,
        stop,
        parameters={"cycleTime": cycle},
        output_interval=interval,
        traces=True,
        workers=0,
        progress=False,
    )
    assert list(result["run"]) == list(range(len(runs)))
    check_against_fmpy(block, cycle, interval, stop, runs, result)


REFERENCE = dict(
    parameters={"cycleTime": 0.01},
    inputs={"value": [(0.0, 0.0), (1.0, 100.0)]},
    output_interval=0.1,
    reach={"delayedValue": [50.0, 95.0]},
    progress=False,
)


def reference_block():
    """The block of the issue's reference sweep (LGF_LimRateOfChangeCI): a block with the
    inputs value and setChangeRate and the output delayedValue."""
    for block in lgf_fmus.blocks():
        md = lgf_fmus.model(block)
        if {"value", "setChangeRate"} <= set(md.inputs) and "delayedValue" in md.outputs:
            return block
    pytest.fail("no bundled block has the reference sweep's variables")


def test_reference_sweep_sample_equals_fmpy():
    block = reference_block()
    rates = np.linspace(0.1, 100, 1000)
    result = sweep(block, {"setChangeRate": rates}, 60.0, ["delayedValue"], workers=0, **REFERENCE)
    assert len(result) == 1000 and result["ok"].all()
    assert identical(result["setChangeRate"].to_numpy(), rates)
    for i in (0, 1, 137, 500, 998, 999):
        y = fmpy_run(
            block,
            60.0,
            {"cycleTime": 0.01, "setChangeRate": rates[i]},
            {"value": [(0.0, 0.0), (1.0, 100.0)]},
            0.1,
            ["delayedValue"],
        )
        t, v = y["time"], y["delayedValue"]
        assert identical(v[-1], result["delayedValue.final"][i])
        assert same_extreme(v, result["delayedValue.max"][i], np.argmax)
        assert same_extreme(v, result["delayedValue.min"][i], np.argmin)
        for threshold in (50.0, 95.0):
            hit = np.flatnonzero(v >= threshold)
            expected = t[hit[0]] if hit.size else np.nan
            assert identical(np.float64(expected), result[f"delayedValue.reach({threshold:g})"][i])


def test_two_worker_local_cluster_equals_in_process(cluster_client):
    block = reference_block()
    runs = {"setChangeRate": np.linspace(0.5, 50, 60), "defaultOutValue": [0.0, 3.0]}
    kwargs = dict(traces=True, chunk_size=7, **REFERENCE)
    here = sweep(block, runs, 10.0, workers=0, **kwargs)
    there = sweep(block, runs, 10.0, client=cluster_client, **kwargs)
    assert len(cluster_client.nthreads()) == 2
    pd.testing.assert_frame_equal(
        here.drop(columns=["time", *lgf_fmus.model(block).outputs]),
        there.drop(columns=["time", *lgf_fmus.model(block).outputs]),
    )
    for column in ["time", *lgf_fmus.model(block).outputs]:
        for a, b in zip(here[column], there[column]):
            assert identical(a, b)
    # a LocalCluster of its own (workers=2) and a scheduler address give the same
    address = cluster_client.scheduler.address
    assert address.startswith("tcp://127.0.0.1:")
    by_address = sweep(block, runs, 10.0, scheduler=address, **{**kwargs, "traces": False})
    pd.testing.assert_frame_equal(
        by_address, here.drop(columns=["time", *lgf_fmus.model(block).outputs])
    )


def test_own_local_cluster(tmp_path):
    block = reference_block()
    runs = {"setChangeRate": np.linspace(1, 20, 20)}
    here = sweep(block, runs, 5.0, workers=0, **REFERENCE)
    try:
        own = sweep(block, runs, 5.0, workers=2, out=tmp_path / "r.parquet", **REFERENCE)
    finally:
        lgf_fmus.sweeps.close_cluster()  # the other tests' processes need the cores
    pd.testing.assert_frame_equal(here, own)
    pd.testing.assert_frame_equal(pd.read_parquet(tmp_path / "r.parquet"), here, check_dtype=False)


@pytest.fixture
def shared():
    """The sweeps module, its shared LocalCluster closed before and after the test (the other
    tests' processes need the cores, whether or not the test passes)."""
    from lgf_fmus import sweeps

    sweeps.close_cluster()
    yield sweeps
    sweeps._close_at_exit()  # also while a failed test's sweep still counts as running


def test_sweeps_share_a_cluster_and_small_ones_run_here(shared, monkeypatch, capsys):
    """Without workers=, a sweep whose steps (PLC calls and samples) are below the cluster's cost
    runs in this process, and the progress line says so; above it, on the LocalCluster the
    sweeps share: the first starts it, the next ones reuse it (then the threshold is
    WARM_STEPS); another number of workers replaces it, and a sweep without workers= uses
    that one too. The results are the same everywhere."""
    sweeps = shared
    block = reference_block()
    runs = {"setChangeRate": np.linspace(1, 20, 20)}
    here = sweep(block, runs, 5.0, workers=0, **REFERENCE)
    # 20 runs of 5 s: 500 calls at 10 ms and 50 samples at 0.1 s each
    work = 20 * (5.0 / 0.01 + 5.0 / 0.1)
    kwargs = {**REFERENCE, "progress": True}

    def swept(**options):
        result = sweep(block, runs, 5.0, **kwargs, **options)
        pd.testing.assert_frame_equal(result, here)
        return capsys.readouterr().err

    capsys.readouterr()
    monkeypatch.setattr(sweeps, "WARM_STEPS", 0)
    monkeypatch.setattr(sweeps, "START_STEPS", work + 1)
    said = swept()
    assert "in this process (20 runs: less work than starting a Dask cluster)" in said
    assert sweeps._shared is None
    monkeypatch.setattr(sweeps, "START_STEPS", work - 1)
    said = swept()
    count = sweeps.default_workers()
    assert f"on Dask ({count} worker thread{'s' if count > 1 else ''})" in said
    first = sweeps._shared
    assert first is not None and first.workers == count and first.users == 0
    monkeypatch.setattr(sweeps, "WARM_STEPS", work + 1)
    said = swept()
    assert "in this process (20 runs: less work than a round trip through the Dask cluster)" in said
    monkeypatch.setattr(sweeps, "WARM_STEPS", work - 1)
    said = swept()
    assert "on Dask" in said and "in this process" not in said
    assert sweeps._shared is first
    # a number of workers runs on Dask whatever the work, on a cluster of that size
    monkeypatch.setattr(sweeps, "WARM_STEPS", 1e18)
    other = 1 if count > 1 else 2
    threads = f"on Dask ({other} worker thread{'s' if other > 1 else ''})"
    said = swept(workers=other)
    assert threads in said
    replaced = sweeps._shared
    assert replaced is not first and first.client.status == "closed"
    assert len(replaced.client.nthreads()) == other
    # ... and a sweep without workers= (on Dask by its work) uses it as it is, of any size
    monkeypatch.setattr(sweeps, "WARM_STEPS", 0)
    said = swept()
    assert threads in said
    assert sweeps._shared is replaced and replaced.client.status == "running"
    sweeps.close_cluster()
    assert sweeps._shared is None


def _held_sweep(tmp_path, **options):
    """A sweep of two runs, a chunk each, whose run setChangeRate=2 waits in its metric
    function until tmp_path/"go" exists (it writes tmp_path/"started" first); the other ends
    at once."""
    go, started = tmp_path / "go", tmp_path / "started"

    def hold(trace):
        import pathlib
        import time

        if trace.run["setChangeRate"] == 2.0:
            pathlib.Path(started).touch()
            for _ in range(1200):  # at most a minute: a test that failed leaves no task behind
                if pathlib.Path(go).exists():
                    break
                time.sleep(0.05)
        return 0.0

    return sweep(
        reference_block(),
        {"setChangeRate": [1.0, 2.0]},
        1.0,
        functions={"held": hold},
        chunk_size=1,
        **{**REFERENCE, **options},
    )


class _Interrupting:
    """A progress bar whose first update raises KeyboardInterrupt, as Ctrl-C while the sweep
    waits for its tasks."""

    def __init__(self, *args, **kwargs):
        self.disable, self.desc = True, kwargs.get("desc", "")

    def update(self, n):
        raise KeyboardInterrupt

    def set_description(self, desc):
        pass

    def close(self):
        pass


def test_an_interrupted_sweep_leaves_no_task_on_a_given_cluster(
    cluster_client, tmp_path, monkeypatch
):
    """A sweep interrupted on a cluster of the caller cancels its tasks, even while the
    traceback (here pytest's) keeps its futures."""
    import tqdm.auto

    monkeypatch.setattr(tqdm.auto, "tqdm", _Interrupting)
    try:
        with pytest.raises(KeyboardInterrupt):
            _held_sweep(tmp_path, client=cluster_client)
        # the cancel goes to the scheduler as a message (Client.cancel does not wait for it)
        deadline = time.monotonic() + 60  # a loaded machine's scheduler takes its time
        while any(cluster_client.processing().values()) and time.monotonic() < deadline:
            time.sleep(0.05)
        assert all(not keys for keys in cluster_client.processing().values())
    finally:
        (tmp_path / "go").touch()  # the chunk that a worker runs ends (cancel cannot stop it)
    monkeypatch.undo()
    assert _held_sweep(tmp_path, client=cluster_client)["ok"].all()


def test_an_interrupted_sweep_closes_the_shared_cluster(shared, tmp_path, monkeypatch):
    """On the shared cluster, a chunk still running when the sweep is interrupted cannot be
    stopped by cancelling it: the sweep closes the cluster, and the next starts another."""
    import tqdm.auto

    monkeypatch.setattr(tqdm.auto, "tqdm", _Interrupting)
    with pytest.raises(KeyboardInterrupt):
        _held_sweep(tmp_path, workers=2)
    assert shared._shared is None
    monkeypatch.undo()
    (tmp_path / "go").touch()
    assert _held_sweep(tmp_path, workers=2)["ok"].all()
    assert shared._shared.users == 0


def test_the_shared_cluster_is_not_closed_under_a_running_sweep(shared, tmp_path, monkeypatch):
    """While a sweep of another thread runs on the shared cluster, close_cluster() and a sweep
    asking for another number of workers are refused, naming the cluster in use; a sweep
    without workers= shares it; once that sweep ends, both work."""
    import threading

    results = {}
    thread = threading.Thread(target=lambda: results.update(r=_held_sweep(tmp_path, workers=2)))
    thread.start()
    try:
        for _ in range(1200):  # until the held chunk runs (at most a minute)
            if (tmp_path / "started").exists() or not thread.is_alive():
                break
            threading.Event().wait(0.05)
        assert (tmp_path / "started").exists()
        in_use = "1 sweep runs on the shared Dask cluster of 2 workers"
        with pytest.raises(RuntimeError, match=f"close_cluster\\(\\): {in_use}"):
            shared.close_cluster()
        with pytest.raises(RuntimeError, match=f"sweep\\(workers=1\\): {in_use}"):
            sweep(reference_block(), {"setChangeRate": [1.0]}, 1.0, workers=1, **REFERENCE)
        cluster = shared._shared
        assert cluster.users == 1
        runs = {"setChangeRate": [1.0, 3.0]}
        on_it = sweep(reference_block(), runs, 1.0, client=cluster.client, **REFERENCE)
        monkeypatch.setattr(shared, "WARM_STEPS", 0)  # on Dask, however small
        pd.testing.assert_frame_equal(sweep(reference_block(), runs, 1.0, **REFERENCE), on_it)
        assert shared._shared is cluster and cluster.users == 1
    finally:
        (tmp_path / "go").touch()
        thread.join()
    assert results["r"]["ok"].all() and cluster.users == 0
    shared.close_cluster()
    assert shared._shared is None and cluster.client.status == "closed"


def test_traces_come_from_the_workers_directly_as_each_chunk_ends(shared, tmp_path):
    """On the shared LocalCluster, whose scheduler runs in this process, a chunk's result
    (its traces) goes from its worker to this process directly, not through the scheduler,
    which would hold a second copy of it here; and it is fetched as soon as the chunk ends,
    while the workers run the others, and then dropped by its worker. The result is the one of
    this process."""
    import threading

    block = reference_block()
    runs = {"setChangeRate": np.linspace(1, 20, 8)}
    here = sweep(block, runs, 5.0, workers=0, traces=True, **REFERENCE)
    there = sweep(block, runs, 5.0, workers=2, traces=True, chunk_size=2, **REFERENCE)
    pd.testing.assert_frame_equal(here, there)
    scheduler = shared._shared.cluster.scheduler
    gathered = []
    handler = scheduler.handlers["gather"]

    def counting(*args, **kwargs):
        gathered.append(kwargs.get("keys"))
        return handler(*args, **kwargs)

    scheduler.handlers["gather"] = counting
    try:
        again = sweep(block, runs, 5.0, workers=2, traces=True, chunk_size=2, **REFERENCE)
        pd.testing.assert_frame_equal(here, again)
        assert gathered == []
        # two chunks: while one is held, the other has ended and its result has been fetched
        # and left its worker (the scheduler forgets the task: only the held one is left)
        thread = threading.Thread(
            target=lambda: again.attrs.update(r=_held_sweep(tmp_path, workers=2, traces=True))
        )
        thread.start()
        try:
            client = shared._shared.client

            def left():
                states = client.run_on_scheduler(
                    lambda dask_scheduler: [t.state for t in dask_scheduler.tasks.values()]
                )
                data = client.run(lambda dask_worker: len(dask_worker.data))
                return states, sum(data.values())

            deadline = time.monotonic() + 60  # a loaded machine's workers take their time
            while time.monotonic() < deadline and left() != (["processing"], 0):
                time.sleep(0.05)
            assert left() == (["processing"], 0)
            assert (tmp_path / "started").exists() and thread.is_alive()
        finally:
            (tmp_path / "go").touch()
            thread.join()
        assert again.attrs["r"]["ok"].all() and gathered == []
    finally:
        scheduler.handlers["gather"] = handler


SCL_COUNTER = """
FUNCTION_BLOCK "Counter"
{ S7_Optimized_Access := 'TRUE' }
   VAR_INPUT
      enable : Bool := TRUE;
   END_VAR
   VAR_OUTPUT
      count : Int;
   END_VAR
BEGIN
    IF #enable THEN
        #count += STEP;
    END_IF;
END_FUNCTION_BLOCK
"""


def test_an_fmu_rebuilt_at_its_path_is_loaded_again(shared, tmp_path):
    """An SCL block compiled again to the same file: simulate() and sweeps in this process and
    on the shared cluster (whose workers outlive the sweep) run the new FMU. The reference is
    the same file copied to a path nothing has seen."""
    import shutil

    source, fmu = tmp_path / "Counter.scl", tmp_path / "Counter.fmu"
    options = dict(parameters={"cycleTime": 0.1}, progress=False)
    finals = {}

    def final(path):
        return int(simulate(str(path), 1.0, parameters={"cycleTime": 0.1})["count"].iloc[-1])

    for step in (1, 5):
        source.write_text(SCL_COUNTER.replace("STEP", str(step)))
        lgf_fmus.compile([source], block="Counter", output=fmu, win64=False)
        fresh = tmp_path / f"fresh{step}" / "Counter.fmu"
        fresh.parent.mkdir()
        shutil.copy(fmu, fresh)
        expected = finals[step] = final(fresh)
        assert final(fmu) == expected
        for workers in (0, 1):
            result = sweep(str(fmu), {"enable": [True]}, 1.0, workers=workers, **options)
            assert result["count.final"][0] == expected, f"step {step}, workers={workers}"
    # a call per cycle, each adding the step
    assert finals[5] == 5 * finals[1] and finals[1] > 0


@pytest.mark.parametrize("block", sorted(BLOCKS))
def test_failing_runs_are_rows_with_their_parameters(block, cluster_client):
    """At t = 1e12 s the shortest cycleTime cannot be resolved: the FMU refuses those runs
    (docs/behaviour.md §1.3); the others run on."""
    shortest = lgf_fmus.model(block).variables["cycleTime"].min
    cycles = [0.1, shortest, 0.5, shortest, 0.25]
    for where in ({"workers": 0}, {"client": cluster_client}):
        result = sweep(
            block,
            {"cycleTime": cycles},
            1e12 + 2.0,
            start_time=1e12,
            output_interval=0.5,
            progress=False,
            chunk_size=2,
            **where,
        )
        assert list(result["ok"]) == [True, False, True, False, True]
        failed = result[~result["ok"]]
        assert list(failed["cycleTime"]) == [shortest, shortest]
        assert all("cannot resolve the call grid" in m for m in failed["message"])
        assert failed.filter(like=".final").isna().all().all()
        assert result[result["ok"]].filter(like=".final").notna().all().all()


def test_bad_names_and_values_are_refused_before_the_sweep():
    block = reference_block()
    md = lgf_fmus.model(block)
    c = md.variables["cycleTime"]
    with pytest.raises(
        LgfValueError,
        match=r"runs: run 2: cycleTime = 0.0 is out of range: "
        r"cycleTime takes a number \(not NaN\) in \[",
    ):
        sweep(block, {"cycleTime": [0.1, 0.2, 0.0]}, 1.0, workers=0, progress=False)
    with pytest.raises(
        LgfValueError,
        match=r"no parameter or input 'setchangerate' \(did you mean "
        r"setChangeRate\?\)",
    ):
        sweep(block, {"setchangerate": [1.0]}, 1.0, workers=0, progress=False)
    with pytest.raises(LgfValueError, match=r"runs: run 1: setChangeRate = nan"):
        sweep(block, pd.DataFrame({"setChangeRate": [1.0, np.nan]}), 1.0, workers=0, progress=False)
    with pytest.raises(LgfValueError, match="unknown metric 'median'"):
        sweep(block, {"setChangeRate": [1.0]}, 1.0, metrics=["median"], workers=0, progress=False)
    with pytest.raises(LgfValueError, match="which inputs= drives with a step table"):
        sweep(
            block, {"value": [1.0]}, 1.0, inputs={"value": [(0.5, 2.0)]}, workers=0, progress=False
        )
    assert c.min > 0


def test_metric_functions_traces_and_parquet(tmp_path):
    block = reference_block()
    seen = []

    def overshoot(trace):
        seen.append(trace.run["setChangeRate"])
        return float(trace["delayedValue"].max() - 100.0)

    def broken(trace):
        if trace.run["setChangeRate"] > 40:
            raise ValueError("too fast")
        return 1

    out = tmp_path / "sweep.parquet"
    result = sweep(
        block,
        [{"setChangeRate": 10.0}, {"setChangeRate": 50.0}],
        5.0,
        ["delayedValue"],
        functions={"overshoot": overshoot, "broken": broken, "after": lambda trace: 2.0},
        traces=True,
        out=out,
        workers=0,
        **REFERENCE,
    )
    assert seen == [10.0, 50.0]
    assert result["overshoot"][0] == result["delayedValue.max"][0] - 100.0
    assert result["overshoot"][1] == 0.0
    assert result["broken"][0] == 1 and np.isnan(result["broken"][1])
    assert list(result["ok"]) == [True, False]
    assert "metric 'broken' raised ValueError: too fast" in result["message"][1]
    # the run itself ran: its other metrics and its traces are kept
    assert list(result["after"]) == [2.0, 2.0]
    assert result["delayedValue.final"][1] == result["delayedValue"][1][-1]
    assert len(result["time"][1]) == len(result["delayedValue"][1]) == 51
    back = pd.read_parquet(out)
    assert list(back.columns) == list(result.columns)
    assert identical(np.asarray(back["delayedValue"][0]), result["delayedValue"][0])
    assert identical(np.asarray(back["time"][0]), result["time"][0])


def test_parquet_holds_the_result_for_runs_of_different_lengths(tmp_path, monkeypatch):
    """The traces go to Parquet as Arrow list columns, a row group at a time: read back, the file
    is the result, for runs of different lengths (each samples at its own cycleTime), a failed
    run (no traces: None) and the Integer and Boolean outputs (their own dtypes)."""
    from lgf_fmus import sweeps

    block = reference_block()
    shortest = lgf_fmus.model(block).variables["cycleTime"].min
    cycles = [0.1, shortest, 0.25, 0.5, 0.1]
    monkeypatch.setattr(sweeps, "GROUP_VALUES", 12)  # rows of one run each (the longest: 11)
    out = tmp_path / "traces.parquet"
    result = sweep(  # at 1e9 s, 1 µs is below the resolution of the call grid: run 1 fails
        block,
        {"cycleTime": cycles},
        1e9 + 2.0,
        start_time=1e9,
        traces=True,
        out=out,
        workers=0,
        progress=False,
    )
    assert list(result["ok"]) == [True, False, True, True, True]
    lengths = [None if t is None else len(t) for t in result["time"]]
    assert lengths[1] is None and len(set(lengths)) == 4 and max(lengths[:1] + lengths[2:]) <= 12
    import pyarrow.parquet as pq

    assert pq.ParquetFile(out).metadata.num_row_groups == len(cycles)
    back = pd.read_parquet(out)
    traces = ["time", *lgf_fmus.model(block).outputs]
    pd.testing.assert_frame_equal(back.drop(columns=traces), result.drop(columns=traces))
    for column in traces:
        for i, (got, expected) in enumerate(zip(back[column], result[column])):
            if expected is None:
                assert got is None, f"run {i}: {column}"
            else:
                assert got.dtype == expected.dtype, f"run {i}: {column}"
                assert identical(got, expected), f"run {i}: {column}"


def test_per_run_tables_and_tables_of_points():
    blocks_with_table = [b for b in lgf_fmus.blocks() if lgf_fmus.model(b).tables]
    for block in blocks_with_table:
        md = lgf_fmus.model(block)
        [table] = md.tables.values()
        inputs = {n: [(0.0, True)] for n in md.inputs if n == "start"}
        runs = [
            {"table": [(0.0, 1.0), (100.0, 0.0)]},
            {"table": [(0.0, 0.5), (10.0, 0.5), (0.0, 0.0)]},
            {},
        ]  # the default table
        result = sweep(
            block,
            runs,
            3.0,
            inputs=inputs,
            output_interval=0.1,
            traces=True,
            workers=0,
            progress=False,
        )
        for i, run in enumerate(runs):
            entries = {}
            if "table" in run:
                entries[table.count] = len(run["table"])
                for k, row in enumerate(run["table"]):
                    for field, value in zip(table.fields, row):
                        entries[f"{table.name}[{k}].{field}"] = value
            reference = fmpy_run(block, 3.0, entries, inputs, 0.1)
            for name, expected in reference.items():
                assert identical(expected, result[name][i]), f"{block} run {i}: {name}"


def _other_value(v):
    """A value of the variable other than its start value, within its range."""
    if v.type == "Boolean":
        return not v.start
    step = 1 if v.type == "Integer" else 0.75
    value = v.start + step
    if v.max is not None and value > v.max:
        value = v.start - step
    return value


@pytest.mark.parametrize("block", lgf_fmus.blocks(fmi_version=2))
def test_every_bundled_block_sweep_equals_fmpy(block):
    """Whatever the block (the bundled ones, with or without a test folder): runs that change
    each input in turn, at the start and by a step table, at two cycle times, equal
    fmpy.simulate_fmu bit for bit."""
    md = lgf_fmus.model(block)
    cycle = md.variables["cycleTime"]
    runs = []
    for cycle_time in (0.01, 0.1):
        if cycle.min is not None and cycle_time < cycle.min:
            continue
        runs.append({"cycleTime": cycle_time})
        for name in md.inputs:
            v = md.variables[name]
            runs.append({"cycleTime": cycle_time, name: [(0.35, _other_value(v)), (1.2, v.start)]})
    result = sweep(block, runs, 2.0, output_interval=0.1, traces=True, workers=0, progress=False)
    assert result["ok"].all(), list(result["message"][~result["ok"]])
    for i, run in enumerate(runs):
        parameters = {"cycleTime": run["cycleTime"]}
        steps = {k: v for k, v in run.items() if k != "cycleTime"}
        reference = fmpy_run(block, 2.0, parameters, steps, 0.1, md.outputs)
        for name, expected in reference.items():
            assert identical(expected, result[name][i]), f"run {i} {run}: {name}"


def uneven_runs(seed=7, n=30):
    """Runs whose step tables put 0 to 5 rows between output points: each such row adds a
    communication point, so the runs have different numbers of samples."""
    rng = np.random.default_rng(seed)
    runs = []
    for _ in range(n):
        times = np.sort(rng.uniform(0.02, 4.9, int(rng.integers(0, 6))))
        rows = [(0.0, 0.0)] + [(float(t), float(rng.uniform(0, 100))) for t in times]
        runs.append({"setChangeRate": float(rng.uniform(1, 60)), "value": rows})
    return runs


def test_metrics_of_a_run_depend_on_that_run_only():
    """A run's metrics are those of its own samples: mean is numpy.mean of them (FMPy's, bit for
    bit), and every metric equals that of the run swept alone, whatever the lengths of the other
    runs in its chunk."""
    block = reference_block()
    outputs = lgf_fmus.model(block).outputs
    runs = uneven_runs()
    kwargs = dict(
        parameters={"cycleTime": 0.01},
        output_interval=0.1,
        progress=False,
        metrics=("final", "min", "max", "mean"),
        reach={"delayedValue": 50.0},
    )
    result = sweep(block, runs, 5.0, workers=0, **kwargs)
    lengths = set()
    for i, run in enumerate(runs):
        y = fmpy_run(
            block,
            5.0,
            {"cycleTime": 0.01, "setChangeRate": run["setChangeRate"]},
            {"value": run["value"]},
            0.1,
            outputs,
        )
        lengths.add(len(y["time"]))
        for name in outputs:
            expected = np.mean(np.asarray(y[name]))
            got = np.float64(result[f"{name}.mean"][i])
            assert identical(expected, got), f"run {i}: {name}.mean {got!r}, not {expected!r}"
        alone = sweep(block, [run], 5.0, workers=0, **kwargs)
        metrics = [
            c
            for c in result.columns
            if c.endswith((".final", ".min", ".max", ".mean")) or ".reach(" in c
        ]
        for column in metrics:
            assert identical(np.float64(alone[column][0]), np.float64(result[column][i])), (
                f"run {i}: {column}"
            )
    assert len(lengths) > 3


def test_metrics_of_failed_runs_are_missing_as_documented(cluster_client):
    """A failed run's metrics: NaN in the float columns (Real outputs, mean, reach), pandas' NA in
    those of Integer and Boolean outputs (Int64 and boolean whatever the runs); isna() finds
    both."""
    block = reference_block()
    md = lgf_fmus.model(block)
    shortest = md.variables["cycleTime"].min
    result = sweep(
        block,
        {"cycleTime": [0.1, shortest]},
        1e12 + 2.0,
        start_time=1e12,
        output_interval=0.5,
        metrics=("final", "min", "max", "mean"),
        reach={"delayedValue": 1.0},
        progress=False,
        workers=0,
    )
    assert list(result["ok"]) == [True, False]
    kinds = {name: md.variables[name].type for name in md.outputs}
    assert {"Real", "Integer", "Boolean"} <= set(kinds.values())
    for name, kind in kinds.items():
        for metric in ("final", "min", "max", "mean"):
            column = result[f"{name}.{metric}"]
            assert column.isna().tolist() == [False, True], column.name
            if metric == "mean" or kind == "Real":
                assert column.dtype == np.float64 and np.isnan(column[1]), column.name
            else:
                assert column.dtype == ("Int64" if kind == "Integer" else "boolean"), column.name
                assert column[1] is pd.NA, column.name
    assert np.isnan(result["delayedValue.reach(1)"][1])


def test_each_run_samples_on_its_own_cycle(cluster_client):
    """Without output_interval, a run samples at its own cycleTime, as simulate() does: its
    samples and the time it reaches 95 are simulate()'s for that cycleTime; output_interval
    still sets one interval for all."""
    block = reference_block()
    step = {"value": [(0.0, 0.0), (1.0, 100.0)]}
    cycles = [0.01, 0.02, 0.05, 0.1, 0.01]
    runs = [{"cycleTime": c} for c in cycles] + [{}]  # the last one: the common cycleTime
    common = {"cycleTime": 0.04, "setChangeRate": 40.0}
    kwargs = dict(
        parameters=common,
        inputs=step,
        reach={"delayedValue": 95.0},
        traces=True,
        metrics=("final", "mean"),
        progress=False,
    )
    here = sweep(block, runs, 5.0, ["delayedValue"], workers=0, **kwargs)
    there = sweep(block, runs, 5.0, ["delayedValue"], client=cluster_client, chunk_size=2, **kwargs)
    for result in (here, there):
        for i, cycle in enumerate(cycles + [0.04]):
            alone = simulate(
                block, 5.0, {**common, "cycleTime": cycle}, step, outputs=["delayedValue"]
            )
            assert identical(alone["time"].to_numpy(), result["time"][i]), f"run {i}"
            y = alone["delayedValue"].to_numpy()
            assert identical(y, result["delayedValue"][i]), f"run {i}"
            t95 = alone["time"][np.flatnonzero(y >= 95.0)[0]]
            assert result["delayedValue.reach(95)"][i] == t95, f"run {i}"
            assert identical(np.mean(y), np.float64(result["delayedValue.mean"][i])), f"run {i}"
    fixed = sweep(block, runs, 5.0, ["delayedValue"], output_interval=0.1, workers=0, **kwargs)
    assert all(len(t) == 51 for t in fixed["time"])


def test_unknown_names_name_their_run():
    """In a list of dicts a name one run gives is checked as that run's, and the error says
    which run, as for bad values."""
    block = reference_block()
    runs = [{"setChangeRate": 1.0}, {"setChangeRate": 2.0}, {"setchangerate": 3.0}]
    with pytest.raises(
        LgfValueError,
        match=r"^runs: run 2: .*has no parameter or input "
        r"'setchangerate' \(did you mean setChangeRate\?\)",
    ):
        sweep(block, runs, 1.0, workers=0, progress=False)
    runs = [{"setChangeRate": 1.0}, {"delayedValue": 2.0}, {}, {"delayedValue": 1.0}]
    with pytest.raises(LgfValueError, match=r"^runs: runs 1 and 3: .*delayedValue is an output"):
        sweep(block, runs, 1.0, workers=0, progress=False)
    runs = [{"value": [(0.0, 1.0)]}, {"value": 2.0}]
    with pytest.raises(
        LgfValueError,
        match=r"^runs: run 1: value is a single value \(2.0\), "
        r"but run 0 gives it a step table",
    ):
        sweep(block, runs, 1.0, workers=0, progress=False)
    with pytest.raises(
        LgfValueError,
        match=r"^runs: run 1: a single value for value, which "
        r"inputs= drives with a step table",
    ):
        sweep(
            block,
            [{}, {"value": 2.0}],
            1.0,
            inputs={"value": [(0.0, 1.0)]},
            workers=0,
            progress=False,
        )
    with pytest.raises(LgfValueError, match=r"^runs: run 1 is a list \(\[2.0\]\), not a dict"):
        sweep(block, [{"setChangeRate": 1.0}, [2.0]], 1.0, workers=0, progress=False)
    # a grid or a DataFrame: a column is in every run
    with pytest.raises(LgfValueError, match=r"^runs: .*no parameter or input 'setchangerate'"):
        sweep(block, {"setchangerate": [1.0, 2.0]}, 1.0, workers=0, progress=False)


@pytest.mark.parametrize(
    "options, says",
    [
        ({"workers": -1}, "workers must be a whole number >= 0"),
        ({"chunk_size": 0}, "chunk_size must be a whole number of runs > 0"),
        ({"reach": {"delayedValue": "high"}}, "reach['delayedValue']: the threshold 'high' is not"),
        ({"reach": ["delayedValue"]}, "reach must be a dict"),
        ({"metrics": 5}, "metrics must be a metric's name or a list of them"),
        ({"parameters": 5}, "parameters must be a dict"),
        ({"outputs": 5}, "outputs must be an output's name or a list of them"),
        ({"out": 5}, "out must be the name of a .parquet or .csv file"),
        ({"scheduler": "nonsense"}, "cannot connect to the scheduler 'nonsense'"),
    ],
    ids=lambda x: str(x) if isinstance(x, dict) else "",
)
def test_options_are_refused_naming_them(options, says):
    with pytest.raises(LgfValueError, match=re.escape(says)):
        sweep(reference_block(), {"setChangeRate": [1.0]}, 1.0, **{"progress": False, **options})


def test_names_as_any_iterable():
    result = sweep(
        reference_block(),
        {"setChangeRate": [1.0]},
        1.0,
        iter(["delayedValue"]),
        metrics={"final"},
        workers=0,
        progress=False,
    )
    assert [c for c in result.columns if "." in c] == ["delayedValue.final"]


def test_runs_from_a_missing_or_broken_csv_are_refused(tmp_path):
    with pytest.raises(LgfValueError, match="runs: no file"):
        sweep(reference_block(), tmp_path / "nowhere.csv", 1.0, workers=0, progress=False)
    broken = tmp_path / "runs.csv"
    broken.write_text('setChangeRate\n"1.0\n')
    with pytest.raises(LgfValueError, match="runs: .*runs.csv cannot be read as CSV"):
        sweep(reference_block(), broken, 1.0, workers=0, progress=False)
