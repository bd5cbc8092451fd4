"""LGF_LimRateOfChangeCI's own fuzz seeds (docs/behaviour.md §3), beside those every block gets
from its interface (tests/fuzz/make_seeds.py): a ramp limited up, a negative rate, the
pre-assignment on and off."""

SCENARIOS = {
    "ramp": "value=10 setChangeRate=5; 30; get delayedValue; setChangeRate=-1; 2;"
    " enDefaultOutValue=1 defaultOutValue=3; 2; enDefaultOutValue=0; 5x2",
}
