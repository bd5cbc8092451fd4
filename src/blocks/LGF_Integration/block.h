/* LGF_Integration: the area under a curve by the trapezoidal rule, timed by the clock of the
 * call (docs/behaviour.md §18). */
#ifndef LGF_INTEGRATION_H
#define LGF_INTEGRATION_H

#include "iec/iec.h"

#define LGF_INTEGRATION_STATUS_NO_ERROR 0x0000

typedef struct {
    /* inputs */
    bool enable;
    double value;
    bool reset;
    /* outputs */
    double integral;
    bool error;
    iec_word status;
    iec_word subFunctionStatus;
    /* statics */
    double statIntegral;
    double statInputOldValue;
    /* statLastTime: the clock reading (whole ms since call 0) of the last integrating call, or
     * cleared (the original's CLEAR_TIME, DTL#1970-01-01-00:00:00) */
    int64_t statLastTimeMs;
    bool statLastTimeCleared;
} lgf_integration;

#endif
