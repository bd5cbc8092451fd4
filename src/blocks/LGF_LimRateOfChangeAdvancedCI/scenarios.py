"""The demo scenarios of LGF_LimRateOfChangeAdvancedCI, as tools/blocks.py describes them."""

from tools.scenario import Scenario

SCENARIOS = [
    Scenario(
        name="lim_rate_advanced",
        title="LGF_LimRateOfChangeAdvancedCI: four ramps across zero, limits, manual mode, "
        "tracking, pre-assignment, reset and both errors",
        stop_time=21.0,
        inputs=[
            (
                0.0,
                {
                    "autoValue": 30.0,
                    "manualValue": 70.0,
                    "setPosUpRateLim": 20.0,
                    "setPosDownRateLim": 40.0,
                    "setNegUpRateLim": 20.0,
                    "setNegDownRateLim": 30.0,
                    "setHighLim": 50.0,
                    "setLowLim": -50.0,
                    "defaultOutValue": -10.0,
                    "enDefaultOutValue": False,
                    "track": False,
                    "manOp": False,
                    "reset": False,
                },
            ),
            (2.0, {"autoValue": -60.0}),  # down across zero to the low limit
            (6.0, {"autoValue": 20.0}),  # up across zero
            (9.0, {"manOp": True}),  # 70, beyond the high limit
            (10.0, {"manOp": False}),  # ramps back, the limits suspended until within
            (13.0, {"track": True, "autoValue": 45.0}),
            (13.5, {"autoValue": 55.0}),  # tracked, cut at the high limit
            (14.0, {"track": False, "enDefaultOutValue": True}),
            (15.0, {"enDefaultOutValue": False}),  # ramps from -10 across zero
            (17.0, {"reset": True}),
            (17.5, {"reset": False}),
            (18.0, {"setLowLim": 60.0}),  # 16#8200
            (18.5, {"setLowLim": -50.0, "setNegUpRateLim": -1.0}),  # 16#8202
            (19.0, {"setNegUpRateLim": 20.0, "autoValue": -20.0}),
        ],
        expected_warning="the scenario sets setLowLim above setHighLim at t = 18 s and a "
        "negative rate at t = 18.5 s to show status 16#8200 and 16#8202",
    ),
    Scenario(
        name="four_ramps",
        title="LGF_LimRateOfChangeAdvancedCI: a square wave of +-100 through its four ramps",
        stop_time=24.0,
        parameters={"cycleTime": 0.05},
        output_interval=0.05,  # every call (Model Exchange reports each time event)
        inputs=[
            (
                0.0,
                {
                    "autoValue": 100.0,
                    "setPosUpRateLim": 25.0,
                    "setPosDownRateLim": 100.0,
                    "setNegUpRateLim": 50.0,
                    "setNegDownRateLim": 12.5,
                    "setHighLim": 1000.0,
                    "setLowLim": -1000.0,
                },
            ),
            (6.0, {"autoValue": -100.0}),
            (12.0, {"autoValue": 100.0}),
            (18.0, {"autoValue": -100.0}),
        ],
    ),
]
