/* LGF_RampCI: runs the output along a time table of setpoints (docs/behaviour.md §4). */
#ifndef LGF_RAMP_CI_H
#define LGF_RAMP_CI_H

#include <stddef.h>

#include "iec/iec.h"

/* The table of the FMU holds this many points; numberOfSetpoints says how many are used. */
#define LGF_RAMP_CI_MAX_SETPOINTS 64

#define LGF_RAMP_CI_STATUS_IDLE_OR_END 0x0000 /* end of a non-cyclic run, reset */
#define LGF_RAMP_CI_STATUS_RUNNING 0x7000     /* running or idle */
#define LGF_RAMP_CI_STATUS_START 0x7001       /* the call of a rising edge of start */
#define LGF_RAMP_CI_STATUS_CYCLIC 0x7002      /* the cyclic wrap from the last point to point 0 */

/* One point of the table (the LGF UDT; V3.0.1 member names). */
typedef struct {
    double outputValue;
    iec_time time; /* ms from this point to the next one (docs/behaviour.md §4.1) */
} lgf_ramp_ci_setpoint;

typedef struct {
    /* parameters */
    iec_int numberOfSetpoints;
    lgf_ramp_ci_setpoint setpoints[LGF_RAMP_CI_MAX_SETPOINTS];
    /* inputs */
    double defaultOutValue;
    iec_int contStepNbr;
    iec_time contStepTime;  /* ms */
    bool enDefaultOutValue; /* V3.0.1 spells it enDefaulftOutValue (docs/behaviour.md §1.5) */
    bool start;
    bool hold;
    bool continue_; /* the LGF input `continue`, a C keyword */
    bool cyclicOP;
    bool updateTime;
    bool reset;
    /* outputs */
    double outputValue;
    bool actTimeTable;
    iec_int stepNumber;
    iec_time remainTime;      /* ms */
    iec_time totalTime;       /* ms */
    iec_time remainTotalTime; /* ms */
    bool error;
    iec_word status;
    iec_word subFunctionStatus; /* V3.0.1 spells it subfunctionStatus (docs/behaviour.md §1.5) */
    /* statics */
    bool statStartOld; /* edge memories */
    bool statResetOld;
    bool statUpdateTimeOld;
    bool statInitRun; /* "initialise run": the next running call starts at point 0 */
    bool statBlocked; /* after a reset, until the next rising edge of start */
    double statPrevOutValue;
    double statTargetValue;
} lgf_ramp_ci;

#endif
