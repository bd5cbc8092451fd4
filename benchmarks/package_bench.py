"""Prints what the lgf_fmus package gains over a naive FMPy loop (run by `make bench` after the C
benchmark; the package must be installed, as `make package` does):

  reference sweep   1000 runs of the block with the inputs value and setChangeRate
                    (LGF_LimRateOfChangeCI): setChangeRate from 0.1 to 100, a step of value
                    0 -> 100 at t = 1 s, 60 s at cycleTime 10 ms, outputs every 0.1 s; the
                    metrics final/min/max of delayedValue and the time to reach 95
    naive           fmpy.simulate_fmu once per run
    in process      lgf_fmus.sweep(workers=0): the native runner, no Dask
    1 / 2 workers   lgf_fmus.sweep on a LocalCluster of 1 and 2 worker processes (both started
                    first, the start printed apart, and warmed up by one sweep; then their
                    sweeps alternate, so that a passing load on a shared machine meets both)
  large sweep       the same with 20 times as many runs (setChangeRate in steps 20 times finer),
                    where the fixed cost of a sweep on Dask (scheduling, transfers) is spread
  long run          lgf_fmus.simulate: 1 h of 1 ms cycles with outputs every second, per block
  sweeps that scale the reference sweep with --trace-runs runs and traces=True: writing them to
                    Parquet against the sweep (and against the former way, lists through
                    pandas, on a tenth of the runs; peak memory by tracemalloc, which sees
                    Python's and numpy's allocations); the README's sweep without workers= (in
                    this process by the work rule) against the same on a LocalCluster started
                    for it and on the shared one running; the traces over Dask (2 workers)
                    against in this process, time and peak of traced memory in this process

Every figure is the best of --repeats runs on this machine, now (it may be shared and loaded:
the load average is printed); all ratios are taken from figures of this one run. The results of
every strategy are checked to be identical. A benchmark, not a test: it prints and never fails
on speed.

    .venv/bin/python -m benchmarks.package_bench [--naive-runs 1000] [--repeats 5]
        [--trace-runs 10000]
"""

from __future__ import annotations

import argparse
import contextlib
import io
import os
import tempfile
import time
import tracemalloc
from pathlib import Path

import numpy as np

GOALS = {"per_worker": 5000.0, "vs_naive": 150.0, "scaling": 1.7, "long_run_s": 0.15}


def load() -> str:
    try:
        return " ".join(f"{x:.2f}" for x in os.getloadavg())
    except OSError:
        return "?"


def reference_block(lgf_fmus) -> str:
    for block in lgf_fmus.blocks():
        md = lgf_fmus.model(block)
        if {"value", "setChangeRate"} <= set(md.inputs) and "delayedValue" in md.outputs:
            return block
    raise SystemExit("no bundled block has the inputs value and setChangeRate")


COMMON = dict(
    parameters={"cycleTime": 0.01},
    inputs={"value": [(0.0, 0.0), (1.0, 100.0)]},
    output_interval=0.1,
    reach={"delayedValue": 95.0},
    progress=False,
)


def naive(block, fmu, rates) -> tuple[float, list]:
    from fmpy import simulate_fmu

    signals = np.array(
        [(0.0, 0.0), (1.0, 100.0), (60.0, 100.0)],
        dtype=[("time", np.float64), ("value", np.float64)],
    )
    finals = []
    began = time.perf_counter()
    # FMPy prints a warning for every input without a column: kept out of the figures' output
    with contextlib.redirect_stdout(io.StringIO()):
        for rate in rates:
            result = simulate_fmu(
                str(fmu),
                stop_time=60.0,
                output_interval=0.1,
                start_values={"cycleTime": 0.01, "setChangeRate": float(rate)},
                input=signals,
                output=["delayedValue"],
            )
            finals.append(result["delayedValue"][-1])
    return time.perf_counter() - began, finals


def lists_to_parquet(result, out):
    """The former writing of sweep(out=...): every array a Python list, then pandas."""
    frame = result.copy()
    for column in frame.columns:
        if frame[column].dtype == object:
            frame[column] = [x.tolist() if isinstance(x, np.ndarray) else x for x in frame[column]]
    frame.to_parquet(out, index=False)


def peak(function):
    """Seconds and the peak of traced memory (MB) of one call."""
    tracemalloc.start()
    began = time.perf_counter()
    try:
        function()
        return time.perf_counter() - began, tracemalloc.get_traced_memory()[1] / 1e6
    finally:
        tracemalloc.stop()


def scaling(lgf_fmus, block, rates, trace_runs: int, repeats: int):
    from lgf_fmus import sweeps

    sweep = lambda runs, **kw: lgf_fmus.sweep(
        block, {"setChangeRate": runs}, 60.0, ["delayedValue"], **COMMON, **kw
    )
    many = np.linspace(0.1, 100.0, trace_runs)
    print()
    print(f"  sweeps that scale ({trace_runs} runs with traces; ratios from this run)")
    sweep_s, result = best(lambda: sweep(many, workers=0, traces=True), repeats)
    with tempfile.TemporaryDirectory() as directory:
        out = Path(directory) / "traces.parquet"
        write_s, write_mb = peak(lambda: sweeps.write(result, out))
        tenth = result.iloc[: max(1, trace_runs // 10)]
        arrow_s, arrow_mb = peak(lambda: sweeps.write(tenth, out))
        lists_s, lists_mb = peak(lambda: lists_to_parquet(tenth, out))
    print(
        f"    traces to Parquet: sweep {sweep_s:.2f} s, writing {write_s:.2f} s "
        f"(peak {write_mb:.0f} MB): writing / sweep {write_s / sweep_s:.2f} (goal < 1)"
    )
    print(
        f"    {len(tenth)} runs: Arrow lists {arrow_s:.2f} s (peak {arrow_mb:.0f} MB), Python "
        f"lists {lists_s:.2f} s (peak {lists_mb:.0f} MB): {lists_s / arrow_s:.1f}x the time, "
        f"{lists_mb / max(arrow_mb, 1e-9):.1f}x the memory"
    )

    # the README's sweep: by default in this process (its work is below START_STEPS), against
    # a LocalCluster started for it (the former default) and the shared cluster running
    sweeps.close_cluster()
    default_s, _ = best(lambda: sweep(rates), repeats)
    began = time.perf_counter()
    sweep(rates, workers=2)
    started_s = time.perf_counter() - began
    warm_s, _ = best(lambda: sweep(rates, workers=2), repeats)
    print(
        f"    the README's sweep ({len(rates)} runs) by default (in this process) "
        f"{default_s:.2f} s; "
        f"starting a LocalCluster for it {started_s:.2f} s ({started_s / default_s:.0f}x), "
        f"on the shared cluster running {warm_s:.2f} s ({warm_s / default_s:.1f}x)"
    )

    metrics_s, _ = best(lambda: sweep(many, workers=2), repeats)
    dask_s, there = best(lambda: sweep(many, workers=2, traces=True), repeats)
    same = all(np.array_equal(a, b) for a, b in zip(there["delayedValue"], result["delayedValue"]))
    # the memory this process needs for it (the scheduler of the LocalCluster runs in it too)
    traces_mb = sum(x.nbytes for c in ("time", "delayedValue") for x in result[c]) / 1e6
    _, dask_mb = peak(lambda: sweep(many, workers=2, traces=True))
    _, here_mb = peak(lambda: sweep(many, workers=0, traces=True))
    sweeps.close_cluster()
    print(
        f"    traces over Dask (2 workers) {dask_s:.2f} s, in this process {sweep_s:.2f} s: "
        f"{dask_s / sweep_s:.1f}x (metrics only over Dask {metrics_s:.2f} s; identical: {same})"
    )
    print(
        f"    their peak of traced memory in this process: over Dask {dask_mb:.0f} MB, in this "
        f"process {here_mb:.0f} MB, for {traces_mb:.0f} MB of traces"
    )


def best(function, repeats: int):
    times, result = [], None
    for _ in range(repeats):
        began = time.perf_counter()
        result = function()
        times.append(time.perf_counter() - began)
    return min(times), result


def main():
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument(
        "--naive-runs",
        type=int,
        default=1000,
        help="runs of the naive loop (default: the whole reference sweep)",
    )
    parser.add_argument("--repeats", type=int, default=9)
    parser.add_argument(
        "--trace-runs",
        type=int,
        default=10000,
        help="runs of the sweeps with traces (default 10000; the issue's figure is 100000)",
    )
    args = parser.parse_args()

    from dask.distributed import Client, LocalCluster

    import lgf_fmus

    block = reference_block(lgf_fmus)
    fmu = lgf_fmus.fmu_path(block)
    rates = np.linspace(0.1, 100.0, 1000)
    large = np.linspace(0.1, 100.0, 20000)
    print(f"lgf_fmus benchmark: {block}, load average {load()} on {os.cpu_count()} CPUs")

    sample = (
        rates
        if args.naive_runs >= len(rates)
        else rates[np.linspace(0, len(rates) - 1, args.naive_runs).round().astype(int)]
    )
    naive_s, naive_finals = naive(block, fmu, sample)
    naive_rate = len(sample) / naive_s
    print(
        f"  naive fmpy.simulate_fmu loop  {len(sample):6d} runs  {naive_s:8.3f} s  "
        f"{naive_rate:9.1f} runs/s"
    )

    sweep = lambda runs, **kw: lgf_fmus.sweep(
        block, {"setChangeRate": runs}, 60.0, ["delayedValue"], **COMMON, **kw
    )
    sweep(rates[:10], workers=0)  # loads the runner
    inproc_s, inproc = best(lambda: sweep(rates, workers=0), args.repeats)
    finals = inproc["delayedValue.final"].to_numpy()
    index = np.searchsorted(rates, sample)
    same = bool(np.array_equal(np.asarray(naive_finals), finals[index]))
    print(
        f"  lgf_fmus.sweep in process     {len(rates):6d} runs  {inproc_s:8.3f} s  "
        f"{len(rates) / inproc_s:9.1f} runs/s   identical to the naive loop: {same}"
    )

    # Both clusters stay up and their sweeps alternate, so that a load that comes and goes on a
    # shared machine meets both alike; each figure is the best of its repeats.
    figures, clusters = {}, {}
    with contextlib.ExitStack() as stack:
        for workers in (1, 2):
            began = time.perf_counter()
            cluster = stack.enter_context(
                LocalCluster(
                    n_workers=workers,
                    threads_per_worker=1,
                    processes=True,
                    host="127.0.0.1",
                    dashboard_address="127.0.0.1:0",
                )
            )
            client = stack.enter_context(Client(cluster))
            clusters[workers] = (client, time.perf_counter() - began)
            sweep(rates, client=client)  # warm-up: every worker extracts the FMU, loads the runner
        for runs, repeats in ((rates, args.repeats), (large, max(1, args.repeats // 2))):
            times = {1: [], 2: []}
            for _ in range(repeats):
                for workers in (1, 2):
                    began = time.perf_counter()
                    result = sweep(runs, client=clusters[workers][0])
                    times[workers].append(time.perf_counter() - began)
                    if runs is rates:
                        figures.setdefault(("identical", workers), result.equals(inproc))
            for workers in (1, 2):
                figures.setdefault(workers, []).append(min(times[workers]))
    for workers in (1, 2):
        reference_s, large_s = figures[workers]
        plural = "s" if workers > 1 else " "
        print(
            f"  lgf_fmus.sweep, {workers} worker{plural}     {len(rates):6d} runs  "
            f"{reference_s:8.3f} s  "
            f"{len(rates) / reference_s:9.1f} runs/s   identical to in process: "
            f"{figures[('identical', workers)]}   (cluster start {clusters[workers][1]:.1f} s)"
        )
        print(
            f"  lgf_fmus.sweep, {workers} worker{plural}     {len(large):6d} runs  "
            f"{large_s:8.3f} s  "
            f"{len(large) / large_s:9.1f} runs/s"
        )

    print()
    print("  goal                                   reference sweep     large sweep")
    rows = []
    # each rate of the two sweeps by the workers, then against the naive loop
    for goal, text in (
        ("per_worker", "runs/s per worker, {} (>= 5000)"),
        ("vs_naive", "x the naive loop, {} (>= 150)"),
    ):
        for workers in (1, 2):
            per = workers if goal == "per_worker" else naive_rate
            rows.append(
                (
                    text.format(f"{workers} worker{'s' if workers > 1 else ''}"),
                    len(rates) / figures[workers][0] / per,
                    len(large) / figures[workers][1] / per,
                    GOALS[goal],
                )
            )
    scale_ref = figures[1][0] / figures[2][0]
    scale_big = figures[1][1] / figures[2][1]
    rows.append(("2 workers / 1 worker (>= 1.7)", scale_ref, scale_big, GOALS["scaling"]))
    for name, ref, big, goal in rows:
        print(
            f"  {name:38} {ref:10.2f} {'met' if ref >= goal else 'NOT met':>7}  "
            f"{big:10.2f} {'met' if big >= goal else 'NOT met':>7}"
        )

    scaling(lgf_fmus, block, rates, args.trace_runs, max(1, args.repeats // 3))

    print()
    print("  long run: lgf_fmus.simulate, 1 h of 1 ms cycles, outputs every 1 s (goal <= 0.15 s)")
    for name in lgf_fmus.blocks():
        cycle = lgf_fmus.model(name).variables["cycleTime"]
        if cycle.min is not None and cycle.min > 0.001:
            print(f"    {name:24} cycleTime 1 ms is out of its range")
            continue
        run = lambda: lgf_fmus.simulate(name, 3600.0, {"cycleTime": 0.001}, output_interval=1.0)
        began = time.perf_counter()
        run()
        first = time.perf_counter() - began
        seconds, result = best(run, args.repeats)
        met = "met" if seconds <= GOALS["long_run_s"] else "NOT met"
        print(
            f"    {name:24} {seconds:8.4f} s  {seconds / GOALS['long_run_s']:5.2f}× the goal  "
            f"{met:7}  ({len(result)} samples; the first call, which extracts and loads the "
            f"FMU: {first:.3f} s)"
        )
    print()
    print("  input tables: lgf_fmus.simulate, a value step every cycle (goal: linear, ratio ~10)")
    timings = {}
    for rows in (3600, 36000):
        steps = [(k * 0.01, float(k % 7)) for k in range(rows)]
        run = lambda: lgf_fmus.simulate(
            block, rows * 0.01, {"cycleTime": 0.01}, inputs={"value": steps}
        )
        timings[rows], _ = best(run, 3)
        print(f"    {rows:6d} rows  {timings[rows]:8.3f} s")
    print(
        f"    36000 rows / 3600 rows: {timings[36000] / timings[3600]:.1f}x the time for 10x rows"
    )
    print(f"  load average at the end {load()}")


if __name__ == "__main__":
    main()
