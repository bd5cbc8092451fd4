"""LGF_LimRateOfChangeAdvancedCI's own fuzz seeds (docs/behaviour.md §21), beside those every
block gets from its interface (tests/fuzz/make_seeds.py): both zero crossings under the four
rate limits, the output limits, manual mode, tracking, pre-assignment, reset, and its errors
(limits out of order, a negative rate, infinities)."""

SCENARIOS = {
    "modes": "autoValue=30 manualValue=70 setPosUpRateLim=20 setPosDownRateLim=40"
    " setNegUpRateLim=20 setNegDownRateLim=30 setHighLim=50 setLowLim=-50 defaultOutValue=-10;"
    " 20; autoValue=-60; 40; autoValue=20; 30; manOp=1; 2; manOp=0; 10; track=1 autoValue=55; 2;"
    " track=0 enDefaultOutValue=1; 2; enDefaultOutValue=0 reset=1; 2; reset=0 setLowLim=60; 2;"
    " get status; setLowLim=-50 setNegUpRateLim=-1; 2; setNegUpRateLim=inf setHighLim=inf"
    " autoValue=1e300; 3; setHighLim=-1 setLowLim=1; 2",
}
