"""Simulates every demo scenario of every block (src/blocks/<Block>/scenarios.py) with FMPy
and writes <scenario>.csv and <scenario>.png. Run from the repository root:

    python -m demo.run_demo --fmus fmus --out results    # the demo
    python -m demo.run_demo --fmus fmus --references     # regenerate the references, written to
                                                         # tests/blocks/<Block>/references/, and
                                                         # the README's picture docs/overview.png
"""

from __future__ import annotations

import argparse
from pathlib import Path

from fmpy import read_model_description, simulate_fmu

from tools import plots
from tools.blocks import blocks
from tools.simulate import fmu_path, simulate, write_csv


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--fmus", default="fmus", type=Path)
    group = parser.add_mutually_exclusive_group()
    group.add_argument("--out", default="results", type=Path, help="CSV and PNG per scenario")
    group.add_argument(
        "--references",
        action="store_true",
        help="write only the reference CSVs, into each block's references/",
    )
    args = parser.parse_args()
    for block in blocks():
        for scenario in block.scenarios:
            result, outputs, md = simulate(scenario, args.fmus)
            if args.references:
                csv = block.reference(scenario)
            else:
                csv = args.out / f"{scenario.name}.csv"
            csv.parent.mkdir(parents=True, exist_ok=True)
            write_csv(result, csv, exact_times=args.references)
            if not args.references:
                plots.plot_run(scenario, result, md, csv.with_suffix(".png"))
            print(f"{scenario.name}: {csv}" + ("" if args.references else " + .png"))
    if args.references:
        write_overview(args.fmus, OVERVIEW)
        print(f"README picture: {OVERVIEW}")
    else:
        print(f"Results in {args.out.resolve()}")


OVERVIEW = Path(__file__).resolve().parent.parent / "docs" / "overview.png"  # and families.png


def write_overview(fmu_dir: Path, path: Path):
    """docs/overview.png: every FMU's default experiment (no start value set, no input); and
    docs/families.png: the blocks that share one interface (the signal generators), each family
    on one time axis."""
    runs = []
    for block in blocks():
        fmu = fmu_path(block.name, fmu_dir)
        md = read_model_description(str(fmu))
        runs.append((block.name, simulate_fmu(str(fmu)), md))
    plots.overview(runs, path)
    plots.families(runs, path.with_name("families.png"))


if __name__ == "__main__":
    main()
