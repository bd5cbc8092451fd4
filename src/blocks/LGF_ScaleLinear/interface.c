/* LGF_ScaleLinear: its interface table (modelDescription/LGF_ScaleLinear.xml is generated from
 * it) and status texts. An FC: no statics (docs/behaviour.md §19). */
#include "blocks/LGF_ScaleLinear/block.c"
#include "core/model.h"

typedef lgf_scale_linear block;

static const model_variable variables[] = {
    CYCLE_TIME_ROW(1e-6, "none: the period of the OB that calls the FC",
                   "Period of the OB that calls the function (one evaluation per call); held in "
                   "whole µs, 1 µs to 60 s"),
    LREAL_INPUT(1, x,
                "Input value to be scaled; FC input without LGF default, FMU start 13824.0 "
                "(half of the S7 analog range 0 ... 27648)"),
    LREAL_INPUT(2, x1, "Point 1 (P1), x coordinate of the linear function; FMU start 0.0"),
    LREAL_INPUT(3, y1, "Point 1 (P1), y coordinate of the linear function; FMU start 0.0"),
    LREAL_INPUT(4, x2, "Point 2 (P2), x coordinate of the linear function; FMU start 27648.0"),
    LREAL_INPUT(5, y2, "Point 2 (P2), y coordinate of the linear function; FMU start 100.0"),
    LREAL_INPUT(6, yMin,
                "Low limit of the output y; yMin > yMax gives status 16#8200; FMU start 0.0"),
    LREAL_INPUT(7, yMax, "High limit of the output y; FMU start 100.0"),
    LREAL_OUTPUT(8, y,
                 "Scaled output value y, limited to yMin ... yMax; 0.0 with status 16#8200 "
                 "(the return value of the original FC)",
                 .original = "the FC's return value (Ret_Val)"),
    ERROR_ROW(9, "FALSE: no error; TRUE: yMin > yMax (status 16#8200)"),
    STATUS_ROW(10, "WORD: 0 = 16#0000 no error; 24577 = 16#6001 y limited to yMin; 24578 = "
                   "16#6002 y limited to yMax; 33280 = 16#8200 yMin > yMax"),
};

BLOCK_FUNCTIONS(lgf_scale_linear)

BLOCK_STATUS(STATUS_TEXT(LGF_SCALE_LINEAR_ERR_LOW_LIMIT_OVER_HIGH_LIMIT,
                         "low limit over high limit: yMin must not exceed yMax; y is 0.0"))

BLOCK_MODEL(
    "LGF_ScaleLinear", "{6f749988-a282-419b-8d31-f9bf3dad0046}", 10,
    "Siemens LGF_ScaleLinear (LGF V5.1, block V3.0.1): scales x along the straight line "
    "through P1 (x1, y1) and P2 (x2, y2) and limits the result to yMin ... yMax. An FC: "
    "evaluated once per call, every cycleTime. Start values: the S7 analog range 0 ... 27648 "
    "to 0 ... 100 at half scale, y = 50.0.",
    NO_CYCLE_CODES, BLOCK_STATUS_FIELDS);
