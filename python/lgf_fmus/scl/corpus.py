"""`lgf-fmus compile --check-folder FOLDER`: every block of a folder of SCL sources (a TIA Portal
export, a library), compiled into an FMU and run, one line per block and the totals
(docs/scl.md §7). It measures how much of real SCL the compiler takes; it is no test of the
results.

- A FUNCTION_BLOCK is compiled from its own file plus every file of the folder that defines only
  types (UDTs) or DBs and every file that defines a block or UDT it uses (by name, and theirs
  in turn; a UDT no file defines is reported as one the folder lacks), then run for `steps` PLC
  cycles of 100 ms with its start values, in a child process. A loop that never ends is stopped
  by the FMU's cycle watchdog, which fails the run naming the loop (docs/scl.md §3.4); a time
  limit on the child guards the check besides.
- A FUNCTION is compiled through a wrapper FB written here: its inputs, outputs and in-outs
  become the wrapper's (their declarations as the FC writes them; an ARRAY[*] input or output
  an in/out, one of more dimensions a fixed ARRAY), its return value an output `Ret_Val`, and
  each cycle calls the FC once.
- Anything else (an OB, a file of types only) is listed as not a block.
"""

from __future__ import annotations

import re
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path

from . import ast as A
from . import types as T
from .ast import SclError
from .types import K

_RUN = """
import sys
from fmpy import simulate_fmu
simulate_fmu(sys.argv[1], stop_time=float(sys.argv[2]), output_interval=0.1, step_size=0.1)
"""


@dataclass
class Result:
    block: str
    file: str
    outcome: str  # "ran", "refused", "failed"
    detail: str = ""

    def line(self) -> str:
        if self.outcome == "ran":
            return f"{self.block}: compiled, {self.detail}"
        return f"{self.block}: {self.outcome}: {self.detail}"


def _first_line(error: BaseException) -> str:
    text = str(error).strip()
    return text.splitlines()[0] if text else type(error).__name__


def _sections(text: str, start: int) -> str:
    """The interface sections (VAR_INPUT, VAR_OUTPUT, VAR_IN_OUT) of the block whose header is
    at `start`, as written, up to its BEGIN."""
    body = re.search(r"^\s*BEGIN\b", text[start:], re.IGNORECASE | re.MULTILINE)
    header = text[start : start + body.start()] if body else text[start:]
    pattern = r"^\s*(VAR_INPUT|VAR_OUTPUT|VAR_IN_OUT)\b.*?^\s*END_VAR\b"
    return "\n".join(
        m.group(0) for m in re.finditer(pattern, header, re.IGNORECASE | re.MULTILINE | re.DOTALL)
    )


# the bounds of each dimension of an ARRAY[*, *] that the wrapper passes to an FC
WRAPPER_SIDE = 4


def _open_arrays(fc, text: str) -> tuple[str, str]:
    """The FC's source without the declarations of its ARRAY[*] parameters, and the wrapper's
    VAR_IN_OUT of them: an FB has ARRAY[*] only as an in/out (S7), the FMU's FB of one
    dimension only (a table, docs/scl.md §4), so one of more dimensions is a fixed ARRAY of
    WRAPPER_SIDE elements in each dimension."""
    lines = text.splitlines(keepends=True)
    moved, statics = [], []
    for d in fc.decls:
        ref = d.type_ref
        if not isinstance(ref, A.ArrayTypeRef) or None not in ref.dims:
            continue
        if isinstance(ref.element, A.Node):
            continue
        wide = _wide(T.lookup(ref.element[0]))
        if d.section == "VAR_IN_OUT" and len(ref.dims) == 1 and not wide:
            continue  # an ARRAY[*] in/out of one dimension: the wrapper's table as written
        element = ref.element[0]
        element = element if re.fullmatch(r"[A-Za-z_]\w*", element) else f'"{element}"'
        if len(ref.dims) > 1 or wide:
            dims = ", ".join([f"0..{WRAPPER_SIDE - 1}"] * len(ref.dims))
        else:
            dims = "*"
        name = d.name if re.fullmatch(r"[A-Za-z_]\w*", d.name) else f'"{d.name}"'
        # a table of 64-bit integers is no FMI 2.0 variable: a static ARRAY of the wrapper's
        (statics if wide else moved).append(f"   {name} : ARRAY[{dims}] OF {element};")
        lines[d.loc.line - 1] = "\n"
    sections = [f"\n{kind}\n" + "\n".join(decls) + "\nEND_VAR" for kind, decls in
                (("VAR_IN_OUT", moved), ("VAR", statics)) if decls]  # fmt: skip
    return "".join(lines), "".join(sections)


def _wide(t) -> bool:
    """A 64-bit integer or bit string (LINT, ULINT, LWORD), which FMI 2.0 cannot carry."""
    return isinstance(t, T.Elementary) and t.bits == 64 and t.kind in (K.INT, K.BITS)


def _wide_parameters(fc, text: str) -> tuple[str, str]:
    """The FC's source without the declarations of its 64-bit integer parameters, and the
    wrapper's VAR of them: FMI 2.0 has no 64-bit integer variable (docs/scl.md §3.1), so the
    wrapper passes statics of its own, which start at 0 as an input left unset would."""
    lines = text.splitlines(keepends=True)
    moved = []
    for d in fc.decls:
        interface = d.section in ("VAR_INPUT", "VAR_OUTPUT", "VAR_IN_OUT")
        if interface and d.type_ref is None and _wide(T.lookup(d.type_name)):
            name = d.name if re.fullmatch(r"[A-Za-z_]\w*", d.name) else f'"{d.name}"'
            moved.append(f"   {name} : {d.type_name};")
            lines[d.loc.line - 1] = "\n"
    if not moved:
        return text, ""
    return "".join(lines), "\nVAR\n" + "\n".join(moved) + "\nEND_VAR"


def _wrapper(fc, text: str) -> tuple[str, str]:
    """(name, SCL) of an FB that calls the FUNCTION `fc` once a cycle."""
    name = f"{fc.name}_Wrapper"
    text, in_outs = _open_arrays(fc, text)
    text, statics = _wide_parameters(fc, text)
    header = re.search(
        r"^\s*FUNCTION\s+\"?" + re.escape(fc.name) + r"\b", text, re.IGNORECASE | re.MULTILINE
    )
    sections = _sections(text, header.start() if header else 0) + in_outs
    returns = fc.return_type and fc.return_type.lower() != "void"
    if returns:
        section = "VAR" if _wide(T.lookup(fc.return_type)) else "VAR_OUTPUT"
        sections += f"\n{section}\n   Ret_Val : {fc.return_type};\nEND_VAR"
    sections += statics
    arguments = []
    for d in fc.decls:
        # a name quoted only where it must be, as TIA writes them
        plain = re.fullmatch(r"[A-Za-z_]\w*", d.name)
        n = d.name if plain else f'"{d.name}"'
        if d.section in ("VAR_INPUT", "VAR_IN_OUT"):
            arguments.append(f"{n} := #{n}")
        elif d.section == "VAR_OUTPUT":
            arguments.append(f"{n} => #{n}")
    call = f'"{fc.name}"({", ".join(arguments)})'
    statement = f"#Ret_Val := {call};" if returns else f"{call};"
    source = f'FUNCTION_BLOCK "{name}"\n{sections}\nBEGIN\n    {statement}\nEND_FUNCTION_BLOCK\n'
    return name, source


def _uses(path: Path, parsed: dict, defined: dict) -> list[Path]:
    """The other files of the folder whose blocks and UDTs the file `path` uses, and theirs in
    turn: every file that defines a name the source writes ("LGF_ShellSort_UDInt")."""
    own = {b.name.lower() for b in parsed[path][1]}  # never a second file of the same name
    found, todo = [], [path]
    while todo:
        text = parsed[todo.pop()][0]
        for word in set(re.findall(r'"([^"\n]+)"|([A-Za-z_]\w*)', text)):
            key = (word[0] or word[1]).lower()
            other = defined.get(key)
            if other is not None and other != path and key not in own and other not in found:
                found.append(other)
                todo.append(other)
    return found


def _run(fmu: Path, steps: int, timeout: float) -> str | None:
    """None when the FMU ran `steps` cycles in FMPy, else why not."""
    try:
        done = subprocess.run(
            [sys.executable, "-c", _RUN, str(fmu), str(steps * 0.1)],
            capture_output=True,
            text=True,
            timeout=timeout,
        )
    except subprocess.TimeoutExpired:
        return f"ran past {timeout:g} s of wall time (a loop that does not end?)"
    if done.returncode != 0:
        # the FMU's own error (FMPy's logger prints it), e.g. the cycle watchdog's time error
        # naming the loop (docs/scl.md §3.4), before FMPy's exception
        logged = [line for line in done.stdout.splitlines() if line.startswith("[ERROR]")]
        if logged:
            return logged[0].removeprefix("[ERROR]").strip()
        lines = [line for line in done.stderr.splitlines() if line.strip()]
        return lines[-1] if lines else f"exit status {done.returncode}"
    return None


def check_folder(
    folder, steps: int = 100, fmi: int = 2, timeout: float = 60.0, out=print, iec_check=False
) -> list[Result]:
    """Compiles and runs every block of the .scl files of `folder` (iec_check: TIA's "IEC
    check", docs/scl.md §3.2); prints a line per block and the totals through `out`, and
    returns the results."""
    from . import _read, compile, parser

    folder = Path(folder)
    files = sorted(p for p in folder.iterdir() if p.suffix.lower() == ".scl")
    if not files:
        raise SclError(None, f"{folder}: no .scl file in it")
    parsed, results = {}, []
    for path in files:
        try:
            ((_, text),) = _read([path])
            parsed[path] = (text, parser.parse(text, str(path)))
        except SclError as e:
            results.append(Result(path.stem, str(path), "refused", _first_line(e)))
    shared = [
        path
        for path, (_, blocks) in parsed.items()
        if blocks and all(b.kind in ("TYPE", "DATA_BLOCK") for b in blocks)
    ]
    defined = {}  # lower-case name of a block or UDT -> the first file that defines it
    for path, (_, blocks) in parsed.items():
        for b in blocks:
            defined.setdefault(b.name.lower(), path)
    with tempfile.TemporaryDirectory(prefix="lgf-check-") as scratch:
        scratch = Path(scratch)
        for path, (text, blocks) in parsed.items():
            if path in shared:
                continue
            for b in blocks:
                if b.kind not in ("FUNCTION_BLOCK", "FUNCTION"):
                    continue
                uses = [p for p in _uses(path, parsed, defined) if p not in shared]
                sources, name = [path, *uses, *shared], b.name
                try:
                    if b.kind == "FUNCTION":
                        name, source = _wrapper(b, text)
                        wrapper = scratch / f"{name}.scl"
                        wrapper.write_text(source, encoding="utf-8")
                        sources.append(wrapper)
                    fmu = compile(sources, block=name, fmi=fmi, output=scratch / f"{name}.fmu",
                                  win64=False, iec_check=iec_check)  # fmt: skip
                except SclError as e:
                    detail = _first_line(e)
                    lacked = re.search(r"unknown or unsupported data type '([^']+)'", detail)
                    lacked = lacked or re.search(
                        r"unknown or unsupported function '([^']+)'", detail
                    )
                    missing = lacked.group(1) if lacked else ""
                    refused = {Path(r.file).stem.lower(): r.file for r in results}
                    if missing.lower() in refused and missing.lower() not in defined:
                        # the file of that name is refused itself (above): it is no block here
                        detail += f": the file {Path(refused[missing.lower()]).name} is refused"
                    elif (
                        lacked
                        and missing.lower() not in defined
                        and f'"{missing}"' in text  # a plain name is no UDT's nor block's
                    ):
                        detail += f": a UDT or block the folder lacks ({missing})"
                    results.append(Result(b.name, str(path), "refused", detail))
                    continue
                except Exception as e:  # a defect of the compiler: counted, never hidden
                    detail = f"internal error {type(e).__name__}: {_first_line(e)}"
                    results.append(Result(b.name, str(path), "failed", detail))
                    continue
                failure = _run(fmu, steps, timeout)
                if failure:
                    results.append(Result(b.name, str(path), "failed", f"run: {failure}"))
                else:
                    results.append(Result(b.name, str(path), "ran", f"ran {steps} steps"))
    for r in sorted(results, key=lambda r: r.block.lower()):
        out(r.line())
    counts = {k: sum(r.outcome == k for r in results) for k in ("ran", "refused", "failed")}
    out(
        f"{len(results)} blocks: {counts['ran']} compiled and ran {steps} steps, "
        f"{counts['refused']} refused, {counts['failed']} failed"
    )
    return results
