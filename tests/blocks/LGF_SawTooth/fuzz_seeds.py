"""LGF_SawTooth's own fuzz seeds (docs/behaviour.md §2), beside those every block gets from its
interface (tests/fuzz/make_seeds.py): the documented staircase with its reset, and plcTiming with
endless steps at 1 ms."""

SCENARIOS = {
    "documented": "startValue=5 incrementRange=3 numberSteps=4 timeRange=0.3; 30; get value;"
    " reset=1; 2; reset=0; 10x3",
    "plc_timing_endless": "cycleTime=0.001 plcTiming=1 endlessSteps=1 incrementRange=30000"
    " timeRange=0; 40",
}
