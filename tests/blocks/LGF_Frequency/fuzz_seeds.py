"""LGF_Frequency's own fuzz seeds (docs/behaviour.md §10), beside those every block gets from its
interface (tests/fuzz/make_seeds.py): the clock at changing frequencies and pulse/pause ratios,
then their limits (accepted, refused, subnormal float32) at 1.5 ms."""

SCENARIOS = {
    "clock": "frequency=2 pulsePauseRatio=3; 14; get clock countdown; pulsePauseRatio=0.5; 6;"
    " frequency=0; 3; frequency=2; 5x3",
    "limits": "cycleTime=0.0015 frequency=inf pulsePauseRatio=1e9; 4; frequency=1"
    " pulsePauseRatio=1e-9; 2; frequency=1e-9; pulsePauseRatio=inf; pulsePauseRatio=-inf; 2;"
    " pulsePauseRatio=1e-40 frequency=1e-40; frequency=4e-7 pulsePauseRatio=1; 4x4",
}
