#include "blocks/LGF_SimpleSmoothingFB/block.h"

#include <string.h>

static void lgf_simple_smoothing_fb_init(lgf_simple_smoothing_fb *block)
{
    memset(block, 0, sizeof *block);
    block->statStatus = LGF_HISTORY_STATUS_NO_CALL;
    /* LGF default FALSE; the FMU is enabled from the first call, so that a master only drives
     * insert and value (docs/behaviour.md §16.1). */
    block->enable = true;
}

/* One call, in the order of docs/behaviour.md §16.2: the shared history call (iec/history.h),
 * then from a full buffer the mean of the last three, then the outputs. */
static void lgf_simple_smoothing_fb_call(lgf_simple_smoothing_fb *block, const plc_call *call)
{
    (void)call; /* the block does not use its cycle */
    double *y = block->statValues;
    if (lgf_history_call(y, LGF_SIMPLE_SMOOTHING_VALUES, &block->statCount, &block->statStatus,
                         &block->statEnableOld, &block->statInsertOld, block->enable, block->insert,
                         block->value, &block->smoothedValue)) {
        double sum = y[0] + y[1];
        sum = sum + y[2];
        block->smoothedValue = sum / 3.0;
        block->statStatus = LGF_HISTORY_STATUS_SUBSEQUENT_CALL;
    }
    lgf_history_outputs(block->statStatus, &block->status, &block->error); /* never an error */
}

/* What every call leaves behind (iec/history.h). */
static const char *lgf_simple_smoothing_fb_check(const lgf_simple_smoothing_fb *b, char *msg,
                                                 size_t size)
{
    return lgf_history_check(b->statStatus, b->statCount, 0, b->statValues,
                             LGF_SIMPLE_SMOOTHING_VALUES, msg, size);
}
