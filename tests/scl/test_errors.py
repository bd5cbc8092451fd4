"""What the compiler refuses (docs/scl.md §5): one SclError `file:line:col: message` that names
the construct (with the S7 rule where one applies), raised before any C is generated; and the
command line's one-line `error: ...` with exit status 2."""

from __future__ import annotations

import subprocess
import sys

import pytest

from lgf_fmus import scl
from lgf_fmus.scl import SclError
from tests.scl.driver import ROOT
from tests.timeouts import hang_guard


def fb(declarations: str, body: str) -> str:
    return (
        'FUNCTION_BLOCK "Fb"\n'  # line 1
        "   VAR_INPUT\n"  # 2
        "      i : Int;\n"  # 3
        "      d : DInt;\n"  # 4
        "      r : Real;\n"  # 5
        "   END_VAR\n"  # 6
        "   VAR_OUTPUT\n"  # 7
        "      o : Int;\n"  # 8
        "   END_VAR\n"  # 9
        f"{declarations}"
        "BEGIN\n"
        f"{body}"
        "END_FUNCTION_BLOCK\n"
    )


def refused(tmp_path, text: str, block="Fb") -> str:
    source = tmp_path / "fb.scl"
    source.write_text(text, encoding="utf-8")
    with pytest.raises(SclError) as caught:
        scl.generate_c([source], block=block)
    return str(caught.value).replace(str(source), "fb.scl")


# (declarations, body, the message's start: file:line:col and the words it must hold)
CASES = {
    "syntax": ("", "    #o := ;\n", "fb.scl:11:11: unexpected ';'"),
    "undeclared": ("", "    #o := #nothing;\n", "fb.scl:11:11: 'nothing' is not declared in Fb"),
    "narrowing": (
        "",
        "    #o := #d;\n",
        "fb.scl:11:11: the assignment to 'o': S7 converts no DINT to INT implicitly; "
        "write DINT_TO_INT(...)",
    ),
    "real to int": (
        "",
        "    #o := #r;\n",
        "fb.scl:11:11: the assignment to 'o': S7 converts no REAL",
    ),
    "literal too big": (
        "",
        "    #o := 40000;\n",
        "fb.scl:11:11: the assignment to 'o': 40000 does not fit INT (-32768 to 32767)",
    ),
    "real too big": (
        "   VAR\n      x : Real;\n   END_VAR\n",
        "    #x := 1e39;\n",
        "fb.scl:14:11: the assignment to 'x': 1e39 is beyond the largest REAL",
    ),
    "exit": ("", "    EXIT;\n", "fb.scl:11:5: EXIT outside FOR, WHILE or REPEAT"),
    "unknown type": (
        "   VAR\n      s : String;\n   END_VAR\n",
        "",
        "fb.scl:11:11: unknown or unsupported data type 'String' of 's'",
    ),
    "unknown function": (
        "",
        "    #o := FOO(#i);\n",
        "fb.scl:11:11: unknown or unsupported function 'FOO'",
    ),
    "input written": ("", "    #i := 1;\n", "fb.scl:11:5: 'i' is an input"),
    "time plus int": (
        "   VAR\n      t : Time;\n   END_VAR\n",
        "    #t := #t + 5;\n",
        "fb.scl:14:11: TIME + an integer literal: TIME takes + and - of TIME",
    ),
    "condition": (
        "",
        "    IF #i THEN #o := 1; END_IF;\n",
        "fb.scl:11:8: the IF condition: S7 converts no INT to BOOL implicitly",
    ),
    "timer argument": (
        "   VAR\n      t : TON;\n   END_VAR\n",
        "    #t(IN := TRUE, PX := T#1s);\n",
        "fb.scl:14:20: TON has no input 'PX' (IN, PT)",
    ),
    "timer output": (
        "   VAR\n      t : TON;\n   END_VAR\n",
        "    #t.Q := TRUE;\n",
        "fb.scl:14:5: 't.Q' is an output of TON",
    ),
    "timer as value": (
        "   VAR\n      t : TON;\n   END_VAR\n",
        "    #o := #t;\n",
        "fb.scl:14:11: the TON instance 't' is not a value",
    ),
    "duplicate": (
        "   VAR\n      I : Bool;\n   END_VAR\n",
        "",
        "fb.scl:11:7: 'I' is declared twice (first at fb.scl:3:7)",
    ),
    "in_out": (
        "   VAR_IN_OUT\n      io : Int;\n   END_VAR\n",
        "",
        "fb.scl:11:7: VAR_IN_OUT 'io': not supported yet",
    ),
    "case label": (
        "",
        "    CASE #i OF 1..3: #o := 1; 2: #o := 2; END_CASE;\n",
        "fb.scl:11:5: the CASE label 2..2 overlaps 1..3",
    ),
    "bad time": ("", "    #o := TIME_TO_INT(T#1x);\n", "fb.scl:11:23: T#1x: not a TIME literal"),
    "conversion": (
        "",
        "    #o := REAL_TO_TIME(#r);\n",
        "fb.scl:11:11: REAL_TO_TIME: S7 has no conversion between REAL and TIME",
    ),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_refusal_names_the_construct_at_its_place(tmp_path, case):
    declarations, body, expected = CASES[case]
    message = refused(tmp_path, fb(declarations, body))
    assert message.startswith(expected), message


# blocks after the FB of fb(): an FC of two inputs and an output, a VOID FC, an FB
BLOCKS = """FUNCTION "Two" : Int
   VAR_INPUT
      x : Int;
      y : Int;
   END_VAR
   VAR_OUTPUT
      z : Int;
   END_VAR
BEGIN
END_FUNCTION
FUNCTION "Nothing" : Void
BEGIN
END_FUNCTION
FUNCTION_BLOCK "Motor"
   VAR_INPUT
      start : Bool;
   END_VAR
   VAR
      calls : Int;
   END_VAR
BEGIN
END_FUNCTION_BLOCK
"""
STATIC_M = '   VAR\n      m : "Motor";\n   END_VAR\n'

# (declarations, body, blocks after the FB, the message's start) for calls and functions
CALL_CASES = {
    "fc recursion": (
        "",
        '    #o := "Rec"(#i);\n',
        'FUNCTION "Rec" : Int\n   VAR_INPUT\n      x : Int;\n   END_VAR\nBEGIN\n'
        '    #Rec := "Rec"(#x);\nEND_FUNCTION\n',
        "fb.scl:18:13: Rec calls itself (Rec -> Rec): S7 has no recursion",
    ),
    "fb recursion": (
        '   VAR\n      m : "Inner";\n   END_VAR\n',
        "",
        'FUNCTION_BLOCK "Inner"\n   VAR\n      f : "Fb";\n   END_VAR\nBEGIN\nEND_FUNCTION_BLOCK\n',
        "fb.scl:17:11: Fb calls itself (Fb -> Inner -> Fb): S7 has no recursion",
    ),
    "fc input missing": (
        "",
        '    #o := "Two"(x := 1);\n',
        BLOCKS,
        'fb.scl:11:11: "Two" needs y: an FC has no instance data',
    ),
    "fc positional count": (
        "",
        '    #o := "Two"(1);\n',
        BLOCKS,
        'fb.scl:11:11: "Two" takes 2 inputs (x, y), not 1',
    ),
    "fc output type": (
        "   VAR\n      s : DInt;\n   END_VAR\n",
        '    #o := "Two"(x := 1, y := 2, z => #s);\n',
        BLOCKS,
        "fb.scl:14:38: \"Two\"'s output z is a INT; 's' is a DINT",
    ),
    "void as value": (
        "",
        '    #o := "Nothing"();\n',
        BLOCKS,
        'fb.scl:11:11: "Nothing" is a FUNCTION : Void, it has no value',
    ),
    "fb called as a function": (
        "",
        '    #o := "Motor"(start := TRUE);\n',
        BLOCKS,
        "fb.scl:11:11: Motor is a FUNCTION_BLOCK: declare an instance of it",
    ),
    "fc as an instance": (
        '   VAR\n      f : "Two";\n   END_VAR\n',
        "",
        BLOCKS,
        "fb.scl:11:11: Two is a FUNCTION: it has no instance",
    ),
    "instance as a value": (
        STATIC_M,
        "    #o := #m;\n",
        BLOCKS,
        "fb.scl:14:11: the Motor instance 'm' is not a value: use #m.<output>",
    ),
    "static of an instance": (
        STATIC_M,
        "    #o := #m.calls;\n",
        BLOCKS,
        "fb.scl:14:11: Motor has no input or output 'calls'",
    ),
    "statics in an fc": (
        "",
        '    #o := "Stat"(1);\n',
        'FUNCTION "Stat" : Int\n   VAR\n      s : Int;\n   END_VAR\n'
        "   VAR_INPUT\n      x : Int;\n   END_VAR\nBEGIN\nEND_FUNCTION\n",
        "fb.scl:15:7: the FUNCTION Stat has no instance data, so no statics",
    ),
    "mux selector": (
        "",
        "    #o := MUX(K := #r, IN0 := 1, IN1 := 2);\n",
        "",
        "fb.scl:11:20: MUX's K must be an integer, not REAL",
    ),
    "shift of a literal": (
        "",
        "    #o := SHL(IN := 5, N := 1);\n",
        "",
        "fb.scl:11:11: SHL of an untyped literal: give it its type",
    ),
    "power of an integer": (
        "",
        "    #o := #i ** 2;\n",
        "",
        "fb.scl:11:11: ** needs a REAL or LREAL base, not INT",
    ),
    "exp of an integer": (
        "",
        "    #o := REAL_TO_INT(EXP(#i));\n",
        "",
        "fb.scl:11:23: EXP needs a REAL or LREAL, not INT",
    ),
    "rd_sys_t target": (
        "",
        "    #o := RD_SYS_T(OUT => #i);\n",
        "",
        "fb.scl:11:20: RD_SYS_T's OUT is a DTL; 'i' is not",
    ),
    "runtime memory": (
        "   VAR\n      m : Real;\n   END_VAR\n",
        "    #o := LREAL_TO_INT(RUNTIME(#m));\n",
        "",
        "fb.scl:14:32: RUNTIME's MEM is an LREAL; 'm' is a REAL",
    ),
    "dtl output": (
        "   VAR_OUTPUT\n      t : DTL;\n   END_VAR\n",
        "",
        "",
        "fb.scl:11:7: the DTL 't': only a static or a VAR_TEMP can be a DTL",
    ),
    "clock parameter name": (
        "   VAR\n      now : DTL;\n      startDateAndTime : LReal;\n   END_VAR\n",
        "    RD_SYS_T(OUT => #now);\n",
        "",
        "fb.scl:12:7: 'startDateAndTime' is the FMU's own parameter of RD_SYS_T/RD_LOC_T",
    ),
    "counter parameter": (
        "   VAR\n      c : CTU;\n   END_VAR\n",
        "    #c(CU := TRUE, PV := 3, LD := TRUE);\n",
        "",
        "fb.scl:14:29: CTU_INT has no input 'LD' (CU, R, PV)",
    ),
}


@pytest.mark.parametrize("case", sorted(CALL_CASES))
def test_refusal_of_a_call_names_it_at_its_place(tmp_path, case):
    declarations, body, after, expected = CALL_CASES[case]
    message = refused(tmp_path, fb(declarations, body) + after)
    assert message.startswith(expected), message


def test_a_missing_block_names_the_blocks_there_are(tmp_path):
    message = refused(tmp_path, fb("", ""), block="Motor")
    assert message == "no block 'Motor' in the sources (they define: Fb)"


def test_a_function_is_not_an_fmu(tmp_path):
    text = 'FUNCTION "Twice" : Int\n   VAR_INPUT\n      x : Int;\n   END_VAR\nBEGIN\nEND_FUNCTION\n'
    message = refused(tmp_path, text, block="Twice")
    assert message == "fb.scl:1:1: Twice: only a FUNCTION_BLOCK becomes an FMU"


def test_the_command_line_prints_one_line_and_exits_2(tmp_path):
    source = tmp_path / "fb.scl"
    source.write_text(fb("", "    #o := #d;\n"), encoding="utf-8")
    code = (
        "import sys, lgf_fmus; from pathlib import Path\n"
        f"lgf_fmus.__path__.insert(0, {str(ROOT / 'python' / 'lgf_fmus')!r})\n"
        "from lgf_fmus.cli import main\n"
        "sys.exit(main(sys.argv[1:]))\n"
    )
    run = subprocess.run(
        [sys.executable, "-c", code, "compile", str(source), "--block", "Fb"],
        capture_output=True,
        text=True,
        cwd=tmp_path,
        timeout=hang_guard(120),
    )
    assert run.returncode == 2
    assert run.stdout == ""
    assert run.stderr == (
        f"error: {source}:11:11: the assignment to 'o': S7 converts no DINT to "
        "INT implicitly; write DINT_TO_INT(...)\n"
    )
    assert not (tmp_path / "Fb.fmu").exists()
