/* LGF_SimpleSmoothingFB: the linear mean of the last three values read in
 * (docs/behaviour.md §16); the first mean comes with the fourth value. */
#ifndef LGF_SIMPLE_SMOOTHING_FB_H
#define LGF_SIMPLE_SMOOTHING_FB_H

#include "iec/history.h"

#define LGF_SIMPLE_SMOOTHING_VALUES 3 /* statValues[0..2] */

typedef struct {
    /* inputs */
    bool enable;
    bool insert;
    double value;
    /* outputs */
    double smoothedValue;
    bool error;
    iec_word status;
    /* statics */
    double statValues[LGF_SIMPLE_SMOOTHING_VALUES]; /* [2] the newest */
    iec_int statCount;
    iec_word statStatus;
    bool statEnableOld;
    bool statInsertOld;
} lgf_simple_smoothing_fb;

#endif
