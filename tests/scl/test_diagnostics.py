"""How refusals are reported (docs/scl.md §5): every error of the program (up to 50), each
`file:line:col: error E0nn: message` with its source line and a caret, notes at related places,
a construct outside the subset named (§6), a refused declaration reported once; the command
line's exit status 2 without a traceback; the table of codes of §5 is the compiler's."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from lgf_fmus import scl
from lgf_fmus.scl import SclError
from lgf_fmus.scl.diagnostics import LIMIT, Code
from tests.scl.driver import ROOT, compile_command, refusal

THREE = """FUNCTION_BLOCK "Fb"
   VAR_INPUT
      i : Int;
      d : LReal;
   END_VAR
   VAR_OUTPUT
      o : Int;
   END_VAR
BEGIN
    #o := #d;
    IF #i THEN
        #o := #nothing;
    END_IF;
END_FUNCTION_BLOCK
"""

THREE_REPORTED = """fb.scl:10:11: error E006: the assignment to 'o': S7 converts no LREAL to INT implicitly; write LREAL_TO_INT(...)
  10 |     #o := #d;
     |           ^
fb.scl:11:8: error E006: the IF condition: S7 converts no INT to BOOL implicitly; write INT_TO_BOOL(...)
  11 |     IF #i THEN
     |        ^
fb.scl:12:15: error E003: 'nothing' is not declared in Fb
  12 |         #o := #nothing;
     |               ^
3 errors"""  # noqa: E501


def shown(error: SclError, tmp_path) -> str:
    return str(error).replace(str(tmp_path / "fb.scl"), "fb.scl")


def test_a_file_with_three_errors_reports_three(tmp_path):
    error = refusal(tmp_path, THREE)
    assert [d.code for d in error.diagnostics] == [
        Code.CONVERSION,
        Code.CONVERSION,
        Code.UNDECLARED,
    ]
    assert shown(error, tmp_path) == THREE_REPORTED


def test_every_syntax_error_is_reported(tmp_path):
    """After a syntax error the parser goes on at the end of its statement or declaration."""
    text = THREE.replace("#o := #d;", "#o := ;").replace("#nothing;", "#nothing + * 2;")
    text = text.replace("      d : LReal;", "      d : LReal := ;")
    error = refusal(tmp_path, text)
    assert [(d.loc.line, d.loc.column, d.code) for d in error.diagnostics] == [
        (4, 20, Code.SYNTAX),
        (10, 11, Code.SYNTAX),
        (12, 26, Code.SYNTAX),
    ]
    assert error.diagnostics[1].message.startswith("unexpected ';'; expected ")


def test_a_duplicate_names_the_first_place_in_a_note(tmp_path):
    text = THREE.replace("      o : Int;", "      o : Int;\n      I : Bool;")
    error = refusal(tmp_path, text)
    assert shown(error, tmp_path).split("\n")[:6] == [
        "fb.scl:8:7: error E004: 'I' is declared twice",
        "   8 |       I : Bool;",
        "     |       ^",
        "fb.scl:3:7: note: first declared here",
        "   3 |       i : Int;",
        "     |       ^",
    ]


# (a declaration, a statement, the first error's line:col: message)
UNSUPPORTED = [
    ("s : WString[300];", "", "10:11: 's': WSTRING[300]: a WSTRING of more than 254 characters"),
    ("s : WString[#N];", "", "10:11: 's': the length of WSTRING[#N] is an integer or a constant"),
    ("t : Date_And_Time;", "", "10:11: DATE_AND_TIME is not supported yet (docs/scl.md §3.1"),
    ("p : REF_TO Int;", "", "10:11: REF_TO is not supported yet (docs/scl.md §6)"),
    ("x : Int;", "#x := ATH(#x);", "13:11: ATH is not supported yet (docs/scl.md §6)"),
    (
        "x : Int;",
        "MOVE_BLK(IN := #x, COUNT := 1, OUT => #x);",
        "13:5: MOVE_BLK is not supported yet",
    ),
    ("x : Time;", "PRESET_TIMER(PT := #x, TIMER := #x);", "13:5: PRESET_TIMER is not supported"),
    ("x : Int;", "#x := S_CONV(#x);", "13:11: S_CONV is not supported yet (docs/scl.md §6)"),
    ("h : HW_ANY;", "", "10:11: HW_ANY is not supported (docs/scl.md §6): a hardware identifier"),
    ("f : FileWriteC;", "", "10:11: FileWriteC is not supported (docs/scl.md §6): a system"),
    ("x : Int;", "#x := WR_SYS_T(#x);", "13:11: WR_SYS_T is not supported (docs/scl.md §6): a"),
]


def unsupported_source(declaration: str, body: str) -> str:
    text = THREE.replace("BEGIN\n", f"   VAR\n      {declaration}\n   END_VAR\nBEGIN\n")
    return text.split("BEGIN\n")[0] + f"BEGIN\n    {body}\nEND_FUNCTION_BLOCK\n"


@pytest.mark.parametrize("declaration, body, expected", UNSUPPORTED)
# docs/scl.md rules: [DEC-TYPE-DATE]
def test_a_construct_outside_the_subset_is_named(tmp_path, declaration, body, expected):
    first = refusal(tmp_path, unsupported_source(declaration, body)).diagnostics[0]
    assert first.code is Code.UNSUPPORTED
    assert f"{first.loc.line}:{first.loc.column}: {first.message}".startswith(expected)


def test_a_refused_declaration_is_reported_once(tmp_path):
    """Its uses end their statements without an error of their own."""
    text = THREE.replace("      d : LReal;", "      d : Strung;").replace(
        "#o := #nothing;", "#o := #d + 1;\n        #d := 2;"
    )
    text = text.replace("IF #i THEN", "IF #d > 0 THEN")
    error = refusal(tmp_path, text)
    assert [d.message for d in error.diagnostics] == [
        "unknown or unsupported data type 'Strung' of 'd' (docs/scl.md §3.1)"
    ]


def test_at_most_fifty_errors(tmp_path):
    body = "".join(f"    #o := #d{k};\n" for k in range(LIMIT + 10))
    error = refusal(tmp_path, THREE.split("BEGIN\n")[0] + "BEGIN\n" + body + "END_FUNCTION_BLOCK\n")
    assert len(error.diagnostics) == LIMIT + 1
    assert error.diagnostics[-1].message == f"stopped after {LIMIT} errors"
    assert shown(error, tmp_path).endswith(f"stopped after {LIMIT} errors\n{LIMIT} errors")


def test_the_command_line_prints_every_error_and_exits_2(tmp_path):
    source = tmp_path / "fb.scl"
    source.write_text(THREE, encoding="utf-8")
    run = compile_command(source, "--block", "Fb", cwd=tmp_path)
    assert run.returncode == 2
    assert run.stdout == ""
    assert run.stderr == THREE_REPORTED.replace("fb.scl", str(source)) + "\n"
    assert not (tmp_path / "Fb.fmu").exists()


def test_an_error_of_no_place_is_one_line(tmp_path):
    source = tmp_path / "fb.scl"
    source.write_text(THREE, encoding="utf-8")
    run = compile_command(source, "--block", "Motor")
    assert run.returncode == 2
    assert run.stderr == "error: no block 'Motor' in the sources (they define: Fb)\n"


def test_the_table_of_codes_is_the_compilers():
    """docs/scl.md §5 lists every code with its summary, as diagnostics.Code has them."""
    text = (ROOT / "docs" / "scl.md").read_text(encoding="utf-8")
    section = text.split("\n## 5 ")[1].split("\n## ")[0]
    rows = re.findall(r"^\| (E\d\d\d) \| `(\w+)` \| (.+?) \|$", section, re.M)
    assert rows == [(c.number, c.name, c.summary) for c in Code]


def test_every_code_is_given_by_some_refusal():
    """No code of the table is dead: the compiler's sources give each one."""
    package = Path(scl.__file__).parent
    sources = "".join(p.read_text(encoding="utf-8") for p in package.rglob("*.py"))
    for code in Code:
        assert f"Code.{code.name}" in sources, code
