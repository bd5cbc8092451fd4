#include "blocks/LGF_SawToothCI/block.h"

/* One call, in the original's order (docs/behaviour.md §6.2): the reset rule, or the counter and
 * the waveform; no block-level error. */
static void lgf_saw_tooth_ci_call(lgf_signal *block, const plc_call *call)
{
    if (block->reset) { /* counter := 0, value := 0.0 + offset */
        block->statCounter = 0;
        block->value = 0.0f + block->offset;
    } else {
        lgf_signal_advance(block, call);
        float p = lgf_signal_position(block), P = (float)block->periode;
        /* value := 2.0 · amplitude / P · p − amplitude, then + offset; C evaluates it left to
         * right, in float32, each operation rounded */
        block->value = 2.0f * block->amplitude / P * p - block->amplitude + block->offset;
    }
    lgf_signal_no_error(block);
}
