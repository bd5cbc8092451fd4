"""The command line of lgf_fmus:

    python -m lgf_fmus list [--variables] [BLOCK ...]
    python -m lgf_fmus simulate BLOCK [--stop-time T] [-p NAME=VALUE ...] [-i NAME=T:V,T:V ...]
                                      [--inputs CSV] [--table CSV|V:T,V:T,...]
                                      [--output-interval H] [--outputs A,B]
                                      [--out file.csv] [--plot file.png]
    python -m lgf_fmus sweep SPEC.toml [--workers N | --scheduler ADDRESS] [--out results.parquet]

A sweep's SPEC.toml (paths in it are relative to the file):

    block = "LGF_LimRateOfChangeCI"
    stop_time = 60.0
    output_interval = 0.1
    outputs = ["delayedValue"]
    metrics = ["final", "min", "max"]        # optional
    traces = false                           # optional: the samples of every run
    out = "results.parquet"                  # optional, --out overrides it

    [parameters]                             # common start values
    cycleTime = 0.01

    [inputs]                                 # common step tables (or inputs = "inputs.csv")
    value = [[0.0, 0.0], [1.0, 100.0]]

    [runs]                                   # a grid (or runs = "runs.csv", one run a row)
    setChangeRate = { start = 0.1, stop = 100.0, num = 1000 }   # numpy.linspace; or a list

    [reach]                                  # time to reach a threshold
    delayedValue = 95.0
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

from ._model import LgfValueError, SimulationError


def _value(text: str):
    low = text.strip().lower()
    if low in ("true", "false"):
        return low == "true"
    try:
        return int(text)
    except ValueError:
        pass
    try:
        return float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number or true/false") from None


def _assignment(text: str):
    if "=" not in text:
        raise argparse.ArgumentTypeError(f"{text!r}: expected NAME=VALUE")
    name, value = text.split("=", 1)
    return name.strip(), value


def _pairs(text: str) -> list[tuple]:
    """'0:0,1:100' -> [(0, 0), (1, 100)]"""
    rows = []
    for item in text.split(","):
        if ":" not in item:
            raise argparse.ArgumentTypeError(f"{item!r}: expected A:B")
        a, b = item.split(":", 1)
        rows.append((_value(a), _value(b)))
    return rows


def csv_text(result) -> str:
    """Floats with 17 significant digits (they read back bit for bit), Booleans as 0/1."""
    return result.astype({c: int for c in result.columns if result[c].dtype == bool}).to_csv(
        index=False, float_format="%.17g"
    )


def plot(result, title: str, path: Path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    names = [c for c in result.columns if c != "time"]
    fig, axes = plt.subplots(
        len(names), 1, figsize=(9, 1.7 * len(names) + 1), sharex=True, squeeze=False
    )
    for ax, name in zip(axes[:, 0], names):
        ax.step(result["time"], result[name].astype(float), where="post")
        ax.set_ylabel(name, rotation=0, ha="right", va="center")
        ax.grid(True, alpha=0.3)
    axes[-1, 0].set_xlabel("time [s]")
    fig.suptitle(title)
    fig.tight_layout()
    path.parent.mkdir(parents=True, exist_ok=True)
    fig.savefig(path, dpi=90)
    plt.close(fig)


def cmd_list(args) -> int:
    from . import blocks, fmi_versions, fmu_path, model

    names = args.blocks or blocks()
    for block in names:
        versions = fmi_versions(block)
        if not versions:
            fmu_path(block)  # raises, naming the bundled blocks
        m = model(block, versions[0])
        print(
            f"{block}  FMI {', '.join(f'{v}.0' for v in versions)}  {fmu_path(block, versions[0])}"
        )
        if args.variables:
            for v in m.variables.values():
                if v.causality in ("parameter", "input", "output"):
                    start = "" if v.start is None else f" start {v.start}"
                    print(f"    {v.causality:9} {v.name:28} {v.type:7} {v.allowed()}{start}")
    return 0


def cmd_simulate(args) -> int:
    from . import simulate

    parameters = {name: _value(value) for name, value in args.parameter}
    inputs: object = {name: _pairs(value) for name, value in args.input}
    if args.inputs:
        if inputs:
            raise LgfValueError("give inputs either with --input or with --inputs CSV, not both")
        inputs = args.inputs
    table = None
    if args.table:
        table = args.table if Path(args.table).suffix.lower() == ".csv" else _pairs(args.table)
    outputs = args.outputs.split(",") if args.outputs else None
    result = simulate(
        args.block,
        args.stop_time,
        parameters,
        inputs or None,
        table=table,
        start_time=args.start_time,
        output_interval=args.output_interval,
        outputs=outputs,
    )
    if args.out:
        Path(args.out).parent.mkdir(parents=True, exist_ok=True)
        Path(args.out).write_text(csv_text(result))
        print(f"{args.block}: {len(result)} samples -> {args.out}")
    else:
        sys.stdout.write(csv_text(result))
    if args.plot:
        plot(result, f"{args.block}", Path(args.plot))
        print(f"plot -> {args.plot}")
    return 0


def _load_spec(path: Path) -> dict:
    import tomllib

    with open(path, "rb") as file:
        return tomllib.load(file)


def _relative(base: Path, value):
    return str(base / value) if isinstance(value, str) else value


def spec_arguments(spec: dict, base: Path) -> dict:
    """The keyword arguments of sweep() that a SPEC.toml gives."""
    known = {
        "block",
        "stop_time",
        "start_time",
        "output_interval",
        "outputs",
        "metrics",
        "traces",
        "out",
        "parameters",
        "inputs",
        "table",
        "runs",
        "reach",
        "chunk_size",
    }
    unknown = sorted(set(spec) - known)
    if unknown:
        raise LgfValueError(
            f"the spec has unknown keys {', '.join(unknown)}; it takes {', '.join(sorted(known))}"
        )
    if "block" not in spec or "runs" not in spec:
        raise LgfValueError("the spec needs `block` and `runs`")
    runs = spec["runs"]
    if isinstance(runs, dict):
        grid = {}
        for name, values in runs.items():
            if isinstance(values, dict):
                try:
                    grid[name] = np.linspace(
                        float(values["start"]), float(values["stop"]), int(values["num"])
                    )
                except KeyError as missing:
                    raise LgfValueError(
                        f"runs.{name}: a range needs start, stop and num (missing {missing})"
                    ) from None
            else:
                grid[name] = values
        runs = grid
    else:
        runs = _relative(base, runs)
    arguments = {
        k: spec[k]
        for k in (
            "stop_time",
            "start_time",
            "output_interval",
            "outputs",
            "metrics",
            "traces",
            "parameters",
            "reach",
            "chunk_size",
            "out",
        )
        if k in spec
    }
    if "out" in arguments:
        arguments["out"] = _relative(base, arguments["out"])
    inputs = spec.get("inputs")
    arguments["inputs"] = (
        _relative(base, inputs)
        if isinstance(inputs, str)
        else (
            {k: [tuple(r) for r in v] if isinstance(v, list) else v for k, v in inputs.items()}
            if inputs
            else None
        )
    )
    table = spec.get("table")
    arguments["table"] = _relative(base, table) if isinstance(table, str) else table
    return {"block": spec["block"], "runs": runs, **arguments}


def cmd_sweep(args) -> int:
    from . import sweep

    spec_path = Path(args.spec)
    arguments = spec_arguments(_load_spec(spec_path), spec_path.parent)
    if args.out:
        arguments["out"] = args.out
    if args.workers is not None:
        arguments["workers"] = args.workers
    if args.scheduler:
        arguments["scheduler"] = args.scheduler
    arguments["progress"] = not args.no_progress
    block, runs = arguments.pop("block"), arguments.pop("runs")
    result = sweep(block, runs, **arguments)
    failed = int((~result["ok"]).sum())
    shown = result.drop(columns=[c for c in result.columns if result[c].dtype == object])
    print(shown.head(10).to_string(index=False))
    print(
        f"{len(result)} runs, {failed} failed"
        + (f" -> {arguments['out']}" if arguments.get("out") else "")
    )
    return 0


def parser() -> argparse.ArgumentParser:
    p = argparse.ArgumentParser(
        prog="python -m lgf_fmus",
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    sub = p.add_subparsers(dest="command", required=True)
    ls = sub.add_parser("list", help="the bundled blocks (with --variables their variables)")
    ls.add_argument("blocks", nargs="*")
    ls.add_argument("-v", "--variables", action="store_true")
    ls.set_defaults(run=cmd_list)

    sim = sub.add_parser("simulate", help="one run: a CSV of the outputs and a plot")
    sim.add_argument("block")
    sim.add_argument("--stop-time", type=float)
    sim.add_argument("--start-time", type=float)
    sim.add_argument("--output-interval", type=float, help="communication step (default cycleTime)")
    sim.add_argument(
        "-p",
        "--parameter",
        type=_assignment,
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="a start value (parameter or input)",
    )
    sim.add_argument(
        "-i",
        "--input",
        type=_assignment,
        action="append",
        default=[],
        metavar="NAME=T:V,T:V",
        help="a step table: value V from time T on",
    )
    sim.add_argument("--inputs", metavar="CSV", help="step tables: a time column and one per input")
    sim.add_argument(
        "--table",
        metavar="CSV|V:T,...",
        help="the block's table of points, e.g. 0:2,100:3,100:2,0:0 (outputValue:time)",
    )
    sim.add_argument("--outputs", metavar="A,B", help="outputs to record (default: all)")
    sim.add_argument("--out", metavar="file.csv")
    sim.add_argument("--plot", metavar="file.png")
    sim.set_defaults(run=cmd_simulate)

    sw = sub.add_parser("sweep", help="many runs on Dask: one row per run")
    sw.add_argument("spec", metavar="SPEC.toml")
    sw.add_argument(
        "--workers", type=int, help="LocalCluster workers (default: one per core; 0: no Dask)"
    )
    sw.add_argument(
        "--scheduler", metavar="ADDRESS", help="a running Dask scheduler, e.g. tcp://host:8786"
    )
    sw.add_argument("--out", metavar="results.parquet")
    sw.add_argument("--no-progress", action="store_true")
    sw.set_defaults(run=cmd_sweep)
    return p


def main(argv=None) -> int:
    args = parser().parse_args(argv)
    try:
        return args.run(args)
    except (LgfValueError, SimulationError) as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # the output went to a program that stopped reading (head)
        sys.stderr.close()
        return 0
