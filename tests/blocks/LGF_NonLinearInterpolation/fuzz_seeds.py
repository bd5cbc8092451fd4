"""LGF_NonLinearInterpolation's own fuzz seeds (docs/behaviour.md §20), beside those every block
gets from its interface (tests/fuzz/make_seeds.py): a four-point curve, the value across it and
beyond and on its points, tracking, pre-assignment, reset and a point changed to 1e300."""

TABLE = " ".join(
    f"setpoints[{i}].inputValue={x} setpoints[{i}].outputValue={y}"
    for i, (x, y) in enumerate([(-10, 5), (0, 0), (10, 30), (40, -20)])
)
SWEEP = "; ".join(f"value={x}; 1" for x in (-30, -10, 5, 10, 25, 60, 10))

SCENARIOS = {
    "curve": f"numberOfSetpoints=4 {TABLE}; {SWEEP}; track=1; 2; track=0 enDefaultOutValue=1"
    " defaultOutValue=7.5; 2; reset=1; 2; enDefaultOutValue=0 reset=0"
    " setpoints[2].outputValue=1e300 value=inf; 3",
}
