"""LGF_FloatingAverage's own fuzz seeds (docs/behaviour.md §15), beside those every block gets from
its interface (tests/fuzz/make_seeds.py): a window that fills and slides, 1e8 and Inf and the NaN
it leaves, a wrong window size (16#8200), trigger edges, a reset, a window of 100 filled."""

SCENARIOS = {
    "window": "cycleTime=0.01 cyclicExecution=1 value=0.1 windowSize=5; 8; value=1e8; 2;"
    " windowSize=2 value=1; 4; value=inf; 1; value=-2.5; 3; windowSize=0; 2; windowSize=100"
    " cyclicExecution=0 trigger=1; 1; trigger=0; 1; trigger=1 reset=1; 2; reset=0"
    " cyclicExecution=1; 120; windowSize=101; 2",
}
