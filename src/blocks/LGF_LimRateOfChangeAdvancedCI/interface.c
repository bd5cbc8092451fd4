/* LGF_LimRateOfChangeAdvancedCI: its interface table (modelDescription/
 * LGF_LimRateOfChangeAdvancedCI.xml is generated from it), statics and status texts. */
#include "blocks/LGF_LimRateOfChangeAdvancedCI/block.c"
#include "core/model.h"

typedef lgf_lim_rate_adv_ci block;

static const model_variable variables[] = {
    CI_CYCLE_TIME_ROW,
    LREAL_INPUT(1, autoValue,
                "Signal to be processed and limited in its rate of change; LGF default 0.0, "
                "FMU start 100.0"),
    LREAL_INPUT(2, manualValue, "Output value in manual mode (manOp); LGF default 0.0"),
    LREAL_INPUT(3, setPosUpRateLim,
                "Rate of change per second of the rising ramp in the positive range (output >= "
                "0 rising); < 0 gives status 16#8202; LGF default 0.0, FMU start 20.0",
                .unit = "1/s",
                .original =
                    "posUpRateLim in the LGF documentation's table, the name of an output as well"),
    LREAL_INPUT(
        4, setPosDownRateLim,
        "Rate of change per second of the falling ramp in the positive range (output >= "
        "0 falling); 0: the output jumps to autoValue, or to 0.0 across the sign; < 0 "
        "gives status 16#8202; LGF default 0.0, FMU start 40.0",
        .unit = "1/s",
        .original =
            "posDownRateLim in the LGF documentation's table, the name of an output as well"),
    LREAL_INPUT(
        5, setNegUpRateLim,
        "Rate of change per second of the ramp of rising magnitude in the negative range (output "
        "< 0 falling, and after a crossing of zero downwards); < 0 gives status 16#8202; LGF "
        "default 0.0, FMU start 20.0",
        .unit = "1/s",
        .original = "negUpRateLim in the LGF documentation's table, the name of an output as well"),
    LREAL_INPUT(
        6, setNegDownRateLim,
        "Rate of change per second of the ramp of falling magnitude in the negative range (output "
        "< 0 rising); 0: the output jumps to autoValue, or to 0.0 across the sign; < 0 gives "
        "status 16#8202; LGF default 0.0, FMU start 40.0",
        .unit = "1/s",
        .original =
            "negDownRateLim in the LGF documentation's table, the name of an output as well"),
    LREAL_INPUT(7, setHighLim,
                "High limit of outputValue; below setLowLim gives status 16#8200; LGF default "
                "0.0, FMU start 80.0",
                .original =
                    "highLim in the LGF documentation's table, the name of an output as well"),
    LREAL_INPUT(8, setLowLim, "Low limit of outputValue; LGF default 0.0, FMU start -80.0",
                .original =
                    "lowLim in the LGF documentation's table, the name of an output as well"),
    LREAL_INPUT(9, defaultOutValue,
                "Value for pre-assignment of the output variable; LGF default 0.0"),
    BOOL_INPUT(10, enDefaultOutValue,
               "TRUE: outputValue = defaultOutValue (within the limits); on release the "
               "output ramps on from it; LGF default FALSE"),
    BOOL_INPUT(
        11, track,
        "TRUE: outputValue = autoValue (within the limits), without ramp; LGF default FALSE"),
    BOOL_INPUT(12, manOp,
               "TRUE: manual mode, outputValue = manualValue without ramps, limits or flags; "
               "the limits stay suspended after it until the output is strictly within; LGF "
               "default FALSE"),
    BOOL_INPUT(13, reset,
               "Level: restart, outputValue 0.0, or with enDefaultOutValue defaultOutValue "
               "cut at the limits (highLim, lowLim); no rate flag; LGF default FALSE"),
    LREAL_OUTPUT(14, outputValue,
                 "Output variable: autoValue limited in its rate of change and by the limits"),
    BOOL_OUTPUT(15, posUpRateLim, "TRUE: the rising ramp in the positive range limited the output"),
    BOOL_OUTPUT(16, posDownRateLim,
                "TRUE: the falling ramp in the positive range limited the output, or its rate "
                "0 made it jump"),
    BOOL_OUTPUT(17, negUpRateLim,
                "TRUE: the ramp of rising magnitude in the negative range limited the output"),
    BOOL_OUTPUT(18, negDownRateLim,
                "TRUE: the ramp of falling magnitude in the negative range limited the output, "
                "or its rate 0 made it jump"),
    BOOL_OUTPUT(19, highLim,
                "TRUE: the value reached setHighLim (>=) in a restart or an automatic call; cut "
                "to it unless the limits are suspended after manual mode"),
    BOOL_OUTPUT(20, lowLim,
                "TRUE: the value reached setLowLim (<=) in a restart or an automatic call; cut "
                "to it unless the limits are suspended after manual mode"),
    ERROR_ROW(21, "FALSE: no error; TRUE: an error occurred during the execution of the FB"),
    STATUS_ROW(22, "WORD: 0 = 16#0000 no error; 33280 = 16#8200 setHighLim < setLowLim; 33282 = "
                   "16#8202 a negative rate of change"),
    SUBFUNCTION_STATUS_ROW(23),
};

BLOCK_FUNCTIONS(lgf_lim_rate_adv_ci)

BLOCK_STATUS(
    STATUS_TEXT(LGF_LIM_ADV_STATUS_LIMITS,
                "setHighLim < setLowLim: the high limit must not lie below the low limit; "
                "outputValue is frozen"),
    STATUS_TEXT(LGF_LIM_ADV_STATUS_RATE,
                "negative rate of change: setPosUpRateLim, setPosDownRateLim, setNegUpRateLim and "
                "setNegDownRateLim must be >= 0; outputValue is frozen"))

static const model_static statics[] = {
    /* NaN after -Inf + Inf in a ramp across zero (docs/behaviour.md §21.3) */
    STATIC(block, statPrevOutputValue, FIELD_RESULT),
    STATIC(block, statManOp, FIELD_BOOL),
};

BLOCK_MODEL("LGF_LimRateOfChangeAdvancedCI", "{aa03da12-c0ea-42d7-a357-180414e358c0}", 6,
            "Siemens LGF_LimRateOfChangeAdvancedCI (LGF V5.1, block V3.0.1): limits the rate of "
            "change of autoValue with four ramps (rising and falling magnitude, positive and "
            "negative range) and outputValue between two limits, with restart, pre-assignment, "
            "tracking and manual mode. One PLC call every cycleTime. Start values: autoValue "
            "100.0 at 20.0 per second, cut at the high limit 80.0.",
            BLOCK_STATICS,
            CI_CYCLE(1, "status 16#8600 (QRY_CINT failed) or 16#8601 (OB not configured)"),
            BLOCK_STATUS_FIELDS);
