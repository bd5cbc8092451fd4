#include "blocks/LGF_SawToothCI/block.h"

/* value := 2.0 · amplitude / P · p − amplitude, then + offset (docs/behaviour.md §6.2): C
 * evaluates it left to right, in float32, each operation rounded. */
static float lgf_saw_tooth_ci_wave(const lgf_signal *block)
{
    float p = lgf_signal_position(block), P = (float)block->periode;
    return 2.0f * block->amplitude / P * p - block->amplitude + block->offset;
}

/* reset: counter := 0, value := 0.0 + offset */
static void lgf_saw_tooth_ci_call(lgf_signal *block, const plc_call *call)
{
    lgf_signal_call(block, call, 0, 0.0f + block->offset, lgf_saw_tooth_ci_wave);
}
