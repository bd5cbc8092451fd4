"""The fixed scenario of LGF_SimpleSmoothingFB for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py): values read in at edges of insert, their mean in
LREAL, enable off and on, ±Inf and a state round trip (docs/behaviour.md §16)."""

import math

from tests.cross.scripts import SIZES_10MS, one_run


def script(md) -> str:
    events: dict[int, dict | list | str] = {}
    values = [0.1, 0.2, 0.3, 1.0 / 3.0, -7.25, 1e300, 1e300, -2.5e-300, 42.0, math.pi]
    for i, v in enumerate(values):  # a rising edge of insert every 6 steps
        events[6 * i + 2] = {"insert": True, "value": v}
        events[6 * i + 5] = {"insert": False}
    events.update(
        {
            70: {"enable": False},
            74: {"enable": True, "insert": True, "value": 5.5},  # both rise: the insert is lost
            78: {"insert": False},
            80: {"insert": True, "value": math.inf},
            83: {"insert": False},
            86: [{"insert": True, "value": -math.inf}, {"value": math.nan}],  # NaN refused
            90: [{"insert": False}, "save"],
            95: {"insert": True, "value": 1.5},
            100: {"insert": False},
            105: {"insert": True, "value": -0.75},
            130: "restore",  # replay from step 90 ...
            160: "reserialize",  # ... and once more via bytes
        }
    )
    return one_run(
        md,
        "simplesmoothing",
        0.5,
        {"cycleTime": 0.01, "enable": True, "insert": False},
        320,
        SIZES_10MS,
        events,
    )
