"""The PLC tags of a program (docs/scl.md §3.12): the tag table as TIA Portal exports it (PLC
tags -> Export: an .xlsx whose sheet "PLC Tags" has the columns Name, Path, Data Type, Logical
Address, Comment, ...; or a CSV of the same columns), each tag with its area, byte, bit and
width, and the rules that tie a tag's type to its address. program.py turns them into the FMU's
inputs (%I), outputs (%Q) and locals (%M) and the process image that the OBs read and write."""

from __future__ import annotations

import csv
import re
from dataclasses import dataclass
from pathlib import Path

from .diagnostics import Code, SclError

COLUMNS = ("Name", "Data Type", "Logical Address")  # a table needs these; Comment, Path optional
SHEET = "PLC Tags"  # TIA's sheet of the tags (its other sheet: "TagTable Properties")
# an absolute address as TIA writes it, %I0.0, %IW64, %QD4, %M10.1, %MB3, with the German
# mnemonics %E (Eingang) and %A (Ausgang) for %I and %Q; X for a bit may be written or not
ADDRESS = re.compile(r"%([IQMEA])([XBWD]?)(\d+)(?:\.(\d+))?", re.IGNORECASE)
AREAS = {"I": "I", "E": "I", "Q": "Q", "A": "Q", "M": "M"}
WIDTH = {"X": 1, "": 1, "B": 8, "W": 16, "D": 32}
LETTER = {1: "", 8: "B", 16: "W", 32: "D"}
# each type a tag may have, by its width in the area (S7-1500 System Manual, "Data types":
# BOOL a bit, BYTE/SINT/USINT a byte, WORD/INT/UINT a word, DWORD/DINT/UDINT/REAL/TIME a double
# word); the subset takes no other (docs/scl.md §3.12)
TYPES = {"BOOL": 1, "BYTE": 8, "SINT": 8, "USINT": 8, "WORD": 16, "INT": 16, "UINT": 16}
TYPES |= {"DWORD": 32, "DINT": 32, "UDINT": 32, "REAL": 32, "TIME": 32}
# the names the generated SCL of the program gives its own statics (program.py)
RESERVED = ("pii", "piq", "cycletime", "maxcycletime")


@dataclass
class Tag:
    name: str
    type_name: str  # as the table writes it: Bool, Int, Real, ...
    area: str  # I, Q or M
    byte: int
    bit: int | None  # the bit of a Bool, else None
    width: int  # 1, 8, 16, 32
    comment: str
    row: int  # its row in the table, for the errors

    @property
    def address(self) -> str:
        """Its address as TIA shows it: %I0.1, %IW64, %MD100."""
        if self.width == 1:
            return f"%{self.area}{self.byte}.{self.bit}"
        return f"%{self.area}{LETTER[self.width]}{self.byte}"

    def bits(self) -> list[tuple[str, int, int]]:
        """The (area, byte, bit) it occupies."""
        if self.width == 1:
            return [(self.area, self.byte, self.bit)]
        return [
            (self.area, b, k)
            for b in range(self.byte, self.byte + self.width // 8)
            for k in range(8)
        ]


def _fail(file: str, message: str):
    raise SclError(None, f"{file}: {message}", Code.PROGRAM)


def parse_address(text: str):
    """(area, byte, bit, width) of an absolute address, or None where it is none."""
    m = ADDRESS.fullmatch(text.strip())
    if m is None:
        return None
    area, size, byte, bit = m.groups()
    width = WIDTH[size.upper()]
    if (width == 1) != (bit is not None) or bit is not None and int(bit) > 7:
        return None
    return AREAS[area.upper()], int(byte), int(bit) if bit is not None else None, width


def _rows(path: Path, file: str) -> list[list[str]]:
    """The table's rows as text, its header first: the sheet "PLC Tags" of an .xlsx (else its
    first sheet), or a CSV (comma, semicolon or tab, as the export's locale writes it)."""
    if path.suffix.lower() in (".xlsx", ".xlsm"):
        try:
            import openpyxl
        except ImportError:
            _fail(file, "reading an .xlsx needs openpyxl (pip install openpyxl), or give a CSV")
        try:
            book = openpyxl.load_workbook(path, read_only=True, data_only=True)
        except Exception as e:  # openpyxl raises zipfile's, KeyError, ... for a broken file
            _fail(file, f"not an .xlsx workbook ({e})")
        sheet = book[SHEET] if SHEET in book.sheetnames else book.worksheets[0]
        rows = [
            ["" if c is None else str(c) for c in row] for row in sheet.iter_rows(values_only=True)
        ]
        book.close()
        return rows
    try:
        text = path.read_text(encoding="utf-8-sig")
    except OSError as e:
        _fail(file, f"cannot read it ({e.strerror})")
    except UnicodeDecodeError:
        _fail(file, "not UTF-8 text")
    first = text.splitlines()[0] if text else ""
    delimiter = max(",;\t", key=first.count)
    return [row for row in csv.reader(text.splitlines(), delimiter=delimiter)]


def load(path) -> list[Tag]:
    """The tags of the table at path, checked (docs/scl.md §3.12)."""
    file = str(path)
    rows = _rows(Path(path), file)
    if not rows:
        _fail(file, "an empty table: its first row names the columns (Name, Data Type, ...)")
    header = [h.strip().lower() for h in rows[0]]
    columns = {}
    for name in (*COLUMNS, "Comment"):
        if name.lower() in header:
            columns[name] = header.index(name.lower())
        elif name in COLUMNS:
            _fail(file, f"no column {name!r} in its first row (TIA's: {', '.join(COLUMNS)}, ...)")
    tags, names, owner = [], {}, {}
    for number, row in enumerate(rows[1:], start=2):
        cell = {k: (row[i].strip() if i < len(row) else "") for k, i in columns.items()}
        if not any(cell.values()):
            continue  # an empty row
        where = f"row {number}"
        name = cell["Name"]
        if not re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]{0,127}", name):
            _fail(
                file,
                f"{where}: the tag {name!r}: only names of letters, digits and _ are supported",
            )
        if name.lower() in names:
            _fail(file, f"{where}: the tag {name!r} is also row {names[name.lower()]}")
        if name.lower() in RESERVED or name.lower().startswith("schedule_"):
            _fail(file, f"{where}: the tag {name!r} has a name the program's FMU gives itself")
        names[name.lower()] = number
        type_name = cell["Data Type"].strip('"')
        width = TYPES.get(type_name.upper())
        if width is None:
            known = "Bool, Byte, SInt, USInt, Word, Int, UInt, DWord, DInt, UDInt, Real, Time"
            _fail(
                file,
                f"{where}: the tag {name!r} of type {type_name!r}: a tag's type is one of {known}",
            )
        address = parse_address(cell["Logical Address"])
        if address is None:
            _fail(
                file,
                f"{where}: the tag {name!r}: {cell['Logical Address']!r} is no address of the "
                "inputs, outputs or bit memory (%I0.0, %IW64, %QD4, %M10.1, %MB3)",
            )
        area, byte, bit, size = address
        if size != width:
            _fail(
                file,
                f"{where}: the tag {name!r} is a {type_name} of {width} bits; "
                f"{cell['Logical Address']} addresses {size}",
            )
        tag = Tag(name, type_name, area, byte, bit, width, cell.get("Comment", ""), number)
        for place in tag.bits():  # two tags on one bit (docs/scl.md §3.12 [DEC-TAG-OVERLAP])
            other = owner.get(place)
            if other is not None:
                _fail(
                    file,
                    f"{where}: the tag {name!r} ({tag.address}) shares memory with {other.name!r} "
                    f"({other.address}, row {other.row}): tags that overlap are not supported",
                )
            owner[place] = tag
        tags.append(tag)
    return tags


def by_address(tags: list[Tag]) -> dict[tuple, Tag]:
    """Each tag by (area, byte, bit, width): an absolute address resolves to the tag of exactly
    its address (docs/scl.md §3.12)."""
    return {(t.area, t.byte, t.bit, t.width): t for t in tags}
