#include "blocks/LGF_DifferenceQuotientFB/block.h"

#include <string.h>

static void lgf_difference_quotient_fb_init(lgf_difference_quotient_fb *block)
{
    memset(block, 0, sizeof *block);
    block->statStatus = LGF_DIFFERENCE_QUOTIENT_STATUS_NO_CALL;
    /* LGF default FALSE (and no documented deltaT); the FMU is enabled from the first call,
     * with the documentation's example interval of 1 s (docs/behaviour.md §17.1). */
    block->enable = true;
    block->deltaT = 1.0;
}

/* One call, in the order of docs/behaviour.md §17.2 (the original's: one of three branches on
 * enable, then the edge memories, then the outputs). */
static void lgf_difference_quotient_fb_call(lgf_difference_quotient_fb *block, const plc_call *call)
{
    (void)call; /* the block does not use its cycle */

    /* 1. Both edge memories, in every call. */
    bool enable_edge = iec_rising_edge(&block->statEnableOld, block->enable);
    bool insert_edge = iec_rising_edge(&block->statInsertOld, block->insert);

    if (enable_edge) {
        /* 2. A rising edge of enable starts again with an empty buffer, and does nothing else:
         * an edge of insert in the same call is not read in. derivatedValue is left alone; it
         * is already 0.0 (the call before was disabled, or this is the first call). */
        memset(block->statValues, 0, sizeof block->statValues);
        block->statCount = 0;
        block->statStatus = LGF_DIFFERENCE_QUOTIENT_STATUS_FIRST_CALL;
    } else if (block->enable) {
        /* 3. A value read in at a rising edge of insert. The first five only count (statCount
         * 0 -> 5); from the sixth on, a derivative. */
        if (insert_edge) {
            double *y = block->statValues;
            for (int i = 0; i < LGF_DIFFERENCE_QUOTIENT_VALUES - 1; i++) y[i] = y[i + 1];
            y[4] = block->value;
            if (block->statCount <= 4) {
                block->statCount = (iec_int)(block->statCount + 1);
                block->statStatus = LGF_DIFFERENCE_QUOTIENT_STATUS_NOT_ENOUGH_VALUES;
            } else if (block->deltaT == 0.0) {
                /* no derivative: derivatedValue keeps the last one */
                block->statStatus = LGF_DIFFERENCE_QUOTIENT_ERR_DELTA_T;
            } else {
                /* (1 / (12 deltaT)) * (y(n-2) - 8 y(n-1) + 8 y(n+1) - y(n+2)): the factor
                 * first, then the sum left to right, then their product, each operation
                 * rounded on its own (§1.4); y(n), the middle one, has weight 0 */
                double factor = 12.0 * block->deltaT;
                factor = 1.0 / factor;
                double sum = y[0] - 8.0 * y[1];
                sum = sum + 8.0 * y[3];
                sum = sum - y[4];
                block->derivatedValue = factor * sum;
                block->statStatus = LGF_DIFFERENCE_QUOTIENT_STATUS_SUBSEQUENT_CALL;
            }
        }
    } else {
        /* 4. Disabled: the buffer stays until the next rising edge of enable. */
        block->derivatedValue = 0.0;
        block->statStatus = LGF_DIFFERENCE_QUOTIENT_STATUS_NO_CALL;
    }

    /* 5. Outputs: error is bit 15 of the status (16#8200). */
    block->status = block->statStatus;
    block->error = (block->statStatus & 0x8000u) != 0;
}
