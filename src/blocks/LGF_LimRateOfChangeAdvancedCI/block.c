#include "blocks/LGF_LimRateOfChangeAdvancedCI/block.h"

#include <string.h>

static void lgf_lim_rate_adv_ci_init(lgf_lim_rate_adv_ci *block)
{
    memset(block, 0, sizeof *block);
    /* The LGF defaults (all 0.0 / FALSE) give a constant 0.0; the FMU starts with a ramp to the
     * high limit instead (docs/behaviour.md §21.1): autoValue 100.0, rising at 20.0 per second,
     * cut at 80.0. */
    block->autoValue = 100.0;
    block->setPosUpRateLim = 20.0;
    block->setPosDownRateLim = 40.0;
    block->setNegUpRateLim = 20.0;
    block->setNegDownRateLim = 40.0;
    block->setHighLim = 80.0;
    block->setLowLim = -80.0;
}

/* The rate flags of one call (docs/behaviour.md §21.2): all FALSE at its start. */
typedef struct {
    bool posUp, posDown, negUp, negDown;
} lgf_lim_adv_flags;

/* docs/behaviour.md §21.3: the ramp from p (the previous output) towards t = autoValue, in the
 * original's order of tests. The result is t unless a branch below replaces it. */
static double lgf_lim_adv_ramp(const lgf_lim_rate_adv_ci *block, lgf_lim_adv_flags *f, double p,
                               double t, double dt)
{
    double out = t;
    /* The negative range; +0.0 and -0.0 belong to the positive one. */
    if (p < 0.0) {
        if (p > t) {
            /* Falling: the magnitude rises. */
            const double c = p - block->setNegUpRateLim * dt;
            if (t < c) {
                f->negUp = true;
                out = c;
            }
        } else if (block->setNegDownRateLim == 0.0) {
            /* A down-rate of 0 jumps, with its flag, to t, or to 0.0 across the sign. */
            f->negDown = true;
            out = t <= 0.0 ? t : 0.0;
        } else if (t <= 0.0) {
            /* Rising within the negative range. */
            const double c = p + block->setNegDownRateLim * dt;
            if (t > c) {
                f->negDown = true;
                out = c;
            }
        } else {
            /* Rising towards the positive range: z is the time to reach zero; within the call,
             * the rest of it is spent on the positive rising ramp. */
            const double z = -p / block->setNegDownRateLim;
            if (z <= dt) {
                const double c = (dt - z) * block->setPosUpRateLim;
                if (t > c) {
                    f->negDown = false;
                    f->posUp = true;
                    out = c;
                }
            } else {
                f->negDown = true;
                f->posUp = false;
                out = p + dt * block->setNegDownRateLim;
            }
        }
    } else {
        if (p < t) {
            /* Rising. */
            const double c = p + block->setPosUpRateLim * dt;
            if (t > c) {
                f->posUp = true;
                out = c;
            }
        }
        if (p >= t) {
            /* Falling, or still. */
            if (block->setPosDownRateLim == 0.0) {
                /* A down-rate of 0 jumps, with its flag, to t, or to 0.0 across the sign. */
                f->posDown = true;
                out = t >= 0.0 ? t : 0.0;
            } else if (t >= 0.0) {
                /* Falling within the positive range. */
                const double c = p - block->setPosDownRateLim * dt;
                if (t < c) {
                    f->posDown = true;
                    out = c;
                }
            } else {
                /* Falling towards the negative range, mirrored. */
                const double z = p / block->setPosDownRateLim;
                if (z <= dt) {
                    /* -(dt - z) is -0.0 where z = dt (a ramp that ends at zero: the original's
                     * -0.0 output). Through a volatile, so that no compiler turns it into
                     * z - dt (+0.0), as clang does with -funsafe-math-optimizations despite
                     * core/numerics.h. */
                    volatile double rest = dt - z;
                    const double c = -rest * block->setNegUpRateLim;
                    if (t < c) {
                        f->posDown = false;
                        f->negUp = true;
                        out = c;
                    }
                } else {
                    f->posDown = true;
                    f->negUp = false;
                    out = p - dt * block->setPosDownRateLim;
                }
            }
        }
    }
    return out;
}

static void lgf_lim_rate_adv_ci_call(lgf_lim_rate_adv_ci *block, const plc_call *call)
{
    block->subFunctionStatus = 0; /* QRY_CINT cannot fail in an FMU (docs/behaviour.md §1.6) */

    /* 1. Checks: limits first, then the rates; an error call changes nothing else. */
    if (block->setHighLim < block->setLowLim) {
        block->error = true;
        block->status = LGF_LIM_ADV_STATUS_LIMITS;
        return;
    }
    if (block->setPosUpRateLim < 0.0 || block->setPosDownRateLim < 0.0 ||
        block->setNegUpRateLim < 0.0 || block->setNegDownRateLim < 0.0) {
        block->error = true;
        block->status = LGF_LIM_ADV_STATUS_RATE;
        return;
    }

    /* 2. Every flag FALSE; dt as the original computes it: UDINT_TO_REAL(cycle in µs) / 1e6 in
     * LREAL (docs/behaviour.md §3.3). */
    lgf_lim_adv_flags f = {false, false, false, false};
    bool high_flag = false;
    bool low_flag = false;
    const double dt = (double)iec_udint_to_real((uint32_t)call->cycle_us) / 1e6;
    const double p = block->statPrevOutputValue;
    const double high = block->setHighLim;
    const double low = block->setLowLim;
    double out;
    if (block->reset) {
        /* 3. Restart: the pre-assigned value cut at both limits in turn, or 0.0 uncut. */
        block->statManOp = false;
        if (block->enDefaultOutValue) {
            out = block->defaultOutValue;
            if (out >= high) {
                out = high;
                high_flag = true;
            }
            if (out <= low) {
                out = low;
                low_flag = true;
            }
        } else {
            out = 0.0;
        }
    } else if (block->manOp) {
        /* 4. Manual: manualValue as it is, no flag; the limits are suspended from now on. */
        out = block->manualValue;
        block->statManOp = true;
    } else {
        /* 5. Automatic. */
        if (block->enDefaultOutValue) {
            out = block->defaultOutValue;
        } else if (block->track) {
            out = block->autoValue;
        } else {
            out = lgf_lim_adv_ramp(block, &f, p, block->autoValue, dt);
        }
        /* The limits: the flag at >= / <=; the cut, and the rate flag's correction, unless
         * suspended; strictly within, the suspension ends. */
        if (out >= high) {
            high_flag = true;
            if (!block->statManOp) {
                out = high;
                if (out - p < block->setPosUpRateLim * dt) f.posUp = false;
            }
        } else if (out <= low) {
            low_flag = true;
            if (!block->statManOp) {
                out = low;
                if (p - out < block->setNegUpRateLim * dt) f.negUp = false;
            }
        } else {
            block->statManOp = false;
        }
    }

    /* 6. */
    block->statPrevOutputValue = out;
    block->error = false;
    block->status = LGF_LIM_ADV_STATUS_NO_ERROR;
    block->outputValue = out;
    block->posUpRateLim = f.posUp;
    block->posDownRateLim = f.posDown;
    block->negUpRateLim = f.negUp;
    block->negDownRateLim = f.negDown;
    block->highLim = high_flag;
    block->lowLim = low_flag;
}
