/* LGF_LimRateOfChangeCI: limits the rate of change of a value (docs/behaviour.md §3). */
#ifndef LGF_LIM_RATE_OF_CHANGE_CI_H
#define LGF_LIM_RATE_OF_CHANGE_CI_H

#include "iec/iec.h"

#define LGF_LIM_RATE_STATUS_NO_ERROR 0x0000
#define LGF_LIM_RATE_STATUS_NEGATIVE_RATE 0x8200

typedef struct {
    /* inputs */
    double value;
    double setChangeRate; /* units per second */
    double defaultOutValue;
    bool enDefaultOutValue;
    /* outputs */
    double delayedValue;
    bool error;
    iec_word status;
    iec_word subFunctionStatus;
    /* statics */
    double statPrevOutValue;
} lgf_lim_rate_of_change_ci;

#endif
