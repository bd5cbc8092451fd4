/* LGF_ScaleLinear: scales a value along the straight line through two points, limited to
 * yMin ... yMax (docs/behaviour.md §19). An FC: no statics, the outputs are a function of the
 * inputs of the call alone. */
#ifndef LGF_SCALE_LINEAR_H
#define LGF_SCALE_LINEAR_H

#include "iec/iec.h"

#define LGF_SCALE_LINEAR_STATUS_NO_ERROR 0x0000
#define LGF_SCALE_LINEAR_WARN_LIMITED_TO_YMIN 0x6001
#define LGF_SCALE_LINEAR_WARN_LIMITED_TO_YMAX 0x6002
#define LGF_SCALE_LINEAR_ERR_LOW_LIMIT_OVER_HIGH_LIMIT 0x8200

/* The original's PRECISION: x1 and x2 within this fraction of |x1| count as the same
 * (§19.2 step 2). */
#define LGF_SCALE_LINEAR_PRECISION 1.0E-06

typedef struct {
    /* inputs */
    double x;
    double x1;
    double y1;
    double x2;
    double y2;
    double yMin;
    double yMax;
    /* outputs: y is the FC's return value */
    double y;
    bool error;
    iec_word status;
} lgf_scale_linear;

#endif
