/* LGF_Frequency: a clock of a frequency and a pulse/pause ratio, timed by two IEC TOFs that start
 * each other, with the time left in the current state (docs/behaviour.md §10). */
#ifndef LGF_FREQUENCY_H
#define LGF_FREQUENCY_H

#include <stddef.h>

#include "iec/iec.h"
#include "iec/timer.h"

typedef struct {
    /* inputs */
    float frequency;       /* REAL, Hz */
    float pulsePauseRatio; /* REAL, time TRUE / time FALSE */
    /* outputs */
    bool clock;
    iec_time countdown;
    /* statics */
    float statFrequencyOld; /* the inputs the times were computed from */
    float statPulsePauseRatioOld;
    iec_time statTimePulse; /* ms */
    iec_time statTimePause; /* ms */
    iec_timer statTofPulse; /* the original's two TOF instances */
    iec_timer statTofPause; /* their Q is read from them (iec_tof_q), never kept */
} lgf_frequency;

#endif
