"""The fixed scenario of LGF_Frequency for tests/cross/scenario_runner.c (tests/test_win64.py,
tests/test_aarch64.py): times in float32 and REAL_TO_UDINT, new settings restarting the clock,
phases of 0 ms, the clock switched off and on, refused values and FMU states."""

import math

from tests.cross.scripts import one_run


def script(md) -> str:
    return one_run(
        md,
        "frequency",
        0.25,
        {"cycleTime": 0.0015, "frequency": 37.0, "pulsePauseRatio": 2.0},
        320,
        [0.0015, 0.0015, 0.0045, 0.00075, 0.00075],
        {
            30: {"pulsePauseRatio": 0.3},  # new settings: a restart with a pulse
            60: {"frequency": 13.7},
            80: {"pulsePauseRatio": 0.0},  # off
            90: {"pulsePauseRatio": 0.3},  # the same settings again: the timers go on
            110: {"frequency": math.inf},  # phases of 0 ms
            120: {"frequency": 250.0, "pulsePauseRatio": 1e9},  # a pause of 0 ms
            140: [{"pulsePauseRatio": math.inf}, {"frequency": math.nan}],  # refused
            141: {"frequency": 1e-9},  # refused: the times exceed a TIME
            150: [{"frequency": 90.0, "pulsePauseRatio": 1.0 / 3.0}, "save"],
            180: {"frequency": -math.inf},
            185: {"frequency": 90.0, "pulsePauseRatio": 5.5},
            240: "restore",  # replay from step 150 ...
            290: "reserialize",  # ... and once more via bytes
        },
    )
