"""The fixed scenario of LGF_StoreMinMax for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py): every rule of docs/behaviour.md §14."""

import math

from tests.cross.scripts import SIZES_10MS, one_run


def script(md) -> str:
    return one_run(
        md,
        "store",
        0.5,
        {"cycleTime": 0.01, "value": 3.0, "reset": False},
        320,
        SIZES_10MS,
        {
            10: {"value": 5.0},
            20: {"value": -2.0},
            30: {"value": 1.0 / 3.0},
            40: {"reset": True, "value": 0.0},  # reset: both follow value
            45: {"value": -0.0},  # -0.0 < 0.0 is false: +0.0 stays
            50: {"reset": False, "value": 1e300},
            60: [{"value": math.nan}, {"value": math.inf}],  # NaN refused, +Inf accepted
            70: {"reset": True, "value": math.inf},  # min stays LREAL_MAX, max +Inf
            80: {"reset": False, "value": -math.inf},
            90: {"reset": True, "value": -1.7976931348623157e308},
            100: [{"reset": False, "value": 7.25}, "save"],
            150: {"value": -7.0},
            200: {"value": 8.0},
            260: "restore",  # replay from step 100 ...
            290: "reserialize",  # ... and once more via bytes
        },
    )
