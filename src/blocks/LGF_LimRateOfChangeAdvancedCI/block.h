/* LGF_LimRateOfChangeAdvancedCI: limits the rate of change of a value with four ramps, limits
 * the output, with restart, pre-assignment, tracking and manual mode (docs/behaviour.md §21). */
#ifndef LGF_LIM_RATE_OF_CHANGE_ADVANCED_CI_H
#define LGF_LIM_RATE_OF_CHANGE_ADVANCED_CI_H

#include "iec/iec.h"

#define LGF_LIM_ADV_STATUS_NO_ERROR 0x0000
#define LGF_LIM_ADV_STATUS_LIMITS 0x8200 /* ERR_NEG_RATE_LIM: setHighLim < setLowLim */
#define LGF_LIM_ADV_STATUS_RATE 0x8202   /* ERR_NEG_RATE_OF_CHANGE: a rate < 0 */

typedef struct {
    /* inputs (docs/behaviour.md §21.1: the rates and limits carry the prefix set) */
    double autoValue;
    double manualValue;
    double setPosUpRateLim; /* units per second */
    double setPosDownRateLim;
    double setNegUpRateLim;
    double setNegDownRateLim;
    double setHighLim;
    double setLowLim;
    double defaultOutValue;
    bool enDefaultOutValue;
    bool track;
    bool manOp;
    bool reset;
    /* outputs */
    double outputValue;
    bool posUpRateLim;
    bool posDownRateLim;
    bool negUpRateLim;
    bool negDownRateLim;
    bool highLim;
    bool lowLim;
    bool error;
    iec_word status;
    iec_word subFunctionStatus; /* V3.0.1 spells it subfunctionStatus (docs/behaviour.md §1.5) */
    /* statics */
    double statPrevOutputValue;
    bool statManOp; /* the limits are suspended after manual mode until a value strictly within */
} lgf_lim_rate_adv_ci;

#endif
