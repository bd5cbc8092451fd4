"""The fixed scenario of LGF_PulseRelay for tests/cross/scenario_runner.c (tests/test_win64.py,
tests/test_aarch64.py): toggles, set, reset, edges in one call, a state saved and restored
(docs/behaviour.md §11)."""

from tests.cross.scripts import one_run


def script(md) -> str:
    events = {k: {"trigger": k % 4 < 2} for k in range(0, 80)}  # a clock of 4 steps of 0.01 s
    events.update(
        {
            80: {"trigger": False, "set": True},
            85: {"set": False, "trigger": True},  # toggle to FALSE
            90: {"trigger": False, "reset": True},
            95: {"reset": False},
            100: [{"trigger": True, "set": True}, "save"],  # set beats trigger: TRUE
            105: {"trigger": False, "set": False},
            110: {"trigger": True, "set": True, "reset": True},  # reset beats both: FALSE
            115: {"trigger": False, "set": False, "reset": False},
            120: {"trigger": True},
            130: "restore",  # replay from step 100 ...
            140: "reserialize",  # ... and once more via bytes
        }
    )
    return one_run(
        md,
        "pulserelay",
        0.0,
        {"cycleTime": 0.01, "trigger": True, "set": False, "reset": False},
        320,
        [0.01, 0.01, 0.02, 0.005, 0.005],
        events,
    )
