/* LGF_RampCI: its interface table (modelDescription/LGF_RampCI.xml is generated from it),
 * statics and the block's own checks. */
#include <math.h>

#include "blocks/LGF_RampCI/block.c"
#include "core/model.h"

typedef lgf_ramp_ci block;

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
    ROW(12, contStepTime, VAR_TIME, ROLE_INPUT, 0, TIME_MAX_S,
        "With hold and continue: time to reach point contStepNbr"),
    BOOL_INPUT(13, enDefaultOutValue,
               "TRUE: outputValue = defaultOutValue while the time table runs on "
               "underneath (original V3.0.1 name: enDefaulftOutValue)",
               .original = "enDefaulftOutValue"),
    BOOL_INPUT(14, start,
               "Rising edge: start the time table at point 0; the table runs while start "
               "is TRUE; LGF default FALSE, FMU start TRUE (the first call is a rising edge)"),
    BOOL_INPUT(15, hold, "Freeze outputValue and the times; the run is extended by the hold time"),
    NAMED_ROW(16, "continue", continue_, VAR_BOOL, ROLE_INPUT, 0, 1,
              "With hold: continue towards point contStepNbr, reached in contStepTime "
              "(no effect without hold)"),
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
    TIME_OUTPUT(23, remainTime, "Remaining time to reach point stepNumber"),
    TIME_OUTPUT(24, totalTime, "Sum of the times of all points of the table"),
    TIME_OUTPUT(25, remainTotalTime,
                "Remaining time until the end of the table (may briefly go negative when "
                "segments are shorter than cycleTime)"),
    ERROR_ROW(26, "Always FALSE: the FMU refuses invalid tables and inputs when they are "
                  "set"),
    STATUS_ROW(27, "WORD: 28672 = 16#7000 running or idle, 28673 = 16#7001 start, 28674 = "
                   "16#7002 cyclic restart, 0 = end of curve or reset"),
    SUBFUNCTION_STATUS_ROW(28),
    /* the table: setpoints[i].outputValue at 100 + i, setpoints[i].time at 200 + i */
    SETPOINTS_ROW(100, outputValue, VAR_LREAL, LGF_RAMP_CI_MAX_SETPOINTS, -INFINITY, INFINITY,
                  "Value of point {i}", .original = "outVal in older LGF versions"),
    SETPOINTS_ROW(
        200, time, VAR_TIME, LGF_RAMP_CI_MAX_SETPOINTS, 0, TIME_MAX_S,
        "time from point {i} to point {i+1}; the last point's time only adds to totalTime"),
};

BLOCK_FUNCTIONS(lgf_ramp_ci)

BLOCK_CHECK(lgf_ramp_ci)

/* 16#7000/7001/7002 and 0 are normal operation, not errors: nothing to log. */
BLOCK_STATUS()

static const model_static statics[] = {
    STATIC(block, statStartOld, FIELD_BOOL),      STATIC(block, statResetOld, FIELD_BOOL),
    STATIC(block, statUpdateTimeOld, FIELD_BOOL), STATIC(block, statInitRun, FIELD_BOOL),
    STATIC(block, statBlocked, FIELD_BOOL),       STATIC(block, statPrevOutValue, FIELD_RESULT),
    STATIC(block, statTargetValue, FIELD_REAL),
};

BLOCK_MODEL(
    "LGF_RampCI", "{60d137d7-fd68-479a-a91f-e6926f22d61c}", 25,
    "Siemens LGF_RampCI (LGF V5.1, block V3.0.1): runs outputValue along a time table "
    "of setpoints (value, time to the next point), with hold, continue, cyclic "
    "operation and reset. One PLC call every cycleTime. Default table: 0 to 100 in 5 "
    "s, 100 for 10 s, back to 0 in 5 s; start is TRUE from the first call, so it runs at once.",
    BLOCK_STATICS, CI_CYCLE(1000, "status 16#8400 or 16#8200"), .check = check,
    BLOCK_STATUS_FIELDS);
