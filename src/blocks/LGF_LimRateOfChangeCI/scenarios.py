"""The demo scenarios of LGF_LimRateOfChangeCI, as tools/blocks.py describes them."""

from tools.scenario import Scenario

SCENARIOS = [
    Scenario(
        name="lim_rate_of_change",
        title="LGF_LimRateOfChangeCI: ramps, a negative rate (16#8200) and a pre-assigned output",
        stop_time=12.0,
        inputs=[
            (
                0.0,
                {
                    "value": 0.0,
                    "setChangeRate": 20.0,
                    "defaultOutValue": 30.0,
                    "enDefaultOutValue": False,
                },
            ),
            (0.5, {"value": 50.0}),
            (4.0, {"value": -20.0}),
            (5.0, {"setChangeRate": -5.0}),
            (6.0, {"setChangeRate": 10.0}),
            (8.0, {"enDefaultOutValue": True}),
            (9.0, {"enDefaultOutValue": False, "value": 0.0}),
        ],
        expected_warning="the scenario sets setChangeRate = -5.0 at t = 5 s to show status 16#8200",
    ),
]
