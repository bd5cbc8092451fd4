#include "blocks/LGF_TriangleCI/block.h"

/* One call, in the original's order (docs/behaviour.md §6.2): the reset rule, or the counter and
 * the waveform; no block-level error. */
static void lgf_triangle_ci_call(lgf_signal *block, const plc_call *call)
{
    if (block->reset) { /* counter := 0, value := 0.0 + offset */
        block->statCounter = 0;
        block->value = 0.0f + block->offset;
    } else {
        lgf_signal_advance(block, call);
        float p = lgf_signal_position(block), P = (float)block->periode;
        /* value := ABS((4.0 / P · p − 2.0) · amplitude) − amplitude, then + offset, in float32
         * left to right */
        block->value =
            fabsf((4.0f / P * p - 2.0f) * block->amplitude) - block->amplitude + block->offset;
    }
    lgf_signal_no_error(block);
}
