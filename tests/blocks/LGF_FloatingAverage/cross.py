"""The fixed scenario of LGF_FloatingAverage for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py): LREAL sums, rounding and their order, Inf and the
NaN it leaves, trigger edges, invalid window sizes and a state round trip
(docs/behaviour.md §15)."""

import math

from tests.cross.scripts import SIZES_10MS, one_run


def script(md) -> str:
    return one_run(
        md,
        "floatingaverage",
        0.5,
        {
            "cycleTime": 0.01,
            "cyclicExecution": True,
            "trigger": False,
            "value": 0.1,
            "windowSize": 7,
            "reset": False,
        },
        300,
        SIZES_10MS,
        {
            10: {"value": 1.0 / 3.0},
            20: {"value": 1e16},
            25: {"value": 1.0, "windowSize": 2},  # the running sum loses the 1.0
            40: {"value": -2.7182817, "windowSize": 5},
            50: {"value": math.inf},
            52: {"value": 12.5},  # Inf leaves the window after 5 values: the sum is NaN
            70: {"reset": True},
            72: [{"reset": False, "cyclicExecution": False}, {"value": math.nan}],  # refused
            80: {"trigger": True, "value": 1.0e308},
            82: {"trigger": False},
            84: {"trigger": True},  # 1e308 + 1e308 overflows to +Inf
            90: {"windowSize": 0, "trigger": False},  # a restart, then 16#8200
            100: {"windowSize": 3, "cyclicExecution": True, "value": 5e-324},
            110: {"windowSize": 100, "value": 0.3},
            140: [{"value": 0.7}, "save"],
            200: {"value": -0.25},
            240: "restore",  # replay from step 140 ...
            270: "reserialize",  # ... and once more via bytes
        },
    )
