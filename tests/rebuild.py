"""FMUs rebuilt from the sources/ inside them alone, as an importer that compiles source-code
FMUs does: a copy of the FMU without binaries/ gets a binary built from sources/ and is packed
again. Two kinds of builder, each one subprocess per FMU, so that the builds run in parallel:

- FMPY, FMPy's fmpy.build.build_platform_binary: CMake with sources/ as include directory and
  the source files the XML names, with FMPy's warnings (-Wall -Wextra -Wpedantic);
- Compiler(cc, flags): one compiler command for the FMU's one translation unit, with the flags
  given and -Wall -Wextra -Wpedantic -Werror; for the floating-point contract of
  src/core/numerics.h under other compilers and flags than the build's.

The session fixture `rebuilt` (tests/conftest.py) builds each FMU once per builder:
rebuilt(builders, fmus)[builder, fmu] is a Rebuilt, by_block(rebuilt, builder, version)
those of one FMI version by block."""

from __future__ import annotations

import os
import shlex
import shutil
import subprocess
import sys
import zipfile
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import fmpy
import pytest
from fmpy import extract, read_model_description

from tests.harness import FMU_DIR, fmu_path
from tests.lgf_blocks import names
from tests.timeouts import hang_guard

HEADERS = Path(fmpy.__file__).parent / "c-code"  # the FMI headers an importer supplies
FMU_DIRS = {2: FMU_DIR, 3: FMU_DIR / "fmi3"}  # the FMUs of each FMI version
WARNINGS = ("-Wall", "-Wextra", "-Wpedantic")


@dataclass(frozen=True)
class Rebuilt:
    original: Path  # the FMU it was rebuilt from
    builder: str  # the builder's name
    command: list[str]  # the build's command
    fmu: Path  # the rebuilt <Block>.fmu, alone in its folder
    unzipped: Path  # its unzipped folder
    log: Path  # the build's output
    returncode: int  # the build's

    @property
    def folder(self) -> Path:
        """The folder to simulate it from (tools.simulate.simulate)."""
        return self.fmu.parent

    @property
    def output(self) -> str:
        return self.log.read_text(errors="replace")

    @property
    def failure(self) -> str | None:
        """Why the build failed, with its output; None if it succeeded."""
        if self.returncode == 0:
            return None
        return (
            f"{self.builder} could not build {self.original} from its sources:\n"
            f"{shlex.join(self.command)}\n{self.output}"
        )


class FMPyBuild:
    """FMPy's build, with all its warnings on, as a subprocess of its own."""

    name = "fmpy"
    _script = (
        "import sys; from fmpy.build import build_platform_binary; "
        "build_platform_binary(sys.argv[1], build_dir=sys.argv[2], all_warnings=True)"
    )

    def missing(self) -> str | None:
        return None if shutil.which("cmake") else "cmake is not on PATH (FMPy's build runs it)"

    def command(self, unzipped: Path, build: Path) -> list[str]:
        return [sys.executable, "-c", self._script, str(unzipped), str(build)]


FMPY = FMPyBuild()


# Flags with which a compiler's driver links its fast-math runtime (crtfastmath.o, which sets
# flush-to-zero when the library loads) into a shared library.
FAST_MATH_RUNTIME = {"-funsafe-math-optimizations", "-ffast-math", "-Ofast"}


@dataclass(frozen=True)
class Compiler:
    """cc with flags, one command: the source files and preprocessor definitions of the XML,
    sources/ and the FMI headers as include directories (as FMPy's build), in the compiler's
    default dialect (GNU C: an ISO -std=c99 would keep GCC from contracting at all)."""

    cc: str
    flags: tuple[str, ...]

    @property
    def name(self) -> str:
        return " ".join((self.cc, *self.flags))

    def missing(self) -> str | None:
        if shutil.which(self.cc):
            return None
        return (
            f"{self.cc} is not installed (`make pytest` and .ci/run install it through "
            "tools/ensure-packages.sh where they run as root)"
        )

    def command(self, unzipped: Path, build: Path) -> list[str]:
        md = read_model_description(str(unzipped))
        files = md.buildConfigurations[0].sourceFileSets[0]
        identifier = (md.coSimulation or md.modelExchange).modelIdentifier
        folder = fmpy.platform if md.fmiVersion == "2.0" else fmpy.platform_tuple
        binary = unzipped / "binaries" / folder / f"{identifier}{fmpy.sharedLibraryExtension}"
        binary.parent.mkdir(parents=True)
        sources = unzipped / "sources"
        compile_ = [
            self.cc,
            *self.flags,
            *WARNINGS,
            "-Werror",
            "-fPIC",
            *(
                f"-D{d.name}={d.value}" if d.value else f"-D{d.name}"
                for d in files.preprocessorDefinitions
            ),
            f"-I{sources}",
            f"-I{HEADERS}",
            *(str(sources / f) for f in files.sourceFiles),
        ]
        if not FAST_MATH_RUNTIME.intersection(self.flags):
            return [*compile_, "-shared", "-o", str(binary), "-lm"]
        # Linked with -funsafe-math-optimizations, clang adds crtfastmath.o even to a shared
        # library: loading it would set flush-to-zero for the whole test process (and every later
        # test's subnormals). The flag is for the code the pragmas must protect, so it is given to
        # the compile only, and the object is linked apart (as a build system links).
        objects = [str(build / (Path(f).stem + ".o")) for f in files.sourceFiles]
        compiles = [
            [*compile_[: -len(objects)], "-c", src, "-o", obj]
            for src, obj in zip(compile_[-len(objects) :], objects)
        ]
        link = [self.cc, "-shared", *objects, "-o", str(binary), "-lm"]
        return ["sh", "-c", " && ".join(shlex.join(c) for c in [*compiles, link])]


def _cpus() -> int:
    if hasattr(os, "sched_getaffinity"):
        return len(os.sched_getaffinity(0))
    return os.cpu_count() or 1


def zip_directory(directory: Path, fmu: Path):
    with zipfile.ZipFile(fmu, "w", zipfile.ZIP_DEFLATED) as z:
        for path in sorted(directory.rglob("*")):
            z.write(path, path.relative_to(directory).as_posix())


def rebuild(builder, fmu: Path, folder: Path) -> Rebuilt:
    """fmu rebuilt by builder from its sources/ alone, in folder (empty)."""
    unzipped = Path(extract(str(fmu), str(folder / "unzipped")))
    shutil.rmtree(unzipped / "binaries")
    build = folder / "build"
    build.mkdir()
    log = folder / "build.log"
    command = builder.command(unzipped, build)
    with open(log, "w") as output:
        try:
            returncode = subprocess.run(
                command,
                check=False,
                stdout=output,
                stderr=subprocess.STDOUT,
                timeout=hang_guard(300),
            ).returncode
        except subprocess.TimeoutExpired as e:
            output.write(f"\n{e}\n")
            returncode = -1
    packed = folder / "fmu"
    packed.mkdir()
    zip_directory(unzipped, packed / fmu.name)
    return Rebuilt(fmu, builder.name, command, packed / fmu.name, unzipped, log, returncode)


class Rebuilds:
    """Each (builder, FMU) built once, in folders of root; what is asked for together and not
    built yet is built in parallel, a build per CPU."""

    def __init__(self, root: Path):
        self.root = root
        self._built: dict[tuple[str, Path], Rebuilt] = {}

    def __call__(self, builders, fmus) -> dict[tuple[object, Path], Rebuilt]:
        fmus = [Path(f) for f in fmus]
        todo = [
            (b, f, self._folder(b, f))
            for b in builders
            for f in fmus
            if (b.name, f) not in self._built
        ]
        with ThreadPoolExecutor(_cpus()) as pool:
            for (builder, fmu, _), rebuilt in zip(todo, pool.map(lambda j: rebuild(*j), todo)):
                self._built[builder.name, fmu] = rebuilt
        return {(b, f): self._built[b.name, f] for b in builders for f in fmus}

    def _folder(self, builder, fmu: Path) -> Path:
        index = len(list(self.root.glob("*")))  # unique, short, whatever the names hold
        folder = self.root / f"{index}-{fmu.stem}"
        folder.mkdir()
        (folder / "builder.txt").write_text(f"{builder.name}\n{fmu}\n")
        return folder


def by_block(rebuilt: Rebuilds, builder, version: int) -> dict[str, Rebuilt]:
    """{block: Rebuilt} of every block's FMU of one FMI version, rebuilt by builder (all of
    them the first time, in parallel); skips the test if the builder is not installed."""
    if reason := builder.missing():
        pytest.skip(reason)
    fmus = {block: fmu_path(block, FMU_DIRS[version]) for block in names()}
    built = rebuilt([builder], fmus.values())
    return {block: built[builder, fmu] for block, fmu in fmus.items()}
