"""The fixed scenarios of LGF_SawTooth for tests/cross/scenario_runner.c (tests/test_win64.py,
tests/test_aarch64.py): documented and PLC-exact timing."""

from tests.cross.scripts import Script

from .spec import EXAMPLE_1, inp


def script(md) -> str:
    s = Script(md)
    # documented timing, a timeRange that is not a multiple of the cycle, INT wrap-around
    s.start(
        "sawtooth",
        0.0,
        {"cycleTime": 0.02, "plcTiming": False, **inp(start=30000, tr=0.25, inc=700, n=4)},
    )
    s.run(
        300,
        [0.02, 0.02, 0.06, 0.01, 0.01],
        {
            60: {"incrementRange": -9, "numberSteps": 7, "timeRange": 0.0125},  # no effect yet
            90: {"reset": True},
            94: {"reset": False},
            150: {"startValue": 40000},  # refused: outside INT
            160: [
                {"endlessSteps": True, "incrementRange": 3000, "timeRange": 0.04, "reset": True},
                "save",
            ],
            161: {"reset": False},
            230: {"timeRange": 0.0, "reset": True},  # a step on every call
            232: {"reset": False},
            260: "restore",
            280: "reserialize",
        },
    )
    s.finish()
    # PLC-exact timing (the TON of the original)
    s.start(
        "sawtooth_plc",
        0.0,
        {"cycleTime": 0.1, "plcTiming": True, **EXAMPLE_1},
    )
    s.run(
        120,
        [0.1, 0.1, 0.2, 0.05, 0.05],
        {
            50: {"reset": True, "timeRange": 0.45, "incrementRange": -7},
            52: {"reset": False},
        },
    )
    s.finish()
    return s.text()
