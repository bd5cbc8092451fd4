"""LGF_DifferenceQuotientFB's own fuzz seeds (docs/behaviour.md §17), beside those every block gets
from its interface (tests/fuzz/make_seeds.py): values read in at rising edges of insert, ±Inf,
deltaT 0 and negative (16#8200), enable off and on with insert rising with it."""


def sample(*values):
    return "; ".join(f"value={x} insert=1; 1; insert=0; 1" for x in values)


SCENARIOS = {
    "quotients": f"cycleTime=0.01 enable=1 value=0.5 deltaT=0.1; {sample(1, 2, 4, 8, 'inf', -3)};"
    f" deltaT=0; {sample(5)}; deltaT=-0.5; {sample(6)}; deltaT=0.1; enable=0; 2;"
    f" enable=1 insert=1; 1; insert=0; 3; {sample(7, 9, -1)}",
}
