"""tools/interface.py: a block's interface.toml that does not describe a block is refused with a
sentence naming the variable or static and what it may be, instead of C that fails to compile or
a table that silently lacks a row. (That the tables it writes are the blocks' interfaces is
tests/test_descriptions.py's: the committed modelDescription.xml files, written before the
descriptions moved to interface.toml, are what they generate.)"""

import copy

import pytest

from tools import interface

BLOCK = "LGF_PulseRelay"


def broken(change) -> dict:
    spec = copy.deepcopy(interface.load(BLOCK))
    change(spec)
    return spec


def first(spec) -> dict:
    return spec["variables"][0]


@pytest.mark.parametrize(
    "change, message",
    [
        (lambda s: first(s).update(descripton="x"), "the variable trigger has no key descripton"),
        (lambda s: first(s).pop("description"), "the variable trigger lacks description"),
        (lambda s: first(s).update(type="DWORD"), "the variable trigger has type DWORD: one of"),
        (lambda s: first(s).update(causality="local"), "has causality local: one of input,"),
        (lambda s: s["variables"].append({"vr": 9, "row": "enable"}), "no shared row enable"),
        (lambda s: s["statics"].update(statOut="BIT"), "the static statOut has type BIT: one of"),
        (lambda s: s.update(stop_tme=1), "no key stop_tme"),
        (lambda s: s.pop("guid"), "it lacks guid"),
        (lambda s: s.update(cycle="OB1"), "the cycle OB1 is none of OB, OB unused, CI"),
    ],
    ids=[
        "unknown key",
        "missing key",
        "type",
        "causality",
        "shared row",
        "static type",
        "unknown top key",
        "missing top key",
        "cycle",
    ],  # fmt: skip
)
def test_a_description_that_is_no_block_is_refused_naming_what_is_wrong(change, message):
    with pytest.raises(interface.InterfaceError, match=message):
        interface.c_source(BLOCK, broken(change))


def test_a_row_is_written_with_its_range_unit_and_original_name():
    """A row of a type's whole range takes the type's macro; any other range, or a field that
    is not the FMI name, the general row (src/core/model.h)."""
    spec = broken(
        lambda s: s["variables"].extend(
            [
                {"vr": 5, "name": "rate", "type": "LREAL", "causality": "input",
                 "description": "r", "unit": "1/s", "original": "setRate"},
                {"vr": 6, "name": "count", "type": "INT", "causality": "parameter", "min": 2,
                 "max": "LGF_MAX", "description": "n"},
                {"vr": 7, "name": "continue", "field": "continue_", "type": "BOOL",
                 "causality": "input", "description": "c"},
            ]
        )
    )  # fmt: skip
    c = interface.c_source(BLOCK, spec)
    assert '    LREAL_INPUT(5, rate, "r", .unit = "1/s", .original = "setRate"),' in c
    assert '    ROW(6, count, VAR_INT, ROLE_FIXED_PARAMETER, 2, LGF_MAX, "n"),' in c
    assert '    NAMED_ROW(7, "continue", continue_, VAR_BOOL, ROLE_INPUT, 0, 1, "c"),' in c


def test_the_command_names_every_description_it_cannot_read(tmp_path, capsys):
    """CMake shows what the command prints when it fails: a line for each broken description,
    and the blocks whose description is sound are written all the same."""
    assert interface.main(["LGF_None", BLOCK, "LGF_Nothing", "--out", str(tmp_path)]) == 1
    lines = capsys.readouterr().err.splitlines()
    assert [line.split(": ")[1] for line in lines] == [
        "src/blocks/LGF_None/interface.toml",
        "src/blocks/LGF_Nothing/interface.toml",
    ]
    assert all(line.startswith("error: ") for line in lines)
    assert (tmp_path / "blocks" / BLOCK / "interface.c").read_text() == interface.c_source(BLOCK)
    assert not (tmp_path / "blocks" / "LGF_None").exists()
