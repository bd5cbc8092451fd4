#include "blocks/LGF_TriangleCI/block.h"

/* value := ABS((4.0 / P · p − 2.0) · amplitude) − amplitude, then + offset (docs/behaviour.md
 * §6.2), in float32 left to right. */
static float lgf_triangle_ci_wave(const lgf_signal *block)
{
    float p = lgf_signal_position(block), P = (float)block->periode;
    return fabsf((4.0f / P * p - 2.0f) * block->amplitude) - block->amplitude + block->offset;
}

/* reset: counter := 0, value := 0.0 + offset */
static void lgf_triangle_ci_call(lgf_signal *block, const plc_call *call)
{
    lgf_signal_call(block, call, 0, 0.0f + block->offset, lgf_triangle_ci_wave);
}
