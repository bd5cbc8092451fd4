/* LGF_Integration: its interface table (modelDescription/LGF_Integration.xml is generated from
 * it), statics and the rules a restored state must satisfy (docs/behaviour.md §18). */
#include <stdio.h>

#include "blocks/LGF_Integration/block.c"
#include "core/model.h"

typedef lgf_integration block;

static const model_variable variables[] = {
    CYCLE_TIME_ROW(1e-6, "none: the period of the OB that calls the block",
                   "Period of the OB that calls the block: the time between two calls that the "
                   "block measures (in whole ms); held in whole µs, 1 µs to 60 s"),
    BOOL_INPUT(1, enable,
               "TRUE: integrate; FALSE: hold integral; LGF default FALSE, FMU start TRUE"),
    LREAL_INPUT(2, value,
                "Value of the function curve to integrate, per second; LGF default 0.0, "
                "FMU start 1.0"),
    BOOL_INPUT(3, reset,
               "TRUE: set integral to 0.0 (a level, before enable); LGF default FALSE, "
               "FMU start FALSE"),
    LREAL_OUTPUT(4, integral,
                 "Integral value: the trapezoids of value over the seconds between calls"),
    ERROR_ROW(5, "Always FALSE: the only error of the original, reading the system time, "
                 "cannot occur in the FMU"),
    STATUS_ROW(6, "WORD: always 0 = 16#0000 no error (16#8600, RD_SYS_T failed, cannot occur)"),
    SUBFUNCTION_STATUS_ROW(7),
};

BLOCK_FUNCTIONS(lgf_integration)

BLOCK_STATUS()

/* A restored state must be one a run produces (docs/behaviour.md §18.6): a reading is never
 * negative, and a cleared last time comes with a cleared last value. */
static const char *check(const void *data, char *msg, size_t size)
{
    const block *b = data;
    if (b->statLastTimeMs < 0) {
        snprintf(msg, size, "the static statLastTimeMs = %lld is negative; a clock reading is not",
                 (long long)b->statLastTimeMs);
        return msg;
    }
    if (b->statLastTimeCleared && b->statInputOldValue != 0.0) {
        snprintf(msg, size,
                 "the statics hold a cleared last time with statInputOldValue = %.17g; a run "
                 "clears both together",
                 b->statInputOldValue);
        return msg;
    }
    return NULL;
}

static const model_static statics[] = {
    STATIC(block, statIntegral, FIELD_RESULT), /* NaN after inf - inf or inf * 0 (§18.4) */
    STATIC(block, statInputOldValue, FIELD_REAL),
    STATIC(block, statLastTimeMs, FIELD_INT64),
    STATIC(block, statLastTimeCleared, FIELD_BOOL),
};

BLOCK_MODEL("LGF_Integration", "{a9f88cc1-999e-496c-8d0c-2ad501c51049}", 10,
            "Siemens LGF_Integration (LGF V5.1, block V3.0.1): the area under the curve of "
            "value by the trapezoidal rule, over the time between calls in whole ms (the "
            "simulated time of the call instead of the CPU clock). One PLC call every "
            "cycleTime. Start values: enable TRUE, value 1.0, so integral is the time "
            "since the first call.",
            BLOCK_STATICS, NO_CYCLE_CODES, .check = check, BLOCK_STATUS_FIELDS);
