/* LGF_StoreMinMax: its interface table (modelDescription/LGF_StoreMinMax.xml is generated from
 * it), statics and the rule a restored state must satisfy (docs/behaviour.md §14). */
#include <math.h>
#include <stdio.h>

#include "blocks/LGF_StoreMinMax/block.c"
#include "core/model.h"

typedef lgf_store_min_max block;

static const model_variable variables[] = {
    CYCLE_TIME_ROW(1e-6, "none: the period of the OB that calls the block",
                   "Period of the OB that calls the block (one call per cycle); held in whole "
                   "µs, 1 µs to 60 s"),
    LREAL_INPUT(1, value,
                "Value whose minimum and maximum are stored; LGF default 0.0, FMU start 0.0"),
    BOOL_INPUT(2, reset,
               "TRUE: clear the stored minimum and maximum at the end of this call, whose "
               "value is not counted (a level, not an edge); LGF default FALSE, FMU start "
               "FALSE"),
    LREAL_OUTPUT(3, minValue,
                 "Smallest value since the first call or after the last reset call; "
                 "LREAL_MAX (1.7976931348623157e308) in a reset call"),
    LREAL_OUTPUT(4, maxValue,
                 "Largest value since the first call or after the last reset call; "
                 "-LREAL_MAX in a reset call"),
};

BLOCK_FUNCTIONS(lgf_store_min_max)

/* A restored state must hold extremes a run can produce (docs/behaviour.md §14.4): the minimum
 * is never +Inf, the maximum never -Inf, and min <= max unless both are as a reset left them. */
static const char *check(const void *data, char *msg, size_t size)
{
    const block *b = data;
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

static const model_static statics[] = {
    STATIC(block, statStoreMinValue, FIELD_REAL), /* never NaN: only input values are stored */
    STATIC(block, statStoreMaxValue, FIELD_REAL),
};

BLOCK_MODEL("LGF_StoreMinMax", "{4f023883-a766-444f-9270-18bf4b668ce9}", 10,
            "Siemens LGF_StoreMinMax (LGF V5.1, block V3.0.1): stores the minimum and the "
            "maximum of value since the first call or after the last call with reset TRUE. One "
            "PLC call every cycleTime. Start values: the LGF defaults.",
            BLOCK_STATICS, NO_CYCLE_CODES, .check = check);
