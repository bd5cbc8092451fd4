/* LGF_Frequency: its interface table (modelDescription/LGF_Frequency.xml is generated from it). */
#include <float.h>
#include <math.h>

#include "blocks/LGF_Frequency/block.c"
#include "core/model.h"

typedef lgf_frequency block;

static const model_variable variables[] = {
    OB_CYCLE_TIME_ROW,
    FREQUENCY_INPUT(1,
                    "REAL: frequency of the clock (stored as the nearest float32); <= 0: the clock "
                    "stops (countdown 0, clock the pulse timer's output); a positive value whose "
                    "pulse or pause time exceeds a TIME is refused "
                    "(LGF default 0.0, FMU start 1.0)"),
    ROW(2, pulsePauseRatio, VAR_REAL, ROLE_INPUT, -INFINITY, FLT_MAX,
        "REAL: time TRUE / time FALSE of each period (stored as the nearest "
        "float32); <= 0: the clock stops, as for frequency <= 0; +Inf is refused (LGF "
        "default 1.0)"),
    BOOL_OUTPUT(3, clock,
                "The clock: TRUE for ceil(pulse time/cycleTime) + 1 calls, FALSE for "
                "ceil(pause time/cycleTime) calls (at least one); it starts with a pulse"),
    TIME_OUTPUT(4, countdown, "TIME: time left in the current state of clock"),
};

BLOCK_FUNCTIONS(lgf_frequency)

BLOCK_CHECK(lgf_frequency)

static const model_static statics[] = {
    STATIC(block, statFrequencyOld, FIELD_FLOAT32),
    STATIC(block, statPulsePauseRatioOld, FIELD_FLOAT32),
    STATIC(block, statTimePulse, FIELD_INT32),
    STATIC(block, statTimePause, FIELD_INT32),
    TIMER_STATICS(statTofPulse),
    TIMER_STATICS(statTofPause),
};

BLOCK_MODEL("LGF_Frequency", "{1833c36e-0474-4b38-8cb4-e2e8512c1458}", 5,
            "Siemens LGF_Frequency (LGF V5.1, block V3.0.1): a clock of a frequency and a "
            "pulse/pause ratio, timed by two IEC TOFs, and the time left in its current "
            "state. One PLC call every cycleTime. The start value of frequency differs from "
            "the LGF default (0.0, a constant FALSE) so that the FMU shows a clock at once.",
            BLOCK_STATICS, NO_CYCLE_CODES, .check = check);
