"""The command line of lgf_fmus:

    python -m lgf_fmus list [--variables] [BLOCK or FMU path ...]
    python -m lgf_fmus simulate BLOCK [--stop-time T] [-p NAME=VALUE ...] [-i NAME=T:V,T:V ...]
                                      [--inputs CSV] [--table CSV|V:T,V:T,...]
                                      [--output-interval H] [--outputs A,B]
                                      [--out file.csv] [--plot file.png]
    python -m lgf_fmus sweep SPEC.toml [--workers N | --scheduler ADDRESS] [--out results.parquet]
    python -m lgf_fmus compile Motor.scl [more.scl ...] --block Motor [--fmi 2|3] [-o Motor.fmu]
                                     [--win64 | --no-win64] [--aarch64 | --no-aarch64]
                                     [--iec-check] [--auto-eno]
    python -m lgf_fmus compile *.scl --program program.toml [--tags PLCTags.xlsx] [--fmi 2|3]
                                     -o Line.fmu (a whole program: its OBs on their cycles, its
                                     PLC tags, docs/scl.md §3.10, §3.12)
    python -m lgf_fmus compile --check-folder FOLDER   (every block of FOLDER compiled and run)

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

Whatever is wrong (a malformed argument or spec, an unknown name, a value out of range, an FMU
that refuses a run of simulate) ends in one line `error: ...` on stderr and exit status 2.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

from ._model import LgfValueError, SimulationError
from .scl.ast import SclError  # a source compile refuses: file:line:col: message


class UsageError(Exception):
    """A command line that argparse refuses: main() prints it as one line."""


class Parser(argparse.ArgumentParser):
    """argparse, but a refused command line raises UsageError (main prints one line and
    returns 2) instead of printing the usage and exiting."""

    def error(self, message):
        raise UsageError(f"{message} (see {self.prog} --help)")


# The argument types: each refuses what it cannot read with the whole argument in the message.


def _value(text: str, argument: str):
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
        raise argparse.ArgumentTypeError(
            f"{argument!r}: {text!r} is not a number or true/false"
        ) from None


def _assignment(text: str, form: str) -> tuple[str, str]:
    if "=" not in text:
        raise argparse.ArgumentTypeError(f"{text!r}: expected {form}")
    name, value = text.split("=", 1)
    return name.strip(), value


def _pairs(text: str, argument: str, pair: str) -> list[tuple]:
    """'0:0,1:100' -> [(0, 0), (1, 100)]"""
    rows = []
    for item in text.split(","):
        if ":" not in item:
            raise argparse.ArgumentTypeError(f"{argument!r}: {item!r} is not {pair}")
        a, b = item.split(":", 1)
        rows.append((_value(a, argument), _value(b, argument)))
    return rows


def parameter_argument(text: str) -> tuple[str, object]:
    """-p NAME=VALUE"""
    name, value = _assignment(text, "NAME=VALUE")
    return name, _value(value, text)


def input_argument(text: str) -> tuple[str, list]:
    """-i NAME=T:V,T:V,..."""
    name, rows = _assignment(text, "NAME=T:V,T:V,...")
    return name, _pairs(rows, text, "T:V")


def table_argument(text: str):
    """--table CSV or V:T,V:T,..."""
    return text if Path(text).suffix.lower() == ".csv" else _pairs(text, text, "V:T")


def csv_text(result) -> str:
    """Floats with 17 significant digits (they read back bit for bit), Booleans as 0/1."""
    return result.astype({c: int for c in result.columns if result[c].dtype == bool}).to_csv(
        index=False, float_format="%.17g"
    )


def plot(result, path: Path, block, parameters=None, inputs=None, *, table=None, named=False):
    """--plot: the run's figure (plot_figure) written to `path`."""
    from . import plots

    fig = plot_figure(result, block, parameters, inputs, table=table, named=named)
    fig.savefig(path, dpi=90)
    plots.pyplot().close(fig)


def plot_figure(result, block, parameters=None, inputs=None, *, table=None, named=False):
    """The run's matplotlib figure in the style of the demo (lgf_fmus.plots): its outputs, then
    the inputs the run changes, each in its lane with its unit; the start values and the inputs
    held from the start listed under the title. named: the outputs were asked for (--outputs),
    so all of them are shown (else not subFunctionStatus, nor an error that never became TRUE
    or a status that stayed 16#0000)."""
    from . import plots
    from ._model import model as model_of
    from ._tables import step_tables, table_parameters

    model = model_of(block)
    variables = model.variables
    names = [c for c in result.columns if c != "time"]
    outputs = [variables[n] for n in names] if named else None
    outputs = outputs or plots.shown_outputs(names, variables, result)
    time = result["time"].to_numpy()
    start, stop = float(time[0]), float(time[-1])
    parameters = dict(parameters or {})
    changing, held = plots.input_histories(
        step_tables(inputs), variables, start, stop, starts=parameters
    )
    settings = plots.parameter_settings({**parameters, **table_parameters(model, table)}, variables)
    settings += [f"{v.name} = {plots.shown_value(v, value)}" for v, value in held.items()]
    lines = [model.identifier]
    if settings:
        lines.append(f"held from t = {start:g}: " + ", ".join(settings))
    return plots.run_figure(
        time,
        [(v, result[v.name].to_numpy(), None) for v in outputs],
        [(v, times, values) for v, (times, values) in changing.items()],
        step=float(time[1] - time[0]) if len(time) > 1 else stop - start,
        span=(start, stop),
        lines=lines,
    )


def cmd_list(args) -> int:
    from . import blocks, fmi_versions, fmu_path, model

    names = args.blocks or blocks()
    for block in names:
        if str(block).endswith(".fmu"):  # an FMU file by its path, as simulate takes it
            m = model(block)
            print(f"{m.identifier}  FMI {m.fmi_version}.0  {block}")
        else:
            versions = fmi_versions(block)
            if not versions:
                fmu_path(block)  # raises, naming the bundled blocks
            m = model(block, versions[0])
            fmi = ", ".join(f"{v}.0" for v in versions)
            print(f"{block}  FMI {fmi}  {fmu_path(block, versions[0])}")
        if args.variables:
            for v in m.variables.values():
                if v.causality in ("parameter", "input", "output"):
                    start = "" if v.start is None else f" start {v.start}"
                    print(f"    {v.causality:9} {v.name:28} {v.type:7} {v.allowed()}{start}")
    return 0


def cmd_simulate(args) -> int:
    from . import simulate

    parameters = dict(args.parameter)
    inputs: object = dict(args.input)
    if args.inputs:
        if inputs:
            raise LgfValueError("give inputs either with --input or with --inputs CSV, not both")
        inputs = args.inputs
    table = args.table
    outputs = args.outputs.split(",") if args.outputs else None
    if args.out:
        _check_writable(Path(args.out), "--out")
    if args.plot:
        _check_plot(Path(args.plot))
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
        Path(args.out).write_text(csv_text(result))
        print(f"{args.block}: {len(result)} samples -> {args.out}")
    else:
        sys.stdout.write(csv_text(result))
    if args.plot:
        plot(
            result,
            Path(args.plot),
            args.block,
            parameters,
            inputs or None,
            table=table,
            named=outputs is not None,
        )
        print(f"plot -> {args.plot}")
    return 0


def _check_writable(path: Path, option: str):
    """Before the run: a file the run can write, in a folder that exists (none is made)."""
    import os

    folder = path.parent
    if path.is_dir():
        raise LgfValueError(f"{option} {path}: a folder, not a file")
    if not folder.is_dir():
        raise LgfValueError(f"{option} {path}: the folder {folder} does not exist")
    if not os.access(folder, os.W_OK) or path.exists() and not os.access(path, os.W_OK):
        raise LgfValueError(f"{option} {path}: not writable")


def _check_plot(path: Path):
    """Before the run: a plot file of a format matplotlib writes, where it can be written."""
    _check_writable(path, "--plot")
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.backend_bases import FigureCanvasBase

    formats = FigureCanvasBase.get_supported_filetypes()
    if path.suffix[1:].lower() not in formats:
        raise LgfValueError(
            f"--plot {path}: matplotlib writes {', '.join(sorted(formats))} "
            f"files, not {path.suffix or 'a file without a suffix'}"
        )


def _load_spec(path: Path) -> dict:
    import tomllib

    try:
        with open(path, "rb") as file:
            return tomllib.load(file)
    except OSError as error:
        raise LgfValueError(f"cannot read the spec {path}: {error.strerror or error}") from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise LgfValueError(f"the spec {path} is not valid TOML: {error}") from None


def _relative(base: Path, value):
    return str(base / value) if isinstance(value, str) else value


# What each key of a SPEC.toml is: its TOML types and, in words, what it takes.
SPEC_KEYS = {
    "block": ((str,), "a block's name (a string)"),
    "stop_time": ((int, float), "a number"),
    "start_time": ((int, float), "a number"),
    "output_interval": ((int, float), "a number"),
    "outputs": ((str, list), "an output's name or a list of them"),
    "metrics": ((str, list), "a metric's name or a list of them"),
    "traces": ((bool,), "true or false"),
    "out": ((str,), "a file name (a string)"),
    "parameters": ((dict,), "a table of start values ([parameters])"),
    "inputs": ((dict, str), "a table of step tables ([inputs]) or a CSV file's name"),
    "table": ((list, str), "a list of rows or a CSV file's name"),
    "runs": ((dict, str), "a table (a grid of values per name, [runs]) or a CSV file's name"),
    "reach": ((dict,), "a table of thresholds ([reach])"),
    "chunk_size": ((int,), "a whole number of runs > 0"),
}


def _spec_value(spec: dict, key: str):
    types, words = SPEC_KEYS[key]
    value = spec[key]
    if not isinstance(value, types) or (isinstance(value, bool) and bool not in types):
        raise LgfValueError(f"the spec's {key} must be {words}, not {value!r}")
    return value


def _range(name: str, values: dict) -> np.ndarray:
    """runs.NAME = { start = A, stop = B, num = N }: numpy.linspace(A, B, N)."""
    missing = [k for k in ("start", "stop", "num") if k not in values]
    unknown = sorted(set(values) - {"start", "stop", "num"})
    if missing or unknown:
        raise LgfValueError(
            f"runs.{name}: a range needs start, stop and num"
            + (
                f" (missing {', '.join(repr(k) for k in missing)})"
                if missing
                else f", not {', '.join(unknown)}"
            )
        )
    start, stop, num = values["start"], values["stop"], values["num"]
    numbers = all(isinstance(x, (int, float)) and not isinstance(x, bool) for x in (start, stop))
    if not numbers or isinstance(num, bool) or not isinstance(num, int) or num < 0:
        raise LgfValueError(
            f"runs.{name}: a range's start, stop and num are two numbers and a "
            f"whole number >= 0, not {start!r}, {stop!r}, {num!r}"
        )
    return np.linspace(float(start), float(stop), num)


def spec_arguments(spec: dict, base: Path) -> dict:
    """The keyword arguments of sweep() that a SPEC.toml gives."""
    unknown = sorted(set(spec) - set(SPEC_KEYS))
    if unknown:
        raise LgfValueError(
            f"the spec has unknown keys {', '.join(unknown)}; it takes "
            f"{', '.join(sorted(SPEC_KEYS))}"
        )
    if "block" not in spec or "runs" not in spec:
        raise LgfValueError("the spec needs `block` and `runs`")
    given = {key: _spec_value(spec, key) for key in spec}
    runs = given["runs"]
    if isinstance(runs, dict):
        runs = {
            name: _range(name, values) if isinstance(values, dict) else values
            for name, values in runs.items()
        }
    else:
        runs = _relative(base, runs)
    arguments = {
        k: given[k]
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
        if k in given
    }
    if "out" in arguments:
        arguments["out"] = _relative(base, arguments["out"])
    inputs = given.get("inputs")
    arguments["inputs"] = (
        _relative(base, inputs)
        if isinstance(inputs, str)
        else (
            {
                k: [tuple(r) if isinstance(r, list) else r for r in v] if isinstance(v, list) else v
                for k, v in inputs.items()
            }
            if inputs
            else None
        )
    )
    table = given.get("table")
    arguments["table"] = _relative(base, table) if isinstance(table, str) else table
    return {"block": given["block"], "runs": runs, **arguments}


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
    p = Parser(
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
        type=parameter_argument,
        action="append",
        default=[],
        metavar="NAME=VALUE",
        help="a start value (parameter or input)",
    )
    sim.add_argument(
        "-i",
        "--input",
        type=input_argument,
        action="append",
        default=[],
        metavar="NAME=T:V,T:V",
        help="a step table: value V from time T on",
    )
    sim.add_argument("--inputs", metavar="CSV", help="step tables: a time column and one per input")
    sim.add_argument(
        "--table",
        metavar="CSV|V:T,...",
        type=table_argument,
        help="the block's table of points, e.g. 0:2,100:3,100:2,0:0 (outputValue:time)",
    )
    sim.add_argument("--outputs", metavar="A,B", help="outputs to record (default: all)")
    sim.add_argument("--out", metavar="file.csv")
    sim.add_argument("--plot", metavar="file.png")
    sim.set_defaults(run=cmd_simulate)

    sw = sub.add_parser("sweep", help="many runs on Dask: one row per run")
    sw.add_argument("spec", metavar="SPEC.toml")
    sw.add_argument(
        "--workers",
        type=int,
        help="LocalCluster workers (default: one per core, and a small sweep in this process; "
        "0: no Dask)",
    )
    sw.add_argument(
        "--scheduler", metavar="ADDRESS", help="a running Dask scheduler, e.g. tcp://host:8786"
    )
    sw.add_argument("--out", metavar="results.parquet")
    sw.add_argument("--no-progress", action="store_true")
    sw.set_defaults(run=cmd_sweep)

    co = sub.add_parser("compile", help="an SCL function block -> an FMU (docs/scl.md)")
    co.add_argument("sources", nargs="*", metavar="SOURCE.scl")
    co.add_argument("--block", help="the FUNCTION_BLOCK that becomes the FMU")
    co.add_argument(
        "--check-folder",
        metavar="FOLDER",
        help="compile and run every block of a folder of SCL, one line per block (no FMU kept)",
    )
    co.add_argument(
        "--program",
        metavar="program.toml",
        help="a whole program instead of --block: its OBs on their cycles (docs/scl.md §3.10)",
    )
    co.add_argument(
        "--tags",
        metavar="PLCTags.xlsx",
        help="with --program, TIA's PLC tag table (.xlsx or .csv): %%I tags the FMU's inputs, %%Q "
        "tags its outputs, %%M tags locals (docs/scl.md §3.12)",
    )
    co.add_argument("--fmi", type=int, choices=(2, 3), default=2, help="FMI version (default 2)")
    co.add_argument("-o", "--output", metavar="BLOCK.fmu", help="default: <block>.fmu")
    co.add_argument(
        "--win64",
        action=argparse.BooleanOptionalAction,
        default=None,
        help="a win64 binary too (default: where mingw-w64 is installed)",
    )
    co.add_argument(
        "--aarch64",
        action=argparse.BooleanOptionalAction,
        default=None,
        help="with --fmi 3, an aarch64-linux binary too (default: where Debian's "
        "gcc-aarch64-linux-gnu is installed)",
    )
    co.add_argument(
        "--iec-check",
        action="store_true",
        help="as TIA Portal's block property 'IEC check': only the implicit conversions towards "
        "a type that holds every value (default off, as in TIA: also those between integers and "
        "bit strings)",
    )
    co.add_argument(
        "--auto-eno",
        action="store_true",
        help="as TIA Portal's block property 'Set ENO automatically': a REAL operation whose "
        "result is no finite REAL sets ENO FALSE (default off, as in TIA)",
    )
    co.set_defaults(run=cmd_compile)
    return p


def cmd_compile(args) -> int:
    from .scl import compile as compile_scl

    if args.check_folder:
        if args.sources or args.block or args.program or args.tags:
            raise SclError(None, "--check-folder takes no SOURCE.scl, --block or --program")
        from .scl.corpus import check_folder

        results = check_folder(args.check_folder, fmi=args.fmi, iec_check=args.iec_check)
        return 0 if all(r.outcome != "failed" for r in results) else 1
    if not args.sources or not (args.block or args.program):
        raise SclError(
            None, "compile needs SOURCE.scl files and --block or --program (or --check-folder)"
        )
    path = compile_scl(
        args.sources,
        block=args.block,
        fmi=args.fmi,
        output=args.output,
        win64=args.win64,
        aarch64=args.aarch64,
        iec_check=args.iec_check,
        auto_eno=args.auto_eno,
        program=args.program,
        tags=args.tags,
    )
    print(path)
    return 0


def _error(error) -> int:
    """Any refused input ends here: one line `error: ...` on stderr, exit status 2; an SCL
    source every error of it, each `file:line:col: error E0nn: ...` with its source line
    (docs/scl.md §5)."""
    if isinstance(error, SclError) and error.loc is not None:
        print(str(error), file=sys.stderr)
        return 2
    text = str(error)
    if isinstance(error, OSError) and error.filename is not None and error.strerror:
        text = f"{error.filename}: {error.strerror}"
    text = "; ".join(line.strip() for line in text.splitlines() if line.strip())
    print(f"error: {text}", file=sys.stderr)
    return 2


def main(argv=None) -> int:
    try:
        args = parser().parse_args(argv)
        return args.run(args)
    except (UsageError, LgfValueError, SimulationError, SclError) as error:
        return _error(error)
    except BrokenPipeError:  # the output went to a program that stopped reading (head)
        sys.stderr.close()
        return 0
    except OSError as error:  # a file that cannot be read or written (--out, --plot, ...)
        return _error(error)
