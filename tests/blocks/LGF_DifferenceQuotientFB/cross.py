"""The fixed scenario of LGF_DifferenceQuotientFB for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py): values read in at edges of insert, the five-point
derivative in LREAL, deltaT 0 (16#8200), enable off and on, ±Inf and a state round trip
(docs/behaviour.md §17)."""

import math

from tests.cross.scripts import SIZES_10MS, one_run


def script(md) -> str:
    events: dict[int, dict | list | str] = {}
    values = [0.1, 0.2, 0.3, 1.0 / 3.0, -7.25, 1e300, 1e300, -2.5e-300, 42.0, math.pi, 2.0, 3.5]
    for i, v in enumerate(values):  # a rising edge of insert every 5 steps
        events[5 * i + 2] = {"insert": True, "value": v}
        events[5 * i + 4] = {"insert": False}
    events.update(
        {
            40: {"deltaT": 0.0},  # 16#8200 at the next edge
            50: {"deltaT": 1.0 / 3.0},
            62: {"insert": True, "value": 9.0, "deltaT": -0.7},
            64: {"insert": False, "enable": False},
            68: {"enable": True, "insert": True, "value": 5.5},  # both rise: insert lost
            70: {"insert": False},
            72: {"insert": True, "value": math.inf},
            74: {"insert": False},
            76: [{"insert": True, "value": -math.inf}, {"deltaT": math.nan}],  # NaN refused
            78: [{"insert": False}, "save"],
            80: {"insert": True, "value": 1.5, "deltaT": 1e-300},
            82: {"insert": False},
            84: {"insert": True, "value": -0.75, "deltaT": math.inf},
            86: {"insert": False},
            88: {"insert": True, "value": 4.0},
            130: "restore",  # replay from step 78 ...
            160: "reserialize",  # ... and once more via bytes
        }
    )
    return one_run(
        md,
        "differencequotient",
        0.5,
        {"cycleTime": 0.01, "enable": True, "insert": False, "deltaT": 0.1},
        320,
        SIZES_10MS,
        events,
    )
