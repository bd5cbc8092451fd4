"""The fixed scenario of LGF_IsValueInToleranceByTime for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py): percent and absolute tolerances in REAL, absolute
limits, the three timers, setpoint changes, reset, disableLimits, the status codes, ±Inf,
values refused, a state saved and restored (docs/behaviour.md §13)."""

import math

from tests.cross.scripts import one_run

from .spec import START

C = "configuration."


def script(md) -> str:
    return one_run(
        md,
        "tolerance",
        0.0,
        {
            "cycleTime": 0.01,
            **START,
            "value": 0.3,
            "setpoint": 0.3,  # 10 %: limits 0.3f * 1.1f and 0.3f * 0.9f, rounded in REAL
            C + "upperLimitMonitoringTime": 0.05,
            C + "lowerLimitMonitoringTime": 0.0755,
            C + "setpointChangeMonitoringTime": 0.1,
        },
        320,
        [0.01, 0.01, 0.02, 0.005, 0.005],
        {
            5: {"value": 0.33000001},  # just at / above the high limit
            15: {"value": 0.4},  # a violation, reported after 50 ms
            30: {"value": 0.3},
            35: {"value": 0.1},  # below, 76 ms
            50: {"setpoint": 7.25, "value": 7.0},  # a change into the band
            60: {"setpoint": 20.0},  # a change out of it: waited out, then timed
            90: {"value": 19.5},
            100: {"reset": True},
            104: {"reset": False, "value": 30.0},
            130: [{C + "disableLimits": True}, "save"],
            134: {"value": -math.inf},
            138: {"value": 20.0, C + "disableLimits": False},
            150: {C + "toleranceAsAbsoluteValues": True, "upperMaximum": 0.5, "lowerMinimum": 0.25},
            160: {"upperMaximum": -1.0},  # 16#8401
            165: {"upperMaximum": 1.0, C + "limitsAsAbsoluteValues": True},  # 16#8402
            170: {"lowerMinimum": 25.0, "upperMaximum": 40.0},  # 16#8403
            175: {"lowerMinimum": 10.0, "setpoint": -math.inf},  # absolute limits: 16#8403
            180: [{"value": math.nan}, {"setpoint": 1e39}, {C + "upperLimitMonitoringTime": 3e6}],
            185: {"setpoint": 30.0, C + "limitsAsAbsoluteValues": False, "upperMaximum": math.inf},
            200: "restore",  # replay from step 130 ...
            240: "reserialize",  # ... and once more via bytes
        },
    )
