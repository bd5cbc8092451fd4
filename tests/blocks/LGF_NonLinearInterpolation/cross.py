"""The fixed scenario of LGF_NonLinearInterpolation for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py)."""

import math

from src.blocks.LGF_NonLinearInterpolation.table import table
from tests.cross.scripts import one_run


def script(md) -> str:
    curve = table((-3.3, 17.0), (0.1, -2.5), (1.0 / 3.0, 1e-3), (7.25, 7.25), (9.0, 100.0 / 3.0))
    events = {k: {"value": -10.0 + 0.37 * k} for k in range(1, 80, 3)}  # across the curve
    events.update(
        {
            80: {"value": 1.0 / 3.0},  # on a point, from above
            90: {"track": True, "value": 2.0 / 7.0},
            100: {"track": False, "enDefaultOutValue": True},
            110: [{"reset": True}, "save"],
            120: {"enDefaultOutValue": False},
            130: {"reset": False, "value": 1.0 / 3.0},  # on the point again, from below
            140: {"setpoints[3].outputValue": -1e5, "value": 5.5},  # tunable at run time
            150: [{"value": math.nan}, {"numberOfSetpoints": 1}],  # refused
            160: {"value": math.inf},
            170: {"value": -1e300},
            190: "restore",  # replay from step 110 ...
            200: "reserialize",  # ... and once more via bytes
        }
    )
    return one_run(
        md,
        "nonlin",
        0.0,
        {
            "cycleTime": 0.02,
            **curve,
            "value": -10.0,
            "defaultOutValue": 4.5,
            "enDefaultOutValue": False,
            "track": False,
            "reset": False,
        },
        320,
        [0.02, 0.02, 0.06, 0.01, 0.01],
        events,
    )
