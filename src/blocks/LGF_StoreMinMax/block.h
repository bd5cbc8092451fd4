/* LGF_StoreMinMax: the smallest and the largest value since the first call or the last reset
 * (docs/behaviour.md §14). */
#ifndef LGF_STORE_MIN_MAX_H
#define LGF_STORE_MIN_MAX_H

#include "iec/iec.h"

/* The clearing values of a reset: the original's constants LREAL_MAX and LREAL_MIN, the latter
 * the most negative finite LREAL (§14.1). */
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

#endif
