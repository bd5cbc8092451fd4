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

/* The period in ms as docs/behaviour.md §9.2 step 2 computes it, each REAL operation rounded to
 * float32: q = 1000000.0 / (frequency * 1000.0), before TRUNC. */
static float lgf_impulse_period(float frequency)
{
    float a = frequency * 1000.0f;
    return 1000000.0f / a;
}

/* TRUNC(q) fits a DINT when q < 2^31 (2147483520, the largest float32 below, is fine). */
#define LGF_IMPULSE_PERIOD_LIMIT 2147483648.0f

static void lgf_impulse_call(lgf_impulse *block, const plc_call *call)
{
    /* §9.2 step 1: no frequency, no pulse; the TOF is not executed */
    if (block->frequency <= 0.0f) {
        block->impulse = false;
        block->countdown = 0;
        return;
    }
    /* step 2: a new frequency, a new period (TRUNC: towards zero; q >= 0 here, and q < 2^31
     * by lgf_impulse_check) */
    if (block->frequency != block->statFrequencyOld) {
        block->statTimePulse = (iec_time)lgf_impulse_period(block->frequency);
        block->statFrequencyOld = block->frequency;
    }
    /* step 3: the TOF with IN = NOT its own Q; PT taken at its falling edge (§1.12) */
    block->statTofQ = iec_tof(&block->statTof, !block->statTofQ, block->statTimePulse, call);
    /* step 4: both in 0 ... 2^31 - 1, so the difference does not wrap */
    block->impulse = !block->statTofQ;
    block->countdown = block->statTimePulse - iec_timer_et(&block->statTof, call);
}

/* Call times are k·cycle in µs, below 2^62 (the FMI layer's bound). */
#define LATEST_CALL_US (INT64_C(1) << 62)

static const char *lgf_impulse_check(const lgf_impulse *block, char *msg, size_t size)
{
    /* §9.4: a period that TRUNC cannot convert is refused when frequency is set */
    if (block->frequency > 0.0f &&
        !(lgf_impulse_period(block->frequency) < LGF_IMPULSE_PERIOD_LIMIT)) {
        snprintf(msg, size,
                 "frequency = %.9g Hz gives a period of 1000 s / (frequency * 1000) beyond the "
                 "largest TIME (2147483.647 s); frequency must be <= 0 or at least "
                 "4.6566132e-07 Hz",
                 (double)block->frequency);
        return msg;
    }
    /* a restored state: statics no run leaves */
    if (!iec_timer_is_valid(&block->statTof, LATEST_CALL_US) || block->statTimePulse < 0 ||
        isnan(block->statFrequencyOld) || block->statFrequencyOld < 0.0f) {
        snprintf(msg, size, "a static of LGF_Impulse holds a value no run produces");
        return msg;
    }
    return NULL;
}
