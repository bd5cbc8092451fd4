"""The one way to write a table of LGF_NonLinearInterpolation as FMI parameters
(docs/behaviour.md §20.1), for the tests, the Hypothesis spec, the demo scenarios and the cross
script."""


def setpoints(points) -> dict:
    """{"setpoints[i].inputValue": x, "setpoints[i].outputValue": y} of (x, y) points, point by
    point (the values may also be Hypothesis strategies)."""
    entries = {}
    for i, (x, y) in enumerate(points):
        entries[f"setpoints[{i}].inputValue"] = x
        entries[f"setpoints[{i}].outputValue"] = y
    return entries


def table(*points) -> dict:
    """The parameters of a table of (x, y) points: numberOfSetpoints, then the points."""
    return {"numberOfSetpoints": len(points), **setpoints(points)}


# The FMU's start table (docs/behaviour.md §20.1).
DEFAULT_TABLE = ((0.0, 0.0), (20.0, 5.0), (50.0, 30.0), (80.0, 90.0), (100.0, 100.0))
