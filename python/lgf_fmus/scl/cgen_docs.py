"""The FMU's documentation/index.html (docs/scl.md §4): the FB's title and headers, and its
interface from the declarations and their comments; every text through escape.html_text."""

from __future__ import annotations

from . import ast as A
from .cnames import is_table
from .escape import html_text
from .types import table_count


def documentation(checker) -> str:
    """documentation/index.html of the FMU: the FB's title and headers, and its interface from
    the declarations and their comments (docs/scl.md §4)."""
    block = checker.block
    e = html_text
    rows = [
        "<tr><td><code>cycleTime</code></td><td>parameter</td><td>REAL, s</td><td>0.1</td>"
        "<td>period of the calling OB: one call of the FB per cycleTime</td></tr>"
    ]
    for d in block.decls:
        if not d.section.interface:
            continue
        causality = {A.Section.INPUT: "input", A.Section.OUTPUT: "output"}.get(d.section)
        if d.section == A.Section.IN_OUT:  # docs/scl.md §4
            causality = (
                f"tunable parameters {d.name}[i], their number {table_count(d.name)}"
                if is_table(d)
                else f"input, and output {d.name}_out"
            )
        causality = e(causality)
        start = e(d.start.text) if isinstance(d.start, A.Literal) else ""
        rows.append(
            f"<tr><td><code>{e(d.name)}</code></td><td>{causality}</td><td>{e(str(d.type))}</td>"
            f"<td>{start}</td><td>{e(d.comment)}</td></tr>"
        )
    rows.append(
        "<tr><td><code>maxCycleTime</code></td><td>parameter</td><td>TIME, s</td><td>0.15</td>"
        "<td>the cycle watchdog: a call whose loops run more than 10000 iterations per ms of it "
        "ends the step with an error, as the CPU's time error (docs/scl.md §3.4)</td></tr>"
    )
    statics = [d.name for d in block.decls if d.section.static]
    headers = "".join(
        f"<li>{e(k.title())}: {e(v)}</li>" for k, v in block.headers.items() if k != "TITLE"
    )
    title = block.headers.get("TITLE", "")
    return "\n".join(
        [
            "<!DOCTYPE html>",
            f'<html lang="en"><head><meta charset="utf-8"/><title>{e(block.name)}</title></head>',
            "<body>",
            f"<h1>{e(block.name)}</h1>",
            f"<p>{e(title)}</p>" if title else "",
            f"<ul>{headers}</ul>" if headers else "",
            "<p>Compiled from its SCL by lgf-fmus (docs/scl.md): the FUNCTION_BLOCK runs once per "
            "<code>cycleTime</code> with S7-1500 semantics, the first call at the start time.</p>",
            "<h2>Interface</h2>",
            "<table><tr><th>name</th><th>causality</th><th>type</th><th>start</th>"
            "<th>description</th></tr>",
            *rows,
            "</table>",
            f"<p>Statics (in the FMU state, and FMI local variables to read): "
            f"{e(', '.join(statics))}.</p>"
            if statics
            else "",
            "</body></html>",
            "",
        ]
    )
