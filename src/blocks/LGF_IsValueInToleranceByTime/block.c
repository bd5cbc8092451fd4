#include "blocks/LGF_IsValueInToleranceByTime/block.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void lgf_is_value_in_tolerance_by_time_init(lgf_is_value_in_tolerance_by_time *block)
{
    memset(block, 0, sizeof *block);
    /* The types' defaults (all 0) make the band the single point 0.0; the FMU starts with a
     * band of ±10 % around 50.0 and a value of 60.0 outside it, so that with no input
     * connected it shows the timing: setpointChange from the start (the value never arrives),
     * overHighLimit from 3 s (docs/behaviour.md §13.1). */
    block->value = 60.0f;
    block->setpoint = 50.0f;
    block->lowerMinimum = 10.0f;
    block->upperMaximum = 10.0f;
    block->configuration.upperLimitMonitoringTime = 1000;
    block->configuration.lowerLimitMonitoringTime = 1000;
    block->configuration.setpointChangeMonitoringTime = 2000;
}

/* docs/behaviour.md §13.2 step 1: where the value is against the limits, in REAL (each
 * operation rounded to float32, in the order the original writes it). Returns whether the limit
 * computation faulted: a limit that is no finite REAL (NaN of inf - inf or 0 * inf, or an
 * infinity from an overflow or an infinite operand), which sets ENO FALSE on the CPU. Absolute
 * limits compute nothing, so they cannot fault. */
static bool lgf_tolerance_position(const lgf_is_value_in_tolerance_by_time *block, bool *over,
                                   bool *under)
{
    const lgf_tolerance_configuration *c = &block->configuration;
    if (c->limitsAsAbsoluteValues) {
        *over = block->value > block->upperMaximum;
        *under = block->value < block->lowerMinimum;
        return false;
    }
    float high, low;
    if (c->toleranceAsAbsoluteValues) {
        high = block->setpoint + block->upperMaximum;
        low = block->setpoint - block->lowerMinimum;
    } else {
        /* percent of the setpoint, of the tolerances' magnitudes */
        float up = fabsf(block->upperMaximum) / 100.0f;
        float down = fabsf(block->lowerMinimum) / 100.0f;
        float up_factor = 1.0f + up;
        float down_factor = 1.0f - down;
        high = block->setpoint * up_factor;
        low = block->setpoint * down_factor;
    }
    *over = block->value > high;
    *under = block->value < low;
    /* An infinity or NaN at any step carries through to the limit, so the limits tell. */
    return !isfinite(high) || !isfinite(low);
}

static void lgf_is_value_in_tolerance_by_time_call(lgf_is_value_in_tolerance_by_time *block,
                                                   const plc_call *call)
{
    const lgf_tolerance_configuration *c = &block->configuration;

    /* 1. Position, and the floating-point fault of the limit computation. */
    bool over, under;
    bool fault = lgf_tolerance_position(block, &over, &under);

    /* 2. A setpoint change (an IEEE comparison: -0.0 equals 0.0) restarts the waiting. */
    if (block->setpointPrevious != block->setpoint) {
        block->arrived = false;
        block->waiting = true;
    }
    block->setpointPrevious = block->setpoint;

    /* 3. disableLimits or a rising edge of reset clear both. */
    bool reset_edge = iec_rising_edge(&block->resetPrevious, block->reset);
    if (c->disableLimits || reset_edge) {
        block->arrived = false;
        block->waiting = false;
    }

    /* 4. Inside the band: arrived. */
    if (!(under || over)) block->arrived = true;

    /* 5. Errors end the call: the timers are not executed, setpointChange keeps its value. */
    if (fault)
        block->status = LGF_TOLERANCE_STATUS_RANGE_LIMIT_VALUE_CALC;
    else if (c->limitsAsAbsoluteValues && block->setpoint > block->upperMaximum)
        block->status = LGF_TOLERANCE_STATUS_SETPOINT_ABOVE_HIGH_LIMIT;
    else if (c->limitsAsAbsoluteValues && block->setpoint < block->lowerMinimum)
        block->status = LGF_TOLERANCE_STATUS_SETPOINT_BELOW_LOW_LIMIT;
    else
        block->status = LGF_TOLERANCE_STATUS_NO_ERROR;
    if (block->status != LGF_TOLERANCE_STATUS_NO_ERROR) {
        block->error = true;
        block->overHighLimit = false;
        block->belowLowLimit = false;
        block->inLimits = false;
        return;
    }

    /* 6. The timers, in the original's order. The change timer's Q is read before it is
     * executed: the S7 update on read (§1.12) gives its Q at this call's time. */
    bool armed = block->arrived || iec_ton_q(&block->changeTimer, call);
    bool upper = iec_ton(&block->upperTimer, over && armed && !c->disableLimits,
                         c->upperLimitMonitoringTime, call);
    bool lower = iec_ton(&block->lowerTimer, under && armed && !c->disableLimits,
                         c->lowerLimitMonitoringTime, call);
    bool waited =
        iec_ton(&block->changeTimer, block->waiting && !block->arrived && !c->disableLimits,
                c->setpointChangeMonitoringTime, call);
    if (block->waiting && block->arrived) block->waiting = false;

    /* 7. Outputs. */
    block->inLimits = !(lower || upper) && !(block->waiting && !waited) && block->arrived;
    block->overHighLimit = upper;
    block->belowLowLimit = lower;
    block->setpointChange = block->waiting && !block->arrived;
    block->error = false;
    block->status = LGF_TOLERANCE_STATUS_NO_ERROR;
}

/* Call times are k·cycle in µs, below 2^62 (the FMI layer's bound): a timer started later
 * cannot come from a run, and would overflow the timer's arithmetic; no run stores a NaN
 * setpoint (NaN inputs are refused). A restored state holding either is refused. */
#define LATEST_CALL_US (INT64_C(1) << 62)

static const char *lgf_is_value_in_tolerance_by_time_check(
    const lgf_is_value_in_tolerance_by_time *block, char *msg, size_t size)
{
    if (!iec_timer_is_valid(&block->upperTimer, LATEST_CALL_US) ||
        !iec_timer_is_valid(&block->lowerTimer, LATEST_CALL_US) ||
        !iec_timer_is_valid(&block->changeTimer, LATEST_CALL_US)) {
        snprintf(msg, size, "a timer of LGF_IsValueInToleranceByTime lies outside any run");
        return msg;
    }
    if (isnan(block->setpointPrevious)) {
        snprintf(msg, size, "the previous setpoint of LGF_IsValueInToleranceByTime is NaN");
        return msg;
    }
    return NULL;
}
