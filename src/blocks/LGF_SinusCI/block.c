#include "blocks/LGF_SinusCI/block.h"

/* One call, in the original's order (docs/behaviour.md §6.2): the reset rule, or the counter and
 * the waveform, value := SIN(rad + shift) · amplitude + offset; no block-level error. */
static void lgf_sinus_ci_call(lgf_signal *block, const plc_call *call)
{
    if (block->reset) { /* counter := 0, value := 0.0 */
        block->statCounter = 0;
        block->value = 0.0f;
    } else {
        lgf_signal_advance(block, call);
        block->value = lgf_signal_harmonic(block, false);
    }
    lgf_signal_no_error(block);
}
