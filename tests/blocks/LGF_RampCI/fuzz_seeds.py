"""LGF_RampCI's own fuzz seeds (docs/behaviour.md §4), beside those every block gets from its
interface (tests/fuzz/make_seeds.py): the worked example's four-point table run through, and
hold, continue, cyclic operation, update of the time and reset."""

TABLE = " ".join(
    f"setpoints[{i}].outputValue={value} setpoints[{i}].time={time}"
    for i, (value, time) in enumerate([(0, 0.3), (30, 0.2), (30, 0.25), (0, 0)])
)

SCENARIOS = {
    "worked_example": f"numberOfSetpoints=4 {TABLE}; 1; start=1; 12;"
    " get outputValue remainTime totalTime remainTotalTime stepNumber",
    "hold_continue_cyclic": "; start=1 cyclicOP=1; 20; hold=1 continue=1 contStepNbr=2"
    " contStepTime=1; 3; hold=0 updateTime=1 reset=1; 3; enDefaultOutValue=1"
    " defaultOutValue=7; 5x4; contStepNbr=70; 3",
}
