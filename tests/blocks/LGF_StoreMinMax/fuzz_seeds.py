"""LGF_StoreMinMax's own fuzz seeds (docs/behaviour.md §14), beside those every block gets from
its interface (tests/fuzz/make_seeds.py): the extremes kept, then cleared by reset."""

SCENARIOS = {
    "extremes": "value=3; 3; value=-2; 2; get minValue maxValue; reset=1 value=7; 2; reset=0; 5x2",
}
