#include "blocks/LGF_Integration/block.h"

#include <stdio.h>
#include <string.h>

static void lgf_integration_init(lgf_integration *block)
{
    memset(block, 0, sizeof *block);
    /* The LGF defaults (enable FALSE, value 0.0) keep integral at 0.0; the FMU integrates 1.0
     * from the first call on, so integral is the time since then (docs/behaviour.md §18.1). */
    block->enable = true;
    block->value = 1.0;
    block->statLastTimeCleared = true;
}

/* The time since the last integrating call, as T_DIFF gives it: whole ms, 0 from CLEAR_TIME,
 * which lies decades before any date and so outside the TIME range (§18.3). */
static iec_time lgf_integration_t_diff(const lgf_integration *block, int64_t reading_ms)
{
    if (block->statLastTimeCleared) return 0;
    return iec_time_saturate(reading_ms - block->statLastTimeMs); /* at most one cycle */
}

static void lgf_integration_call(lgf_integration *block, const plc_call *call)
{
    block->subFunctionStatus = 0; /* RD_SYS_T cannot fail in the FMU (§18.5) */
    block->error = false;
    block->status = LGF_INTEGRATION_STATUS_NO_ERROR;

    /* 1. Reset, with priority over enable. */
    if (block->reset) {
        block->statInputOldValue = 0.0;
        block->statIntegral = 0.0;
        block->statLastTimeCleared = true;
        block->statLastTimeMs = 0;
        block->integral = 0.0;
        return;
    }
    /* 2. Disabled: hold the integral, forget the last value and time. */
    if (!block->enable) {
        block->statInputOldValue = 0.0;
        block->statLastTimeCleared = true;
        block->statLastTimeMs = 0;
        block->integral = block->statIntegral;
        return;
    }

    /* 3. The clock: the call's time since call 0 in whole ms (§18.2, §18.3). */
    int64_t reading_ms = call->now_us / 1000;
    /* 4, 5. dt = DINT_TO_REAL(T_DIFF in ms) / 1000.0: the ms count as a REAL, divided in LREAL. */
    iec_time diff_ms = lgf_integration_t_diff(block, reading_ms);
    double dt = (double)iec_dint_to_real(diff_ms) / 1000.0;
    /* 6. */
    block->statLastTimeMs = reading_ms;
    block->statLastTimeCleared = false;
    /* 7, 8. The trapezoid, in the order ((value + old) * dt) / 2.0, each step rounded. */
    double sum = block->value + block->statInputOldValue;
    double area = sum * dt;
    area = area / 2.0;
    block->statIntegral = block->statIntegral + area;
    block->statInputOldValue = block->value;
    /* 9. */
    block->integral = block->statIntegral;
}

/* A restored state must be one a run produces (docs/behaviour.md §18.6): a reading is never
 * negative, and a cleared last time comes with a cleared last value. */
static const char *lgf_integration_check(const lgf_integration *b, char *msg, size_t size)
{
    if (b->statLastTimeMs < 0) {
        snprintf(msg, size, "the static statLastTimeMs = %lld is negative; a clock reading is not",
                 (long long)b->statLastTimeMs);
        return msg;
    }
    if (b->statLastTimeCleared && b->statInputOldValue != 0.0) {
        snprintf(msg, size,
                 "the statics hold a cleared last time with statInputOldValue = %.17g; a run "
                 "clears both together",
                 b->statInputOldValue);
        return msg;
    }
    return NULL;
}
