"""The committed fuzz seeds are those tests/fuzz/make_seeds.py makes from each block's interface
(modelDescription/) and its tests/blocks/<Block>/fuzz_seeds.py, and the regressions it writes are
as committed: after a change of an interface, of a block's seeds or of the input format, run
`.venv/bin/python -m tests.fuzz.make_seeds` and commit tests/fuzz/corpus/. Also the script
language of the blocks' seeds (make_seeds' docstring)."""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.fuzz import make_seeds

FUZZ = Path(make_seeds.HERE)
AGAIN = "run .venv/bin/python -m tests.fuzz.make_seeds and commit tests/fuzz/"


def committed(folder: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in folder.iterdir()} if folder.is_dir() else {}


@pytest.mark.parametrize("block", make_seeds.blocks())
def test_corpus_is_what_make_seeds_writes(block):
    made, there = make_seeds.seeds_of(block), committed(FUZZ / "corpus" / block)
    assert sorted(there) == sorted(made), f"{block}: other seeds than make_seeds writes: {AGAIN}"
    differ = sorted(name for name in made if made[name] != there[name])
    assert not differ, f"{block}: {differ} differ from what make_seeds writes: {AGAIN}"


@pytest.mark.parametrize("block", make_seeds.blocks())
def test_written_regressions_are_committed(block):
    there = committed(FUZZ / "regressions" / block)
    for name, data in make_seeds.regressions_of(block).items():
        assert there.get(name) == data, f"{block}: regressions/{name}: {AGAIN}"


def test_scripts_name_variables_and_check_steps():
    interface = make_seeds.Interface("LGF_StoreMinMax", fmi3=True)
    with pytest.raises(KeyError, match="LGF_StoreMinMax has no variable 'nothing'"):
        make_seeds.scenario(interface, "; nothing=1")
    with pytest.raises(ValueError, match="1 to 4 cycles"):
        make_seeds.scenario(interface, "; 3x5")
    # FMI 3.0 reads a type byte after every set operation, OP_SET_BOOLEAN's too (set_kind)
    reset = interface["reset"]
    assert interface.set(("reset", True)) == bytes([make_seeds.SET_BOOLEAN, 0, 1]) + make_seeds.vr(
        reset.vr
    ) + bytes([0, 1])
