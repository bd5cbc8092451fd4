#include "blocks/LGF_StoreMinMax/block.h"

#include <stdio.h>
#include <string.h>

static void lgf_store_min_max_init(lgf_store_min_max *block)
{
    memset(block, 0, sizeof *block);
    /* The start values are the LGF defaults (value 0.0, reset FALSE); the statics start as a
     * reset leaves them, so the extremes count from the first call (docs/behaviour.md §14.1). */
    block->statStoreMinValue = LGF_STORE_MIN_MAX_LREAL_MAX;
    block->statStoreMaxValue = LGF_STORE_MIN_MAX_LREAL_MIN;
}

static void lgf_store_min_max_call(lgf_store_min_max *block, const plc_call *call)
{
    (void)call; /* the block does not depend on the time of the call */

    /* 1, 2. Two separate strict comparisons: one value may update both (§14.2). */
    if (block->value < block->statStoreMinValue) block->statStoreMinValue = block->value;
    if (block->value > block->statStoreMaxValue) block->statStoreMaxValue = block->value;
    /* 3. A reset comes after the comparisons: it clears what they stored, so a reset call
     * shows the clearing values and its own value is not counted (§14.2). */
    if (block->reset) {
        block->statStoreMinValue = LGF_STORE_MIN_MAX_LREAL_MAX;
        block->statStoreMaxValue = LGF_STORE_MIN_MAX_LREAL_MIN;
    }
    /* 4. */
    block->minValue = block->statStoreMinValue;
    block->maxValue = block->statStoreMaxValue;
}

/* A restored state must hold extremes a run can produce (docs/behaviour.md §14.4): the minimum
 * is never +Inf, the maximum never -Inf, and min <= max unless both are as a reset left them. */
static const char *lgf_store_min_max_check(const lgf_store_min_max *b, char *msg, size_t size)
{
    double lo = b->statStoreMinValue, hi = b->statStoreMaxValue;
    bool cleared = lo == LGF_STORE_MIN_MAX_LREAL_MAX && hi == LGF_STORE_MIN_MAX_LREAL_MIN;
    if (lo == INFINITY || hi == -INFINITY || (!cleared && lo > hi)) {
        snprintf(msg, size,
                 "the statics statStoreMinValue = %.17g and statStoreMaxValue = %.17g are no "
                 "pair a run produces (the minimum is below +Inf, the maximum above -Inf, and "
                 "minimum <= maximum unless both hold their reset values)",
                 lo, hi);
        return msg;
    }
    return NULL;
}
