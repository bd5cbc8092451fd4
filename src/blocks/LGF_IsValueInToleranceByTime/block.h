/* LGF_IsValueInToleranceByTime: whether a value lies within limits around a setpoint, with
 * violations hidden for a monitoring time and a time to reach the band after setpoint changes
 * (docs/behaviour.md §13). */
#ifndef LGF_IS_VALUE_IN_TOLERANCE_BY_TIME_H
#define LGF_IS_VALUE_IN_TOLERANCE_BY_TIME_H

#include <stddef.h>

#include "iec/iec.h"
#include "iec/timer.h"

#define LGF_TOLERANCE_STATUS_NO_ERROR 0x0000
#define LGF_TOLERANCE_STATUS_RANGE_LIMIT_VALUE_CALC 0x8401
#define LGF_TOLERANCE_STATUS_SETPOINT_ABOVE_HIGH_LIMIT 0x8402
#define LGF_TOLERANCE_STATUS_SETPOINT_BELOW_LOW_LIMIT 0x8403

/* The UDT LGF_typeIsValueInToleranceByTimeConfiguration (flattened into configuration.<member>
 * variables by the interface table). */
typedef struct {
    bool disableLimits;
    bool limitsAsAbsoluteValues;
    bool toleranceAsAbsoluteValues;
    iec_time upperLimitMonitoringTime;
    iec_time lowerLimitMonitoringTime;
    iec_time setpointChangeMonitoringTime;
} lgf_tolerance_configuration;

typedef struct {
    /* inputs (REAL: float32) */
    float value;
    float setpoint;
    float lowerMinimum;
    float upperMaximum;
    bool reset;
    lgf_tolerance_configuration configuration;
    /* outputs */
    bool overHighLimit;
    bool belowLowLimit;
    bool inLimits;
    bool setpointChange;
    bool error;
    iec_word status;
    /* statics */
    float setpointPrevious; /* 0.0 before the first call */
    bool resetPrevious;     /* the edge memory of reset, FALSE before the first call */
    bool waiting;           /* a setpoint change is being waited out */
    bool arrived;           /* the value has been inside the band since the last restart */
    iec_timer upperTimer;   /* TON: how long the high limit has been violated */
    iec_timer lowerTimer;   /* TON: the same for the low limit */
    iec_timer changeTimer;  /* TON: the time given to reach the band after a change */
} lgf_is_value_in_tolerance_by_time;

#endif
