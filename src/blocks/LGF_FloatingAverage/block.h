/* LGF_FloatingAverage: the moving arithmetic mean of the last windowSize REAL values read in
 * (docs/behaviour.md §15). */
#ifndef LGF_FLOATING_AVERAGE_H
#define LGF_FLOATING_AVERAGE_H

#include "iec/iec.h"

#define LGF_FLOATING_AVERAGE_STATUS_NO_ERROR 0x0000
#define LGF_FLOATING_AVERAGE_ERR_WRONG_WINDOW_SIZE 0x8200
#define LGF_FLOATING_AVERAGE_WINDOW_MAX 100 /* statValues[0..99] */

typedef struct {
    /* inputs */
    bool cyclicExecution;
    bool trigger;
    float value;
    iec_int windowSize;
    bool reset;
    /* outputs */
    float average;
    bool windowSizeReached;
    bool error;
    iec_word status;
    /* statics */
    float statValues[LGF_FLOATING_AVERAGE_WINDOW_MAX];
    float statSum;
    iec_int statCount;
    iec_int statIndex;
    iec_int statWindowSizeOld;
    bool statTriggerOld;
} lgf_floating_average;

static void lgf_floating_average_init(lgf_floating_average *block);
static void lgf_floating_average_call(lgf_floating_average *block, const plc_call *call);

#endif
