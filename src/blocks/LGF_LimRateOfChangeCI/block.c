#include "blocks/LGF_LimRateOfChangeCI/block.h"

#include <string.h>

static void lgf_lim_rate_of_change_ci_init(lgf_lim_rate_of_change_ci *block)
{
    memset(block, 0, sizeof *block);
    /* The LGF defaults (all 0.0 / FALSE) give a constant 0.0; the FMU starts with a visible
     * ramp instead (docs/behaviour.md §3.1): value 100.0 at 20.0 per second, so delayedValue
     * rises from 0.0 and lands on 100.0 after 5 s. */
    block->value = 100.0;
    block->setChangeRate = 20.0;
}

static void lgf_lim_rate_of_change_ci_call(lgf_lim_rate_of_change_ci *block, const plc_call *call)
{
    block->subFunctionStatus = 0; /* QRY_CINT cannot fail in an FMU (docs/behaviour.md §1.6) */

    /* 1. A negative rate is a block error: output and memory keep their values. */
    if (block->setChangeRate < 0.0) {
        block->error = true;
        block->status = LGF_LIM_RATE_STATUS_NEGATIVE_RATE;
        return;
    }
    block->error = false;
    block->status = LGF_LIM_RATE_STATUS_NO_ERROR;

    /* 2. Pre-assignment jumps; the ramp continues from there once released. */
    if (block->enDefaultOutValue) {
        block->statPrevOutValue = block->defaultOutValue;
        block->delayedValue = block->defaultOutValue;
        return;
    }

    /* 3. Move towards value by at most setChangeRate·dt, landing exactly on it. The
     * comparisons are written out so that the result is defined for ±Inf as on the PLC. */
    /* dt as the original computes it: UDINT_TO_REAL(cycle in µs) / 1e6 in LREAL, so the µs
     * count is rounded to a REAL first (docs/behaviour.md §3.3). */
    double dt = (double)iec_udint_to_real((uint32_t)call->cycle_us) / 1e6;
    double previous = block->statPrevOutValue;
    double out = previous;
    if (block->value < previous) {
        double ramp = previous - block->setChangeRate * dt;
        out = ramp >= block->value ? ramp : block->value;
    } else if (block->value > previous) {
        double ramp = previous + block->setChangeRate * dt;
        out = ramp <= block->value ? ramp : block->value;
    }
    block->statPrevOutValue = out;
    block->delayedValue = out;
}
