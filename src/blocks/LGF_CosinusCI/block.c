#include "blocks/LGF_CosinusCI/block.h"

/* value := COS(rad + shift) · amplitude + offset (docs/behaviour.md §6.2); reset: counter := 0,
 * value := 0.0. */
static float lgf_cosinus_ci_wave(const lgf_signal *block)
{
    return lgf_signal_harmonic(block, true);
}

static void lgf_cosinus_ci_call(lgf_signal *block, const plc_call *call)
{
    lgf_signal_call(block, call, 0, 0.0f, lgf_cosinus_ci_wave);
}
