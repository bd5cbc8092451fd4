"""The one way to write a table of LGF_NonLinearInterpolation as FMI parameters
(docs/behaviour.md §20.1), for the tests, the Hypothesis spec, the demo scenarios and the cross
script: a point is (inputValue, outputValue), written as tools/scenario.py writes the setpoints of
both table blocks."""

from functools import partial

from tools.scenario import setpoint_table
from tools.scenario import setpoints as _setpoints

FIELDS = ("inputValue", "outputValue")

setpoints = partial(_setpoints, FIELDS)  # setpoints(points): the points only
table = partial(setpoint_table, FIELDS)  # table(*points): numberOfSetpoints, then the points


# The FMU's start table (docs/behaviour.md §20.1).
DEFAULT_TABLE = ((0.0, 0.0), (20.0, 5.0), (50.0, 30.0), (80.0, 90.0), (100.0, 100.0))
