/* LGF_DifferenceQuotientFB: its interface table (modelDescription/LGF_DifferenceQuotientFB.xml
 * is generated from it), statics, state check and status texts (docs/behaviour.md §17). */
#include "blocks/LGF_DifferenceQuotientFB/block.c"
#include "core/model.h"

typedef lgf_difference_quotient_fb block;

static const model_variable variables[] = {
    OB_CYCLE_TIME_ROW_UNUSED,
    HISTORY_ENABLE_INPUT(1),
    BOOL_INPUT(2, insert,
               "Rising edge: value is read in (not in the call of a rising edge of enable); "
               "from the sixth value on a derivatedValue is output (LGF default FALSE)"),
    LREAL_INPUT(3, value, "LREAL: the sampled value to differentiate (LGF default 0.0)"),
    LREAL_INPUT(4, deltaT,
                "LREAL: the equidistant interval between two samples, in any time unit (the "
                "derivative is per that unit); 0.0 gives status 16#8200 when a derivative "
                "is due (no LGF default documented, FMU start 1.0)"),
    LREAL_OUTPUT(5, derivatedValue,
                 "LREAL: the derivative at the middle of the last five values, "
                 "(1 / (12 deltaT)) (y0 - 8 y1 + 8 y3 - y4); 0.0 until the sixth value and "
                 "while enable is FALSE"),
    ERROR_ROW(6, "Bit 15 of status: TRUE with 16#8200 (deltaT = 0)"),
    STATUS_ROW(7, "WORD: 28672 = 16#7000 enable FALSE; 28673 = 16#7001 enabled, no value "
                  "read in yet; 28688 = 16#7010 one to five values read in; 28674 = 16#7002 a "
                  "derivative is output; 33280 = 16#8200 deltaT is 0"),
};

BLOCK_FUNCTIONS(lgf_difference_quotient_fb)

HISTORY_CHECK(LGF_DIFFERENCE_QUOTIENT_VALUES, LGF_DIFFERENCE_QUOTIENT_ERR_DELTA_T)

BLOCK_STATUS(STATUS_TEXT(LGF_DIFFERENCE_QUOTIENT_ERR_DELTA_T,
                         "deltaT is 0: no derivative is formed; derivatedValue keeps its value"))

static const model_static statics[] = {
    STATIC(block, statValues[0], FIELD_REAL), STATIC(block, statValues[1], FIELD_REAL),
    STATIC(block, statValues[2], FIELD_REAL), STATIC(block, statValues[3], FIELD_REAL),
    STATIC(block, statValues[4], FIELD_REAL), HISTORY_STATICS,
};

BLOCK_MODEL("LGF_DifferenceQuotientFB", "{52008ce5-61cc-496f-b43c-6167d22a57aa}", 2,
            "Siemens LGF_DifferenceQuotientFB (LGF V5.1, block V3.0.1): the numeric "
            "derivative of a signal sampled every deltaT, from the last five values read "
            "in at rising edges of insert (a third-degree compensating polynomial), "
            "from the sixth on. One "
            "PLC call every cycleTime. Start values: enable TRUE, deltaT 1.0.",
            BLOCK_STATICS, NO_CYCLE_CODES, .check = check, BLOCK_STATUS_FIELDS);
