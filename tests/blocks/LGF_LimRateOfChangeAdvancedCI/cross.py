"""The fixed scenario of LGF_LimRateOfChangeAdvancedCI for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py)."""

import math

from tests.cross.scripts import SIZES_10MS, one_run


def script(md) -> str:
    return one_run(
        md,
        "limrateadv",
        0.25,
        {
            "cycleTime": 0.01,
            "autoValue": 33.3,
            "manualValue": 123.456,
            "setPosUpRateLim": 70.0,
            "setPosDownRateLim": 130.0,
            "setNegUpRateLim": 45.5,
            "setNegDownRateLim": 1.0 / 0.07,
            "setHighLim": 40.0,
            "setLowLim": -35.25,
            "defaultOutValue": -7.125,
            "enDefaultOutValue": False,
            "track": False,
            "manOp": False,
            "reset": False,
        },
        340,
        SIZES_10MS,
        {
            20: {"autoValue": -50.0},  # down across zero, cut at the low limit
            60: {"autoValue": 1.0 / 3.0},  # up across zero
            90: {"manOp": True},
            100: {"manOp": False, "autoValue": -1e3},  # back, the limits suspended
            150: {"track": True, "autoValue": 17.0},
            160: {"track": False, "enDefaultOutValue": True},
            170: [{"enDefaultOutValue": False, "autoValue": 39.9}, "save"],
            200: {"setLowLim": 41.0},  # 16#8200
            210: {"setLowLim": -35.25, "setPosUpRateLim": -0.5},  # 16#8202
            220: {"setPosUpRateLim": math.inf, "autoValue": 12.0},
            230: [{"autoValue": math.nan}, {"reset": True}],  # NaN refused
            240: {"reset": False, "setHighLim": math.inf, "autoValue": 1e300},
            260: {"autoValue": -1e300, "setLowLim": -math.inf},
            280: "restore",  # replay from step 170 ...
            300: "reserialize",  # ... and once more via bytes
        },
    )
