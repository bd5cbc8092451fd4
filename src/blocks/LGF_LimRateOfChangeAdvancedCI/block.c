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

/* max(c, t) and min(c, t) of docs/behaviour.md §21.3, written out so that a NaN candidate
 * (∞ − ∞) gives t. */
static double lgf_lim_adv_max(double c, double t) { return c >= t ? c : t; }

static double lgf_lim_adv_min(double c, double t) { return c <= t ? c : t; }

/* docs/behaviour.md §21.3: one ramp step from p towards t, setting the flag of the ramp that
 * limited it. */
static double lgf_lim_adv_ramp(lgf_lim_rate_adv_ci *block, double p, double t, double dt)
{
    if (t > p) {
        if (p >= 0.0) { /* rising in the positive range (and from zero) */
            const double c = p + block->setPosUpRateLim * dt;
            block->posUpRateLim = c < t;
            return lgf_lim_adv_min(c, t);
        }
        /* rising in the negative range: the magnitude falls */
        const double c = p + block->setNegDownRateLim * dt;
        if (c > 0.0 && t > 0.0) { /* crosses zero: the rest of the cycle on the positive ramp */
            const double z = (0.0 - p) / block->setNegDownRateLim;
            const double r = dt - z;
            const double c2 = 0.0 + block->setPosUpRateLim * r;
            block->posUpRateLim = c2 < t;
            return lgf_lim_adv_min(c2, t);
        }
        block->negDownRateLim = c < t;
        return lgf_lim_adv_min(c, t);
    }
    if (t < p) {
        if (p <= 0.0) { /* falling in the negative range (and from zero): the magnitude rises */
            const double c = p - block->setNegUpRateLim * dt;
            block->negUpRateLim = c > t;
            return lgf_lim_adv_max(c, t);
        }
        /* falling in the positive range */
        const double c = p - block->setPosDownRateLim * dt;
        if (c < 0.0 && t < 0.0) { /* crosses zero: the rest of the cycle on the negative ramp */
            const double z = p / block->setPosDownRateLim;
            const double r = dt - z;
            const double c2 = 0.0 - block->setNegUpRateLim * r;
            block->negUpRateLim = c2 > t;
            return lgf_lim_adv_max(c2, t);
        }
        block->posDownRateLim = c > t;
        return lgf_lim_adv_max(c, t);
    }
    return p;
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
    /* 2. */
    block->error = false;
    block->status = LGF_LIM_ADV_STATUS_NO_ERROR;
    block->posUpRateLim = false;
    block->posDownRateLim = false;
    block->negUpRateLim = false;
    block->negDownRateLim = false;
    block->highLim = false;
    block->lowLim = false;

    const double high = block->setHighLim;
    const double low = block->setLowLim;
    double out;
    if (block->reset) {
        /* 3. Restart: the pre-assigned value within the limits, or 0.0; no flag. */
        block->statManOp = false;
        if (block->enDefaultOutValue) {
            out = block->defaultOutValue;
            if (out > high) {
                out = high;
            } else if (out < low) {
                out = low;
            }
        } else {
            out = 0.0;
        }
    } else if (block->manOp) {
        /* 4. Manual: manualValue as it is; the limits are suspended until it is back within. */
        out = block->manualValue;
        block->statManOp = true;
    } else {
        /* 5. Automatic. dt as the original computes it: UDINT_TO_REAL(cycle in µs) / 1e6 in
         * LREAL (docs/behaviour.md §3.3). */
        if (block->enDefaultOutValue) {
            out = block->defaultOutValue;
        } else if (block->track) {
            out = block->autoValue;
        } else {
            const double dt = (double)iec_udint_to_real((uint32_t)call->cycle_us) / 1e6;
            out = lgf_lim_adv_ramp(block, block->statPrevOutputValue, block->autoValue, dt);
        }
        if (block->statManOp && low <= out && out <= high) block->statManOp = false;
        if (!block->statManOp) {
            if (out > high) {
                out = high;
                block->highLim = true;
            } else if (out < low) {
                out = low;
                block->lowLim = true;
            }
        }
    }
    /* 6. */
    block->statPrevOutputValue = out;
    block->outputValue = out;
}
