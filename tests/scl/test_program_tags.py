"""PLC tags and the process image (docs/scl.md §3.12): a tag table as TIA exports it (the .xlsx,
written here with openpyxl as TIA lays it out, and the CSV of its columns) makes %I tags the
FMU's inputs, %Q tags its outputs and %M tags locals; "Tag" and its absolute address resolve to
the same variable; the process image is updated as the schedule says. The expected times are
computed by hand from the rules: OB1 every 10 ms copies the inputs of the automatic update in
before it runs and the outputs out after it; the cyclic OB "Fast" every 5 ms does so for the
tags of its partition only, and at a time both are due runs first (priority 15 > 1)."""

from __future__ import annotations

import functools

import pytest

import lgf_fmus
from lgf_fmus import scl
from tests.scl.driver import Instance

SOURCE = """
ORGANIZATION_BLOCK "Main"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    %QW0 := "In1";
    "Ticks" := "Ticks" + 1;
END_ORGANIZATION_BLOCK

ORGANIZATION_BLOCK "Fast"
{ S7_Optimized_Access := 'TRUE' }
VERSION : 0.1
BEGIN
    "Out2" := %IW2;
    "Seen" := "In1";
    "Run" := NOT "Run";
END_ORGANIZATION_BLOCK
"""
PROGRAM = """
name = "Image"
[ob.Main]
number = 1
[ob.Fast]
number = 38
cycle_us = 5000
process_image = ["In2", "Out2"]
"""
HEADER = ["Name", "Path", "Data Type", "Logical Address", "Comment", "Hmi Visible"]
HEADER += ["Hmi Accessible", "Hmi Writeable", "Typeobject ID", "Version ID"]
ROWS = [
    ["In1", "Default tag table", "Int", "%IW0", "first input", "True", "True", "True", "", ""],
    ["In2", "Default tag table", "Int", "%IW2", "second input", "True", "True", "True", "", ""],
    ["Out1", "Default tag table", "Int", "%QW0", "", "True", "True", "True", "", ""],
    ["Out2", "Default tag table", "Int", "%QW2", "", "True", "True", "True", "", ""],
    ["Run", "Default tag table", "Bool", "%Q4.3", "toggles", "True", "True", "True", "", ""],
    [
        "Seen",
        "Default tag table",
        "Int",
        "%MW0",
        "In1 as Fast sees it",
        "True",
        "True",
        "True",
        "",
        "",
    ],
    ["Ticks", "Default tag table", "DInt", "%MD4", "", "True", "True", "True", "", ""],
]


def write_xlsx(path):
    """The table as TIA's export lays it out: the sheet "PLC Tags", then "TagTable
    Properties"."""
    openpyxl = pytest.importorskip("openpyxl")
    book = openpyxl.Workbook()
    sheet = book.active
    sheet.title = "PLC Tags"
    for row in [HEADER, *ROWS]:
        sheet.append(row)
    properties = book.create_sheet("TagTable Properties")
    properties.append(["Path", "BelongsToUnit", "Accessibility"])
    properties.append(["Default tag table", "", ""])
    book.save(path)


@pytest.fixture(scope="module")
def fmus(tmp_path_factory):
    tmp = tmp_path_factory.mktemp("tags")
    (tmp / "image.scl").write_text(SOURCE, encoding="utf-8")
    (tmp / "program.toml").write_text(PROGRAM, encoding="utf-8")
    (tmp / "tags.csv").write_text(
        "\n".join(",".join(r) for r in [HEADER, *ROWS]) + "\n", encoding="utf-8"
    )
    write_xlsx(tmp / "PLCTags.xlsx")
    built = {}
    # the CSV through the compiler, the xlsx through the package's public lgf_fmus.compile
    for key, fmi, table, compile_ in (
        ("csv", 2, "tags.csv", functools.partial(scl.compile, werror=True)),
        ("xlsx", 3, "PLCTags.xlsx", lgf_fmus.compile),
    ):
        built[key] = compile_(
            [tmp / "image.scl"],
            fmi=fmi,
            output=tmp / f"Image_{key}.fmu",
            program=tmp / "program.toml",
            tags=tmp / table,
            win64=False,
            aarch64=False,
        )  # fmt: skip
    return built


# docs/scl.md rules: [S7-TAG-TABLE] [S7-TAG-AREAS]
@pytest.mark.parametrize("table", ["csv", "xlsx"])
def test_tags_are_inputs_outputs_and_locals(fmus, table):
    s = Instance(fmus[table], {}, {})
    causality = {n: s.variables[n].causality for n in ("In1", "In2", "Out1", "Out2", "Run")}
    assert causality == {
        "In1": "input",
        "In2": "input",
        "Out1": "output",
        "Out2": "output",
        "Run": "output",
    }
    for name in ("Seen", "Ticks", "PII.In1", "PIQ.Out1"):
        assert s.variables[name].causality == "local", name
    assert "%IW0 first input" in s.variables["In1"].description
    assert "%MW0 In1 as Fast sees it" in s.variables["Seen"].description
    s.free()


# docs/scl.md rules: [S7-TAG-IMAGE] [DEC-TAG-IMAGE] [S7-TAG-ADDRESS]
@pytest.mark.parametrize("table", ["csv", "xlsx"])
def test_the_process_image_by_partition(fmus, table):
    s = Instance(fmus[table], {}, {"In1": 0, "In2": 0})
    rows = {}
    for k in range(50):  # steps of 1 ms; both inputs 7 from 23 ms on
        if k == 23:
            s.set({"In1": 7, "In2": 7})
        s.fmu.doStep(currentCommunicationPoint=k / 1000, communicationStepSize=1 / 1000)
        rows[k + 1] = s.get(["Out1", "Out2", "Seen", "Ticks", "Run", "PIQ.Run"])
    s.free()

    def first(name):
        return min(t for t, r in rows.items() if r[name] == 7)

    # Fast at 25 ms reads In2 through its own partition and writes Out2 out at its end
    assert first("Out2") == 25
    # OB1 at 30 ms copies In1 in, then Out1 (written as %QW0) out
    assert first("Out1") == 30
    # Fast reads In1 from OB1's image: at 30 ms Fast runs before OB1, so only at 35 ms
    assert first("Seen") == 35
    # the %M tag counts OB1's runs: 0, 10, ..., 50 ms
    assert rows[50]["Ticks"] == 6
    # Run, a %Q bit of the automatic update that Fast toggles every 5 ms, goes out with OB1 every
    # 10 ms, after Fast's run at that time: after 2k + 1 runs, always TRUE; its image alternates
    assert all(r["Run"] for r in rows.values())
    assert [rows[t]["PIQ.Run"] for t in (40, 45, 50)] == [True, False, True]


TABLE_CASES = {
    "no column": ("Name,Data Type\nA,Int\n", "no column 'Logical Address'"),
    "type against width": (
        "Name,Data Type,Logical Address\nA,Int,%ID0\n",
        "row 2: the tag 'A' is a Int of 16 bits; %ID0 addresses 32",
    ),
    "no address": ("Name,Data Type,Logical Address\nA,Int,%DB1.DBW0\n", "is no address of"),
    "overlap": (
        "Name,Data Type,Logical Address\nA,Word,%MW0\nB,Bool,%M1.2\n",
        "row 3: the tag 'B' (%M1.2) shares memory with 'A' (%MW0, row 2)",
    ),
    "type": ("Name,Data Type,Logical Address\nA,LReal,%MD0\n", "of type 'LReal'"),
    "twice": ("Name,Data Type,Logical Address\nA,Int,%MW0\na,Int,%MW2\n", "is also row 2"),
}


# docs/scl.md rules: [S7-TAG-TABLE] [DEC-TAG-OVERLAP]
@pytest.mark.parametrize("case", TABLE_CASES)
def test_a_tag_table_refused(tmp_path, case):
    table, message = TABLE_CASES[case]
    (tmp_path / "t.csv").write_text(table, encoding="utf-8")
    (tmp_path / "p.scl").write_text(SOURCE, encoding="utf-8")
    (tmp_path / "program.toml").write_text(PROGRAM, encoding="utf-8")
    with pytest.raises(scl.SclError) as e:
        scl.compile(
            [tmp_path / "p.scl"], program=tmp_path / "program.toml", tags=tmp_path / "t.csv"
        )
    assert message in str(e.value)


# docs/scl.md rules: [S7-TAG-ADDRESS] [DEC-TAG-IMAGE]
def test_an_address_without_tag_and_a_partition_refused(tmp_path):
    (tmp_path / "t.csv").write_text("\n".join(",".join(r) for r in [HEADER, *ROWS]))
    (tmp_path / "program.toml").write_text(PROGRAM, encoding="utf-8")
    (tmp_path / "p.scl").write_text(SOURCE.replace("%IW2", "%IW6"), encoding="utf-8")
    with pytest.raises(scl.SclError) as e:
        scl.compile(
            [tmp_path / "p.scl"], program=tmp_path / "program.toml", tags=tmp_path / "t.csv"
        )
    assert "no tag of the tag table has the address %IW6" in str(e.value)
    (tmp_path / "p.scl").write_text(SOURCE.replace('"Seen" := "In1"', '"Run" := %I0.9'))
    with pytest.raises(scl.SclError) as e:
        scl.compile(
            [tmp_path / "p.scl"], program=tmp_path / "program.toml", tags=tmp_path / "t.csv"
        )
    assert "%I0.9: the byte of a bit address takes .0 to .7" in str(e.value)
    (tmp_path / "p.scl").write_text(SOURCE, encoding="utf-8")
    wrong = PROGRAM.replace('["In2", "Out2"]', '["In2", "Seen"]')
    (tmp_path / "program.toml").write_text(wrong, encoding="utf-8")
    with pytest.raises(scl.SclError) as e:
        scl.compile(
            [tmp_path / "p.scl"], program=tmp_path / "program.toml", tags=tmp_path / "t.csv"
        )
    assert "'Seen' is an %M tag, which has no process image" in str(e.value)
    with pytest.raises(scl.SclError) as e:
        scl.compile([tmp_path / "p.scl"], block="Main", tags=tmp_path / "t.csv")
    assert "a tag table belongs to a program" in str(e.value)
