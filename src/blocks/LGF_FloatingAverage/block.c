#include "blocks/LGF_FloatingAverage/block.h"

#include <stdio.h>
#include <string.h>

static void lgf_floating_average_init(lgf_floating_average *block)
{
    memset(block, 0, sizeof *block);
    /* The LGF defaults (cyclicExecution FALSE, value 0.0, windowSize 100) read nothing; the FMU
     * reads 1.0 in every call (from call 1 on: call 0 takes the window size) into a window of
     * 10 (docs/behaviour.md §15.1). */
    block->cyclicExecution = true;
    block->value = 1.0;
    block->windowSize = 10;
}

static bool lgf_floating_average_size_is_valid(iec_int size)
{
    return size >= 1 && size <= LGF_FLOATING_AVERAGE_WINDOW_MAX;
}

/* A restart (reset, a new windowSize) or an invalid windowSize: the window is emptied, the
 * outputs are written and the call ends without a read-in (docs/behaviour.md §15.2 steps 2, 3). */
static void lgf_floating_average_restart(lgf_floating_average *block, bool error, iec_word status)
{
    block->statWindowSizeOld = block->windowSize;
    block->statCount = 0;
    block->statSum = 0.0;
    block->statAverage = 0.0;
    block->average = 0.0;
    block->windowSizeReached = false;
    block->statWindowSizeReached = false;
    block->error = error;
    block->status = status;
}

/* One call, in the order of docs/behaviour.md §15.2. All arithmetic is LREAL (double), each
 * operation rounded on its own (§1.4). */
static void lgf_floating_average_call(lgf_floating_average *block, const plc_call *call)
{
    (void)call; /* the block does not use its cycle */

    /* 1. The edge memory of trigger, in every call. */
    bool trigger_edge = iec_rising_edge(&block->statTriggerOld, block->trigger);

    /* 2. A reset or a new window size restarts the window; nothing is read in. */
    if (block->reset || block->windowSize != block->statWindowSizeOld) {
        lgf_floating_average_restart(block, false, LGF_FLOATING_AVERAGE_STATUS_NO_ERROR);
        return;
    }
    /* 3. A window size outside 1 ... 100 (and the same as in the call before) is the block
     * error 16#8200; nothing is read in. */
    if (!lgf_floating_average_size_is_valid(block->windowSize)) {
        lgf_floating_average_restart(block, true, LGF_FLOATING_AVERAGE_ERR_WRONG_WINDOW_SIZE);
        return;
    }

    /* 4. At most one read-in per call: cyclically or at a rising edge of trigger. */
    if (block->cyclicExecution || trigger_edge) {
        iec_int size = block->windowSize;
        /* statCount lies in 0 ... 2 size in every state the FMU accepts (its state_check) */
        iec_int index = (iec_int)(block->statCount % size);
        if (block->statCount < size) {
            /* filling: the mean of the values read so far */
            block->statSum = block->statSum + block->value;
            block->statValues[index] = block->value;
            block->statCount = (iec_int)(block->statCount + 1);
            block->statAverage = block->statSum / (double)block->statCount;
        } else {
            /* sliding: the new value replaces the oldest; the sum is updated by their
             * difference, never recomputed (§15.3) */
            block->statWindowSizeReached = true;
            block->statSum = block->statSum + (block->value - block->statValues[index]);
            block->statValues[index] = block->value;
            block->statAverage = block->statSum / (double)size;
            block->statCount = index == 0 ? (iec_int)(size + 1) : (iec_int)(block->statCount + 1);
        }
    }

    /* 5. Outputs. */
    block->average = block->statAverage;
    block->windowSizeReached = block->statWindowSizeReached;
    block->error = false;
    block->status = LGF_FLOATING_AVERAGE_STATUS_NO_ERROR;
}

/* What every call leaves behind (docs/behaviour.md §15.2), so that a restored state is one a
 * run can produce: statCount fits the window size of the last call, windowSizeReached says the
 * window slides, and a window without a value holds no sum. (The slots beyond statCount keep
 * what an earlier window left: a restart does not clear them, and no call reads them.) It reads
 * statics alone, which no set changes: a state check (model.state_check), not run by every set. */
static const char *lgf_floating_average_state_check(const lgf_floating_average *b, char *msg,
                                                    size_t size)
{
    iec_int old = b->statWindowSizeOld, count = b->statCount;
    bool valid = lgf_floating_average_size_is_valid(old);
    if (valid ? count < 0 || count > 2 * old : count != 0) {
        snprintf(msg, size, "statCount %d does not fit a window of statWindowSizeOld %d", count,
                 old);
        return msg;
    }
    if (b->statWindowSizeReached != (valid && count > old)) {
        snprintf(msg, size, "statWindowSizeReached %d does not fit statCount %d in a window of %d",
                 b->statWindowSizeReached, count, old);
        return msg;
    }
    if (count == 0 && (b->statSum != 0.0 || b->statAverage != 0.0)) {
        snprintf(msg, size, "statSum and statAverage are not 0.0 with no value read in");
        return msg;
    }
    return NULL;
}
