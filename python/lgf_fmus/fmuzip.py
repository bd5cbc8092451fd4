"""The one packer of the project's zips, so that the same files give the same bytes on every
machine: the entries in sorted order, every one with the same time stamp (1980-01-01, the
earliest a zip holds) and the same permissions, deflated; an FMU's folders are entries of their
own (some unzip libraries want them). It packs the bundled FMUs (CMakeLists.txt runs
`python -m lgf_fmus.fmuzip <stage> <fmu>` on each staged FMU: CMake's own `tar --format=zip`
records each file's build time and takes the files in the order the file system lists them),
the FMUs the SCL compiler writes (scl/build.py) and the release zip (release/dist.py).

    python -m lgf_fmus.fmuzip <folder> <file.zip|file.fmu>
"""

from __future__ import annotations

import sys
import zipfile
from pathlib import Path

ZIP_TIME = (1980, 1, 1, 0, 0, 0)


def pack(files: dict[str, bytes], archive: Path, folders: bool = True) -> None:
    """Writes archive from {name: bytes} (a name ending in / is a folder); with folders, every
    folder of a name is an entry too. Written beside it first, so that no half zip is left."""
    names = set(files)
    if folders:
        names |= {name[: i + 1] for name in files for i, c in enumerate(name) if c == "/"}
    archive.parent.mkdir(parents=True, exist_ok=True)
    partial = archive.with_name(archive.name + ".partial")
    with zipfile.ZipFile(partial, "w", zipfile.ZIP_DEFLATED) as z:
        for name in sorted(names):
            info = zipfile.ZipInfo(name, ZIP_TIME)
            if name.endswith("/"):
                info.external_attr = (0o40755 << 16) | 0x10  # a directory, for Unix and DOS
                z.writestr(info, b"")
            else:
                info.compress_type = zipfile.ZIP_DEFLATED
                info.external_attr = 0o644 << 16
                z.writestr(info, files[name])
    partial.replace(archive)


def pack_folder(folder: Path, archive: Path) -> None:
    """Every file and folder (an empty one too) below folder."""
    pack(
        {
            p.relative_to(folder).as_posix() + ("/" if p.is_dir() else ""): (
                b"" if p.is_dir() else p.read_bytes()
            )
            for p in folder.rglob("*")
        },
        archive,
    )


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    pack_folder(Path(sys.argv[1]), Path(sys.argv[2]))


if __name__ == "__main__":
    main()
