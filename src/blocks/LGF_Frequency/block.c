#include "blocks/LGF_Frequency/block.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static void lgf_frequency_init(lgf_frequency *block)
{
    memset(block, 0, sizeof *block);
    /* The LGF default frequency (0.0) gives a constant FALSE; the FMU starts at 1 Hz with the
     * LGF default ratio 1.0, so that its default experiment shows a clock (docs/behaviour.md
     * §10.1). */
    block->frequency = 1.0f;
    block->pulsePauseRatio = 1.0f;
}

/* The pulse and pause times in ms before REAL_TO_UDINT, as docs/behaviour.md §10.2 step 2
 * computes them, each REAL operation rounded to float32. */
static void lgf_frequency_times(float frequency, float ratio, float *pulse, float *pause)
{
    float pulse_rate = ratio / (ratio + 1.0f);
    float pause_rate = 1.0f - pulse_rate;
    *pulse = (1000.0f * pulse_rate) / frequency;
    *pause = (1000.0f * pause_rate) / frequency;
}

/* A time fits a TIME when it is below 2^31 (2147483520, the largest float32 below, is fine). */
#define LGF_FREQUENCY_TIME_LIMIT 2147483648.0f

static void lgf_frequency_call(lgf_frequency *block, const plc_call *call)
{
    iec_time countdown = 0;
    /* §10.2 step 1: off; no timer is executed (clock is still read in step 7) */
    if (block->frequency > 0.0f && block->pulsePauseRatio > 0.0f) {
        /* step 2: new settings reset both timers (RESET_TIMER) and give new times;
         * REAL_TO_UDINT rounds to nearest, halves to even (rintf in the default rounding
         * mode); the times are >= 0 and below 2^31 by lgf_frequency_check */
        if (block->frequency != block->statFrequencyOld ||
            block->pulsePauseRatio != block->statPulsePauseRatioOld) {
            memset(&block->statTofPulse, 0, sizeof block->statTofPulse);
            memset(&block->statTofPause, 0, sizeof block->statTofPause);
            float pulse, pause;
            lgf_frequency_times(block->frequency, block->pulsePauseRatio, &pulse, &pause);
            block->statTimePulse = (iec_time)rintf(pulse);
            block->statTimePause = (iec_time)rintf(pause);
            block->statFrequencyOld = block->frequency;
            block->statPulsePauseRatioOld = block->pulsePauseRatio;
        }
        /* step 3: the pulse TOF runs while the pause TOF's Q is FALSE; that Q is read before
         * the pause TOF runs in this call, so it is updated to this call's time (§1.12) */
        bool pause_q = iec_tof_q(&block->statTofPause, call);
        iec_tof(&block->statTofPulse, !pause_q, block->statTimePulse, call);
        /* step 4 */
        countdown = block->statTimePulse - iec_timer_et(&block->statTofPulse, call);
        /* step 5: the pause TOF runs while the pulse TOF's Q (of this call) is TRUE */
        iec_tof(&block->statTofPause, iec_tof_q(&block->statTofPulse, call), block->statTimePause,
                call);
        /* step 6 */
        if (countdown == 0)
            countdown = block->statTimePause - iec_timer_et(&block->statTofPause, call);
    }
    /* step 7, in every call, off or not: clock is the pulse TOF's Q read now */
    block->clock = iec_tof_q(&block->statTofPulse, call);
    block->countdown = countdown;
}

/* Call times are k·cycle in µs, below 2^62 (the FMI layer's bound). */
#define LATEST_CALL_US (INT64_C(1) << 62)

static const char *lgf_frequency_check(const lgf_frequency *block, char *msg, size_t size)
{
    /* §10.4: times that do not fit a TIME are refused when the inputs are set */
    if (block->frequency > 0.0f && block->pulsePauseRatio > 0.0f) {
        float pulse, pause;
        lgf_frequency_times(block->frequency, block->pulsePauseRatio, &pulse, &pause);
        if (!(pulse < LGF_FREQUENCY_TIME_LIMIT && pause < LGF_FREQUENCY_TIME_LIMIT)) {
            snprintf(msg, size,
                     "frequency = %.9g Hz with pulsePauseRatio = %.9g gives a %s time of %.9g ms, "
                     "beyond the largest TIME (2147483647 ms); raise frequency (or set an input "
                     "<= 0 to switch the clock off)",
                     (double)block->frequency, (double)block->pulsePauseRatio,
                     pulse < LGF_FREQUENCY_TIME_LIMIT ? "pause" : "pulse",
                     (double)(pulse < LGF_FREQUENCY_TIME_LIMIT ? pause : pulse));
            return msg;
        }
    }
    /* a restored state: statics no run leaves */
    if (!iec_timer_is_valid(&block->statTofPulse, LATEST_CALL_US) ||
        !iec_timer_is_valid(&block->statTofPause, LATEST_CALL_US) || block->statTimePulse < 0 ||
        block->statTimePause < 0 || isnan(block->statFrequencyOld) ||
        isnan(block->statPulsePauseRatioOld)) {
        snprintf(msg, size, "a static of LGF_Frequency holds a value no run produces");
        return msg;
    }
    return NULL;
}
