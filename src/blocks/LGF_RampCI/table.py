"""The one way to write a setpoint table of LGF_RampCI as FMI parameters (docs/behaviour.md §4.1),
for the tests, the Hypothesis spec, the demo scenarios and the cross script."""


def setpoints(points) -> dict:
    """{"setpoints[i].outputValue": value, "setpoints[i].time": time} of (value, time in s)
    points, point by point (the values may also be Hypothesis strategies)."""
    entries = {}
    for i, (value, time) in enumerate(points):
        entries[f"setpoints[{i}].outputValue"] = value
        entries[f"setpoints[{i}].time"] = time
    return entries


def table(*points) -> dict:
    """The parameters of a table of (value, time in s) points: numberOfSetpoints, then the
    points."""
    return {"numberOfSetpoints": len(points), **setpoints(points)}
