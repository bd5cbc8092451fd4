/* LGF_NonLinearInterpolation: a characteristic curve from a table of points, linear between
 * them (docs/behaviour.md §20). */
#ifndef LGF_NON_LINEAR_INTERPOLATION_H
#define LGF_NON_LINEAR_INTERPOLATION_H

#include "iec/iec.h"

/* The table of the FMU holds this many points; numberOfSetpoints says how many are used. */
#define LGF_NON_LIN_MAX_SETPOINTS 64

/* One point of the table (the LGF UDT LGF_typeNonLinSetpoints). */
typedef struct {
    double inputValue;
    double outputValue;
} lgf_non_lin_setpoint;

typedef struct {
    /* parameters */
    iec_int numberOfSetpoints;
    lgf_non_lin_setpoint setpoints[LGF_NON_LIN_MAX_SETPOINTS];
    /* inputs */
    double value;
    double defaultOutValue;
    bool enDefaultOutValue;
    bool track;
    bool reset;
    /* outputs */
    double outputValue;
    /* statics: the right-hand point of the segment found last (docs/behaviour.md §20.3) */
    iec_int statIndex;
} lgf_non_linear_interpolation;

#endif
