/* LGF_IecTimerOnOff: an IEC TON whose Q feeds an IEC TOF, both S7 timers: out follows in with an
 * on delay and an off delay (docs/behaviour.md §8). */
#ifndef LGF_IEC_TIMER_ON_OFF_H
#define LGF_IEC_TIMER_ON_OFF_H

#include <stddef.h>

#include "iec/iec.h"
#include "iec/timer.h"

typedef struct {
    /* inputs */
    bool in;
    iec_time timeOnDelay;
    iec_time timeOffDelay;
    /* output */
    bool out;
    /* statics: the original's two timer instances */
    iec_timer statTon;
    iec_timer statTof;
} lgf_iec_timer_on_off;

#endif
