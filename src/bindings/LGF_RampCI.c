/* LGF_RampCI as an FMU: its variable table (modelDescription/LGF_RampCI.xml), start values and
 * the block's own checks. */
#include <math.h>

#include "blocks/lgf_ramp_ci.c"
#include "fmi2/model.h"

typedef lgf_ramp_ci block;

#define TIME_MIN (-2147483.648) /* the range of an IEC TIME in s (docs/behaviour.md §1.4) */
#define TIME_MAX 2147483.647

static const model_variable variables[] = {
    /* The original counts its cycle in whole ms: below 1 ms it would never advance (4.5). */
    SCALAR(0, "cycleTime", VAR_CYCLE, ROLE_FIXED_PARAMETER, block, outputValue, 0.001, 60.0),
    SCALAR(1, "numberOfSetpoints", VAR_INT, ROLE_FIXED_PARAMETER, block, numberOfSetpoints, 2,
           LGF_RAMP_CI_MAX_SETPOINTS),
    /* inputs, docs/behaviour.md §4.1; contStepNbr is further limited by lgf_ramp_ci_check */
    SCALAR(10, "defaultOutValue", VAR_LREAL, ROLE_INPUT, block, defaultOutValue, -INFINITY,
           INFINITY),
    SCALAR(11, "contStepNbr", VAR_INT, ROLE_INPUT, block, contStepNbr, -32768, 32767),
    SCALAR(12, "contStepTime", VAR_TIME, ROLE_INPUT, block, contStepTime, 0, TIME_MAX),
    SCALAR(13, "enDefaultOutValue", VAR_BOOL, ROLE_INPUT, block, enDefaultOutValue, 0, 1),
    SCALAR(14, "start", VAR_BOOL, ROLE_INPUT, block, start, 0, 1),
    SCALAR(15, "hold", VAR_BOOL, ROLE_INPUT, block, hold, 0, 1),
    SCALAR(16, "continue", VAR_BOOL, ROLE_INPUT, block, continue_, 0, 1),
    SCALAR(17, "cyclicOP", VAR_BOOL, ROLE_INPUT, block, cyclicOP, 0, 1),
    SCALAR(18, "updateTime", VAR_BOOL, ROLE_INPUT, block, updateTime, 0, 1),
    SCALAR(19, "reset", VAR_BOOL, ROLE_INPUT, block, reset, 0, 1),
    /* outputs */
    SCALAR(20, "outputValue", VAR_LREAL, ROLE_OUTPUT, block, outputValue, -INFINITY, INFINITY),
    SCALAR(21, "actTimeTable", VAR_BOOL, ROLE_OUTPUT, block, actTimeTable, 0, 1),
    SCALAR(22, "stepNumber", VAR_INT, ROLE_OUTPUT, block, stepNumber, -32768, 32767),
    SCALAR(23, "remainTime", VAR_TIME, ROLE_OUTPUT, block, remainTime, TIME_MIN, TIME_MAX),
    SCALAR(24, "totalTime", VAR_TIME, ROLE_OUTPUT, block, totalTime, TIME_MIN, TIME_MAX),
    SCALAR(25, "remainTotalTime", VAR_TIME, ROLE_OUTPUT, block, remainTotalTime, TIME_MIN,
           TIME_MAX),
    SCALAR(26, "error", VAR_BOOL, ROLE_OUTPUT, block, error, 0, 1),
    SCALAR(27, "status", VAR_WORD, ROLE_OUTPUT, block, status, 0, 65535),
    SCALAR(28, "subFunctionStatus", VAR_WORD, ROLE_OUTPUT, block, subFunctionStatus, 0, 65535),
    /* the table: setpoints[i].outputValue at 100 + i, setpoints[i].time at 200 + i */
    {100, "setpoints", ".outputValue", VAR_LREAL, ROLE_TUNABLE_PARAMETER,
     offsetof(block, setpoints[0].outputValue), LGF_RAMP_CI_MAX_SETPOINTS,
     sizeof(lgf_ramp_ci_setpoint), -INFINITY, INFINITY},
    {200, "setpoints", ".time", VAR_TIME, ROLE_TUNABLE_PARAMETER,
     offsetof(block, setpoints[0].time), LGF_RAMP_CI_MAX_SETPOINTS,
     sizeof(lgf_ramp_ci_setpoint), 0, TIME_MAX},
};

static void init(void *data) { lgf_ramp_ci_init(data); }

static void call(void *data, const plc_call *plc) { lgf_ramp_ci_call(data, plc); }

static const char *check(const void *data, char *msg, size_t size)
{
    return lgf_ramp_ci_check(data, msg, size);
}

static iec_word status(const void *data) { return ((const block *)data)->status; }

/* 16#7000/7001/7002 and 0 are normal operation, not errors: nothing to log. */
static const char *status_text(iec_word code)
{
    (void)code;
    return NULL;
}

static const model_static statics[] = {
    STATIC(block, statStartOld, FIELD_BOOL),
    STATIC(block, statResetOld, FIELD_BOOL),
    STATIC(block, statUpdateTimeOld, FIELD_BOOL),
    STATIC(block, statInitRun, FIELD_BOOL),
    STATIC(block, statBlocked, FIELD_BOOL),
    STATIC(block, statPrevOutValue, FIELD_RESULT),
    STATIC(block, statTargetValue, FIELD_REAL),
};

static const model lgf_model = {
    .identifier = "LGF_RampCI",
    .guid = "{60d137d7-fd68-479a-a91f-e6926f22d61c}",
    .variables = variables,
    .variable_count = sizeof variables / sizeof variables[0],
    .statics = statics,
    .static_count = sizeof statics / sizeof statics[0],
    .data_size = sizeof(block),
    .cycle_granularity_us = 1000,
    .cycle_codes = "status 16#8400 or 16#8200",
    .init = init,
    .call = call,
    .check = check,
    .status = status,
    .status_text = status_text,
};

#include "fmi2/fmu.c" /* the FMI layer, in this translation unit */
