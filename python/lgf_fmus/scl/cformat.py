"""The generated C in the project's C style (docs/scl.md §4): block.h, block.c and interface.c
through clang-format with the style of the repository's .clang-format, as the hand-written
blocks are. The clang-format of the `clang-format` Python package where it is installed (as in
the project's virtual environment), else one on the PATH; without one, or where it fails (an
older version without a key of the style), the C stays as generated: the same C, laid out
otherwise. The same SCL gives the same C with the same clang-format."""

from __future__ import annotations

import os
import shutil
import subprocess
import tempfile
from pathlib import Path

# .clang-format of the repository
STYLE = {
    "BasedOnStyle": "LLVM",
    "IndentWidth": 4,
    "ColumnLimit": 100,
    "BreakBeforeBraces": "Linux",
    "AllowShortFunctionsOnASingleLine": "All",
    "AllowShortIfStatementsOnASingleLine": "WithoutElse",
    "AllowShortLoopsOnASingleLine": "true",
    "AllowShortCaseLabelsOnASingleLine": "true",
    "AllowShortBlocksOnASingleLine": "Never",
    "AlignConsecutiveMacros": "false",
    "AlignTrailingComments": "true",
    "AlignAfterOpenBracket": "Align",
    "BinPackArguments": "true",
    "BinPackParameters": "true",
    "IndentCaseLabels": "false",
    "PointerAlignment": "Right",
    "SortIncludes": "Never",
    "SpaceAfterCStyleCast": "false",
    "IncludeBlocks": "Preserve",
    "ReflowComments": "false",
    "AlignEscapedNewlines": "Right",
    "BreakBinaryOperations": "Never",
    "BreakBeforeBinaryOperators": "None",
    "BreakBeforeTernaryOperators": "true",
    "PenaltyReturnTypeOnItsOwnLine": 1000,
}


def executable() -> str | None:
    try:
        import clang_format

        path = clang_format.get_executable("clang-format")
        if os.path.exists(path):
            return path
    except (ImportError, AttributeError, OSError):
        pass
    return shutil.which("clang-format")


def formatted(files: dict[str, str]) -> dict[str, str]:
    """The C files (by path) in the project's style, formatted by one run of clang-format; the
    others as they are."""
    tool = executable()
    names = [n for n in files if n.endswith((".c", ".h"))]
    if tool is None or not names:
        return files
    style = "{" + ", ".join(f"{k}: {v}" for k, v in STYLE.items()) + "}"
    with tempfile.TemporaryDirectory(prefix="lgf-scl-format-") as folder:
        paths = []
        for k, name in enumerate(names):
            path = Path(folder) / f"{k}{Path(name).suffix}"
            path.write_text(files[name], encoding="utf-8")
            paths.append(path)
        try:
            run = subprocess.run(
                [tool, f"-style={style}", "-i", *map(str, paths)],
                capture_output=True,
                text=True,
                timeout=60,
            )
        except (OSError, subprocess.TimeoutExpired):
            return files
        if run.returncode != 0:
            return files  # every file formatted, or none
        out = dict(files)
        for name, path in zip(names, paths):
            out[name] = path.read_text(encoding="utf-8")
        return out
