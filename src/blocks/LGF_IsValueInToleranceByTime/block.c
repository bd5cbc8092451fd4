#include "blocks/LGF_IsValueInToleranceByTime/block.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void lgf_is_value_in_tolerance_by_time_init(lgf_is_value_in_tolerance_by_time *block)
{
    memset(block, 0, sizeof *block);
    /* The types' defaults (all 0) make the band the single point 0.0; the FMU starts with a
     * band of ±10 % around 50.0 and a value of 60.0 outside it, so that with no input
     * connected it shows the timing: setpointChange until 2 s, overHighLimit from 3 s
     * (docs/behaviour.md §13.1). */
    block->value = 60.0f;
    block->setpoint = 50.0f;
    block->lowerMinimum = 10.0f;
    block->upperMaximum = 10.0f;
    block->configuration.upperLimitMonitoringTime = 1000;
    block->configuration.lowerLimitMonitoringTime = 1000;
    block->configuration.setpointChangeMonitoringTime = 2000;
}

/* The limits of docs/behaviour.md §13.2 step 2, in REAL: each operation rounded to float32. */
static void lgf_tolerance_limits(const lgf_is_value_in_tolerance_by_time *block, float *high,
                                 float *low)
{
    const lgf_tolerance_configuration *c = &block->configuration;
    if (c->limitsAsAbsoluteValues) {
        *high = block->upperMaximum;
        *low = block->lowerMinimum;
    } else if (c->toleranceAsAbsoluteValues) {
        *high = block->setpoint + block->upperMaximum;
        *low = block->setpoint - block->lowerMinimum;
    } else {
        float up = block->upperMaximum / 100.0f;
        float down = block->lowerMinimum / 100.0f;
        float up_factor = 1.0f + up;
        float down_factor = 1.0f - down;
        *high = block->setpoint * up_factor;
        *low = block->setpoint * down_factor;
    }
}

static void lgf_is_value_in_tolerance_by_time_call(lgf_is_value_in_tolerance_by_time *block,
                                                   const plc_call *call)
{
    const lgf_tolerance_configuration *c = &block->configuration;

    /* 1. Setpoint change (an IEEE comparison: -0.0 equals 0.0). */
    bool changed = block->setpoint != block->setpointPrevious;
    block->setpointPrevious = block->setpoint;

    /* 2., 3. Limits and their checks; NOT (low <= high) is also TRUE for a NaN limit. */
    float high, low;
    lgf_tolerance_limits(block, &high, &low);
    if (!(low <= high))
        block->status = LGF_TOLERANCE_STATUS_RANGE_LIMIT_VALUE_CALC;
    else if (c->limitsAsAbsoluteValues && block->setpoint > high)
        block->status = LGF_TOLERANCE_STATUS_SETPOINT_ABOVE_HIGH_LIMIT;
    else if (c->limitsAsAbsoluteValues && block->setpoint < low)
        block->status = LGF_TOLERANCE_STATUS_SETPOINT_BELOW_LOW_LIMIT;
    else
        block->status = LGF_TOLERANCE_STATUS_NO_ERROR;
    block->error = block->status != LGF_TOLERANCE_STATUS_NO_ERROR;

    /* 4. Where the value is. */
    bool above = block->value > high;
    bool below = block->value < low;
    bool within = !above && !below;

    /* 5. Monitoring off: reset, an error or disableLimits clear it; the timers stop. */
    if (block->reset || block->error || c->disableLimits) {
        block->wasWithinTolerance = false;
        block->setpointChangeActive = false;
        iec_ton(&block->graceTimer, false, c->setpointChangeMonitoringTime, call);
        iec_ton(&block->highTimer, false, c->upperLimitMonitoringTime, call);
        iec_ton(&block->lowTimer, false, c->lowerLimitMonitoringTime, call);
        bool direct = c->disableLimits && !block->reset && !block->error;
        block->overHighLimit = direct && above;
        block->belowLowLimit = direct && below;
        block->inLimits = direct && within;
        block->setpointChange = false;
        return;
    }

    /* 6. Monitoring on. */
    if (changed) {
        block->setpointChangeActive = true;
        block->wasWithinTolerance = false;
    }
    if (within) {
        block->wasWithinTolerance = true;
        block->setpointChangeActive = false;
    }
    bool grace = iec_ton(&block->graceTimer, !block->wasWithinTolerance,
                         c->setpointChangeMonitoringTime, call);
    if (grace) block->setpointChangeActive = false;
    bool monitored = block->wasWithinTolerance || grace;
    block->overHighLimit =
        iec_ton(&block->highTimer, above && monitored, c->upperLimitMonitoringTime, call);
    block->belowLowLimit =
        iec_ton(&block->lowTimer, below && monitored, c->lowerLimitMonitoringTime, call);
    block->inLimits = block->wasWithinTolerance && !block->overHighLimit && !block->belowLowLimit;
    block->setpointChange = block->setpointChangeActive;
}

/* Call times are k·cycle in µs, below 2^62 (the FMI layer's bound): a timer started later
 * cannot come from a run, and would overflow the timer's arithmetic; no run stores a NaN
 * setpoint (NaN inputs are refused). A restored state holding either is refused. */
#define LATEST_CALL_US (INT64_C(1) << 62)

static const char *lgf_is_value_in_tolerance_by_time_check(
    const lgf_is_value_in_tolerance_by_time *block, char *msg, size_t size)
{
    if (!iec_timer_is_valid(&block->graceTimer, LATEST_CALL_US) ||
        !iec_timer_is_valid(&block->highTimer, LATEST_CALL_US) ||
        !iec_timer_is_valid(&block->lowTimer, LATEST_CALL_US)) {
        snprintf(msg, size, "a timer of LGF_IsValueInToleranceByTime lies outside any run");
        return msg;
    }
    if (isnan(block->setpointPrevious)) {
        snprintf(msg, size, "the previous setpoint of LGF_IsValueInToleranceByTime is NaN");
        return msg;
    }
    return NULL;
}
