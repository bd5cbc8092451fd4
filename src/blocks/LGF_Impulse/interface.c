/* LGF_Impulse: its interface table (modelDescription/LGF_Impulse.xml is generated from it). */
#include "blocks/LGF_Impulse/block.c"
#include "core/model.h"

typedef lgf_impulse block;

static const model_variable variables[] = {
    OB_CYCLE_TIME_ROW,
    FREQUENCY_INPUT(1,
                    "REAL: frequency of the pulses (stored as the nearest float32); <= 0: no "
                    "pulses; the period is T#1000s / TRUNC(frequency * 1000), 0 ms below 0.001 Hz "
                    "(a division by 0) and above 1000 Hz (LGF default 0.0, FMU start 1.0)"),
    BOOL_OUTPUT(2, impulse,
                "TRUE for one call at each pulse, the first in the first call; pulses come "
                "every ceil(period/cycleTime) + 1 calls, at least every other call"),
    TIME_OUTPUT(3, countdown,
                "TIME: the period minus the timer's elapsed time: the time until the next "
                "pulse, the whole period in the call of a pulse (negative for the rest of a "
                "period after a higher frequency is set)"),
};

BLOCK_FUNCTIONS(lgf_impulse)

BLOCK_CHECK(lgf_impulse)

static const model_static statics[] = {
    STATIC(block, statFrequencyOld, FIELD_FLOAT32),
    STATIC(block, statTimePulse, FIELD_INT32),
    TIMER_STATICS(statTof),
};

BLOCK_MODEL("LGF_Impulse", "{71f1267c-2c44-462f-b426-2e684c2b1cd7}", 5,
            "Siemens LGF_Impulse (LGF V5.1, block V3.0.1): a pulse of one call at a given "
            "frequency, timed by an IEC TOF, and the time until the next pulse. One PLC "
            "call every cycleTime. The start value of frequency differs from the LGF "
            "default (0.0, no pulses) so that the FMU shows pulses at once.",
            BLOCK_STATICS, NO_CYCLE_CODES, .check = check);
