#include "blocks/LGF_CountBooleanEdges/block.h"

#include <stdio.h>
#include <string.h>

static void lgf_count_boolean_edges_init(lgf_count_boolean_edges *block)
{
    memset(block, 0, sizeof *block);
    /* The LGF defaults (FALSE, T#0s) never show anything; the FMU starts with trigger TRUE and
     * a monitoring time of 1 s, so long is TRUE from t0 + 1 s (docs/behaviour.md §12.1). */
    block->trigger = true;
    block->monitorTime = 1000;
}

static void lgf_count_boolean_edges_call(lgf_count_boolean_edges *block, const plc_call *call)
{
    /* docs/behaviour.md §12.2, steps 1 to 6 in this order. */
    bool edge = iec_rising_edge(&block->triggerPrevious, block->trigger);
    bool q = iec_tp(&block->statTimer, block->trigger, block->monitorTime, call);
    if (edge) block->edges = (uint8_t)(block->edges + 1u); /* USINT: 255 + 1 wraps to 0 */

    block->single_ = false;
    block->double_ = false;
    block->long_ = false;
    block->severalEdges = false;
    block->noOfEdges = 0;
    if (!q && (block->qPrevious || block->trigger)) {
        if (block->edges == 0) {
            /* nothing to show */
        } else if (block->trigger && block->edges == 1) {
            block->long_ = true;
        } else if (block->edges == 1) {
            block->single_ = true;
        } else if (block->edges == 2) {
            block->double_ = true;
        } else {
            block->severalEdges = true;
        }
        block->noOfEdges = block->edges;
    }
    if (!q && !block->trigger) block->edges = 0;
    block->qPrevious = q;
}

/* Call times are k·cycle in µs, below 2^62 (the FMI layer's bound): a timer started later
 * cannot come from a run, and would overflow the timer's arithmetic, so a restored state
 * holding one is refused. */
#define LATEST_CALL_US (INT64_C(1) << 62)

static const char *lgf_count_boolean_edges_check(const lgf_count_boolean_edges *block, char *msg,
                                                 size_t size)
{
    if (!iec_timer_is_valid(&block->statTimer, LATEST_CALL_US)) {
        snprintf(msg, size, "the monitoring timer of LGF_CountBooleanEdges lies outside any run");
        return msg;
    }
    return NULL;
}
