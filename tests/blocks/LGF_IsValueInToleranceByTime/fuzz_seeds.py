"""LGF_IsValueInToleranceByTime's own fuzz seeds (docs/behaviour.md §13), beside those every block
gets from its interface (tests/fuzz/make_seeds.py): the value above, below and back in its
tolerance past the monitoring times, a setpoint change, reset and disabled limits; then the
status codes: limits out of order, infinite limits, absolute values."""

C = "configuration."

SCENARIOS = {
    "timing": f"value=50 {C}upperLimitMonitoringTime=0.3 {C}lowerLimitMonitoringTime=0.2"
    f" {C}setpointChangeMonitoringTime=0.5; 3; value=58; 6; value=40; 5; setpoint=80 value=50;"
    f" 8; get overHighLimit belowLowLimit inLimits setpointChange; reset=1; 1; reset=0"
    f" {C}disableLimits=1; 2; {C}disableLimits=0; 10x2",
    "status_codes": f"cycleTime=0.01; {C}limitsAsAbsoluteValues=1; 2; get status;"
    " lowerMinimum=60 upperMaximum=40; 2; lowerMinimum=70 upperMaximum=90; 2;"
    f" {C}limitsAsAbsoluteValues=0 {C}toleranceAsAbsoluteValues=1 setpoint=inf"
    f" upperMaximum=-inf; 2; {C}toleranceAsAbsoluteValues=0 setpoint=-100; 3",
}

# Model Exchange: the value in and out of its tolerance, reset, a setpoint change.
EVENTS = (
    f"{C}setpointChangeMonitoringTime=0.3 {C}upperLimitMonitoringTime=0.2; value=50; value=58;"
    " reset=1; value=40; setpoint=80; reset=0"
)
