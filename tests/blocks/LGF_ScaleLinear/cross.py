"""The fixed scenario of LGF_ScaleLinear for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py): every rule of docs/behaviour.md §19."""

import math

from tests.cross.scripts import SIZES_10MS, one_run

from .spec import START


def script(md) -> str:
    return one_run(
        md,
        "scale",
        0.5,
        {"cycleTime": 0.01, **START, "x": -100.0},
        320,
        SIZES_10MS,
        {
            10: {"x": 1.0 / 3.0},
            20: {"x": 13824.0},
            30: {"x": 30000.0},  # limited to yMax, 16#6002
            40: {"x1": 4.0, "y1": 100.0, "x2": 20.0, "y2": 0.0, "x": 7.3},  # a falling line
            50: {"yMin": 60.0, "yMax": 50.0},  # 16#8200, y = 0.0
            60: {"yMin": -1e300, "yMax": 1e300, "x2": 4.0 + 1e-6},  # within PRECISION: y1
            70: {"x2": 4.0 + 2e-6},  # outside PRECISION: a steep line
            80: [{"x": math.nan}, {"x": math.inf}],  # NaN refused, +Inf accepted
            90: {"x1": math.inf, "x2": math.inf},  # inf - inf: y NaN, status 0
            100: [{"x1": 0.0, "x2": 10.0, "y1": -5.0, "y2": 5.0, "x": 2.5}, "save"],
            200: {"x": -7.0, "yMin": -1.0},
            260: "restore",  # replay from step 100 ...
            290: "reserialize",  # ... and once more via bytes
        },
    )
