#include "blocks/LGF_FloatingAverage/block.h"

#include <string.h>

static void lgf_floating_average_init(lgf_floating_average *block)
{
    memset(block, 0, sizeof *block);
    /* The LGF defaults (cyclicExecution FALSE, value 0.0, windowSize 100) read nothing; the FMU
     * reads 1.0 in every call into a window of 10, full after the tenth call
     * (docs/behaviour.md §15.1). */
    block->cyclicExecution = true;
    block->value = 1.0f;
    block->windowSize = 10;
}

static bool lgf_floating_average_size_is_valid(iec_int size)
{
    return size >= 1 && size <= LGF_FLOATING_AVERAGE_WINDOW_MAX;
}

/* One call, in the order of docs/behaviour.md §15.2. All arithmetic is float32, each operation
 * rounded on its own (§1.4). */
static void lgf_floating_average_call(lgf_floating_average *block, const plc_call *call)
{
    (void)call; /* the block does not use its cycle */

    /* 1. The edge memory of trigger, in every call. */
    bool trigger_edge = iec_rising_edge(&block->statTriggerOld, block->trigger);

    /* 2. A reset or a new window size restarts the window. */
    if (block->reset || block->windowSize != block->statWindowSizeOld) {
        memset(block->statValues, 0, sizeof block->statValues);
        block->statSum = 0.0f;
        block->statCount = 0;
        block->statIndex = 0;
        block->average = 0.0f;
        block->windowSizeReached = false;
    }
    block->statWindowSizeOld = block->windowSize;

    /* 3. A window size outside 1 ... 100 is the block error 16#8200; nothing is read in. */
    if (!lgf_floating_average_size_is_valid(block->windowSize)) {
        block->error = true;
        block->status = LGF_FLOATING_AVERAGE_ERR_WRONG_WINDOW_SIZE;
        return;
    }
    iec_int size = block->windowSize;

    /* 4. At most one read-in per call: cyclically or at a rising edge of trigger. */
    if (block->cyclicExecution || trigger_edge) {
        /* statIndex < statWindowSizeOld = size and statCount <= size hold after every call and
         * in every state the FMU accepts (interface.c: check); a restart above leaves 0. */
        iec_int index = block->statIndex;
        if (index < 0 || index >= size) index = 0;
        float *slot = &block->statValues[index];
        if (block->statCount < size) {
            /* filling: the mean of the values read so far */
            *slot = block->value;
            block->statSum = block->statSum + block->value;
            block->statCount = (iec_int)(block->statCount + 1);
            block->average = block->statSum / iec_dint_to_real(block->statCount);
        } else {
            /* sliding: the new value replaces the oldest; the sum is updated, never
             * recomputed (§15.3) */
            float sum = block->statSum + block->value;
            block->statSum = sum - *slot;
            *slot = block->value;
            block->average = block->statSum / iec_dint_to_real(size);
        }
        block->statIndex = (iec_int)((index + 1) % size);
    }

    /* 5. Outputs. */
    block->windowSizeReached = block->statCount >= size;
    block->error = false;
    block->status = LGF_FLOATING_AVERAGE_STATUS_NO_ERROR;
}
