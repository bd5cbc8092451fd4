/* LGF_Impulse: a pulse of one call at a given frequency, timed by an IEC TOF fed by its own
 * negated Q, with the time left until the next pulse (docs/behaviour.md §9). */
#ifndef LGF_IMPULSE_H
#define LGF_IMPULSE_H

#include <stddef.h>

#include "iec/iec.h"
#include "iec/timer.h"

typedef struct {
    /* input */
    float frequency; /* REAL, Hz */
    /* outputs */
    bool impulse;
    iec_time countdown;
    /* statics */
    float statFrequencyOld; /* the frequency statTimePulse was computed from */
    iec_time statTimePulse; /* the period in ms */
    iec_timer statTof;      /* the original's TOF instance; its Q is read from it (iec_tof_q) */
} lgf_impulse;

#endif
