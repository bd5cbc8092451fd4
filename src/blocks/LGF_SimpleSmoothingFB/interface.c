/* LGF_SimpleSmoothingFB: its interface table (modelDescription/LGF_SimpleSmoothingFB.xml is
 * generated from it), statics, state check and status texts (docs/behaviour.md §16). */
#include "blocks/LGF_SimpleSmoothingFB/block.c"
#include "core/model.h"

typedef lgf_simple_smoothing_fb block;

static const model_variable variables[] = {
    OB_CYCLE_TIME_ROW_UNUSED,
    HISTORY_ENABLE_INPUT(1),
    BOOL_INPUT(2, insert,
               "Rising edge: value is read in (not in the call of a rising edge of enable); "
               "from the fourth value on a smoothedValue is output (LGF default FALSE)"),
    LREAL_INPUT(3, value, "LREAL: the value to include in the smoothing (LGF default 0.0)"),
    LREAL_OUTPUT(4, smoothedValue,
                 "LREAL: the mean of the last three values read in; 0.0 until the fourth "
                 "and while enable is FALSE"),
    ERROR_ROW(5, "Bit 15 of status: always FALSE (the block has no error code)"),
    STATUS_ROW(6, "WORD: 28672 = 16#7000 enable FALSE; 28673 = 16#7001 enabled, no value "
                  "read in yet; 28688 = 16#7010 one to three values read in; 28674 = 16#7002 a "
                  "smoothed value is output"),
};

BLOCK_FUNCTIONS(lgf_simple_smoothing_fb)

HISTORY_CHECK(LGF_SIMPLE_SMOOTHING_VALUES, 0)

/* 16#7000/7001/7002/7010 are normal operation, not errors: nothing to log. */
BLOCK_STATUS()

static const model_static statics[] = {
    STATIC(block, statValues[0], FIELD_REAL),
    STATIC(block, statValues[1], FIELD_REAL),
    STATIC(block, statValues[2], FIELD_REAL),
    HISTORY_STATICS,
};

BLOCK_MODEL("LGF_SimpleSmoothingFB", "{91404555-2af2-42ab-a584-de14e7597949}", 2,
            "Siemens LGF_SimpleSmoothingFB (LGF V5.1, block V3.0.1): smooths measured "
            "values by the linear mean of the last three read in, one at each rising "
            "edge of insert while enable is TRUE, from the fourth on. One PLC call every "
            "cycleTime. Start "
            "values: enable TRUE, waiting for values at insert.",
            BLOCK_STATICS, NO_CYCLE_CODES, .check = check, BLOCK_STATUS_FIELDS);
