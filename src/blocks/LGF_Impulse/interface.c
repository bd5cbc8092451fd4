/* LGF_Impulse: its interface table (modelDescription/LGF_Impulse.xml is generated from it). */
#include <math.h>

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
    {.vr = 3,
     .name = "countdown",
     .type = VAR_TIME,
     .role = ROLE_OUTPUT,
     AT(block, countdown),
     .min = -2147483.648,
     .max = 2147483.647,
     .description = "TIME: the period minus the timer's elapsed time: the time until the next "
                    "pulse, the whole period in the call of a pulse (negative for the rest of a "
                    "period after a higher frequency is set)"},
};

BLOCK_FUNCTIONS(lgf_impulse)

BLOCK_CHECK(lgf_impulse)

static const model_static statics[] = {
    STATIC(block, statFrequencyOld, FIELD_FLOAT32), STATIC(block, statTimePulse, FIELD_INT32),
    STATIC(block, statTof.in, FIELD_BOOL),          STATIC(block, statTof.running, FIELD_BOOL),
    STATIC(block, statTof.pt, FIELD_INT32),         STATIC(block, statTof.start_us, FIELD_INT64),
};

static const model lgf_model = {
    .identifier = "LGF_Impulse",
    .guid = "{71f1267c-2c44-462f-b426-2e684c2b1cd7}",
    .description = "Siemens LGF_Impulse (LGF V5.1, block V3.0.1): a pulse of one call at a given "
                   "frequency, timed by an IEC TOF, and the time until the next pulse. One PLC "
                   "call every cycleTime. The start value of frequency differs from the LGF "
                   "default (0.0, no pulses) so that the FMU shows pulses at once.",
    .stop_time = 5,
    BLOCK_TABLES,
    NO_CYCLE_CODES,
    .check = check,
    /* LGF_Impulse has no status output: status and status_text NULL */
};
