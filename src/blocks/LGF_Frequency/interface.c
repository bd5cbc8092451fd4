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
    {.vr = 2,
     .name = "pulsePauseRatio",
     .type = VAR_REAL,
     .role = ROLE_INPUT,
     AT(block, pulsePauseRatio),
     .min = -INFINITY,
     .max = FLT_MAX,
     .description = "REAL: time TRUE / time FALSE of each period (stored as the nearest "
                    "float32); <= 0: the clock stops, as for frequency <= 0; +Inf is refused (LGF "
                    "default 1.0)"},
    BOOL_OUTPUT(3, clock,
                "The clock: TRUE for ceil(pulse time/cycleTime) + 1 calls, FALSE for "
                "ceil(pause time/cycleTime) calls (at least one); it starts with a pulse"),
    {.vr = 4,
     .name = "countdown",
     .type = VAR_TIME,
     .role = ROLE_OUTPUT,
     AT(block, countdown),
     .min = -2147483.648,
     .max = 2147483.647,
     .description = "TIME: time left in the current state of clock"},
};

BLOCK_FUNCTIONS(lgf_frequency)

BLOCK_CHECK(lgf_frequency)

static const model_static statics[] = {
    STATIC(block, statFrequencyOld, FIELD_FLOAT32),
    STATIC(block, statPulsePauseRatioOld, FIELD_FLOAT32),
    STATIC(block, statTimePulse, FIELD_INT32),
    STATIC(block, statTimePause, FIELD_INT32),
    STATIC(block, statTofPulse.in, FIELD_BOOL),
    STATIC(block, statTofPulse.running, FIELD_BOOL),
    STATIC(block, statTofPulse.pt, FIELD_INT32),
    STATIC(block, statTofPulse.start_us, FIELD_INT64),
    STATIC(block, statTofPause.in, FIELD_BOOL),
    STATIC(block, statTofPause.running, FIELD_BOOL),
    STATIC(block, statTofPause.pt, FIELD_INT32),
    STATIC(block, statTofPause.start_us, FIELD_INT64),
};

static const model lgf_model = {
    .identifier = "LGF_Frequency",
    .guid = "{1833c36e-0474-4b38-8cb4-e2e8512c1458}",
    .description = "Siemens LGF_Frequency (LGF V5.1, block V3.0.1): a clock of a frequency and a "
                   "pulse/pause ratio, timed by two IEC TOFs, and the time left in its current "
                   "state. One PLC call every cycleTime. The start value of frequency differs from "
                   "the LGF default (0.0, a constant FALSE) so that the FMU shows a clock at once.",
    .stop_time = 5,
    BLOCK_TABLES,
    NO_CYCLE_CODES,
    .check = check,
    /* LGF_Frequency has no status output: status and status_text NULL */
};
