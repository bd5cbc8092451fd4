/* LGF_SawTooth: a sawtooth of numberSteps steps of incrementRange every timeRange
 * (docs/behaviour.md §2). */
#ifndef LGF_SAW_TOOTH_H
#define LGF_SAW_TOOTH_H

#include <stddef.h>

#include "iec/iec.h"
#include "iec/timer.h"

typedef struct {
    /* parameter of the FMU: false = documented timing, true = the original's TON timing */
    bool plcTiming;
    /* inputs: copied into the block only on the first call and while reset is TRUE */
    iec_int startValue;
    iec_time timeRange;
    iec_int incrementRange;
    iec_int numberSteps;
    bool endlessSteps;
    bool reset;
    /* output */
    iec_int value;
    /* statics */
    bool statLatched; /* the first call has latched the inputs */
    iec_int statStartValue;
    iec_time statTimeRange;
    iec_int statIncrement;
    iec_int statNumberSteps;
    bool statEndless;
    iec_int statStepCount;  /* steps since the tooth began */
    int64_t statNextStepUs; /* documented timing: when the next step is due */
    bool statTimerDone;     /* PLC timing: the TON output of the previous call */
    iec_timer statTimer;    /* PLC timing: the original's TON */
} lgf_saw_tooth;

#endif
