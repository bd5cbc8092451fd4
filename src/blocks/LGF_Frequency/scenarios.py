"""The demo scenarios of LGF_Frequency, as tools/blocks.py describes them."""

from tools.scenario import Scenario

# cycleTime 0.1 s: a pulse of Pp ms lasts ceil(Pp / 100) + 1 calls, a pause of Pz ms
# ceil(Pz / 100) calls, at least one (docs/behaviour.md §10.3).
SCENARIOS = [
    Scenario(
        name="frequency",
        title="LGF_Frequency: 1 Hz at ratios 1 and 3, 2 Hz at ratio 0.5, off, and on again",
        stop_time=12.0,
        inputs=[
            (0.0, {"frequency": 1.0, "pulsePauseRatio": 1.0}),  # 500 / 500 ms: 6 + 5 calls
            (3.0, {"pulsePauseRatio": 3.0}),  # 750 / 250 ms: restarts with a pulse, 9 + 3 calls
            (6.0, {"frequency": 2.0, "pulsePauseRatio": 0.5}),  # 167 / 333 ms: 3 + 4 calls
            (9.0, {"pulsePauseRatio": 0.0}),  # off: countdown 0, clock the pulse TOF's Q
            (10.0, {"pulsePauseRatio": 1.0}),  # new settings: 250 / 250 ms, 4 + 3 calls
        ],
    ),
    Scenario(
        name="frequency_limits",
        title="LGF_Frequency: phases of 0 ms, and the timers going on after a pause",
        stop_time=8.0,
        inputs=[
            (0.0, {"frequency": 5.0, "pulsePauseRatio": 1.0}),  # 100 / 100 ms: 2 + 1 calls
            (1.0, {"frequency": float("inf")}),  # 0 / 0 ms: TRUE and FALSE in turn
            (2.0, {"frequency": 1.0, "pulsePauseRatio": 1e9}),  # 1000 / 0 ms: 11 + 1 calls
            (4.0, {"pulsePauseRatio": 1e-9}),  # 0 / 1000 ms: 1 + 10 calls
            (5.5, {"frequency": 0.0}),  # off for 1 s: the timers stand ...
            (6.5, {"frequency": 1.0}),  # ... no new settings: they go on where they were
        ],
    ),
]
