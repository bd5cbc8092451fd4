#include "blocks/LGF_ScaleLinear/block.h"

#include <math.h>
#include <string.h>

static void lgf_scale_linear_init(lgf_scale_linear *block)
{
    memset(block, 0, sizeof *block);
    /* An FC's inputs have no LGF defaults; the FMU starts with the scaling of an S7 analog
     * input, raw 0 ... 27648 to 0 ... 100 %, at half scale: y = 50.0 (docs/behaviour.md §19.1). */
    block->x = 13824.0;
    block->x1 = 0.0;
    block->y1 = 0.0;
    block->x2 = 27648.0;
    block->y2 = 100.0;
    block->yMin = 0.0;
    block->yMax = 100.0;
}

static void lgf_scale_linear_call(lgf_scale_linear *block, const plc_call *call)
{
    (void)call; /* an FC: the time of the call does not matter */

    /* 1. Limits in the wrong order are the block's only error: y = 0.0 (§19.2). */
    if (block->yMin > block->yMax) {
        block->y = 0.0;
        block->error = true;
        block->status = LGF_SCALE_LINEAR_ERR_LOW_LIMIT_OVER_HIGH_LIMIT;
        return;
    }

    /* 2. y1 where x1 and x2 are "the same": |x1 - x2| <= PRECISION * |x1|, a tolerance relative
     * to x1 with the limit included (the original's test; so x1 = 0 needs x2 = 0 exactly, and
     * x1 = +-Inf takes y1 unless x2 is the same infinity, whose NaN difference fails the test).
     * Otherwise the line, each operation rounded to double in the original's order (§19.2). */
    double y;
    if (fabs(block->x1 - block->x2) <= LGF_SCALE_LINEAR_PRECISION * fabs(block->x1)) {
        y = block->y1;
    } else {
        double slope = (block->y2 - block->y1) / (block->x2 - block->x1);
        y = slope * (block->x - block->x1);
        y = y + block->y1;
    }

    /* 3. Limit y; NaN passes both tests unchanged. */
    iec_word status = LGF_SCALE_LINEAR_STATUS_NO_ERROR;
    if (y < block->yMin) {
        y = block->yMin;
        status = LGF_SCALE_LINEAR_WARN_LIMITED_TO_YMIN;
    } else if (y > block->yMax) {
        y = block->yMax;
        status = LGF_SCALE_LINEAR_WARN_LIMITED_TO_YMAX;
    }

    /* 4. The warnings leave error FALSE (bit 15 of the status is 0). */
    block->y = y;
    block->error = false;
    block->status = status;
}
