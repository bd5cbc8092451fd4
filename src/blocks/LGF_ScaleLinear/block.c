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

    /* 2. The line through P1 and P2, or y1 where the points share their x (within PRECISION).
     * Each operation is rounded to double in the order of the manual's formula; a NaN
     * difference (the same infinity twice) fails the test and gives a NaN line (§19.3). */
    double dx = block->x2 - block->x1;
    double y;
    if (fabs(dx) <= LGF_SCALE_LINEAR_PRECISION) {
        y = block->y1;
    } else {
        double slope = (block->y2 - block->y1) / dx;
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
