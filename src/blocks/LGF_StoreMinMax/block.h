/* LGF_StoreMinMax: the smallest and the largest value since the first call or the last reset
 * (docs/behaviour.md §14). */
#ifndef LGF_STORE_MIN_MAX_H
#define LGF_STORE_MIN_MAX_H

#include "iec/iec.h"

/* LREAL_MAX, and the most negative LREAL that the original's LREAL_MIN stands for (§14.4). */
#define LGF_STORE_MIN_MAX_LREAL_MAX 1.7976931348623157e308
#define LGF_STORE_MIN_MAX_LREAL_MIN (-1.7976931348623157e308)

typedef struct {
    /* inputs */
    double value;
    bool reset;
    /* outputs */
    double minValue;
    double maxValue;
    /* statics */
    double statStoreMinValue;
    double statStoreMaxValue;
} lgf_store_min_max;

static void lgf_store_min_max_init(lgf_store_min_max *block);
static void lgf_store_min_max_call(lgf_store_min_max *block, const plc_call *call);

#endif
