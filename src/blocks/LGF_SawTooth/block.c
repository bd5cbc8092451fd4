#include "blocks/LGF_SawTooth/block.h"

#include <stdio.h>
#include <string.h>

static void lgf_saw_tooth_init(lgf_saw_tooth *block)
{
    memset(block, 0, sizeof *block);
    /* The LGF defaults (all 0) give a constant 0; the FMU starts with a visible sawtooth
     * instead: 0, 10, ..., 50 in steps of 0.5 s, a tooth of 3 s. */
    block->timeRange = 500;
    block->incrementRange = 10;
    block->numberSteps = 5;
}

static void latch(lgf_saw_tooth *block, const plc_call *call)
{
    block->statStartValue = block->startValue;
    block->statTimeRange = block->timeRange;
    block->statIncrement = block->incrementRange;
    block->statNumberSteps = block->numberSteps;
    block->statEndless = block->endlessSteps;
    block->statStepCount = 0;
    block->statNextStepUs = call->now_us + (int64_t)block->timeRange * 1000;
    block->value = block->startValue;
    block->statLatched = true;
}

/* One step. The original counts the steps of a tooth in an INT and returns to startValue when
 * the count exceeds numberSteps: numberSteps <= 0 gives a constant output, and since the count
 * wraps like every INT, numberSteps = 32767 never returns (docs/behaviour.md §2.3). */
static void step(lgf_saw_tooth *block)
{
    if (block->statEndless) {
        block->value = iec_int_add(block->value, block->statIncrement);
        return;
    }
    block->statStepCount = iec_int_add(block->statStepCount, 1);
    if (block->statStepCount > block->statNumberSteps) {
        block->statStepCount = 0;
        block->value = block->statStartValue;
    } else {
        block->value = iec_int_add(block->value, block->statIncrement);
    }
}

static void lgf_saw_tooth_call(lgf_saw_tooth *block, const plc_call *call)
{
    bool latching = !block->statLatched || block->reset; /* reset is a level */

    if (block->plcTiming) {
        /* The original's order (docs/behaviour.md §2.5): (1) latch; (2) step if the TON's Q of
         * the previous call is TRUE and reset is FALSE, and only then is the TON's IN FALSE;
         * (3) run the TON, whose Q the next call reads. So a step lasts
         * ceil(timeRange/cycle)·cycle + 2·cycle, and a reset call neither steps nor stops the
         * timer: a timer that elapsed during a held reset steps in the first call after it.
         * The TON takes PT at IN's rising edge, so a timeRange latched by a reset while it
         * runs applies from its next start (docs/behaviour.md §2.5). */
        if (latching) latch(block, call);
        bool stepping = block->statTimerDone && !block->reset;
        if (stepping) step(block);
        block->statTimerDone = iec_ton(&block->statTimer, !stepping, block->statTimeRange, call);
        return;
    }

    /* Documented timing: step m falls on the first call at or after t_ref + m·timeRange,
     * at most one step per call. A timeRange <= 0 steps on every call. */
    if (latching) {
        latch(block, call);
    } else if (call->now_us >= block->statNextStepUs) {
        step(block);
        if (block->statTimeRange > 0) block->statNextStepUs += (int64_t)block->statTimeRange * 1000;
    }
}

/* Call times are k·cycle in µs, below 2^62 (the FMI layer's bound); a step is due at most a
 * TIME after a call. Times outside these bounds cannot come from a run, and would overflow the
 * timer's arithmetic, so a restored state holding them is refused. */
#define LATEST_CALL_US (INT64_C(1) << 62)
#define TIME_SPAN_US (INT64_C(1) << 42) /* > 2^31 ms */

static const char *lgf_saw_tooth_check(const lgf_saw_tooth *block, char *msg, size_t size)
{
    if (!iec_timer_is_valid(&block->statTimer, LATEST_CALL_US) ||
        block->statNextStepUs < -TIME_SPAN_US ||
        block->statNextStepUs > LATEST_CALL_US + TIME_SPAN_US) {
        snprintf(msg, size, "a time static of LGF_SawTooth lies outside any run");
        return msg;
    }
    return NULL;
}
