"""Simulates every demo scenario of every block (src/blocks/<Block>/scenarios.py) with FMPy
and writes <scenario>.csv and <scenario>.png, and overview.png: every block's typical run (its
first scenario, as its documentation shows it). Run from the repository root:

    python -m demo.run_demo --fmus fmus --out results    # the demo
    python -m demo.run_demo --fmus fmus --references     # regenerate the references, written to
                                                         # tests/blocks/<Block>/references/, the
                                                         # README's pictures docs/overview.png and
                                                         # docs/families.png, and each block page's
                                                         # src/blocks/<Block>/typical_run.png
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
    typical = []  # every block's first scenario, run: the overview
    for block in blocks():
        for scenario in block.scenarios:
            result, outputs, md = simulate(scenario, args.fmus)
            if scenario is block.scenarios[0]:  # the picture of its page, README.md
                typical.append((scenario, result, md))
                if args.references:
                    plots.plot_run(scenario, result, md, block.folder / "typical_run.png", dpi=80)
            if args.references:
                csv = block.reference(scenario)
            else:
                csv = args.out / f"{scenario.name}.csv"
            csv.parent.mkdir(parents=True, exist_ok=True)
            write_csv(result, csv, exact_times=args.references)
            if not args.references:
                plots.plot_run(scenario, result, md, csv.with_suffix(".png"))
            print(f"{scenario.name}: {csv}" + ("" if args.references else " + .png"))
    overview = OVERVIEW if args.references else args.out / OVERVIEW.name
    plots.overview(typical, overview)
    print(f"overview of the typical runs: {overview}")
    if args.references:
        write_families(args.fmus, FAMILIES)
        print(f"README picture of the families: {FAMILIES}")
    else:
        print(f"Results in {args.out.resolve()}")


DOCS = Path(__file__).resolve().parent.parent / "docs"
OVERVIEW, FAMILIES = DOCS / "overview.png", DOCS / "families.png"


def write_families(fmu_dir: Path, path: Path):
    """docs/families.png: the blocks that share one interface (the signal generators), each
    family's default experiments (no start value set, no input) on one time axis."""
    runs = []
    for block in blocks():
        fmu = fmu_path(block.name, fmu_dir)
        md = read_model_description(str(fmu))
        runs.append((block.name, simulate_fmu(str(fmu)), md))
    plots.families(runs, path)


if __name__ == "__main__":
    main()
