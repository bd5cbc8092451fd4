"""From the generated C to the .fmu (docs/scl.md §4): the FMU's one translation unit as CMake
forms it for the bundled FMUs (core/numerics.h first, the block's interface.c, a front-end), the
modelDescription.xml printed by src/describe.c from the interface table, the library compiled by
the system's C compiler with the build's flags (-ffp-contract=off among them), and the zip with
binaries/<platform>/ and sources/."""

from __future__ import annotations

import os
import platform as host
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

from ..fmuzip import pack
from .ast import SclError

PACKAGE = Path(__file__).resolve().parent
RUNTIME = PACKAGE / "runtime"
FRONT_END = {2: "fmi2/fmi2.c", 3: "fmi3/fmi3.c"}
# C11 without extensions and CMake's Release optimisation, as CMakeLists.txt builds the bundled
# FMUs, then the flags both take from cflags.txt (lgf_compile_options)
FLAGS = ["-std=c11", "-O3", "-DNDEBUG"] + [
    line.strip()
    for line in (PACKAGE / "cflags.txt").read_text(encoding="utf-8").splitlines()
    if line.strip() and not line.lstrip().startswith("#")
]


def c_sources() -> Path:
    """The C the package carries (core, iec, fmi2, fmi3, describe.c: installed as package data
    by python/CMakeLists.txt), or in a source checkout the repository's src/."""
    installed = PACKAGE / "csrc"
    if (installed / "core" / "model.h").exists():
        return installed
    checkout = PACKAGE.parents[2] / "src"
    if (checkout / "core" / "model.h").exists():
        return checkout
    raise SclError(None, f"the C sources of the core are missing from {installed}")


def fmi_headers() -> Path:
    """The FMI 2.0 and 3.0 headers of the installed FMPy, as the project's build takes them."""
    import fmpy

    path = Path(fmpy.__file__).parent / "c-code"
    if not (path / "fmi2Functions.h").exists() or not (path / "fmi3Functions.h").exists():
        raise SclError(None, f"FMPy's FMI headers are missing from {path}")
    return path


def core_kinds(src: Path) -> tuple[set[str], set[str]]:
    """The var_type and field_type names the core of src/core/model.h knows."""
    text = (src / "core" / "model.h").read_text(encoding="utf-8")
    var = re.search(r"typedef enum \{(.*?)\} var_type;", text, re.S).group(1)
    fields = re.search(r"typedef enum \{(.*?)\} field_type;", text, re.S).group(1)
    strip = lambda body: re.sub(r"/\*.*?\*/", "", body, flags=re.S)  # noqa: E731
    return (
        set(re.findall(r"\bVAR_[A-Z0-9_]+", strip(var))),
        set(re.findall(r"\bFIELD_[A-Z0-9_]+", strip(fields))),
    )


def c_compiler() -> str:
    """The system's C compiler: $CC, else cc, gcc or clang on the PATH (docs/scl.md §4)."""
    for candidate in (os.environ.get("CC"), "cc", "gcc", "clang"):
        if candidate and shutil.which(candidate):
            return candidate
    raise SclError(
        None,
        "no C compiler found (set CC, or install gcc or clang): the FMU's "
        "binary is compiled from the generated C",
    )


# mingw-w64's gcc (Debian: gcc-mingw-w64-x86-64), the cross compiler of the bundled FMUs' win64
# binaries (cmake/mingw-w64.cmake): where it is installed, the FMU carries a win64 binary too
WIN64_CC = "x86_64-w64-mingw32-gcc"
WIN64_PLATFORM = {2: "win64", 3: "x86_64-windows"}


def win64_compiler(win64: bool | None) -> str | None:
    """mingw-w64's gcc for win64: with win64 None where it is on the PATH (on Windows the
    system's compiler builds the win64 binary itself), with True required, with False none."""
    if win64 is False or sys.platform == "win32":
        return None
    found = shutil.which(WIN64_CC)
    if win64 and not found:
        raise SclError(
            None,
            f"no {WIN64_CC} found for the win64 binary (install mingw-w64: on Debian "
            "gcc-mingw-w64-x86-64)",
        )
    return found


# Debian's aarch64 cross compiler (gcc-aarch64-linux-gnu with libc6-dev-arm64-cross), that of the
# bundled FMI 3.0 FMUs' aarch64-linux binaries (cmake/aarch64-linux.cmake): where it works with
# its C library, an FMI 3.0 FMU carries binaries/aarch64-linux too (FMI 2.0 names no platform
# for aarch64 Linux, importers take linux64 to be x86_64)
AARCH64_CC = "aarch64-linux-gnu-gcc"
AARCH64_PLATFORM = "aarch64-linux"


def aarch64_compiler(fmi: int, aarch64: bool | None) -> str | None:
    """The aarch64 cross compiler for an FMI 3.0 FMU: with aarch64 None where it is on the PATH
    and finds its C library (as the Makefile asks it), with True required, with False none; none
    on an aarch64 Linux machine, whose own compiler builds that binary."""
    if aarch64 is False:
        return None
    if fmi != 3:
        if aarch64:
            raise SclError(None, "FMI 2.0 names no platform for aarch64 Linux: use --fmi 3")
        return None
    if sys.platform == "linux" and host.machine() in ("aarch64", "arm64"):
        return None
    found = shutil.which(AARCH64_CC)
    if found:
        probe = [found, "-E", "-x", "c", "-"]
        ok = subprocess.run(probe, input="#include <math.h>\n", capture_output=True, text=True)
        found = found if ok.returncode == 0 else None
    if aarch64 and not found:
        raise SclError(
            None,
            f"no {AARCH64_CC} with its C library found for the aarch64-linux binary (on Debian "
            "gcc-aarch64-linux-gnu and libc6-dev-arm64-cross)",
        )
    return found


def includes(cc: str, flags: list[str], unit: Path, roots: list[Path]) -> dict[str, Path]:
    """Every file of the roots that the unit includes, directly or not, with itself, by its path
    relative to its root (the FMU's sources/ layout), as the C compiler's own preprocessor finds
    them (-MM: its dependencies without the system headers, here the FMI headers), as
    lgf_includes of CMakeLists.txt lists the bundled FMUs' sources."""
    rule = _run([cc, *flags, "-MM", str(unit)], "listing the included files")
    # "<target>: <file> <file> \\<newline> <file> ...": a make rule, its lines continued by \\
    paths = rule.replace("\\\n", " ").partition(": ")[2].split()
    found: dict[str, Path] = {}
    for path in (Path(p).resolve() for p in paths):
        for root in (r.resolve() for r in roots):
            if path.is_relative_to(root):
                found[path.relative_to(root).as_posix()] = path
                break
    return found


def _run(command: list[str], what: str, cwd=None) -> str:
    run = subprocess.run(command, capture_output=True, text=True, cwd=cwd)
    if run.returncode != 0:
        # a C compiler error reaching the user is a defect of the compiler (docs/scl.md §5)
        raise SclError(
            None,
            f"internal error: {what} failed (a defect of lgf_fmus.scl, please "
            f"report it):\n{run.stderr or run.stdout}",
        )
    return run.stdout


def _compile_all(jobs: list[tuple[list[str], str, Path | None]]) -> None:
    """Runs the compiler commands side by side, each (command, what it makes, folder to run
    it in or None)."""
    running = [
        (
            subprocess.Popen(c, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, cwd=cwd),
            what,
        )
        for c, what, cwd in jobs
    ]
    failures = []
    for process, what in running:
        out, err = process.communicate()
        if process.returncode != 0:
            failures.append(f"{what}:\n{err or out}")
    if failures:
        raise SclError(
            None,
            "internal error: the C compiler refused the generated C (a defect "
            "of lgf_fmus.scl, please report it):\n" + "\n".join(failures),
        )


def platform(fmi: int) -> str:
    import fmpy

    return fmpy.platform if fmi == 2 else fmpy.platform_tuple


def build(
    identifier: str,
    generated: dict[str, str],
    fmi: int,
    output: Path,
    werror: bool = False,
    win64: bool | None = None,
    aarch64: bool | None = None,
) -> Path:
    src = c_sources()
    headers = fmi_headers()
    cc = c_compiler()
    mingw = win64_compiler(win64)
    arm = aarch64_compiler(fmi, aarch64)
    flags = FLAGS + (["-Werror"] if werror else [])
    with tempfile.TemporaryDirectory(prefix=f"lgf-scl-{identifier}-") as tmp:
        tmp = Path(tmp)
        gen = tmp / "gen"
        generated = dict(generated)
        doc = generated.pop("documentation/index.html", None)
        for name, text in generated.items():
            (gen / name).parent.mkdir(parents=True, exist_ok=True)
            (gen / name).write_text(text, encoding="utf-8")
        unit = (
            f"/* The FMU {identifier}: one translation unit, its floating-point contract first, "
            f"its block and\n * interface, then the FMI {fmi} front-end. */\n"
            '#include "core/numerics.h"\n'
            f'#include "blocks/{identifier}/interface.c"\n'
            f'#include "{FRONT_END[fmi]}"\n'
        )
        (gen / f"{identifier}.c").write_text(unit, encoding="utf-8")
        describe = f'#include "blocks/{identifier}/interface.c"\n#include "describe.c"\n'
        (gen / "describe.c.unit.c").write_text(describe, encoding="utf-8")
        roots = [gen, RUNTIME, src]
        include = [f"-I{r}" for r in roots] + ["-isystem", str(headers)]

        describer = tmp / "describe"
        library = tmp / (identifier + (".dll" if sys.platform == "win32" else ".so"))
        dll = tmp / "win64" / f"{identifier}.dll"
        jobs = []
        if mingw:
            dll.parent.mkdir()
            # as CMakeLists.txt links the bundled win64 DLLs: no libgcc DLL beside the FMU, no
            # link time in the PE header; and linked in its folder by its file name, since
            # mingw's ld derives the DLL's image base from the output path as given (the same
            # SCL gives the same bytes)
            cross = [mingw, *flags, "-shared", "-static-libgcc", "-Wl,--no-insert-timestamp"]
            cross += [*include, str(gen / f"{identifier}.c"), "-o", dll.name]
            jobs.append((cross, "compiling the FMU for win64", dll.parent))
        arm_library = tmp / AARCH64_PLATFORM / f"{identifier}.so"
        if arm:
            arm_library.parent.mkdir()
            # as the native library, with the flags of the bundled FMUs' aarch64 build
            cross = [arm, *flags, "-fPIC", "-shared", "-fvisibility=hidden", *include]
            cross += [str(gen / f"{identifier}.c"), "-o", str(arm_library), "-lm"]
            jobs.append((cross, "compiling the FMU for aarch64-linux", None))
        # the modelDescription writer and the libraries, compiled side by side
        _compile_all(
            jobs
            + [
                (
                    [
                        cc,
                        *flags,
                        "-O0",  # a host tool that prints text: compiled in a third of the time
                        "-Wno-unused-function",
                        *include,
                        str(gen / "describe.c.unit.c"),
                        "-o",
                        str(describer),
                        "-lm",
                    ],
                    "compiling the modelDescription writer",
                    None,
                ),
                (
                    [
                        cc,
                        *flags,
                        "-fPIC",
                        "-shared",
                        "-fvisibility=hidden",
                        *include,
                        str(gen / f"{identifier}.c"),
                        "-o",
                        str(library),
                        "-lm",
                    ],
                    "compiling the FMU",
                    None,
                ),
            ]
        )
        xml = _run([str(describer), "xml" if fmi == 2 else "xml3"], "writing modelDescription.xml")

        sources = includes(cc, [*flags, *include], gen / f"{identifier}.c", roots)
        output.parent.mkdir(parents=True, exist_ok=True)
        files: dict[str, bytes] = {"modelDescription.xml": xml.encode()}
        if doc is not None:
            files["documentation/index.html"] = doc.encode()
        files[f"binaries/{platform(fmi)}/{library.name}"] = library.read_bytes()
        if mingw:
            files[f"binaries/{WIN64_PLATFORM[fmi]}/{dll.name}"] = dll.read_bytes()
        if arm:
            files[f"binaries/{AARCH64_PLATFORM}/{arm_library.name}"] = arm_library.read_bytes()
        for name, path in sources.items():
            files[f"sources/{name}"] = path.read_bytes()
        if fmi == 3:
            build3 = _run([str(describer), "build3"], "writing buildDescription.xml")
            files["sources/buildDescription.xml"] = build3.encode()
        pack(files, output)
    return output
