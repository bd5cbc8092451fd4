/* LGF_IsValueInToleranceByTime: its interface table (modelDescription/
 * LGF_IsValueInToleranceByTime.xml is generated from it), statics and status texts. The input
 * configuration (a UDT) is flattened into configuration.<member> variables. */
#include "blocks/LGF_IsValueInToleranceByTime/block.c"
#include "core/model.h"

typedef lgf_is_value_in_tolerance_by_time block;

static const model_variable variables[] = {
    OB_CYCLE_TIME_ROW,
    REAL_INPUT(1, value,
               "REAL: value to check against the limits (stored as the nearest float32); "
               "LGF default 0.0, FMU start 60.0"),
    REAL_INPUT(2, setpoint,
               "REAL: setpoint; a change makes the value reach the band again before it "
               "counts as inside; LGF default 0.0, FMU start 50.0"),
    REAL_INPUT(3, lowerMinimum,
               "REAL: lower tolerance below the setpoint (in % of the setpoint, the "
               "magnitude taken, or absolute), or with "
               "limitsAsAbsoluteValues the low limit itself; LGF default 0.0, FMU start "
               "10.0"),
    REAL_INPUT(4, upperMaximum,
               "REAL: upper tolerance above the setpoint (in % of the setpoint, the "
               "magnitude taken, or absolute), or with "
               "limitsAsAbsoluteValues the high limit itself; LGF default 0.0, FMU start "
               "10.0"),
    BOOL_INPUT(5, reset,
               "Rising edge: clear the monitoring (the value has to reach the band "
               "again); the timers run on"),
    BOOL_INPUT(6, configuration.disableLimits,
               "TRUE: no monitoring: the timers stop, overHighLimit, belowLowLimit and "
               "setpointChange FALSE, inLimits TRUE while the value is inside the band"),
    BOOL_INPUT(7, configuration.limitsAsAbsoluteValues,
               "TRUE: lowerMinimum and upperMaximum are the limits; FALSE: tolerances "
               "around the setpoint"),
    BOOL_INPUT(8, configuration.toleranceAsAbsoluteValues,
               "With tolerances: TRUE absolute values, FALSE in percent of the setpoint"),
    TIME_INPUT(9, configuration.upperLimitMonitoringTime,
               "TIME: how long the high limit must be violated to be reported (an S7 "
               "TON, negative counts as 0); LGF default T#0s, FMU start 1 s"),
    TIME_INPUT(10, configuration.lowerLimitMonitoringTime,
               "TIME: how long the low limit must be violated to be reported; LGF "
               "default T#0s, FMU start 1 s"),
    TIME_INPUT(11, configuration.setpointChangeMonitoringTime,
               "TIME: time given to reach the band after a setpoint change; once it "
               "has passed, violations are timed although the value has not arrived; LGF "
               "default T#0s, FMU start 2 s"),
    BOOL_OUTPUT(12, overHighLimit, "TRUE: value above the high limit for upperLimitMonitoringTime"),
    BOOL_OUTPUT(13, belowLowLimit, "TRUE: value below the low limit for lowerLimitMonitoringTime"),
    BOOL_OUTPUT(14, inLimits,
                "TRUE: the value has been inside the band since the last setpoint "
                "change or reset, and no violation is reported"),
    BOOL_OUTPUT(15, setpointChange,
                "TRUE: after a setpoint change, until the value is inside the band"),
    ERROR_ROW(16, "TRUE while status is an error code"),
    STATUS_ROW(17, "WORD: 0 = 16#0000 no error; 33793 = 16#8401 floating-point fault in the "
                   "limit computation (a limit that is no finite REAL); 33794 = 16#8402 "
                   "setpoint above the absolute high limit; 33795 = 16#8403 setpoint below the "
                   "absolute low limit"),
};

BLOCK_FUNCTIONS(lgf_is_value_in_tolerance_by_time)

BLOCK_CHECK(lgf_is_value_in_tolerance_by_time)

BLOCK_STATUS(
    STATUS_TEXT(LGF_TOLERANCE_STATUS_RANGE_LIMIT_VALUE_CALC,
                "floating-point fault in the limit computation: a limit is no finite REAL "
                "(infinite or NaN); the three position flags are FALSE"),
    STATUS_TEXT(LGF_TOLERANCE_STATUS_SETPOINT_ABOVE_HIGH_LIMIT,
                "the setpoint is above the absolute high limit upperMaximum; the three position "
                "flags are FALSE"),
    STATUS_TEXT(LGF_TOLERANCE_STATUS_SETPOINT_BELOW_LOW_LIMIT,
                "the setpoint is below the absolute low limit lowerMinimum; the three position "
                "flags are FALSE"))

static const model_static statics[] = {
    STATIC(block, setpointPrevious, FIELD_FLOAT32),
    STATIC(block, resetPrevious, FIELD_BOOL),
    STATIC(block, waiting, FIELD_BOOL),
    STATIC(block, arrived, FIELD_BOOL),
    TIMER_STATICS(upperTimer),
    TIMER_STATICS(lowerTimer),
    TIMER_STATICS(changeTimer),
};

BLOCK_MODEL("LGF_IsValueInToleranceByTime", "{85e86a51-2651-4d58-a669-62c755db73ac}", 5,
            "Siemens LGF_IsValueInToleranceByTime (LGF V5.1, block V1.0.0): whether value lies "
            "within limits around setpoint (in % or absolute) or absolute limits; violations are "
            "reported after a monitoring time, and after a setpoint change the value has a time "
            "to reach the band. One PLC call every cycleTime. Start values: setpoint 50.0 +-10 %, "
            "value 60.0: setpointChange from the start (the value never arrives), overHighLimit "
            "from 3 s.",
            BLOCK_STATICS, NO_CYCLE_CODES, .check = check, BLOCK_STATUS_FIELDS);
