/* LGF_LimRateOfChangeCI: its interface table (modelDescription/LGF_LimRateOfChangeCI.xml is
 * generated from it), statics and status texts. */
#include "blocks/LGF_LimRateOfChangeCI/block.c"
#include "core/model.h"

typedef lgf_lim_rate_of_change_ci block;

static const model_variable variables[] = {
    CI_CYCLE_TIME_ROW,
    LREAL_INPUT(1, value, "Input variable (jump function); LGF default 0.0, FMU start 100.0"),
    LREAL_INPUT(2, setChangeRate,
                "Rate of change of the ramp function, units per second; negative gives "
                "status 16#8200; LGF default 0.0, FMU start 20.0",
                .unit = "1/s"),
    LREAL_INPUT(3, defaultOutValue, "Value for pre-assignment of the output variable"),
    BOOL_INPUT(4, enDefaultOutValue,
               "Pre-assign output value (original V3.0.1 name: enDefaultOutValue)"),
    LREAL_OUTPUT(5, delayedValue, "Output variable"),
    ERROR_ROW(6, "FALSE: no error; TRUE: an error occurred during the execution of the FB"),
    STATUS_ROW(7, "WORD: 0 = 16#0000 no error; 33280 = 16#8200 negative rate of change"),
    SUBFUNCTION_STATUS_ROW(8),
};

BLOCK_FUNCTIONS(lgf_lim_rate_of_change_ci)

BLOCK_STATUS(
    STATUS_TEXT(LGF_LIM_RATE_STATUS_NEGATIVE_RATE,
                "negative rate of change: setChangeRate must be >= 0; delayedValue is frozen"))

static const model_static statics[] = {
    STATIC(block, statPrevOutValue,
           FIELD_REAL) /* never NaN: a NaN ramp gives value (docs/behaviour.md §3) */,
};

BLOCK_MODEL("LGF_LimRateOfChangeCI", "{6b1c3f0e-2a47-4d8e-9c51-0f3e7a2d4b11}", 10,
            "Siemens LGF_LimRateOfChangeCI (LGF V5.1, block V3.0.1): limits the rate of "
            "change of value; a jump becomes a ramp. One PLC call every cycleTime. Start values: "
            "value 100.0 at 20.0 per second, a ramp from 0.0 to 100.0 in 5 s.",
            BLOCK_STATICS,
            CI_CYCLE(1, "status 16#8600 (QRY_CINT failed) or 16#8601 (OB not configured)"),
            BLOCK_STATUS_FIELDS);
