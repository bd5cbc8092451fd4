"""The one way to write a setpoint table of LGF_RampCI as FMI parameters (docs/behaviour.md §4.1),
for the tests, the Hypothesis spec, the demo scenarios and the cross script: a point is
(outputValue, time in s), written as tools/scenario.py writes the setpoints of both table blocks."""

from functools import partial

from tools.scenario import setpoint_table
from tools.scenario import setpoints as _setpoints

FIELDS = ("outputValue", "time")

setpoints = partial(_setpoints, FIELDS)  # setpoints(points): the points only
table = partial(setpoint_table, FIELDS)  # table(*points): numberOfSetpoints, then the points
