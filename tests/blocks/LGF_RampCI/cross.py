"""The fixed scenario of LGF_RampCI for tests/cross/scenario_runner.c (tests/test_win64.py,
tests/test_aarch64.py)."""

from src.blocks.LGF_RampCI.table import table
from tests.cross.scripts import one_run


def script(md) -> str:
    setpoints = table(
        (0.0, 0.3), (33.3, 0.25), (-17.25, 0.0), (-17.25, 1.234), (1e-3, 0.5), (100.0 / 3.0, 0.0)
    )
    parameters = {"cycleTime": 0.05, **setpoints}
    return one_run(
        md,
        "ramp",
        0.0,
        {
            **parameters,
            "start": False,
            "cyclicOP": True,
            "hold": False,
            "continue": False,
            "contStepNbr": 3,
            "contStepTime": 0.77,
            "defaultOutValue": 12.5,
            "enDefaultOutValue": False,
            "updateTime": False,
            "reset": False,
        },
        340,
        [0.05, 0.05, 0.1, 0.025, 0.025],
        {
            5: {"start": True},
            40: {"hold": True},
            50: {"continue": True},
            55: {"hold": False, "continue": False},
            90: {"enDefaultOutValue": True},
            100: {"enDefaultOutValue": False},
            130: {
                "setpoints[1].outputValue": 45.6,
                "setpoints[3].time": 0.6,
            },  # tunable at run time
            131: {"updateTime": True},
            140: [{"updateTime": False}, "save"],
            180: {"cyclicOP": False},
            220: {"reset": True},
            225: {"reset": False},
            230: {"start": False},
            240: {"start": True},
            250: [{"contStepNbr": 9}, {"setpoints[2].time": -1.0}],  # refused: outside the table
            270: "restore",
            300: "reserialize",
        },
    )
