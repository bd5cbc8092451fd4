"""SIN and COS of src/iec/sin_cos.h (docs/behaviour.md §6.2): the quadrant taken from the low
bits of k instead of fmod(k, 4) gives the same float32 bits as the fmod version, which
tests/c/sin_cos.c keeps as the oracle. Dense over the arguments the signal generators form
(0 ... 2pi·4294967040 + 2pi, k below 2^35), every float32 of the second period and around
where k passes 2^31, 2^35, 2^53 and 2^63, and spread over every float32 (SCL's SIN and COS
take any REAL). All 2^32 arguments, once, by hand: `sin_cos 0 0xffffffff 1` (a few minutes)."""

import math
import shutil
import struct
import subprocess

import pytest

from tests.harness import ROOT


def compile_driver(directory, *defines):
    if not shutil.which("cc"):
        pytest.fail("cc is needed to compile tests/c/sin_cos.c")
    program = directory / "sin_cos"
    subprocess.run(
        ["cc", "-std=c11", "-O2", "-ffp-contract=off", "-Wall", "-Wextra", "-Wpedantic",
         "-Werror", *defines, f"-I{ROOT / 'src'}", str(ROOT / "tests/c/sin_cos.c"), "-o",
         str(program), "-lm"],
        check=True, capture_output=True, text=True,
    )  # fmt: skip
    return program


@pytest.fixture(scope="module")
def driver(tmp_path_factory):
    return compile_driver(tmp_path_factory.mktemp("sin_cos"))


def bits(x: float) -> int:
    return struct.unpack("<I", struct.pack("<f", x))[0]


def compare(program, first: int, last: int, stride: int) -> tuple[int, list[str]]:
    """(arguments compared, mismatch lines) of the patterns first, first + stride, ... <= last."""
    out = subprocess.run([str(program), hex(first), hex(last), str(stride)], check=True,
                         capture_output=True, text=True).stdout.splitlines()  # fmt: skip
    arguments, mismatches = map(int, out[0].split())
    assert arguments == (last - first) // stride + 1
    return mismatches, out[1:]


# The largest argument of a signal generator: rad + shift with rad < 2pi and shift at most
# 2pi · 4294967040 (phaseShift's REAL, periode 1), about 2.7e10.
BLOCK_MAX = bits(2 * math.pi * 4294967040 + 2 * math.pi) + 64


def k_passes(power: int) -> int:
    """The bits of the float32 at which k = nearbyint(x · 2/pi) reaches 2^power."""
    return bits(2.0**power * math.pi / 2)


@pytest.mark.parametrize(
    "first, last, stride",
    [
        (0, BLOCK_MAX, 257),  # the signal generators' arguments, densely
        (bits(2 * math.pi), bits(4 * math.pi), 1),  # every float32 of the second period
        (0x8000_0000 | bits(2 * math.pi), 0x8000_0000 | bits(4 * math.pi), 7),  # negative
        (k_passes(31) - 2**20, k_passes(31) + 2**20, 1),
        (k_passes(35) - 2**20, k_passes(35) + 2**20, 1),  # where Cody-Waite stops being exact
        (k_passes(53) - 2**20, k_passes(53) + 2**20, 1),
        (k_passes(63) - 2**20, k_passes(63) + 2**20, 1),
        (0x8000_0000 | (k_passes(63) - 2**19), 0x8000_0000 | (k_passes(63) + 2**19), 1),
        (0, 0xFFFF_FFFF, 4099),  # every sign and binade, ±0, subnormals, ±Inf, NaNs
        (0x7F7F_0000, 0x7F80_0001, 1),  # up to FLT_MAX, +Inf and a NaN
    ],
)
def test_same_bits_as_the_fmod_version(driver, first, last, stride):
    mismatches, lines = compare(driver, first, last, stride)
    assert mismatches == 0, lines


def test_the_comparison_finds_a_wrong_quadrant(tmp_path):
    # An oracle with the wrong sign for k = 5 only (x in about 7.07 ... 8.64): the dense
    # sweep of the blocks' arguments must see it, in sine and cosine.
    broken = compile_driver(tmp_path, "-DSIN_COS_DEFECT")
    mismatches, lines = compare(broken, 0, BLOCK_MAX, 257)
    assert mismatches > 0
    assert {line.split()[1] for line in lines} <= {"sin", "cos"}
    mismatches, _ = compare(broken, bits(7.2), bits(8.5), 1)
    assert mismatches == 2 * (bits(8.5) - bits(7.2) + 1)  # each argument, sine and cosine
