#include "blocks/LGF_SinusCI/block.h"

/* One call, in the original's order (docs/behaviour.md §6): the reset rule, or the counter and
 * the waveform; no block-level error. */
static void lgf_sinus_ci_call(lgf_signal *block, const plc_call *call)
{
    if (block->reset) { /* counter := 0, value := 0.0 */
        block->statCounter = 0;
        block->value = 0.0f;
    } else {
        lgf_signal_advance(block, call);
        float P = (float)block->periode;
        /* rad := REAL(counter) · 6.283185 / P; shift := (phaseShift · 6.283185) / P;
         * value := SIN(rad + shift) · amplitude + offset */
        float rad = (float)block->statCounter * 6.283185f;
        rad = rad / P;
        float shift = block->phaseShift * 6.283185f;
        shift = shift / P;
        float value = iec_sin_cos(rad + shift, false) * block->amplitude;
        block->value = value + block->offset;
    }
    lgf_signal_no_error(block);
}
