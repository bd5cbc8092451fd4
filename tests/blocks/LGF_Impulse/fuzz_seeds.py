"""LGF_Impulse's own fuzz seeds (docs/behaviour.md §9), beside those every block gets from its
interface (tests/fuzz/make_seeds.py): pulses at changing frequencies, then the limits of the
frequency (the smallest accepted, just below it, a subnormal float32, beyond 1 kHz) at 1.5 ms."""

SCENARIOS = {
    "pulses": "frequency=3; 14; get impulse countdown; frequency=20; 6; frequency=0; 3;"
    " frequency=0.8; 5x3",
    "limits": "cycleTime=0.0015 frequency=inf; 4; frequency=4.656613157294487e-07; 2;"
    " frequency=4.6e-7; frequency=1e-40; frequency=-inf; 2; frequency=1001; 4x4",
}
