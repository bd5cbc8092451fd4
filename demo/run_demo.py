"""Simulates every demo scenario of every block (tests/blocks/<Block>/scenarios.py) with FMPy
and writes <scenario>.csv and <scenario>.png. Run from the repository root:

    python -m demo.run_demo --fmus fmus --out results    # the demo
    python -m demo.run_demo --fmus fmus --references     # regenerate the references, written to
                                                         # tests/blocks/<Block>/references/
"""
from __future__ import annotations

import argparse
from pathlib import Path

import numpy as np
from fmpy import read_model_description, simulate_fmu

from demo.scenarios import input_defaults
from tests.harness import fmu_path
from tests.lgf_blocks import blocks


def simulate(scenario, fmu_dir: Path):
    fmu = fmu_path(scenario.block, fmu_dir)
    md = read_model_description(str(fmu))
    outputs = [v.name for v in md.modelVariables if v.causality == "output"]
    result = simulate_fmu(str(fmu), stop_time=scenario.stop_time,
                          output_interval=scenario.output_interval,
                          start_values=scenario.parameters,
                          input=scenario.input_signals(input_defaults(md)),
                          output=outputs, validate=True)
    return result, outputs, md


def write_csv(result, path: Path):
    """Numeric CSV: floats with 17 significant digits (they read back bit for bit), Booleans
    as 0/1, which FMPy's read_csv and any spreadsheet understand."""
    names = result.dtype.names
    with open(path, "w") as f:
        f.write(",".join(names) + "\n")
        for row in result:
            cells = []
            for name in names:
                value = row[name]
                if isinstance(value, (bool, np.bool_)):
                    cells.append("1" if value else "0")
                elif isinstance(value, (int, np.integer)):
                    cells.append(str(int(value)))
                else:
                    cells.append(repr(float(value)))
            f.write(",".join(cells) + "\n")


def plot(scenario, result, outputs, md, path: Path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    changing = {name for _, changes in scenario.inputs for name in changes}
    signals = scenario.input_signals(input_defaults(md))[["time", *sorted(changing)]] if changing else None
    shown = [n for n in outputs if n not in ("subFunctionStatus", "error")]
    rows = len(shown) + (1 if signals is not None else 0)
    fig, axes = plt.subplots(rows, 1, figsize=(10, 1.6 * rows + 1), sharex=True, squeeze=False)
    axes = axes[:, 0]
    t = result["time"]
    for ax, name in zip(axes, shown):
        y = result[name].astype(float)
        label = name + (" (hex)" if name == "status" else "")
        ax.step(t, y, where="post", color="tab:blue")
        ax.set_ylabel(label, rotation=0, ha="right", va="center")
        if name == "status":
            ax.set_yticks(sorted(set(int(v) for v in y)))
            ax.set_yticklabels([f"16#{int(v):04X}" for v in sorted(set(int(v) for v in y))])
        ax.grid(True, alpha=0.3)
    if signals is not None:
        ax = axes[-1]
        for name in signals.dtype.names[1:]:
            tt = np.append(signals["time"], scenario.stop_time)
            yy = np.append(signals[name], signals[name][-1]).astype(float)
            ax.step(tt, yy, where="post", label=name)
        ax.set_ylabel("inputs", rotation=0, ha="right", va="center")
        ax.legend(loc="upper right", fontsize="small", ncol=3)
        ax.grid(True, alpha=0.3)
    axes[-1].set_xlabel("time [s]")
    fig.suptitle(scenario.title)
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--fmus", default="fmus", type=Path)
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--out", default="results", type=Path, help="CSV and PNG per scenario")
    group.add_argument("--references", action="store_true",
                       help="write only the reference CSVs, into each block's references/")
    args = parser.parse_args()
    for block in blocks():
        for scenario in block.scenarios:
            result, outputs, md = simulate(scenario, args.fmus)
            if args.references:
                csv = block.reference(scenario)
            else:
                csv = args.out / f"{scenario.name}.csv"
            csv.parent.mkdir(parents=True, exist_ok=True)
            write_csv(result, csv)
            if not args.references:
                plot(scenario, result, outputs, md, csv.with_suffix(".png"))
            print(f"{scenario.name}: {csv}" + ("" if args.references else " + .png"))
    if not args.references:
        print(f"Results in {args.out.resolve()}")


if __name__ == "__main__":
    main()
