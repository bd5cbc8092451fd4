#include "blocks/LGF_SinusCI/block.h"

/* value := SIN(rad + shift) · amplitude + offset (docs/behaviour.md §6.2); reset: counter := 0,
 * value := 0.0. */
static float lgf_sinus_ci_wave(const lgf_signal *block)
{
    return lgf_signal_harmonic(block, false);
}

static void lgf_sinus_ci_call(lgf_signal *block, const plc_call *call)
{
    lgf_signal_call(block, call, 0, 0.0f, lgf_sinus_ci_wave);
}
