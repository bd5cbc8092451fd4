"""The demo scenarios of LGF_IecTimerOnOff, as tools/blocks.py describes them."""

from tools.scenario import Scenario

# An input set at t reaches the calls after t (docs/behaviour.md §1.3): the first call that sees
# the change of t = 0.5 s is the one at 0.6 s.
SCENARIOS = [
    Scenario(
        name="iec_timer_on_off",
        title="LGF_IecTimerOnOff: on delay 1 s, off delay 2 s; a short pulse is swallowed",
        stop_time=16.0,
        inputs=[
            (0.0, {"in": False, "timeOnDelay": 1.0, "timeOffDelay": 2.0}),
            (0.5, {"in": True}),  # out TRUE at 1.6 s
            (3.0, {"in": False}),  # out FALSE at 5.1 s
            (6.0, {"in": True}),
            (6.5, {"in": False}),  # TRUE for less than the on delay: out stays FALSE
            (8.0, {"in": True}),  # out TRUE at 9.1 s
            (9.5, {"in": False}),  # the off delay would end at 11.6 s ...
            (10.0, {"in": True}),  # ... but the on delay ends at 11.1 s: no gap
            (12.5, {"in": False}),  # the off delay ends at 14.6 s ...
            (14.0, {"in": True}),  # ... before the on delay (15.1 s): a gap
        ],
    ),
    Scenario(
        name="iec_timer_on_off_retrigger",
        title="LGF_IecTimerOnOff: delays changed while the timers run apply at their next start",
        stop_time=8.0,
        inputs=[
            (0.0, {"in": True, "timeOnDelay": 0.5, "timeOffDelay": 1.0}),  # out TRUE at 0.5 s
            (0.2, {"timeOnDelay": 3.0}),  # the running TON keeps 0.5 s
            (1.0, {"in": False, "timeOffDelay": 0.3}),  # the TOF takes 0.3 s: FALSE at 1.4 s
            (2.0, {"in": True}),  # the TON takes 3.0 s: out TRUE at 5.1 s
            (5.5, {"in": False, "timeOffDelay": 2.0}),  # the off delay would end at 7.6 s
            (6.0, {"in": True, "timeOnDelay": 0.0}),  # on delay 0: TRUE again at 6.1 s, no gap
        ],
    ),
]
