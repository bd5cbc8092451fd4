#include "blocks/LGF_NonLinearInterpolation/block.h"

#include <string.h>

static void lgf_non_linear_interpolation_init(lgf_non_linear_interpolation *block)
{
    /* Inputs and statics start at 0.0 / FALSE / 0, the LGF defaults (docs/behaviour.md §20.1). */
    memset(block, 0, sizeof *block);
    /* The original has no default table; the FMU's is a valve-like characteristic, and value
     * starts at 65.0 (LGF 0.0), so the FMU outputs 60.0 at once (docs/behaviour.md §20.1).
     * Entries 5 ... 63 stay (0.0, 0.0). */
    block->numberOfSetpoints = 5;
    block->setpoints[0] = (lgf_non_lin_setpoint){0.0, 0.0};
    block->setpoints[1] = (lgf_non_lin_setpoint){20.0, 5.0};
    block->setpoints[2] = (lgf_non_lin_setpoint){50.0, 30.0};
    block->setpoints[3] = (lgf_non_lin_setpoint){80.0, 90.0};
    block->setpoints[4] = (lgf_non_lin_setpoint){100.0, 100.0};
    block->value = 65.0;
}

/* The last index of the table. numberOfSetpoints is checked to 2 ... 64 whenever it is set or
 * a state is restored; the clamp only keeps a call inside the array whatever the data holds. */
static int lgf_non_lin_last(const lgf_non_linear_interpolation *block)
{
    int n = block->numberOfSetpoints;
    if (n < 2) n = 2;
    if (n > LGF_NON_LIN_MAX_SETPOINTS) n = LGF_NON_LIN_MAX_SETPOINTS;
    return n - 1;
}

/* docs/behaviour.md §20.3: find the segment of value from the one used last (statIndex, valid
 * here), then the straight line through its two points. */
static double lgf_non_lin_curve(lgf_non_linear_interpolation *block)
{
    const lgf_non_lin_setpoint *points = block->setpoints;
    const int last = lgf_non_lin_last(block);
    const double v = block->value;
    int k = block->statIndex;

    /* 1. Search, as the original's loop: above the segment's left point, step up while value is
     * also above its right point and a segment follows; at or below the left point, step down
     * while a segment precedes. It moves one way only in a call, so it ends for any table. */
    for (;;) {
        if (v > points[k - 1].inputValue) {
            if (v > points[k].inputValue && k < last) {
                k++;
                continue;
            }
        } else if (k > 1) {
            k--;
            continue;
        }
        break;
    }
    block->statIndex = (iec_int)k;

    /* 2. Interpolate in exactly this order (each LREAL operation rounded on its own). */
    const double x0 = points[k - 1].inputValue;
    const double y0 = points[k - 1].outputValue;
    const double slope = (points[k].outputValue - y0) / (points[k].inputValue - x0);
    return slope * v + (y0 - slope * x0);
}

static void lgf_non_linear_interpolation_call(lgf_non_linear_interpolation *block,
                                              const plc_call *call)
{
    (void)call; /* no rule depends on the cycle or the time (docs/behaviour.md §20) */

    /* docs/behaviour.md §20.2 step 1: in every call, a statIndex outside 1 ... n-1 (0 before
     * the first call) restarts the search at segment 1. */
    if (block->statIndex < 1 || block->statIndex > lgf_non_lin_last(block)) block->statIndex = 1;

    /* step 2: pre-assignment > tracking > reset > curve; only the reset and the curve touch
     * statIndex, so a reset under pre-assignment or tracking leaves it as it is. */
    if (block->enDefaultOutValue) {
        block->outputValue = block->defaultOutValue;
    } else if (block->track) {
        block->outputValue = block->value;
    } else if (block->reset) {
        block->statIndex = 1;
        block->outputValue = 0.0;
    } else {
        block->outputValue = lgf_non_lin_curve(block);
    }
}
