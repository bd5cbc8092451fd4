"""Every FMU is complete (README.md, "What is in each FMU"): the modelDescription.xml of
modelDescription/, the linux64 binary exporting only the fmi2 entry points, sources/ that compile
on their own (every file of the XML's SourceFiles, every private header they include, nothing else),
documentation/index.html with the interface, the behaviour, the status codes and a plot, and a
model.png icon. A second, independent checker, fmutool of the FMU Manipulation Toolbox, finds
no error in any FMU (FMPy's validate_fmu runs in test_fmi_interface.py). The win64 binary is
checked in test_win64.py, the sources' rebuild in test_sources_build.py, the FMI 3.0 FMUs in
test_fmi3.py and their aarch64-linux binary in test_aarch64.py."""

from __future__ import annotations

import base64
import re
import shutil
import struct
import subprocess
import sys
import zipfile
from html.parser import HTMLParser
from pathlib import Path, PurePosixPath

import pytest

from tests.harness import FMU_DIR, ROOT, binaries, built_platforms, fmu_path, unpacked
from tests.lgf_blocks import find, names
from tests.timeouts import hang_guard
from tools import interface

BLOCKS = names()
FMI_HEADERS = {"fmi2Functions.h", "fmi2FunctionTypes.h", "fmi2TypesPlatform.h"}
TOP_LEVEL = {"modelDescription.xml", "model.png", "binaries", "sources", "documentation", "extra"}


def entries(block: str) -> list[str]:
    with zipfile.ZipFile(fmu_path(block)) as z:
        return [PurePosixPath(n).as_posix().removeprefix("./") for n in z.namelist()]


def read(block: str, name: str) -> bytes:
    _, directory = unpacked(block)
    return (Path(directory) / name).read_bytes()


def png_size(data: bytes) -> tuple[int, int]:
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    return struct.unpack(">II", data[16:24])


@pytest.mark.parametrize("block", BLOCKS)
def test_layout(block):
    files = [n for n in entries(block) if not n.endswith("/")]
    assert {n.split("/")[0] for n in files} <= TOP_LEVEL, files
    for required in (
        "modelDescription.xml",
        "model.png",
        "documentation/index.html",
        f"binaries/linux64/{block}.so",
    ):
        assert required in files
    assert (
        read(block, "modelDescription.xml")
        == (ROOT / "modelDescription" / f"{block}.xml").read_bytes()
    )


@pytest.mark.parametrize("block", BLOCKS)
def test_binaries(block):
    """linux64, and win64 where mingw-w64 is installed; never aarch64-linux, for which FMI 2.0
    has no platform name (FMPy would load binaries/linux64 on any architecture)."""
    suffix = {"linux64": ".so", "win64": ".dll"}
    assert binaries(fmu_path(block)) == {
        p: [f"{block}{suffix[p]}"] for p in built_platforms("fmi2")
    }


@pytest.mark.parametrize("block", BLOCKS)
def test_native_binary_exports_only_fmi2_entry_points(block):
    if not shutil.which("nm"):
        pytest.skip("nm (binutils) is not installed")
    _, directory = unpacked(block)
    nm = subprocess.run(
        [
            "nm",
            "-D",
            "--defined-only",
            str(Path(directory) / "binaries" / "linux64" / f"{block}.so"),
        ],
        check=True,
        capture_output=True,
        text=True,
    ).stdout
    symbols = [line.split()[-1] for line in nm.splitlines() if len(line.split()) == 3]
    assert symbols and [s for s in symbols if not s.startswith("fmi2")] == []


def source_files(block: str) -> list[str]:
    md, _ = unpacked(block)
    return md.buildConfigurations[0].sourceFileSets[0].sourceFiles  # as fmpy.build reads them


@pytest.mark.parametrize("block", BLOCKS)
def test_sources_are_complete(block):
    """Every file of SourceFiles is there; every #include "..." resolves inside sources/ (relative
    to sources/, the include directory an importer such as FMPy adds, or to the including file)
    or names an FMI header, which the importer supplies; no file is there that nothing uses;
    every file equals its original in src/ (the interface.c, what its interface.toml makes)."""
    _, directory = unpacked(block)
    sources = Path(directory) / "sources"
    present = {p.relative_to(sources).as_posix() for p in sources.rglob("*") if p.is_file()}
    listed = source_files(block)
    assert listed and set(listed) <= present, set(listed) - present
    # One translation unit, written by the build: the floating-point contract first, so that
    # it holds for all that follows (src/core/numerics.h), the block's interface (which
    # includes the block) and the FMI 2.0 front-end (which includes the core), so that nothing
    # but the fmi2 entry points has external linkage (see test_sources_link_beside_each_other).
    assert listed == [f"{block}.c"]
    unit = (sources / f"{block}.c").read_text()
    assert re.findall(r'^#include "([^"]+)"', unit, re.M) == [
        "core/numerics.h",
        f"blocks/{block}/interface.c",
        "fmi2/fmi2.c",
    ]
    used, todo = set(listed), list(listed)
    while todo:
        name = todo.pop()
        for include in re.findall(
            r'^\s*#\s*include\s+"([^"]+)"', (sources / name).read_text(), re.M
        ):
            if include in FMI_HEADERS:
                continue
            candidates = [include, (PurePosixPath(name).parent / include).as_posix()]
            found = next((c for c in candidates if c in present), None)
            assert found, f"{name} includes {include}, which sources/ does not hold"
            if found not in used:
                used.add(found)
                todo.append(found)
    assert present == used, f"files nothing uses: {present - used}"
    # the interface.c that tools/interface.py writes from the block's interface.toml, the
    # other files as they are in src/
    generated = f"blocks/{block}/interface.c"
    assert (sources / generated).read_text(encoding="utf-8") == interface.c_source(block)
    for name in present - {f"{block}.c", generated}:
        assert (sources / name).read_bytes() == (ROOT / "src" / name).read_bytes(), name


class _Page(HTMLParser):
    def __init__(self):
        super().__init__()
        self.images, self.text = [], []

    def handle_starttag(self, tag, attrs):
        if tag == "img":
            self.images.append(dict(attrs)["src"])

    def handle_data(self, data):
        self.text.append(data)


@pytest.mark.parametrize("block", BLOCKS)
def test_documentation(block):
    md, directory = unpacked(block)
    page = _Page()
    page.feed(read(block, "documentation/index.html").decode("utf-8"))
    text = " ".join(page.text)
    for section in ("Purpose", "Interface", "Behaviour", "Status codes", "A typical run"):
        assert section in text, section
    # The interface table: every variable, arrays as name[i].member
    for v in md.modelVariables:
        assert re.sub(r"\[\d+\]", "[i]", v.name) in text, v.name
    for name in find(block).original_names:  # of the original block (docs/behaviour.md §1.5)
        assert name in text, name
    # Images resolve inside the FMU; the typical run is a plot of the block's first demo
    # scenario, which the page names
    documentation = Path(directory) / "documentation"
    assert "typical_run.png" in page.images
    for src in page.images:  # files of the FMU, or the icon inlined (it moves in FMI 3.0)
        inline = src.startswith("data:image/png;base64,")
        png_size(
            base64.b64decode(src.split(",", 1)[1]) if inline else (documentation / src).read_bytes()
        )
    assert any(src.startswith("data:image/png;base64,") for src in page.images), "the icon"
    assert find(block).scenarios[0].name in text


@pytest.mark.parametrize("block", BLOCKS)
def test_icon(block):
    width, height = png_size(read(block, "model.png"))
    assert 32 <= width <= 512 and 32 <= height <= 512
    icons = {read(b, "model.png") for b in BLOCKS}
    assert len(icons) == len(BLOCKS), "the blocks' icons are not distinct"


def fmutool() -> str:
    path = Path(sys.executable).with_name("fmutool")
    if not path.exists():
        pytest.fail(f"{path} is missing: install requirements.txt (make venv)")
    return str(path)


@pytest.mark.parametrize("block", BLOCKS)
def test_fmutool_check(block, tmp_path):
    """fmutool -check exits non-zero when it finds an error; its report goes to the log."""
    run = subprocess.run(
        [fmutool(), "-input", str(fmu_path(block)), "-check"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=hang_guard(120),
    )
    report = run.stdout + run.stderr
    assert run.returncode == 0, report
    assert "ERROR" not in report, report
    assert "compliant with FMI-2.0" in report, report


@pytest.mark.parametrize("block", BLOCKS)
def test_the_same_commit_packs_the_same_bytes(block):
    """What a build would vary is fixed (lgf_fmus.fmuzip, CMakeLists.txt): the entries of every FMU
    in sorted order, each with the time stamp 1980-01-01 and fixed permissions, and no link time
    in the win64 DLLs' PE header. (Two builds of one commit in different folders gave the same
    bytes for every FMU when this was written.)"""
    for path in (fmu_path(block), fmu_path(block, FMU_DIR / "fmi3")):
        with zipfile.ZipFile(path) as z:
            infos = z.infolist()
            assert [i.filename for i in infos] == sorted(i.filename for i in infos), path
            for info in infos:
                assert info.date_time == (1980, 1, 1, 0, 0, 0), (path, info.filename)
                mode = info.external_attr >> 16
                assert mode == (0o40755 if info.is_dir() else 0o644), (path, info.filename)
                if info.filename.endswith(".dll"):
                    dll = z.read(info)
                    pe = struct.unpack_from("<I", dll, 0x3C)[0]  # e_lfanew: the PE header
                    assert dll[pe : pe + 4] == b"PE\0\0"
                    assert struct.unpack_from("<I", dll, pe + 8)[0] == 0, "TimeDateStamp"
