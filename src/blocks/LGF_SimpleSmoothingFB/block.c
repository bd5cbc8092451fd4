#include "blocks/LGF_SimpleSmoothingFB/block.h"

#include <string.h>

static void lgf_simple_smoothing_fb_init(lgf_simple_smoothing_fb *block)
{
    memset(block, 0, sizeof *block);
    block->statStatus = LGF_SIMPLE_SMOOTHING_STATUS_NO_CALL;
    /* LGF default FALSE; the FMU is enabled from the first call, so that a master only drives
     * insert and value (docs/behaviour.md §16.1). */
    block->enable = true;
}

/* One call, in the order of docs/behaviour.md §16.2 (the original's: one of three branches on
 * enable, then the edge memories, then the outputs). */
static void lgf_simple_smoothing_fb_call(lgf_simple_smoothing_fb *block, const plc_call *call)
{
    (void)call; /* the block does not use its cycle */

    /* 1. Both edge memories, in every call. */
    bool enable_edge = iec_rising_edge(&block->statEnableOld, block->enable);
    bool insert_edge = iec_rising_edge(&block->statInsertOld, block->insert);

    if (enable_edge) {
        /* 2. A rising edge of enable starts again with an empty buffer, and does nothing else:
         * an edge of insert in the same call is not read in. smoothedValue is left alone; it is
         * already 0.0 (the call before was disabled, or this is the first call). */
        memset(block->statValues, 0, sizeof block->statValues);
        block->statCount = 0;
        block->statStatus = LGF_SIMPLE_SMOOTHING_STATUS_FIRST_CALL;
    } else if (block->enable) {
        /* 3. A value read in at a rising edge of insert. The first three only count (statCount
         * 0 -> 3); from the fourth on, the mean of the last three. */
        if (insert_edge) {
            block->statValues[0] = block->statValues[1];
            block->statValues[1] = block->statValues[2];
            block->statValues[2] = block->value;
            if (block->statCount <= 2) {
                block->statCount = (iec_int)(block->statCount + 1);
                block->statStatus = LGF_SIMPLE_SMOOTHING_STATUS_NOT_ENOUGH_VALUES;
            } else {
                double sum = block->statValues[0] + block->statValues[1];
                sum = sum + block->statValues[2];
                block->smoothedValue = sum / 3.0;
                block->statStatus = LGF_SIMPLE_SMOOTHING_STATUS_SUBSEQUENT_CALL;
            }
        }
    } else {
        /* 4. Disabled: the buffer stays until the next rising edge of enable. */
        block->smoothedValue = 0.0;
        block->statStatus = LGF_SIMPLE_SMOOTHING_STATUS_NO_CALL;
    }

    /* 5. Outputs: error is bit 15 of the status, never set by this block. */
    block->status = block->statStatus;
    block->error = (block->statStatus & 0x8000u) != 0;
}
