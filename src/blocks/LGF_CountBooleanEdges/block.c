#include "blocks/LGF_CountBooleanEdges/block.h"

#include <stdio.h>
#include <string.h>

static void lgf_count_boolean_edges_init(lgf_count_boolean_edges *block)
{
    memset(block, 0, sizeof *block);
    /* The LGF defaults (FALSE, T#0s) never show anything; the FMU starts with trigger TRUE and
     * a monitoring time of 0.7 s, so long is TRUE from t0 + 0.7 s (docs/behaviour.md §12.1). */
    block->trigger = true;
    block->monitorTime = 700;
}

static void lgf_count_boolean_edges_call(lgf_count_boolean_edges *block, const plc_call *call)
{
    /* docs/behaviour.md §12.2, steps 1 to 4 in this order. The TP is executed only where the
     * original executes it: with IN TRUE at an edge, with IN FALSE when the count is cleared.
     * Its Q is read in between with the S7 update on read (§1.12). */
    bool edge = iec_rising_edge(&block->triggerPrevious, block->trigger);
    if (edge) {
        (void)iec_tp(&block->statTimer, true, block->monitorTime, call);
        block->edges = (uint8_t)(block->edges + 1u); /* USINT: 255 + 1 wraps to 0 */
    }

    bool single = false, twice = false, held = false, several = false;
    uint8_t shown = 0;
    if (!iec_tp_q(&block->statTimer, call)) {
        if (!block->trigger && block->resultShown) {
            /* clear: the outputs stay FALSE, the timer gets IN FALSE */
            block->edges = 0;
            block->resultShown = false;
            (void)iec_tp(&block->statTimer, false, block->monitorTime, call);
        } else if (block->edges != 0) {
            if (block->trigger && block->edges == 1)
                held = true;
            else if (block->edges == 1)
                single = true;
            else if (block->edges == 2)
                twice = true;
            else
                several = true;
            shown = block->edges;
            block->resultShown = true;
        }
    }
    block->single_ = single;
    block->double_ = twice;
    block->long_ = held;
    block->severalEdges = several;
    block->noOfEdges = shown;
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
