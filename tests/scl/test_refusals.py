"""Every refusal site of the compiler (each `refuse(...)` and `SclError(...)` of lgf_fmus.scl) is
reached by a test: the tests of refusals (REFUSAL_TESTS: test_errors.py, test_diagnostics.py,
..., and the refusals of the environment here: no source, no C compiler, ...) run once more
under a line tracer (refusal_tracer.py), and a site that none of them reaches fails, unless it
is one of EXCEPTIONS, with the reason no test can reach it."""

from __future__ import annotations

import ast
import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from lgf_fmus import scl
from lgf_fmus.scl import build
from lgf_fmus.scl.corpus import check_folder
from tests.scl import test_errors as errors
from tests.scl.driver import ROOT
from tests.timeouts import hang_guard

PACKAGE = Path(scl.__file__).parent
# (file, a part of the site's text): the sites no source can reach, and why
EXCEPTIONS = {
    # the lexer takes every T#, TIME#, LT# and LTIME# literal as a time literal first
    ("check_expressions.py", "write a TIME as T#"),
    # every elementary type of the subset has its field kind in src/core/model.h
    ("check_types.py", "the core cannot keep a"),
    # the modelDescription writer failing when it runs: compiled from the core's describe.c
    ("build.py", "failed (a defect of lgf_fmus.scl"),
}
FB = errors.fb("", "    #o := #i;\n")


def sites() -> dict[tuple[str, int], str]:
    """(file, line) -> the text of every call of refuse or SclError in the compiler."""
    found = {}
    for path in sorted(PACKAGE.glob("*.py")):
        text = path.read_text(encoding="utf-8")
        for node in ast.walk(ast.parse(text)):
            if not isinstance(node, ast.Call):
                continue
            f = node.func
            name = f.id if isinstance(f, ast.Name) else getattr(f, "attr", None)
            if name in ("refuse", "SclError") and path.name != "diagnostics.py":
                found[path.name, node.lineno] = ast.get_source_segment(text, node)
    return found


def refused(call) -> str:
    with pytest.raises(scl.SclError) as caught:
        call()
    return str(caught.value)


# The refusals of the environment and of the input files (docs/scl.md §4, §5): each a function
# of a folder and pytest's monkeypatch that must be refused, and the message's start
def no_source(tmp, mp):
    return refused(lambda: scl.generate_c([], "Fb"))


def unreadable(tmp, mp):
    return refused(lambda: scl.generate_c([tmp / "missing.scl"], "Fb"))


def not_utf8(tmp, mp):
    (tmp / "latin1.scl").write_bytes(b'FUNCTION_BLOCK "Fb" // \xe4\nBEGIN\nEND_FUNCTION_BLOCK\n')
    return refused(lambda: scl.generate_c([tmp / "latin1.scl"], "Fb"))


def fmi_4(tmp, mp):
    (tmp / "fb.scl").write_text(FB, encoding="utf-8")
    return refused(lambda: scl.compile([tmp / "fb.scl"], "Fb", fmi=4))


def no_c_compiler(tmp, mp):
    (tmp / "fb.scl").write_text(FB, encoding="utf-8")
    mp.delenv("CC", raising=False)
    mp.setattr(build.shutil, "which", lambda name: None)
    return refused(lambda: scl.compile([tmp / "fb.scl"], "Fb", output=tmp / "Fb.fmu"))


def no_mingw(tmp, mp):
    (tmp / "fb.scl").write_text(FB, encoding="utf-8")
    which = shutil.which
    mp.setattr(build.shutil, "which", lambda name: None if "mingw" in name else which(name))
    return refused(lambda: scl.compile([tmp / "fb.scl"], "Fb", output=tmp / "F.fmu", win64=True))


def no_aarch64(tmp, mp):
    (tmp / "fb.scl").write_text(FB, encoding="utf-8")
    which = shutil.which
    mp.setattr(build.shutil, "which", lambda name: None if "aarch64" in name else which(name))
    mp.setattr(build.host, "machine", lambda: "x86_64")  # the cross build, on any machine
    compile = lambda: scl.compile(  # noqa: E731
        [tmp / "fb.scl"], "Fb", fmi=3, output=tmp / "F.fmu", win64=False, aarch64=True
    )
    return refused(compile)


def aarch64_fmi2(tmp, mp):
    (tmp / "fb.scl").write_text(FB, encoding="utf-8")
    return refused(lambda: scl.compile([tmp / "fb.scl"], "Fb", output=tmp / "F.fmu", aarch64=True))


def no_core_sources(tmp, mp):
    mp.setattr(build, "PACKAGE", tmp / "lgf_fmus" / "scl")
    return refused(build.c_sources)


def no_fmi_headers(tmp, mp):
    import fmpy

    mp.setattr(fmpy, "__file__", str(tmp / "fmpy" / "__init__.py"))
    return refused(build.fmi_headers)


def c_compiler_refuses(tmp, mp):
    (tmp / "fb.scl").write_text(FB, encoding="utf-8")
    mp.setattr(build, "FLAGS", [*build.FLAGS, "-include", str(tmp / "missing.h")])
    return refused(lambda: scl.compile([tmp / "fb.scl"], "Fb", output=tmp / "Fb.fmu", win64=False))


def empty_folder(tmp, mp):
    (tmp / "empty").mkdir()
    return refused(lambda: check_folder(tmp / "empty", out=lambda line: None))


ENVIRONMENT = {
    no_source: "no SCL source given",
    unreadable: "missing.scl: cannot read it (No such file or directory)",
    not_utf8: "latin1.scl: not UTF-8 text",
    fmi_4: "fmi must be 2 or 3, not 4",
    no_c_compiler: "no C compiler found (set CC, or install gcc or clang)",
    no_mingw: "no x86_64-w64-mingw32-gcc found for the win64 binary",
    no_aarch64: "no aarch64-linux-gnu-gcc with its C library found for the aarch64-linux binary",
    aarch64_fmi2: "FMI 2.0 names no platform for aarch64 Linux: use --fmi 3",
    no_core_sources: "the C sources of the core are missing from ",
    no_fmi_headers: "FMPy's FMI headers are missing from ",
    c_compiler_refuses: "internal error: the C compiler refused the generated C (a defect",
    empty_folder: "empty: no .scl file in it",
}


@pytest.mark.parametrize("case", list(ENVIRONMENT), ids=lambda f: f.__name__)
def test_a_refusal_of_the_environment(tmp_path, monkeypatch, case):
    message = case(tmp_path, monkeypatch)
    assert ENVIRONMENT[case] in message.splitlines()[0], message


# the tests of refusals, run once more under the tracer (a new one of its own file joins here)
REFUSAL_TESTS = [
    "test_errors.py",
    "test_diagnostics.py",
    "test_tia_syntax.py",
    "test_program_errors.py",
    "test_program_tags.py::test_a_tag_table_refused",
    "test_program_tags.py::test_an_address_without_tag_and_a_partition_refused",
    "test_inout.py",
    "test_strings.py::test_refused_at_its_place",
    "test_string_numbers.py::test_refused_at_its_place",
    "test_instance_arrays.py",
    "test_structures.py",
    "test_quoted_names.py::test_names_alike_in_the_c_are_refused",
    "test_goto.py::test_a_jump_s7_does_not_take_is_refused",
    "test_refusals.py::test_a_refusal_of_the_environment",
]


def test_every_refusal_site_is_reached(tmp_path):
    trace = tmp_path / "reached.json"
    here = Path(__file__).parent
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "pytest",
            *[str(here / t) for t in REFUSAL_TESTS],
            "-q",
            "-p",
            "tests.scl.refusal_tracer",
            "-p",
            "no:xdist",
            "-p",
            "no:cacheprovider",
        ],
        capture_output=True,
        text=True,
        cwd=ROOT,
        env={**os.environ, "LGF_REFUSAL_TRACE": str(trace)},
        timeout=hang_guard(600),
    )
    assert trace.exists(), run.stdout[-3000:] + run.stderr[-3000:]
    reached = {tuple(x) for x in json.loads(trace.read_text())}
    missed = {
        (name, line): text
        for (name, line), text in sites().items()
        if (name, line) not in reached
        and not any(name == f and part in text for f, part in EXCEPTIONS)
    }
    listed = "\n".join(f"{n}:{line}: {' '.join(t.split())[:90]}" for (n, line), t in missed.items())
    assert not missed, f"refusal sites no refusal test reaches:\n{listed}"
    excepted = [
        (f, p) for f, p in EXCEPTIONS if any(f == n and p in t for (n, _), t in sites().items())
    ]
    assert sorted(excepted) == sorted(EXCEPTIONS)  # each exception names a site there is
