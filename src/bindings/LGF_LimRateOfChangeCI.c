/* LGF_LimRateOfChangeCI as an FMU: its variable table (modelDescription/
 * LGF_LimRateOfChangeCI.xml), start values and status texts. */
#include <math.h>

#include "blocks/lgf_lim_rate_of_change_ci.c"
#include "fmi2/model.h"

typedef lgf_lim_rate_of_change_ci block;

static const model_variable variables[] = {
    SCALAR(0, "cycleTime", VAR_CYCLE, ROLE_FIXED_PARAMETER, block, value, 1e-6, 60.0),
    SCALAR(1, "value", VAR_LREAL, ROLE_INPUT, block, value, -INFINITY, INFINITY),
    SCALAR(2, "setChangeRate", VAR_LREAL, ROLE_INPUT, block, setChangeRate, -INFINITY, INFINITY),
    SCALAR(3, "defaultOutValue", VAR_LREAL, ROLE_INPUT, block, defaultOutValue, -INFINITY, INFINITY),
    SCALAR(4, "enDefaultOutValue", VAR_BOOL, ROLE_INPUT, block, enDefaultOutValue, 0, 1),
    SCALAR(5, "delayedValue", VAR_LREAL, ROLE_OUTPUT, block, delayedValue, -INFINITY, INFINITY),
    SCALAR(6, "error", VAR_BOOL, ROLE_OUTPUT, block, error, 0, 1),
    SCALAR(7, "status", VAR_WORD, ROLE_OUTPUT, block, status, 0, 65535),
    SCALAR(8, "subFunctionStatus", VAR_WORD, ROLE_OUTPUT, block, subFunctionStatus, 0, 65535),
};

static void init(void *data) { lgf_lim_rate_of_change_ci_init(data); }

static void call(void *data, const plc_call *plc) { lgf_lim_rate_of_change_ci_call(data, plc); }

static iec_word status(const void *data) { return ((const block *)data)->status; }

static const char *status_text(iec_word code)
{
    return code == LGF_LIM_RATE_STATUS_NEGATIVE_RATE
               ? "negative rate of change: setChangeRate must be >= 0; delayedValue is frozen"
               : NULL;
}

static const model_static statics[] = {
    STATIC(block, statPrevOutValue, FIELD_REAL) /* never NaN: a NaN ramp gives value (docs/behaviour.md §3) */,
};

static const model lgf_model = {
    .identifier = "LGF_LimRateOfChangeCI",
    .guid = "{6b1c3f0e-2a47-4d8e-9c51-0f3e7a2d4b11}",
    .variables = variables,
    .variable_count = sizeof variables / sizeof variables[0],
    .statics = statics,
    .static_count = sizeof statics / sizeof statics[0],
    .data_size = sizeof(block),
    .cycle_granularity_us = 1,
    .cycle_codes = "status 16#8600 (QRY_CINT failed) or 16#8601 (OB not configured)",
    .init = init,
    .call = call,
    .check = NULL,
    .status = status,
    .status_text = status_text,
};

#include "fmi2/fmu.c" /* the FMI layer, in this translation unit */
