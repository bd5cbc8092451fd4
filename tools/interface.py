"""A block's interface.c, written from its interface.toml (src/blocks/<Block>/): the one
description of the block's interface, from which the FMU's table (src/core/model.h), and through
it the modelDescription.xml, the documentation and the block's page, are made. CMake runs it when
it configures the build, for every block in one run (python -m tools.interface <Block>...
--out <folder>), into the build's generated/ folder, which stands before src/ on the include
path; the FMU's sources/ carry the file it writes.

interface.toml holds, at its top:
    prefix            the C prefix of the block's struct and functions (<prefix>_init, _call)
    guid, stop_time   the FMU's GUID and its default experiment's stop time (s)
    description       the FMU's description
    cycle             "OB" (the block uses the period of the OB that calls it), "OB unused" (it
                      does not) or "CI" (a cyclic-interrupt block, the period replacing callOB);
                      or a table [cycleTime] with min (s), original and description
    cycle_granularity_us, cycle_codes
                      a cyclic-interrupt block's grain of the period and what its original
                      reports for an invalid one (model.cycle_granularity_us, .cycle_codes)
    check, state_check
                      true where block.c defines <prefix>_check or <prefix>_state_check, the
                      rules of model.check and model.state_check
    signal_generator  true for a signal generator, whose table is the one they share
                      (src/iec/signal_generator.h): it has prefix, guid and description only
then its tables:
    [[variables]]     a row each: vr, name (the FMI name, and the field of the block's struct
                      unless field names another), type (BOOL INT USINT WORD REAL LREAL TIME),
                      causality (input, output, parameter: fixed, tunable), description; unit,
                      original; min and max where they are not the type's whole range (a
                      number, or a constant of the block's C); an array of structures
                      (setpoints[i].member) has member and count. `row` names one of the rows
                      blocks share (src/core/model.h): subFunctionStatus, historyEnable.
    [status]          the texts of the block's error codes for the log, by the code's constant
    [statics]         the block's statics in the FMU state, in order: field = type (BOOL INT8
                      UINT8 INT16 UINT16 INT32 UINT32 FLOAT32 INT64 REAL RESULT; TIMER for an IEC
                      timer's; "REAL[n]" for the n elements of an array)
"""

from __future__ import annotations

import argparse
import re
import sys
import tomllib
from pathlib import Path

from lgf_fmus.scl.escape import c_string
from tools import ROOT

BLOCKS_DIR = ROOT / "src" / "blocks"

# The cycleTime rows that blocks share (src/core/model.h).
CYCLE_ROWS = {
    "OB": "OB_CYCLE_TIME_ROW",
    "OB unused": "OB_CYCLE_TIME_ROW_UNUSED",
    "CI": "CI_CYCLE_TIME_ROW",
}
SHARED_ROWS = {
    "subFunctionStatus": "SUBFUNCTION_STATUS_ROW",
    "historyEnable": "HISTORY_ENABLE_INPUT",
}
ROLES = {
    "input": "ROLE_INPUT",
    "output": "ROLE_OUTPUT",
    "parameter": "ROLE_FIXED_PARAMETER",
    "tunable": "ROLE_TUNABLE_PARAMETER",
}
# Each type's whole range in FMI units, by causality where they differ (src/core/model.h: TIME).
RANGES = {
    "BOOL": ("0", "1"),
    "INT": ("-32768", "32767"),
    "USINT": ("0", "255"),
    "WORD": ("0", "65535"),
    "REAL": ("-INFINITY", "INFINITY"),
    "LREAL": ("-INFINITY", "INFINITY"),
    "TIME": ("-TIME_MAX_S", "TIME_MAX_S"),
}
TIME_OUTPUT_RANGE = ("-2147483.648", "TIME_MAX_S")
# The types and causalities that model.h has a row macro for (BOOL_INPUT, ...).
ROW_MACROS = {"BOOL", "INT", "REAL", "LREAL", "TIME"}
TOP_KEYS = {"prefix", "guid", "description", "stop_time", "cycle", "cycleTime",
            "cycle_granularity_us", "cycle_codes", "check", "state_check", "signal_generator",
            "variables", "status", "statics"}  # fmt: skip
REQUIRED_KEYS = {"vr", "name", "type", "causality", "description"}
ROW_KEYS = REQUIRED_KEYS | {"field", "min", "max", "unit", "original", "member", "count"}
FIELD_TYPES = {
    "BOOL", "INT8", "UINT8", "INT16", "UINT16", "INT32", "UINT32", "FLOAT32", "INT64", "REAL",
    "RESULT",
}  # fmt: skip


class InterfaceError(Exception):
    """An interface.toml that does not describe a block."""


def load(block: str) -> dict:
    path = BLOCKS_DIR / block / "interface.toml"
    try:
        with path.open("rb") as file:
            return tomllib.load(file)
    except (OSError, tomllib.TOMLDecodeError) as error:
        raise InterfaceError(str(error)) from None


def number(value) -> str:
    """A min or max as C: a number, or the name of a constant of the block's C."""
    if isinstance(value, str):
        return value
    if value == float("inf"):
        return "INFINITY"
    if value == float("-inf"):
        return "-INFINITY"
    return repr(value) if isinstance(value, float) else str(value)


def variable(block: str, row: dict) -> str:
    """One row of the table."""
    name = row.get("name", row.get("row", f"value reference {row.get('vr')}"))
    allowed = {"vr", "row"} if "row" in row else ROW_KEYS
    unknown = sorted(set(row) - allowed)
    missing = sorted(key for key in ({"vr"} if "row" in row else REQUIRED_KEYS) if key not in row)
    if unknown or missing:
        raise InterfaceError(
            f"the variable {name} has no key {', '.join(unknown)}"
            if unknown
            else f"the variable {name} lacks {', '.join(missing)}"
        )
    if "row" in row:
        if row["row"] not in SHARED_ROWS:
            raise InterfaceError(f"no shared row {row['row']}: one of {', '.join(SHARED_ROWS)}")
        return f"{SHARED_ROWS[row['row']]}({row['vr']})"
    kind, causality = row["type"], row["causality"]
    if kind not in RANGES:
        raise InterfaceError(f"the variable {name} has type {kind}: one of {', '.join(RANGES)}")
    if causality not in ROLES:
        raise InterfaceError(
            f"the variable {name} has causality {causality}: one of {', '.join(ROLES)}"
        )
    whole = TIME_OUTPUT_RANGE if (kind, causality) == ("TIME", "output") else RANGES[kind]
    low, high = number(row.get("min", whole[0])), number(row.get("max", whole[1]))
    extras = [c_string(row["description"])]
    extras += [f".{key} = {c_string(row[key])}" for key in ("unit", "original") if key in row]
    field = row.get("field", name)
    whole_range = (low, high) == whole
    typed = f"VAR_{kind}, {ROLES[causality]}, {low}, {high}"
    if "member" in row:  # setpoints[i].member, an array of structures
        head = (
            f"SETPOINTS_ROW({row['vr']}, {row['member']}, VAR_{kind}, {row['count']}, {low}, {high}"
        )
    elif kind in ROW_MACROS and causality in ("input", "output") and whole_range and field == name:
        head = f"{kind}_{causality.upper()}({row['vr']}, {name}"
    elif field == name:
        head = f"ROW({row['vr']}, {name}, {typed}"
    else:
        head = f'NAMED_ROW({row["vr"]}, "{name}", {field}, {typed}'
    return f"{head}, {', '.join(extras)})"


def statics(spec: dict) -> list[str]:
    rows = []
    for field, kind in spec.items():
        array = re.fullmatch(r"(\w+)\[(\d+)\]", kind)
        if kind == "TIMER":
            rows.append(f"TIMER_STATICS({field})")
        elif array and array[1] in FIELD_TYPES:
            rows += [f"STATIC(block, {field}[{i}], FIELD_{array[1]})" for i in range(int(array[2]))]
        elif kind in FIELD_TYPES:
            rows.append(f"STATIC(block, {field}, FIELD_{kind})")
        else:
            types = ", ".join(sorted(FIELD_TYPES))
            raise InterfaceError(
                f"the static {field} has type {kind}: one of TIMER, {types} or an array of one, "
                "as REAL[5]"
            )
    return rows


def c_source(block: str, spec: dict | None = None) -> str:
    """The interface.c of block."""
    spec = load(block) if spec is None else spec
    unknown = sorted(set(spec) - TOP_KEYS)
    needed = {"prefix", "guid", "description"} | (
        set() if spec.get("signal_generator") else {"stop_time"}
    )
    missing = sorted(needed - set(spec))
    if "cycle" not in spec and "cycleTime" not in spec and not spec.get("signal_generator"):
        missing.append("cycle")
    if unknown or missing:
        raise InterfaceError(
            f"no key {', '.join(unknown)}" if unknown else f"it lacks {', '.join(missing)}"
        )
    prefix = spec["prefix"]
    head = [
        f"/* {block}: its interface table, generated by tools/interface.py from",
        f" * src/blocks/{block}/interface.toml: edit that file, not this one. */",
        "#include <float.h>",
        "#include <math.h>",
        "",
        f'#include "blocks/{block}/block.c"',
    ]
    if spec.get("signal_generator"):
        return "\n".join(
            head
            + [
                "",
                f"LGF_SIGNAL_MODEL({prefix}, {c_string(block)}, {c_string(spec['guid'])},",
                f"                 {c_string(spec['description'])});",
                "",
            ]
        )
    cycle = spec.get("cycle")
    if cycle is None:
        own = spec["cycleTime"]
        cycle_row = (
            f"CYCLE_TIME_ROW({number(own['min'])}, {c_string(own['original'])}, "
            f"{c_string(own['description'])})"
        )
    else:
        if cycle not in CYCLE_ROWS:
            raise InterfaceError(f"the cycle {cycle} is none of {', '.join(CYCLE_ROWS)}")
        cycle_row = CYCLE_ROWS[cycle]
    rows = [cycle_row] + [variable(block, row) for row in spec.get("variables", [])]
    lines = head + ['#include "core/model.h"', "", f"typedef {prefix} block;", ""]
    lines += ["static const model_variable variables[] = {"]
    lines += [f"    {row}," for row in rows]
    lines += ["};", "", f"BLOCK_FUNCTIONS({prefix})", ""]
    fields = []
    for check in ("check", "state_check"):
        if spec.get(check):
            lines += [
                f"static const char *{check}(const void *data, char *msg, size_t size)",
                "{",
                f"    return {prefix}_{check}(data, msg, size);",
                "}",
                "",
            ]
            fields.append(f".{check} = {check}")
    if any(row.get("name") == "status" for row in spec.get("variables", [])):
        texts = [
            f"STATUS_TEXT({code}, {c_string(text)})"
            for code, text in spec.get("status", {}).items()
        ]
        lines += ["BLOCK_STATUS(" + ", ".join(texts) + ")", ""]
        fields.append("BLOCK_STATUS_FIELDS")
    if spec.get("statics"):
        lines += ["static const model_static statics[] = {"]
        lines += [f"    {row}," for row in statics(spec["statics"])]
        lines += ["};", ""]
        fields.insert(0, "BLOCK_STATICS")
    if "cycle_codes" in spec:
        cycle_fields = f"CI_CYCLE({spec['cycle_granularity_us']}, {c_string(spec['cycle_codes'])})"
    else:
        cycle_fields = "NO_CYCLE_CODES"
    fields.insert(1 if spec.get("statics") else 0, cycle_fields)
    lines += [
        f"BLOCK_MODEL({c_string(block)}, {c_string(spec['guid'])}, {number(spec['stop_time'])},",
        f"            {c_string(spec['description'])},",
        f"            {', '.join(fields)});",
        "",
    ]
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("blocks", nargs="+", help="the blocks' folder names in src/blocks/")
    parser.add_argument(
        "--out", required=True, type=Path, help="the folder of blocks/<Block>/interface.c"
    )
    args = parser.parse_args(argv)
    failed = False
    for block in args.blocks:
        try:
            text = c_source(block)
        except InterfaceError as error:  # every description's error, not only the first
            print(f"error: src/blocks/{block}/interface.toml: {error}", file=sys.stderr)
            failed = True
            continue
        # written only when it changes, so that nothing is rebuilt for nothing
        out = args.out / "blocks" / block / "interface.c"
        if not out.exists() or out.read_text(encoding="utf-8") != text:
            out.parent.mkdir(parents=True, exist_ok=True)
            out.write_text(text, encoding="utf-8")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
