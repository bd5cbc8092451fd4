#include "blocks/LGF_RectangleCI/block.h"

/* ps := REAL_TO_UDINT(phaseShift) MOD periode */
static iec_udint lgf_rectangle_ci_ps(const lgf_signal *block)
{
    return iec_real_to_udint(block->phaseShift) % block->periode;
}

/* High while ps <= counter < periode / 2 + ps (integer division, the UDINT sum wrapping); the
 * window is not wrapped, so for ps > periode/2 the duty cycle falls below 50 %, as on the PLC
 * (docs/behaviour.md §6.2). */
static float lgf_rectangle_ci_wave(const lgf_signal *block)
{
    iec_udint ps = lgf_rectangle_ci_ps(block);
    iec_udint end = block->periode / 2 + ps;
    bool high = ps <= block->statCounter && block->statCounter < end;
    return high ? block->offset + block->amplitude : block->offset - block->amplitude;
}

/* reset: counter := ps, value := 0.0 */
static void lgf_rectangle_ci_call(lgf_signal *block, const plc_call *call)
{
    lgf_signal_call(block, call, lgf_rectangle_ci_ps(block), 0.0f, lgf_rectangle_ci_wave);
}
