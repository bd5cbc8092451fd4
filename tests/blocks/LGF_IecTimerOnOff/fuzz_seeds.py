"""LGF_IecTimerOnOff's own fuzz seeds (docs/behaviour.md §8), beside those every block gets from
its interface (tests/fuzz/make_seeds.py): the on and off delays running out and cut short, then
a zero, a negative and the largest delay at a cycle of 1.5 ms."""

SCENARIOS = {
    "delays": "in=1 timeOnDelay=0.3 timeOffDelay=0.2; 5; get out; in=0; 3; in=1; 1;"
    " in=0 timeOffDelay=0.05; 5x2",
    "zero_negative_largest": "cycleTime=0.0015 timeOnDelay=-1 timeOffDelay=0; 3; in=1; 3;"
    " timeOnDelay=2147483.647 timeOffDelay=0.0025 in=0; 2; in=1; 4x4",
}
