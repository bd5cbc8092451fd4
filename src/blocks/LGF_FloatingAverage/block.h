/* LGF_FloatingAverage: the moving arithmetic mean of the last windowSize LREAL values read in
 * (docs/behaviour.md §15). */
#ifndef LGF_FLOATING_AVERAGE_H
#define LGF_FLOATING_AVERAGE_H

#include "iec/iec.h"

#define LGF_FLOATING_AVERAGE_STATUS_NO_ERROR 0x0000
#define LGF_FLOATING_AVERAGE_ERR_WRONG_WINDOW_SIZE 0x8200
/* statValues[0..99]: the original declares one element more, which no call reaches (the slot is
 * statCount MOD windowSize, below windowSize <= 100) */
#define LGF_FLOATING_AVERAGE_WINDOW_MAX 100

typedef struct {
    /* inputs */
    bool cyclicExecution;
    bool trigger;
    double value;
    iec_int windowSize;
    bool reset;
    /* outputs */
    double average;
    bool windowSizeReached;
    bool error;
    iec_word status;
    /* statics */
    double statValues[LGF_FLOATING_AVERAGE_WINDOW_MAX];
    double statSum;     /* the running sum of the window */
    double statAverage; /* the last average, output in every call */
    /* values read in while filling (0 ... windowSize), then windowSize + 1 ... 2 windowSize
     * while sliding; its remainder by windowSize is the slot to write */
    iec_int statCount;
    iec_int statWindowSizeOld;
    bool statWindowSizeReached;
    bool statTriggerOld;
} lgf_floating_average;

#endif
