"""The fixed scenario of LGF_LimRateOfChangeCI for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py)."""

import math

from tests.cross.scripts import SIZES_10MS, one_run


def script(md) -> str:
    return one_run(
        md,
        "limrate",
        0.5,
        {
            "cycleTime": 0.01,
            "value": 0.0,
            "setChangeRate": 20.0,
            "defaultOutValue": 30.0,
            "enDefaultOutValue": False,
        },
        320,
        SIZES_10MS,
        {
            10: {"value": 50.0},
            60: {"value": -20.125, "setChangeRate": 7.3},
            100: {"setChangeRate": -5.0},  # error, status 16#8200, frozen
            120: {"setChangeRate": 0.0, "value": 1e6},  # rate 0 freezes
            140: {"setChangeRate": 1e5},
            160: {"enDefaultOutValue": True, "defaultOutValue": 0.1},
            180: {"enDefaultOutValue": False, "value": 1.0 / 3.0, "setChangeRate": 0.37},
            200: [{"value": math.nan}, {"setChangeRate": math.inf}],  # NaN refused; +Inf allowed
            210: [{"setChangeRate": 2.5, "value": -1e-3}, "save"],
            260: {"value": 77.7},
            280: "restore",  # replay from step 210 ...
            290: "reserialize",  # ... and once more via bytes
        },
    )
