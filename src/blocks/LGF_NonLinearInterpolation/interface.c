/* LGF_NonLinearInterpolation: its interface table (modelDescription/LGF_NonLinearInterpolation.xml
 * is generated from it) and statics. */
#include <math.h>

#include "blocks/LGF_NonLinearInterpolation/block.c"
#include "core/model.h"

typedef lgf_non_linear_interpolation block;

static const model_variable variables[] = {
    CYCLE_TIME_ROW(1e-6, "none: the block may be called from any OB",
                   "Period of the PLC calls, 1 µs to 60 s; no result depends on it"),
    SETPOINT_COUNT_ROW(1, LGF_NON_LIN_MAX_SETPOINTS,
                       "Number of points of setpoints that form the characteristic curve (2 to "
                       "64); entries from numberOfSetpoints on are ignored; FMU start 5"),
    /* inputs (docs/behaviour.md §20.1) */
    LREAL_INPUT(10, value,
                "Input value for calculating the output value; LGF default 0.0, FMU start "
                "65.0"),
    LREAL_INPUT(11, defaultOutValue,
                "Value for pre-assignment of the output variable; LGF default 0.0"),
    BOOL_INPUT(12, enDefaultOutValue,
               "TRUE: outputValue = defaultOutValue (first priority); LGF default FALSE"),
    BOOL_INPUT(13, track,
               "TRUE: outputValue = value, without the characteristic curve (second "
               "priority, before reset); LGF default FALSE"),
    BOOL_INPUT(14, reset,
               "TRUE: outputValue 0.0 and the segment search restarts at the first "
               "segment, unless enDefaultOutValue or track (they come first and leave the "
               "search as it is); LGF default FALSE"),
    LREAL_OUTPUT(20, outputValue,
                 "The output value calculated from value on the characteristic curve"),
    /* the table: setpoints[i].inputValue at 100 + i, setpoints[i].outputValue at 200 + i */
    SETPOINTS_ROW(100, inputValue, VAR_LREAL, LGF_NON_LIN_MAX_SETPOINTS, -INFINITY, INFINITY,
                  "Input value of point {i}; the points must ascend in inputValue"),
    SETPOINTS_ROW(200, outputValue, VAR_LREAL, LGF_NON_LIN_MAX_SETPOINTS, -INFINITY, INFINITY,
                  "Output value of point {i}"),
};

BLOCK_FUNCTIONS(lgf_non_linear_interpolation)

static const model_static statics[] = {
    /* any value is safe: a call validates it first (docs/behaviour.md §20.2 step 1) */
    STATIC(block, statIndex, FIELD_INT16),
};

BLOCK_MODEL("LGF_NonLinearInterpolation", "{445a9f81-8103-49b2-8ce0-e661d1086812}", 5,
            "Siemens LGF_NonLinearInterpolation (LGF V5.1, block V3.0.1): a characteristic "
            "curve from a table of points (inputValue, outputValue), linear between them and "
            "continued beyond the first and last points; with pre-assignment, tracking and "
            "reset. One PLC call every cycleTime. Default table (0, 0), (20, 5), (50, 30), "
            "(80, 90), (100, 100); value 65 gives 60.",
            BLOCK_STATICS, NO_CYCLE_CODES);
