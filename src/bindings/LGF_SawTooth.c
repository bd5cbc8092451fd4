/* LGF_SawTooth as an FMU: its variable table (modelDescription/LGF_SawTooth.xml). */
#include "blocks/lgf_saw_tooth.c"
#include "fmi2/model.h"

typedef lgf_saw_tooth block;

static const model_variable variables[] = {
    SCALAR(0, "cycleTime", VAR_CYCLE, ROLE_FIXED_PARAMETER, block, value, 1e-6, 60.0),
    SCALAR(1, "plcTiming", VAR_BOOL, ROLE_FIXED_PARAMETER, block, plcTiming, 0, 1),
    SCALAR(2, "startValue", VAR_INT, ROLE_INPUT, block, startValue, -32768, 32767),
    SCALAR(3, "timeRange", VAR_TIME, ROLE_INPUT, block, timeRange, -2147483.647, 2147483.647),
    SCALAR(4, "incrementRange", VAR_INT, ROLE_INPUT, block, incrementRange, -32768, 32767),
    SCALAR(5, "numberSteps", VAR_INT, ROLE_INPUT, block, numberSteps, -32768, 32767),
    SCALAR(6, "endlessSteps", VAR_BOOL, ROLE_INPUT, block, endlessSteps, 0, 1),
    SCALAR(7, "reset", VAR_BOOL, ROLE_INPUT, block, reset, 0, 1),
    SCALAR(8, "value", VAR_INT, ROLE_OUTPUT, block, value, -32768, 32767),
};

static void init(void *data) { lgf_saw_tooth_init(data); }

static void call(void *data, const plc_call *plc) { lgf_saw_tooth_call(data, plc); }

static const char *check(const void *data, char *msg, size_t size)
{
    return lgf_saw_tooth_check(data, msg, size);
}

static const model_static statics[] = {
    STATIC(block, statLatched, FIELD_BOOL),
    STATIC(block, statStartValue, FIELD_INT16),
    STATIC(block, statTimeRange, FIELD_INT32),
    STATIC(block, statIncrement, FIELD_INT16),
    STATIC(block, statNumberSteps, FIELD_INT16),
    STATIC(block, statEndless, FIELD_BOOL),
    STATIC(block, statStepCount, FIELD_INT16),
    STATIC(block, statNextStepUs, FIELD_INT64),
    STATIC(block, statTimerDone, FIELD_BOOL),
    STATIC(block, statTimer.in, FIELD_BOOL),
    STATIC(block, statTimer.start_us, FIELD_INT64),
};

static const model lgf_model = {
    .identifier = "LGF_SawTooth",
    .guid = "{3f9d2c71-8e0a-4b6f-a1d4-5c7e9b2f0a63}",
    .variables = variables,
    .variable_count = sizeof variables / sizeof variables[0],
    .statics = statics,
    .static_count = sizeof statics / sizeof statics[0],
    .data_size = sizeof(block),
    .cycle_granularity_us = 1,
    .cycle_codes = NULL /* not a CI block: it has no cycle status codes */,
    .init = init,
    .call = call,
    .check = check,
    .status = NULL, /* LGF_SawTooth has no status output */
    .status_text = NULL,
};

#include "fmi2/fmu.c" /* the FMI layer, in this translation unit */
