"""LGF_SimpleSmoothingFB's own fuzz seeds (docs/behaviour.md §16), beside those every block gets
from its interface (tests/fuzz/make_seeds.py): values read in at rising edges of insert, enough
and not enough of them, ±Inf, enable off and on with insert rising with it."""

SAMPLE = "value={} insert=1; 1; insert=0; 1"

SCENARIOS = {
    "smoothing": "cycleTime=0.01 enable=1 value=0.5; "
    + "; ".join(SAMPLE.format(x) for x in (1, 2, 4, 8, 16, 32, "inf", -3, 0.1, 0.2, 0.3))
    + "; enable=0; 2; enable=1 insert=1; 1; insert=0; 3; "
    + "; ".join(SAMPLE.format(x) for x in (7, 9, -1)),
}
