"""The demo scenarios of LGF_Impulse (tools/blocks.py lists them); each has its reference result
in tests/blocks/LGF_Impulse/references/<name>.csv. The first one is the typical run of the FMU's
documentation."""

from tools.scenario import Scenario

# The scenario of the FMU's compatibility information (tools/compat.py: <Block>_in.csv,
# <Block>_ref.csv, <Block>_ref.opt inside the FMU and in the release): it runs on the FMU's
# parameter start values, since the FMI cross-check format carries only inputs.
COMPATIBILITY = "impulse"

# cycleTime 0.1 s: a period of P ms gives a pulse every ceil(P / 100) + 2 calls
# (docs/behaviour.md §9.3).
SCENARIOS = [
    Scenario(
        name="impulse",
        block="LGF_Impulse",
        title="LGF_Impulse: pulses at 1 Hz, 2 Hz (set while the TOF runs), none at 0 Hz, then 4 Hz",
        stop_time=12.0,
        inputs=[
            (0.0, {"frequency": 1.0}),  # P 1000 ms: a pulse every 12 calls
            (4.0, {"frequency": 2.0}),  # P 500 ms from the TOF's next start: every 7 calls
            (7.0, {"frequency": 0.0}),  # no pulses, countdown 0
            (8.0, {"frequency": 4.0}),  # P 250 ms: every 5 calls
        ],
    ),
    Scenario(
        name="impulse_fast",
        block="LGF_Impulse",
        title="LGF_Impulse: periods shorter than the cycle, and a period truncated to whole ms",
        stop_time=4.0,
        inputs=[
            (0.0, {"frequency": 20.0}),  # P 50 ms <= one cycle: a pulse every 3 calls
            (1.0, {"frequency": 2000.0}),  # P 0 ms: every 2 calls
            (2.0, {"frequency": 3.0}),  # P TRUNC(333.33334) = 333 ms: every 6 calls
        ],
    ),
]
