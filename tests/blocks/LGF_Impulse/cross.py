"""The fixed scenario of LGF_Impulse for tests/cross/scenario_runner.c (tests/test_win64.py,
tests/test_aarch64.py): periods as a TIME divided by TRUNC in float32 (and by 0), a new
frequency while the TOF runs, frequencies <= 0 and infinite, a refused value and FMU states."""

import math

from tests.cross.scripts import one_run


def script(md) -> str:
    return one_run(
        md,
        "impulse",
        0.25,
        {"cycleTime": 0.0015, "frequency": 97.0},
        320,
        [0.0015, 0.0015, 0.0045, 0.00075, 0.00075],
        {
            30: {"frequency": 33.3},  # taken at the TOF's next start
            60: {"frequency": 0.8},  # P 1000000 / TRUNC(800.0) = 1250 ms
            70: {"frequency": 0.0},  # no pulses, the TOF stands
            90: {"frequency": 250.0},
            120: {"frequency": -math.inf},
            125: {"frequency": math.inf},  # P 0: a pulse every other call
            140: [{"frequency": math.nan}, {"frequency": 1e-9}],  # NaN refused; 1e-9: P 0
            150: [{"frequency": 700.0}, "save"],
            170: {"frequency": 1001.0},  # P 0
            200: {"frequency": 0.0123},  # P 1000000 / 12 = 83333 ms
            210: {"frequency": 333.0},
            240: "restore",  # replay from step 150 ...
            290: "reserialize",  # ... and once more via bytes
        },
    )
