"""The demo scenarios of LGF_IsValueInToleranceByTime (docs/behaviour.md §13), as
tools/blocks.py describes them."""

from tools.scenario import Scenario

SCENARIOS = [
    Scenario(
        name="is_value_in_tolerance_by_time",
        title="LGF_IsValueInToleranceByTime: ±10 % of 50, a hidden peak, violations after 1 s, "
        "a setpoint change, a reset edge, disableLimits, absolute limits",
        stop_time=18.0,
        inputs=[
            (
                0.0,
                {
                    "value": 50.0,
                    "setpoint": 50.0,
                    "lowerMinimum": 10.0,
                    "upperMaximum": 10.0,
                    "reset": False,
                    "configuration.disableLimits": False,
                    "configuration.limitsAsAbsoluteValues": False,
                    "configuration.toleranceAsAbsoluteValues": False,
                    "configuration.upperLimitMonitoringTime": 1.0,
                    "configuration.lowerLimitMonitoringTime": 1.0,
                    "configuration.setpointChangeMonitoringTime": 2.0,
                },
            ),
            (2.0, {"value": 57.0}),  # above 55 for 0.5 s: hidden, inLimits stays TRUE
            (2.5, {"value": 50.0}),
            (4.0, {"value": 58.0}),  # above for 2 s: overHighLimit from 5.1 s
            (6.0, {"value": 50.0}),
            (7.0, {"value": 40.0}),  # below 45: belowLowLimit from 8.1 s
            (8.5, {"value": 50.0}),
            (9.0, {"setpoint": 80.0}),  # band 72 ... 88: setpointChange until the value arrives
            (10.0, {"value": 75.0}),
            (11.0, {"value": 90.0}),  # above 88: overHighLimit from 12.1 s
            (12.5, {"reset": True}),  # its edge clears: 90 is outside, so nothing is timed
            (12.8, {"reset": False}),
            (13.0, {"value": 75.0}),  # arrived again: inLimits
            (13.5, {"configuration.disableLimits": True}),  # no timers, no violation flags
            (14.0, {"value": 90.0}),  # inLimits FALSE at once, overHighLimit stays FALSE
            (14.5, {"value": 75.0}),
            (15.0, {"configuration.disableLimits": False}),
            (15.5, {"configuration.limitsAsAbsoluteValues": True}),  # 80 > 10: 16#8402
            (16.5, {"lowerMinimum": 70.0, "upperMaximum": 100.0}),  # absolute limits 70 ... 100
        ],
        expected_warning="the scenario sets absolute limits 10 ... 10 at t = 15.5 s, below the "
        "setpoint 80, to show status 16#8402",
    ),
]
