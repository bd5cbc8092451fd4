#include "blocks/LGF_LimRateOfChangeCI/block.h"

#include <string.h>

static void lgf_lim_rate_of_change_ci_init(lgf_lim_rate_of_change_ci *block)
{
    memset(block, 0, sizeof *block); /* the LGF defaults are all 0.0 / FALSE */
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
    double dt = call->cycle_s; /* µs / 1e6 in LREAL, as the original (docs/behaviour.md §3) */
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
