"""The fixed scenario of LGF_IecTimerOnOff for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py): on and off delays, delays changed while the timers
run, a cycle that is not a whole number of ms, refused values and FMU states."""

import math

from tests.cross.scripts import one_run


def script(md) -> str:
    return one_run(
        md,
        "iectimer",
        0.25,
        {"cycleTime": 0.0015, "in": False, "timeOnDelay": 0.004, "timeOffDelay": 0.0025},
        300,
        [0.0015, 0.0015, 0.0045, 0.00075, 0.00075],
        {
            5: {"in": True},
            20: {"in": False},
            24: {"in": True},  # during the off delay
            26: {"in": False},
            40: {"in": True, "timeOnDelay": 0.03},
            45: {"timeOnDelay": 0.001},  # no effect on the running TON
            70: {"in": False, "timeOffDelay": -0.5},  # a negative delay acts as 0
            80: {"in": True, "timeOnDelay": 0.0},
            90: [{"timeOffDelay": math.nan}, {"timeOnDelay": 3e6}],  # refused
            100: [{"in": False, "timeOffDelay": 0.05}, "save"],
            110: {"in": True},
            112: {"in": False},
            150: {"in": True, "timeOnDelay": 2147483.647},
            200: "restore",  # replay from step 100 ...
            250: "reserialize",  # ... and once more via bytes
        },
    )
