/* LGF_DifferenceQuotientFB: the numeric derivative of a signal sampled at equal intervals, from
 * the last five values read in, from the sixth on (docs/behaviour.md §17). */
#ifndef LGF_DIFFERENCE_QUOTIENT_FB_H
#define LGF_DIFFERENCE_QUOTIENT_FB_H

#include "iec/history.h"

#define LGF_DIFFERENCE_QUOTIENT_ERR_DELTA_T 0x8200
#define LGF_DIFFERENCE_QUOTIENT_VALUES 5 /* statValues[0..4]: y(n-2) ... y(n+2) */

typedef struct {
    /* inputs */
    bool enable;
    bool insert;
    double value;
    double deltaT;
    /* outputs */
    double derivatedValue;
    bool error;
    iec_word status;
    /* statics */
    double statValues[LGF_DIFFERENCE_QUOTIENT_VALUES]; /* [0] the oldest, [4] the newest */
    iec_int statCount; /* values counted since the rising edge of enable, at most 5 */
    iec_word statStatus;
    bool statEnableOld;
    bool statInsertOld;
} lgf_difference_quotient_fb;

#endif
