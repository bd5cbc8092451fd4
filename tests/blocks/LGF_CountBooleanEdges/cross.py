"""The fixed scenario of LGF_CountBooleanEdges for tests/cross/scenario_runner.c
(tests/test_win64.py, tests/test_aarch64.py): single, double, long, several edges, the TP's PT
kept while it runs, a zero and a negative monitoring time, values refused, a state saved and
restored (docs/behaviour.md §12)."""

import math

from tests.cross.scripts import one_run


def script(md) -> str:
    events = {
        5: {"trigger": True},  # single
        7: {"trigger": False},
        30: {"trigger": True},  # double
        31: {"trigger": False},
        33: {"trigger": True},
        34: {"trigger": False},
        60: {"trigger": True, "monitorTime": 0.0755},  # long (PT rounded to 76 ms)
        62: {"monitorTime": 0.5},  # no effect on the running pulse
        100: {"trigger": False},
        120: [{"monitorTime": math.nan}, {"monitorTime": 3e6}],  # refused
    }
    for k in range(130, 170):  # several edges, one every other step
        events[k] = {"trigger": k % 2 == 0}
    events.update(
        {
            170: [{"trigger": False, "monitorTime": 0.0}, "save"],
            172: {"trigger": True},  # monitorTime 0: long at once
            175: {"trigger": False, "monitorTime": -0.2},
            177: {"trigger": True},
            178: {"trigger": False},
            190: "restore",  # replay from step 170 ...
            200: "reserialize",  # ... and once more via bytes
        }
    )
    k = 240
    events[k] = {"trigger": False, "monitorTime": 0.3}
    for n in (3, 4, 5, 6):
        for edge in range(n):
            events[k + 1 + 4 * edge] = {"trigger": True}
            events[k + 3 + 4 * edge] = {"trigger": False}
        k += 4 * n + 40
    return one_run(
        md,
        "countedges",
        0.0,
        {"cycleTime": 0.01, "trigger": False, "monitorTime": 0.1},
        k,
        [0.01, 0.01, 0.02, 0.005, 0.005],
        events,
    )
