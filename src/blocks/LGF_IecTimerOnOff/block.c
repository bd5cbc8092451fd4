#include "blocks/LGF_IecTimerOnOff/block.h"

#include <stdio.h>
#include <string.h>

static void lgf_iec_timer_on_off_init(lgf_iec_timer_on_off *block)
{
    memset(block, 0, sizeof *block);
    /* The LGF defaults (in FALSE, both delays T#0s) give a constant FALSE; the FMU starts with
     * in TRUE and delays of 0.1 s and 0.2 s, so that its default experiment shows the on delay
     * and an input toggled every few cycles reaches out (docs/behaviour.md §8.1). */
    block->in = true;
    block->timeOnDelay = 100;
    block->timeOffDelay = 200;
}

/* docs/behaviour.md §8.2: the TON first, with IN = in; then the TOF, with IN = the TON's Q of
 * this same call; out = the TOF's Q. Both are S7 timers (§1.12): PT taken at the starting edge,
 * a negative PT taken as 0. */
static void lgf_iec_timer_on_off_call(lgf_iec_timer_on_off *block, const plc_call *call)
{
    bool on = iec_ton(&block->statTon, block->in, block->timeOnDelay, call);
    block->out = iec_tof(&block->statTof, on, block->timeOffDelay, call);
}

/* Call times are k·cycle in µs, below 2^62 (the FMI layer's bound): a timer started later
 * cannot come from a run, so a restored state holding one is refused. */
#define LATEST_CALL_US (INT64_C(1) << 62)

static const char *lgf_iec_timer_on_off_check(const lgf_iec_timer_on_off *block, char *msg,
                                              size_t size)
{
    if (!iec_timer_is_valid(&block->statTon, LATEST_CALL_US) ||
        !iec_timer_is_valid(&block->statTof, LATEST_CALL_US)) {
        snprintf(msg, size, "a timer static of LGF_IecTimerOnOff lies outside any run");
        return msg;
    }
    return NULL;
}
