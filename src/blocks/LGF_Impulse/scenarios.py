"""The demo scenarios of LGF_Impulse, as tools/blocks.py describes them."""

from tools.scenario import Scenario

# cycleTime 0.1 s: a period of P ms gives a pulse every ceil(P / 100) + 1 calls, every other
# call at least, the first pulse in the first call (docs/behaviour.md §9.3).
SCENARIOS = [
    Scenario(
        name="impulse",
        title="LGF_Impulse: pulses at 1 Hz, 2 Hz (set while the TOF runs), none at 0 Hz, then 4 Hz",
        stop_time=12.0,
        inputs=[
            (0.0, {"frequency": 1.0}),  # P 1000 ms: a pulse every 11 calls
            (4.0, {"frequency": 2.0}),  # P 500 ms from the TOF's next start: every 6 calls
            (7.0, {"frequency": 0.0}),  # no pulses, countdown 0
            (8.0, {"frequency": 4.0}),  # P 250 ms: every 4 calls
        ],
    ),
    Scenario(
        name="impulse_fast",
        title="LGF_Impulse: short periods, periods truncated to whole ms, and 0 ms below 0.001 Hz",
        stop_time=4.0,
        inputs=[
            (0.0, {"frequency": 20.0}),  # P 50 ms <= one cycle: a pulse every 2 calls
            (1.0, {"frequency": 7.0}),  # P 1000000 / 7000 = 142 ms: every 3 calls
            (2.0, {"frequency": 3.0}),  # P 1000000 / 3000 = 333 ms: every 5 calls
            (3.0, {"frequency": 0.0005}),  # TRUNC(0.5) = 0: a division by 0, P 0: every 2 calls
        ],
    ),
]
