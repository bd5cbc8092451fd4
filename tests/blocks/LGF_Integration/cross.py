"""The fixed scenario of LGF_Integration for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py): every rule of docs/behaviour.md §18."""

import math

from tests.cross.scripts import SIZES_10MS, one_run


def script(md) -> str:
    return one_run(
        md,
        "integrate",
        0.5,
        {"cycleTime": 0.01, "enable": True, "value": 2.0, "reset": False},
        320,
        SIZES_10MS,
        {
            10: {"value": 1.0 / 3.0},
            30: {"value": -7.25},
            50: {"enable": False},  # held
            60: {"enable": True, "value": 1e300},  # first call again adds nothing
            70: {"reset": True},
            75: {"reset": False, "enable": False},
            80: [{"enable": True, "value": math.nan}, {"value": math.inf}],  # NaN refused
            90: {"value": -math.inf},  # inf + -inf: NaN until a reset
            100: [{"reset": True, "value": 0.1}, "save"],
            110: {"reset": False},
            200: {"value": -0.3},
            260: "restore",  # replay from step 100 ...
            290: "reserialize",  # ... and once more via bytes
        },
    )
