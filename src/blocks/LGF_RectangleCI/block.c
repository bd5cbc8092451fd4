#include "blocks/LGF_RectangleCI/block.h"

/* One call, in the original's order (docs/behaviour.md §6.2): the reset rule, or the counter and
 * the waveform; no block-level error. */
static void lgf_rectangle_ci_call(lgf_signal *block, const plc_call *call)
{
    iec_udint ps = iec_real_to_udint(block->phaseShift) % block->periode;
    if (block->reset) { /* counter := REAL_TO_UDINT(phaseShift) MOD periode, value := 0.0 */
        block->statCounter = ps;
        block->value = 0.0f;
    } else {
        lgf_signal_advance(block, call);
        /* High while ps <= counter < periode / 2 + ps (integer division, the UDINT sum
         * wrapping); the window is not wrapped, so for ps > periode/2 the duty cycle falls
         * below 50 %, as on the PLC. */
        iec_udint end = block->periode / 2 + ps;
        bool high = ps <= block->statCounter && block->statCounter < end;
        block->value = high ? block->offset + block->amplitude : block->offset - block->amplitude;
    }
    lgf_signal_no_error(block);
}
