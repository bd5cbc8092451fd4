/* LGF_SawTooth: its interface table (modelDescription/LGF_SawTooth.xml is generated from it). */
#include "blocks/LGF_SawTooth/block.c"
#include "core/model.h"

typedef lgf_saw_tooth block;

static const model_variable variables[] = {
    OB_CYCLE_TIME_ROW,
    ROW(1, plcTiming, VAR_BOOL, ROLE_FIXED_PARAMETER, 0, 1,
        "false: documented timing, a tooth lasts timeRange*(numberSteps+1); true: "
        "PLC-exact timing of the original's TON, each step lasts "
        "ceil(timeRange/cycleTime)*cycleTime + 2*cycleTime",
        .original = "none: FMU only"),
    INT_INPUT(2, startValue,
              "INT: start value at which the signal begins (takes effect on the first "
              "call and with reset; LGF default 0)"),
    TIME_INPUT(3, timeRange,
               "TIME: time after which value is incremented, rounded to whole ms (takes "
               "effect with reset; LGF default T#0s, FMU start 0.5 s)"),
    INT_INPUT(4, incrementRange,
              "INT: size of the jump from one increment to the next, may be negative "
              "(takes effect with reset; LGF default 0, FMU start 10)"),
    INT_INPUT(5, numberSteps,
              "INT: number of increments per sawtooth, not used when endlessSteps "
              "(takes effect with reset; LGF default 0, FMU start 5)"),
    BOOL_INPUT(6, endlessSteps,
               "Endless sawtooth: add incrementRange forever, wrapping from 32767 to "
               "-32768 (takes effect with reset)"),
    BOOL_INPUT(7, reset,
               "While TRUE (a level): copy the inputs into the block and restart at "
               "startValue"),
    INT_OUTPUT(8, value, "INT: current value of the sawtooth signal"),
};

BLOCK_FUNCTIONS(lgf_saw_tooth)

BLOCK_CHECK(lgf_saw_tooth)

static const model_static statics[] = {
    STATIC(block, statLatched, FIELD_BOOL),      STATIC(block, statStartValue, FIELD_INT16),
    STATIC(block, statTimeRange, FIELD_INT32),   STATIC(block, statIncrement, FIELD_INT16),
    STATIC(block, statNumberSteps, FIELD_INT16), STATIC(block, statEndless, FIELD_BOOL),
    STATIC(block, statStepCount, FIELD_INT16),   STATIC(block, statNextStepUs, FIELD_INT64),
    STATIC(block, statTimerDone, FIELD_BOOL),    TIMER_STATICS(statTimer),
};

BLOCK_MODEL("LGF_SawTooth", "{3f9d2c71-8e0a-4b6f-a1d4-5c7e9b2f0a63}", 10,
            "Siemens LGF_SawTooth (LGF V5.1, block V3.0.1): a sawtooth of numberSteps steps "
            "of incrementRange every timeRange. One PLC call every cycleTime. Start values "
            "differ from the LGF defaults (all 0) so that the FMU shows a sawtooth at once: "
            "0, 10, ..., 50 every 0.5 s.",
            BLOCK_STATICS, NO_CYCLE_CODES, .check = check);
