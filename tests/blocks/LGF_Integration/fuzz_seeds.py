"""LGF_Integration's own fuzz seeds (docs/behaviour.md §18), beside those every block gets from
its interface (tests/fuzz/make_seeds.py): trapezoids up and down, hold, reset."""

SCENARIOS = {
    "integrate": "value=2; 10; value=-3; 3; get integral; enable=0; 2; enable=1; 2; reset=1; 2;"
    " reset=0; 5x2",
}
