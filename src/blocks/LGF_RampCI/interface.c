/* LGF_RampCI: its interface table (modelDescription/LGF_RampCI.xml is generated from it),
 * statics and the block's own checks. */
#include <math.h>

#include "blocks/LGF_RampCI/block.c"
#include "core/model.h"

typedef lgf_ramp_ci block;

#define TIME_MIN (-2147483.648) /* the range of an IEC TIME in s (docs/behaviour.md §1.4) */
#define TIME_MAX 2147483.647

static const model_variable variables[] = {
    CYCLE_TIME_ROW(0.001, "none: replaces callOB",
                   "Period of the calling cyclic-interrupt OB (replaces callOB); the block "
                   "counts whole ms, so 1 ms to 60 s, and a period that is not a whole "
                   "number of ms runs truncated (with a warning)"),
    SETPOINT_COUNT_ROW(1, LGF_RAMP_CI_MAX_SETPOINTS,
                       "Number of points of setpoints that form the time table (2 to 64); "
                       "entries from numberOfSetpoints on are ignored"),
    /* inputs (docs/behaviour.md §4.1); contStepNbr is further limited by lgf_ramp_ci_check */
    LREAL_INPUT(10, defaultOutValue, "Value for pre-assignment of the output variable"),
    INT_INPUT(11, contStepNbr,
              "With hold and continue: number of the point to continue towards (0 to "
              "numberOfSetpoints - 1)"),
    {.vr = 12,
     .name = "contStepTime",
     .type = VAR_TIME,
     .role = ROLE_INPUT,
     AT(block, contStepTime),
     .min = 0,
     .max = TIME_MAX,
     .description = "With hold and continue: time to reach point contStepNbr"},
    {.vr = 13,
     .name = "enDefaultOutValue",
     .type = VAR_BOOL,
     .role = ROLE_INPUT,
     AT(block, enDefaultOutValue),
     .min = 0,
     .max = 1,
     .original = "enDefaulftOutValue",
     .description = "TRUE: outputValue = defaultOutValue while the time table runs on "
                    "underneath (original V3.0.1 name: enDefaulftOutValue)"},
    BOOL_INPUT(14, start,
               "Rising edge: start the time table at point 0; the table runs while start "
               "is TRUE; LGF default FALSE, FMU start TRUE (the first call is a rising edge)"),
    BOOL_INPUT(15, hold, "Freeze outputValue and the times; the run is extended by the hold time"),
    {.vr = 16,
     .name = "continue",
     .type = VAR_BOOL,
     .role = ROLE_INPUT,
     AT(block, continue_),
     .min = 0,
     .max = 1,
     .description = "With hold: continue towards point contStepNbr, reached in contStepTime "
                    "(no effect without hold)"},
    BOOL_INPUT(17, cyclicOP, "Cyclic operation: after the last point start again at point 0"),
    BOOL_INPUT(18, updateTime,
               "Rising edge: recompute totalTime and remainTotalTime from the (changed) "
               "table"),
    BOOL_INPUT(19, reset,
               "Rising edge: outputValue 0.0 and stop; a new run needs a new rising edge "
               "of start"),
    LREAL_OUTPUT(20, outputValue, "Output value of the time table"),
    BOOL_OUTPUT(21, actTimeTable, "TRUE: the time table is being processed"),
    INT_OUTPUT(22, stepNumber, "INT: number of the point outputValue is moving towards"),
    {.vr = 23,
     .name = "remainTime",
     .type = VAR_TIME,
     .role = ROLE_OUTPUT,
     AT(block, remainTime),
     .min = TIME_MIN,
     .max = TIME_MAX,
     .description = "Remaining time to reach point stepNumber"},
    {.vr = 24,
     .name = "totalTime",
     .type = VAR_TIME,
     .role = ROLE_OUTPUT,
     AT(block, totalTime),
     .min = TIME_MIN,
     .max = TIME_MAX,
     .description = "Sum of the times of all points of the table"},
    {.vr = 25,
     .name = "remainTotalTime",
     .type = VAR_TIME,
     .role = ROLE_OUTPUT,
     AT(block, remainTotalTime),
     .min = TIME_MIN,
     .max = TIME_MAX,
     .description = "Remaining time until the end of the table (may briefly go negative when "
                    "segments are shorter than cycleTime)"},
    ERROR_ROW(26, "Always FALSE: the FMU refuses invalid tables and inputs when they are "
                  "set"),
    STATUS_ROW(27, "WORD: 28672 = 16#7000 running or idle, 28673 = 16#7001 start, 28674 = "
                   "16#7002 cyclic restart, 0 = end of curve or reset"),
    SUBFUNCTION_STATUS_ROW(28),
    /* the table: setpoints[i].outputValue at 100 + i, setpoints[i].time at 200 + i */
    {.vr = 100,
     .name = "setpoints",
     .member = ".outputValue",
     .type = VAR_LREAL,
     .role = ROLE_TUNABLE_PARAMETER,
     .offset = offsetof(block, setpoints[0].outputValue),
     .count = LGF_RAMP_CI_MAX_SETPOINTS,
     .stride = sizeof(lgf_ramp_ci_setpoint),
     .min = -INFINITY,
     .max = INFINITY,
     .original = "outVal in the seed and older LGF versions",
     .description = "Value of point {i}"},
    {.vr = 200,
     .name = "setpoints",
     .member = ".time",
     .type = VAR_TIME,
     .role = ROLE_TUNABLE_PARAMETER,
     .offset = offsetof(block, setpoints[0].time),
     .count = LGF_RAMP_CI_MAX_SETPOINTS,
     .stride = sizeof(lgf_ramp_ci_setpoint),
     .min = 0,
     .max = TIME_MAX,
     .description = "time from point {i} to point {i+1}; the last point's time only adds to "
                    "totalTime"},
};

BLOCK_FUNCTIONS(lgf_ramp_ci)

BLOCK_CHECK(lgf_ramp_ci)

BLOCK_STATUS

/* 16#7000/7001/7002 and 0 are normal operation, not errors: nothing to log. */
static const char *status_text(iec_word code)
{
    (void)code;
    return NULL;
}

static const model_static statics[] = {
    STATIC(block, statStartOld, FIELD_BOOL),      STATIC(block, statResetOld, FIELD_BOOL),
    STATIC(block, statUpdateTimeOld, FIELD_BOOL), STATIC(block, statInitRun, FIELD_BOOL),
    STATIC(block, statBlocked, FIELD_BOOL),       STATIC(block, statPrevOutValue, FIELD_RESULT),
    STATIC(block, statTargetValue, FIELD_REAL),
};

static const model lgf_model = {
    .identifier = "LGF_RampCI",
    .guid = "{60d137d7-fd68-479a-a91f-e6926f22d61c}",
    .description =
        "Siemens LGF_RampCI (LGF V5.1, block V3.0.1): runs outputValue along a time table "
        "of setpoints (value, time to the next point), with hold, continue, cyclic "
        "operation and reset. One PLC call every cycleTime. Default table: 0 to 100 in 5 "
        "s, 100 for 10 s, back to 0 in 5 s; start is TRUE from the first call, so it runs at once.",
    .stop_time = 25,
    BLOCK_TABLES,
    .cycle_granularity_us = 1000,
    .cycle_codes = "status 16#8400 or 16#8200",
    .check = check,
    BLOCK_STATUS_FIELDS,
};
