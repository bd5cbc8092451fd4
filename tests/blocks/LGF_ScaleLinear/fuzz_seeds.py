"""LGF_ScaleLinear's own fuzz seeds (docs/behaviour.md §19), beside those every block gets from
its interface (tests/fuzz/make_seeds.py): an analog value scaled, past both limits, yMin above
yMax, x1 = x2."""

SCENARIOS = {
    "scale": "x=-100 x2=27648 y2=100 yMax=100; 5; x=13824; 2; get y; x=30000; 2; yMin=120; 2;"
    " yMin=0 x2=0 y1=25; 5x2",
}
