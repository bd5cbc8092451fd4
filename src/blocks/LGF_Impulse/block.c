#include "blocks/LGF_Impulse/block.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void lgf_impulse_init(lgf_impulse *block)
{
    memset(block, 0, sizeof *block);
    /* The LGF default (0.0) gives no pulse; the FMU starts at 1 Hz, so that its default
     * experiment shows pulses (docs/behaviour.md §9.1). */
    block->frequency = 1.0f;
}

/* The period in ms as docs/behaviour.md §9.2 step 2 computes it: T#1000s / TRUNC(frequency *
 * 1000.0), a TIME divided by a DINT, towards zero. The product is a REAL, rounded to float32,
 * and > 0 here. A product of 2^31 or more (+Inf too) does not fit a DINT: TRUNC gives the limit
 * 2147483647 (the CPU reports it on ENO, which the block ignores), and the quotient is 0. A
 * product below 1 truncates to 0: the integer division by 0 gives 0 (§9.5). */
static iec_time lgf_impulse_period(float frequency)
{
    float product = frequency * 1000.0f;
    if (!(product < 2147483648.0f)) return 0;
    int32_t divisor = (int32_t)product;
    return divisor == 0 ? 0 : (iec_time)(1000000 / divisor);
}

/* The longest period: a divisor of 1 (0.001 Hz up to 0.002 Hz). */
#define LGF_IMPULSE_PERIOD_MAX 1000000

static void lgf_impulse_call(lgf_impulse *block, const plc_call *call)
{
    /* §9.2 step 1: no frequency, no pulse; the TOF is neither executed nor read */
    if (block->frequency <= 0.0f) {
        block->impulse = false;
        block->countdown = 0;
        return;
    }
    /* step 2: a new frequency, a new period */
    if (block->frequency != block->statFrequencyOld) {
        block->statTimePulse = lgf_impulse_period(block->frequency);
        block->statFrequencyOld = block->frequency;
    }
    /* step 3: the TOF's Q read before the TOF runs in this call, so up to date at this call's
     * time (the S7 update on read, §1.12): FALSE once its time has passed */
    bool q = iec_tof_q(&block->statTof, call);
    block->impulse = !q;
    /* step 4: the TOF with IN = NOT its Q (read again: the same value) and PT = the period */
    iec_tof(&block->statTof, !q, block->statTimePulse, call);
    /* step 5: both in 0 ... 1000000, so the difference does not wrap */
    block->countdown = block->statTimePulse - iec_timer_et(&block->statTof, call);
}

/* Call times are k·cycle in µs, below 2^62 (the FMI layer's bound). */
#define LATEST_CALL_US (INT64_C(1) << 62)

static const char *lgf_impulse_check(const lgf_impulse *block, char *msg, size_t size)
{
    /* every frequency but NaN (refused by the core, §1.4) gives a period (§9.2): only a
     * restored state can hold statics no run leaves */
    if (!iec_timer_is_valid(&block->statTof, LATEST_CALL_US) || block->statTimePulse < 0 ||
        block->statTimePulse > LGF_IMPULSE_PERIOD_MAX || isnan(block->statFrequencyOld) ||
        block->statFrequencyOld < 0.0f) {
        snprintf(msg, size, "a static of LGF_Impulse holds a value no run produces");
        return msg;
    }
    return NULL;
}
