"""TIA Portal's "IEC check" (docs/scl.md §3.2, issue 30): off, as TIA creates every block and as
the exports carry no other setting, S7 converts implicitly between integers and bit strings of
every width (the low bits of a wider value, a narrower one zero- or sign-extended as its
explicit *_TO_* conversion does) and between a bit string and BOOL; `--iec-check`
(`lgf_fmus.compile(..., iec_check=True)`) keeps only the conversions towards a type that holds
every value. The SCL is written here; every expected value is computed by hand."""

from __future__ import annotations

import pytest

from lgf_fmus import scl
from lgf_fmus.scl import SclError
from tests.scl.driver import compile_command, compile_text, run_cs


def block(declarations: str, body: str) -> str:
    return (
        'FUNCTION_BLOCK "Relaxed"\n'  # line 1
        "   VAR_INPUT\n"  # 2
        "      w : Word := 16#ABCD;\n"  # 3
        "      d : DInt := 100000;\n"  # 4
        "      i : Int := -2;\n"  # 5
        "      b : Byte := 16#81;\n"  # 6
        "      dw : DWord := 16#12345678;\n"  # 7
        "   END_VAR\n"  # 8
        f"{declarations}"
        "BEGIN\n"
        f"{body}"
        "END_FUNCTION_BLOCK\n"
    )


RELAXED = block(
    """   VAR_OUTPUT
      lowByte : Byte;
      fromInt : Byte;
      toInt : Int;
      narrowed : Int;
      word : Word;
      bit : Bool;
      bitOfWord : Bool;
      sum : Int;
      mixed : Word;
      flagWord : Word;
      fromLiteral : Int;
      maskOut : Byte;
   END_VAR
   VAR CONSTANT
      MASK : Byte := 16#FFFF;
   END_VAR
""",
    """    #lowByte := #w;
    #fromInt := #i;
    #toInt := #b;
    #narrowed := #d;
    #word := #dw;
    #bit := #b AND 16#01;
    #bitOfWord := SHR(IN := #w, N := 1) AND 16#0001;
    #sum := #i + #b;
    #mixed := #i AND #w;
    #flagWord := #bit;
    #fromLiteral := B#16#05;
    #maskOut := #MASK;
""",
)


# docs/scl.md rules: [S7-CONV-IEC] [DEC-LIT-BITS]
def test_without_the_iec_check_integers_and_bit_strings_convert(tmp_path):
    fmu = compile_text(tmp_path, RELAXED, "Relaxed", fmi=3)
    (row,) = run_cs(fmu, 100_000, {}, {}, [])
    assert row == {
        "lowByte": 0xCD,  # WORD 16#ABCD into a BYTE: its low byte
        "fromInt": 0xFE,  # INT -2 = 16#FFFE: its low byte
        "toInt": 129,  # BYTE 16#81 into an INT: zero-extended
        "narrowed": -31072,  # DINT 100000 = 16#0001_86A0: its low word 16#86A0 as an INT
        "word": 0x5678,  # DWORD 16#12345678: its low word
        "bit": True,  # 16#81 AND 16#01 = 16#01: a BYTE into a BOOL, as BYTE_TO_BOOL
        "bitOfWord": False,  # 16#ABCD SHR 1 = 16#55E6, AND 16#0001 = 0
        "sum": 127,  # INT + BYTE in INT: -2 + 129
        "mixed": 0xABCC,  # INT AND WORD in WORD: 16#FFFE AND 16#ABCD
        "flagWord": 1,  # BOOL TRUE into a WORD
        "fromLiteral": 5,  # B#16#05 into an INT
        "maskOut": 0xFF,  # Byte := 16#FFFF keeps the low bits 16#FF
    }


STRICT = [
    ("#lowByte := #w;", "S7 converts no WORD to BYTE implicitly; write WORD_TO_BYTE(...)"),
    ("#fromInt := #i;", "S7 converts no INT to BYTE implicitly; write INT_TO_BYTE(...)"),
    ("#toInt := #b;", "S7 converts no BYTE to INT implicitly; write BYTE_TO_INT(...)"),
    ("#narrowed := #d;", "S7 converts no DINT to INT implicitly; write DINT_TO_INT(...)"),
    ("#bit := #b AND 16#01;", "S7 converts no BYTE to BOOL implicitly; write BYTE_TO_BOOL(...)"),
    ("#fromLiteral := B#16#05;", "S7 converts no BYTE to INT implicitly"),
    ("#mixed := #i AND #w;", "INT AND WORD: S7 converts neither operand to the other's type"),
    ("#maskOut := 16#FFFF;", "16#FFFF does not fit BYTE (0 to 255)"),
]


# docs/scl.md rules: [S7-CONV-1] [S7-CONV-3]
@pytest.mark.parametrize("statement, message", STRICT)
def test_with_the_iec_check_they_are_refused(tmp_path, statement, message):
    source = tmp_path / "relaxed.scl"
    declarations = (
        RELAXED.split("BEGIN\n")[0].split("   END_VAR\n", 1)[1].split("   VAR CONSTANT")[0]
    )
    source.write_text(block(declarations, f"    {statement}\n"), encoding="utf-8")
    scl.generate_c([source], "Relaxed")  # without the check: taken
    with pytest.raises(SclError) as caught:
        scl.generate_c([source], "Relaxed", iec_check=True)
    assert message in caught.value.diagnostics[0].message


def test_the_option_of_compile_and_of_the_command_line(tmp_path):
    source = tmp_path / "relaxed.scl"
    source.write_text(RELAXED, encoding="utf-8")
    with pytest.raises(SclError, match="S7 converts no WORD to BYTE implicitly"):
        scl.compile([source], "Relaxed", output=tmp_path / "r.fmu", iec_check=True)
    run = compile_command(source, "--block", "Relaxed", "--iec-check", cwd=tmp_path)
    assert run.returncode == 2
    # the constant's 16#FFFF, then every statement but the last (#maskOut := #MASK)
    assert "relaxed.scl:24:22: error E007: the initial value of 'MASK': 16#FFFF" in run.stderr
    assert "error E006: the assignment to 'lowByte': S7 converts no WORD to BYTE" in run.stderr
    assert run.stderr.endswith("\n12 errors\n")
