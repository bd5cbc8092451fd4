/* LGF_SawTooth: its interface table (modelDescription/LGF_SawTooth.xml is generated from it). */
#include "blocks/LGF_SawTooth/block.c"
#include "core/model.h"

typedef lgf_saw_tooth block;

static const model_variable variables[] = {
    CYCLE_TIME_ROW(1e-6, "none: the period of the calling OB",
                   "Period of the calling OB: the block is called once per cycleTime; held "
                   "in whole µs, 1 µs to 60 s"),
    {.vr = 1,
     .name = "plcTiming",
     .type = VAR_BOOL,
     .role = ROLE_FIXED_PARAMETER,
     AT(block, plcTiming),
     .min = 0,
     .max = 1,
     .original = "none: FMU only",
     .description = "false: documented timing, a tooth lasts timeRange*(numberSteps+1); true: "
                    "PLC-exact timing of the original's TON, each step lasts "
                    "ceil(timeRange/cycleTime)*cycleTime + 2*cycleTime"},
    {.vr = 2,
     .name = "startValue",
     .type = VAR_INT,
     .role = ROLE_INPUT,
     AT(block, startValue),
     .min = -32768,
     .max = 32767,
     .description = "INT: start value at which the signal begins (takes effect on the first "
                    "call and with reset; LGF default 0)"},
    {.vr = 3,
     .name = "timeRange",
     .type = VAR_TIME,
     .role = ROLE_INPUT,
     AT(block, timeRange),
     .min = -2147483.647,
     .max = 2147483.647,
     .description = "TIME: time after which value is incremented, rounded to whole ms (takes "
                    "effect with reset; LGF default T#0s, FMU start 0.5 s)"},
    {.vr = 4,
     .name = "incrementRange",
     .type = VAR_INT,
     .role = ROLE_INPUT,
     AT(block, incrementRange),
     .min = -32768,
     .max = 32767,
     .description = "INT: size of the jump from one increment to the next, may be negative "
                    "(takes effect with reset; LGF default 0, FMU start 10)"},
    {.vr = 5,
     .name = "numberSteps",
     .type = VAR_INT,
     .role = ROLE_INPUT,
     AT(block, numberSteps),
     .min = -32768,
     .max = 32767,
     .description = "INT: number of increments per sawtooth, not used when endlessSteps "
                    "(takes effect with reset; LGF default 0, FMU start 5)"},
    {.vr = 6,
     .name = "endlessSteps",
     .type = VAR_BOOL,
     .role = ROLE_INPUT,
     AT(block, endlessSteps),
     .min = 0,
     .max = 1,
     .description = "Endless sawtooth: add incrementRange forever, wrapping from 32767 to "
                    "-32768 (takes effect with reset)"},
    {.vr = 7,
     .name = "reset",
     .type = VAR_BOOL,
     .role = ROLE_INPUT,
     AT(block, reset),
     .min = 0,
     .max = 1,
     .description = "While TRUE (a level): copy the inputs into the block and restart at "
                    "startValue"},
    {.vr = 8,
     .name = "value",
     .type = VAR_INT,
     .role = ROLE_OUTPUT,
     AT(block, value),
     .min = -32768,
     .max = 32767,
     .description = "INT: current value of the sawtooth signal"},
};

BLOCK_FUNCTIONS(lgf_saw_tooth)

BLOCK_CHECK(lgf_saw_tooth)

static const model_static statics[] = {
    STATIC(block, statLatched, FIELD_BOOL),         STATIC(block, statStartValue, FIELD_INT16),
    STATIC(block, statTimeRange, FIELD_INT32),      STATIC(block, statIncrement, FIELD_INT16),
    STATIC(block, statNumberSteps, FIELD_INT16),    STATIC(block, statEndless, FIELD_BOOL),
    STATIC(block, statStepCount, FIELD_INT16),      STATIC(block, statNextStepUs, FIELD_INT64),
    STATIC(block, statTimerDone, FIELD_BOOL),       STATIC(block, statTimer.in, FIELD_BOOL),
    STATIC(block, statTimer.running, FIELD_BOOL),   STATIC(block, statTimer.pt, FIELD_INT32),
    STATIC(block, statTimer.start_us, FIELD_INT64),
};

static const model lgf_model = {
    .identifier = "LGF_SawTooth",
    .guid = "{3f9d2c71-8e0a-4b6f-a1d4-5c7e9b2f0a63}",
    .description = "Siemens LGF_SawTooth (LGF V5.1, block V3.0.1): a sawtooth of numberSteps steps "
                   "of incrementRange every timeRange. One PLC call every cycleTime. Start values "
                   "differ from the LGF defaults (all 0) so that the FMU shows a sawtooth at once: "
                   "0, 10, ..., 50 every 0.5 s.",
    .stop_time = 10,
    BLOCK_TABLES,
    NO_CYCLE_CODES,
    .check = check,
    /* LGF_SawTooth has no status output: status and status_text NULL */
};
