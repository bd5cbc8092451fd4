"""The three-way check of the 22 blocks (`make originals SCL=<folder>`): each block's original SCL,
as TIA Portal exports it, compiled by lgf_fmus.scl, against the hand-written FMU (fmus/) and the
block's independent model (tests/blocks/<Block>/model.py), call for call on the random scenarios
of the block's own property tests, in co-simulation (FMI 2.0 and 3.0) and Model Exchange.

The folder holds third-party SCL (Siemens' LGF): it is read where it lies and never enters the
repository, which is why this is a make target of its own and not part of `make test`. The one
source written here is the UDT the LGF exports leave out (LGF_RampCI's table row, from the
block's documentation). One line per block: refused (where the compiler stops), the number of
calls compared and the result, or the first difference with its scenario.

    python -m tests.originals.check --scl FOLDER [--examples N] [--blocks LGF_A LGF_B ...]
"""

from __future__ import annotations

import argparse
import importlib
import math
import random
import struct
import sys
import tempfile
from pathlib import Path

from fmpy import read_model_description
from hypothesis import HealthCheck, given, settings
from hypothesis import seed as seeded
from hypothesis import strategies as st

from lgf_fmus import scl
from lgf_fmus.scl import corpus, parser
from tests.harness import Trace, run_fmu, run_model
from tests.lgf_blocks import blocks
from tests.scl.driver import hand_written, run_cs, run_me

HERE = Path(__file__).resolve().parent
UDTS = [HERE / "udts.scl"]

# The hand-written FMU's parameters that fix what the original does (LGF_SawTooth's PLC-exact
# timing is the original's, docs/behaviour.md §2.5).
FIXED = {"LGF_SawTooth": {"plcTiming": True}}
# The block properties an export does not carry, as the hand-written FMU assumes them:
# LGF_IsValueInToleranceByTime reads ENO after its REAL limits, so "Set ENO automatically"
# (docs/behaviour.md §13.5, docs/scl.md §3.4 [S7-ENO-AUTO]).
PROPERTIES = {"LGF_IsValueInToleranceByTime": {"auto_eno": True}}


class Difference(Exception):
    pass


def bits(value):
    return struct.pack("<d", value) if isinstance(value, float) else value


def same(a, b) -> bool:
    if isinstance(a, float) and isinstance(b, float):
        return bits(a) == bits(b) or (math.isnan(a) and math.isnan(b))
    return a == b


def names_of(fmu: Path) -> dict[str, str]:
    """The original's variable names by their lower-case form (the interface keeps the LGF
    names; docs/behaviour.md §1.5 lists the aliases, which differ only in case or a typo)."""
    return {v.name.lower(): v.name for v in read_model_description(str(fmu)).modelVariables}


ALIASES = {
    "subfunctionstatus": "subfunctionstatus",
    "endefaultoutvalue": "endefaulftoutvalue",
    "y": "ret_val",  # LGF_ScaleLinear, an FC: its return value is the wrapper's Ret_Val
    # LGF_IsValueInToleranceByTime's configuration as its code spells the members
    "configuration.limitsasabsolutevalues": "configuration.limitsasabsolutvalues",
    "configuration.toleranceasabsolutevalues": "configuration.toleranzasabsolutevalues",
    "configuration.setpointchangemonitoringtime": "configuration.setpointchangemonitingtime",
}


def mapping(block: str, original: Path) -> dict[str, str]:
    """Hand-written name -> the original's name, for every variable the two share."""
    theirs = names_of(original)
    result = {}
    for v in read_model_description(str(hand_written(block))).modelVariables:
        key = v.name.lower()
        name = theirs.get(key) or theirs.get(ALIASES.get(key, key))
        if name:
            result[v.name] = name
    return result


def renamed(values: dict, names: dict[str, str]) -> dict:
    return {names[n]: v for n, v in values.items() if n in names}


def wrapped(source: Path, name: str, scratch: Path) -> tuple[list[Path], str]:
    """(sources, FB name) that compile the original: an FC (LGF_ScaleLinear) through the
    wrapper FB of `--check-folder` (its return value the output Ret_Val), an FB as it is."""
    text = source.read_text(encoding="utf-8-sig")
    fc = next((b for b in parser.parse(text, str(source)) if b.kind == "FUNCTION"), None)
    if fc is None or fc.name != name:
        return [source], name
    wrapper_name, wrapper = corpus._wrapper(fc, text)
    path = scratch / f"{wrapper_name}.scl"
    path.write_text(wrapper, encoding="utf-8")
    return [source, path], wrapper_name


def check_block(block, original: Path, examples: int, seed: int) -> str:
    spec = importlib.import_module(f"tests.blocks.{block.name}.spec").SPEC
    fixed = FIXED.get(block.name, {})
    names = mapping(block.name, original[2])
    outputs = [
        v.name
        for v in read_model_description(str(hand_written(block.name))).modelVariables
        if v.causality == "output"
    ]
    missing = [n for n in outputs if n not in names]
    if missing:
        return f"the original has no output {', '.join(missing)}"
    calls = [0]

    @st.composite
    def scenarios(draw):
        cycle_us = draw(spec.cycles_us)
        parameters = draw(spec.parameters())
        initial = {name: draw(strategy) for name, strategy in spec.inputs.items()}
        steps = []
        for _ in range(draw(st.integers(1, 60))):
            changed = draw(st.lists(st.sampled_from(sorted(spec.inputs)), max_size=3, unique=True))
            steps.append((cycle_us, {n: draw(spec.inputs[n]) for n in changed}))
        return cycle_us, parameters, initial, steps

    @settings(
        max_examples=examples,
        deadline=None,
        database=None,
        derandomize=False,
        suppress_health_check=list(HealthCheck),
    )
    @seeded(seed)
    @given(scenarios())
    def compare(scenario):
        cycle_us, parameters, initial, steps = scenario
        parameters = {**parameters, **fixed}
        trace = Trace(initial, steps)
        model = run_model(spec.make_model(cycle_us, parameters), cycle_us, trace)
        ours = run_fmu(block.name, cycle_us, trace, parameters)
        theirs_parameters = renamed({k: v for k, v in parameters.items() if k not in fixed}, names)
        theirs_parameters.pop(names.get("cycleTime", "cycleTime"), None)
        per_call = [initial]
        for _, changes in steps:
            per_call.append({**per_call[-1], **changes})
        runs = {
            f"FMI {fmi}.0 co-simulation": run_cs(
                original[fmi],
                cycle_us,
                theirs_parameters,
                renamed(initial, names),
                [(h, renamed(c, names)) for h, c in steps],
                [names[n] for n in outputs],
            )  # fmt: skip
            for fmi in (2, 3)
        }
        for fmi in (2, 3):
            runs[f"FMI {fmi}.0 Model Exchange"] = run_me(
                original[fmi], cycle_us, theirs_parameters, [renamed(c, names) for c in per_call],
                [names[n] for n in outputs],
            )  # fmt: skip
        calls[0] += len(steps) + 1
        shown = f" (cycle {cycle_us} µs, parameters {parameters}, inputs {initial}, then {steps})"
        for k, (want, got) in enumerate(zip(model, ours)):
            for n in outputs:
                if not same(want[n], got[n]):
                    raise Difference(
                        f"after step {k}: {n} hand-written {got[n]!r}, model {want[n]!r}"
                    )
                for what, rows in runs.items():
                    value = rows[k][names[n]]
                    if not same(float(value) if isinstance(got[n], float) else value, got[n]):
                        raise Difference(
                            f"after step {k}: {n} original ({what}) {value!r}, hand-written "
                            f"{got[n]!r}{shown}"
                        )

    try:
        compare()
    except Difference as e:
        return f"DIFFERS {e}"
    return f"{calls[0]:,} calls: original = hand-written = model (FMI 2.0, 3.0; CS, ME)"


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--scl", required=True, type=Path, help="the folder of the LGF exports")
    parser.add_argument("--examples", type=int, default=200, help="scenarios per block")
    parser.add_argument("--blocks", nargs="*", help="only these blocks")
    parser.add_argument("--seed", type=int, default=random.randrange(2**32))
    args = parser.parse_args(argv)
    if not args.scl.is_dir():
        print(f"error: --scl {args.scl}: no such folder", file=sys.stderr)
        return 2
    chosen = [b for b in blocks() if not args.blocks or b.name in args.blocks]
    equal = 0
    with tempfile.TemporaryDirectory(prefix="lgf-originals-") as scratch:
        for block in chosen:
            source = args.scl / f"{block.name}.scl"
            if not source.is_file():
                print(f"{block.name}: no {source.name} in the folder", flush=True)
                continue
            try:
                sources, name = wrapped(source, block.name, Path(scratch))
                original = {
                    fmi: scl.compile([*sources, *UDTS], block=name, fmi=fmi,
                                     output=Path(scratch) / f"{block.name}-{fmi}.fmu", win64=False,
                                     **PROPERTIES.get(block.name, {}))
                    for fmi in (2, 3)
                }  # fmt: skip
            except scl.SclError as e:
                first = str(e).strip().splitlines()[0]
                print(f"{block.name}: refused: {first}", flush=True)
                continue
            line = check_block(block, original, args.examples, args.seed)
            equal += line[0].isdigit()
            print(f"{block.name}: {line}", flush=True)
    print(f"{equal} of {len(chosen)} blocks: original = hand-written = model (seed {args.seed})")
    return 0 if equal == len(chosen) else 1


if __name__ == "__main__":
    sys.exit(main())
