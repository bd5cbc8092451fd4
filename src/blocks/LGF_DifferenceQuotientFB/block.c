#include "blocks/LGF_DifferenceQuotientFB/block.h"

#include <string.h>

static void lgf_difference_quotient_fb_init(lgf_difference_quotient_fb *block)
{
    memset(block, 0, sizeof *block);
    block->statStatus = LGF_HISTORY_STATUS_NO_CALL;
    /* LGF default FALSE (and no documented deltaT); the FMU is enabled from the first call,
     * with the documentation's example interval of 1 s (docs/behaviour.md §17.1). */
    block->enable = true;
    block->deltaT = 1.0;
}

/* One call, in the order of docs/behaviour.md §17.2: the shared history call (iec/history.h),
 * then from a full buffer the derivative, then the outputs. */
static void lgf_difference_quotient_fb_call(lgf_difference_quotient_fb *block, const plc_call *call)
{
    (void)call; /* the block does not use its cycle */
    double *y = block->statValues;
    if (!lgf_history_call(y, LGF_DIFFERENCE_QUOTIENT_VALUES, &block->statCount, &block->statStatus,
                          &block->statEnableOld, &block->statInsertOld, block->enable,
                          block->insert, block->value, &block->derivatedValue)) {
        /* nothing to compute */
    } else if (block->deltaT == 0.0) {
        /* no derivative: derivatedValue keeps the last one */
        block->statStatus = LGF_DIFFERENCE_QUOTIENT_ERR_DELTA_T;
    } else {
        /* (1 / (12 deltaT)) * (y(n-2) - 8 y(n-1) + 8 y(n+1) - y(n+2)): the factor first, then
         * the sum left to right, then their product, each operation rounded on its own (§1.4);
         * y(n), the middle one, has weight 0 */
        double factor = 12.0 * block->deltaT;
        factor = 1.0 / factor;
        double sum = y[0] - 8.0 * y[1];
        sum = sum + 8.0 * y[3];
        sum = sum - y[4];
        block->derivatedValue = factor * sum;
        block->statStatus = LGF_HISTORY_STATUS_SUBSEQUENT_CALL;
    }
    lgf_history_outputs(block->statStatus, &block->status, &block->error); /* 16#8200 */
}

/* What every call leaves behind (iec/history.h). */
static const char *lgf_difference_quotient_fb_check(const lgf_difference_quotient_fb *b, char *msg,
                                                    size_t size)
{
    return lgf_history_check(b->statStatus, b->statCount, LGF_DIFFERENCE_QUOTIENT_ERR_DELTA_T,
                             b->statValues, LGF_DIFFERENCE_QUOTIENT_VALUES, msg, size);
}
