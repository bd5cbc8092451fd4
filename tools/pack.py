"""Packs an FMU (or any zip) from a staged folder so that the same files give the same bytes on
every machine: the entries in sorted order, every one with the same time stamp (1980-01-01, the
earliest a zip holds) and the same permissions, deflated. CMake's own `tar --format=zip` records
each file's build time and takes the files in the order the file system lists them, so two
builds of one commit differed (CMakeLists.txt, lgf_pack, runs this instead).

    python -m tools.pack <folder> <file.zip|file.fmu>
"""

from __future__ import annotations

import sys
import zipfile
from pathlib import Path

ZIP_TIME = (1980, 1, 1, 0, 0, 0)


def pack(folder: Path, archive: Path) -> None:
    """Every folder (as an entry of its own, which some unzip libraries want) and every file."""
    entries = sorted(
        p.relative_to(folder).as_posix() + ("/" if p.is_dir() else "") for p in folder.rglob("*")
    )
    partial = archive.with_name(archive.name + ".partial")
    with zipfile.ZipFile(partial, "w", zipfile.ZIP_DEFLATED) as z:
        for name in entries:
            info = zipfile.ZipInfo(name, ZIP_TIME)
            if name.endswith("/"):
                info.external_attr = (0o40755 << 16) | 0x10  # a directory, for Unix and DOS
                z.writestr(info, b"")
            else:
                info.compress_type = zipfile.ZIP_DEFLATED
                info.external_attr = 0o644 << 16
                z.writestr(info, (folder / name).read_bytes())
    partial.replace(archive)


def main():
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    pack(Path(sys.argv[1]), Path(sys.argv[2]))


if __name__ == "__main__":
    main()
