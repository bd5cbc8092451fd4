/* LGF_FloatingAverage: its interface table (modelDescription/LGF_FloatingAverage.xml is
 * generated from it), statics, state check and status texts (docs/behaviour.md §15). */
#include <stdio.h>

#include "blocks/LGF_FloatingAverage/block.c"
#include "core/model.h"

typedef lgf_floating_average block;

static const model_variable variables[] = {
    OB_CYCLE_TIME_ROW_UNUSED,
    BOOL_INPUT(1, cyclicExecution,
               "TRUE: value is read in every call, trigger is not used (LGF default "
               "FALSE, FMU start true)"),
    BOOL_INPUT(2, trigger, "Rising edge: value is read in (LGF default FALSE)"),
    LREAL_INPUT(3, value, "LREAL: the value to average (LGF default 0.0, FMU start 1.0)"),
    INT_INPUT(4, windowSize,
              "INT: window length, 1 to 100; any other value gives status 16#8200 "
              "from the call after the change; a change restarts the window and reads "
              "nothing in (LGF default 100, FMU start 10)"),
    BOOL_INPUT(5, reset,
               "TRUE: the window is emptied and the calculation starts again; nothing is "
               "read in (LGF default FALSE)"),
    LREAL_OUTPUT(6, average, "LREAL: the moving average of the values in the window"),
    BOOL_OUTPUT(7, windowSizeReached,
                "TRUE from the first value that replaces an old one (value windowSize + "
                "1) until a restart"),
    ERROR_ROW(8, "FALSE: no error; TRUE: an error occurred during the execution of the FB"),
    STATUS_ROW(9, "WORD: 0 = 16#0000 no error; 33280 = 16#8200 windowSize outside 1 to 100"),
};

BLOCK_FUNCTIONS(lgf_floating_average)

/* What every call leaves behind (docs/behaviour.md §15.2), so that a restored state is one a
 * run can produce: statCount fits the window size of the last call, windowSizeReached says the
 * window slides, and a window without a value holds no sum. (The slots beyond statCount keep
 * what an earlier window left: a restart does not clear them, and no call reads them.) It reads
 * statics alone, which no set changes: a state check (model.state_check), not run by every set. */
static const char *state_check(const void *data, char *msg, size_t size)
{
    const block *b = data;
    iec_int old = b->statWindowSizeOld, count = b->statCount;
    bool valid = lgf_floating_average_size_is_valid(old);
    if (valid ? count < 0 || count > 2 * old : count != 0) {
        snprintf(msg, size, "statCount %d does not fit a window of statWindowSizeOld %d", count,
                 old);
        return msg;
    }
    if (b->statWindowSizeReached != (valid && count > old)) {
        snprintf(msg, size, "statWindowSizeReached %d does not fit statCount %d in a window of %d",
                 b->statWindowSizeReached, count, old);
        return msg;
    }
    if (count == 0 && (b->statSum != 0.0 || b->statAverage != 0.0)) {
        snprintf(msg, size, "statSum and statAverage are not 0.0 with no value read in");
        return msg;
    }
    return NULL;
}

BLOCK_STATUS(STATUS_TEXT(LGF_FLOATING_AVERAGE_ERR_WRONG_WINDOW_SIZE,
                         "wrong window size: windowSize must be 1 to 100; nothing is read in"))

static const model_static statics[] = {
    STATIC(block, statValues[0], FIELD_REAL),
    STATIC(block, statValues[1], FIELD_REAL),
    STATIC(block, statValues[2], FIELD_REAL),
    STATIC(block, statValues[3], FIELD_REAL),
    STATIC(block, statValues[4], FIELD_REAL),
    STATIC(block, statValues[5], FIELD_REAL),
    STATIC(block, statValues[6], FIELD_REAL),
    STATIC(block, statValues[7], FIELD_REAL),
    STATIC(block, statValues[8], FIELD_REAL),
    STATIC(block, statValues[9], FIELD_REAL),
    STATIC(block, statValues[10], FIELD_REAL),
    STATIC(block, statValues[11], FIELD_REAL),
    STATIC(block, statValues[12], FIELD_REAL),
    STATIC(block, statValues[13], FIELD_REAL),
    STATIC(block, statValues[14], FIELD_REAL),
    STATIC(block, statValues[15], FIELD_REAL),
    STATIC(block, statValues[16], FIELD_REAL),
    STATIC(block, statValues[17], FIELD_REAL),
    STATIC(block, statValues[18], FIELD_REAL),
    STATIC(block, statValues[19], FIELD_REAL),
    STATIC(block, statValues[20], FIELD_REAL),
    STATIC(block, statValues[21], FIELD_REAL),
    STATIC(block, statValues[22], FIELD_REAL),
    STATIC(block, statValues[23], FIELD_REAL),
    STATIC(block, statValues[24], FIELD_REAL),
    STATIC(block, statValues[25], FIELD_REAL),
    STATIC(block, statValues[26], FIELD_REAL),
    STATIC(block, statValues[27], FIELD_REAL),
    STATIC(block, statValues[28], FIELD_REAL),
    STATIC(block, statValues[29], FIELD_REAL),
    STATIC(block, statValues[30], FIELD_REAL),
    STATIC(block, statValues[31], FIELD_REAL),
    STATIC(block, statValues[32], FIELD_REAL),
    STATIC(block, statValues[33], FIELD_REAL),
    STATIC(block, statValues[34], FIELD_REAL),
    STATIC(block, statValues[35], FIELD_REAL),
    STATIC(block, statValues[36], FIELD_REAL),
    STATIC(block, statValues[37], FIELD_REAL),
    STATIC(block, statValues[38], FIELD_REAL),
    STATIC(block, statValues[39], FIELD_REAL),
    STATIC(block, statValues[40], FIELD_REAL),
    STATIC(block, statValues[41], FIELD_REAL),
    STATIC(block, statValues[42], FIELD_REAL),
    STATIC(block, statValues[43], FIELD_REAL),
    STATIC(block, statValues[44], FIELD_REAL),
    STATIC(block, statValues[45], FIELD_REAL),
    STATIC(block, statValues[46], FIELD_REAL),
    STATIC(block, statValues[47], FIELD_REAL),
    STATIC(block, statValues[48], FIELD_REAL),
    STATIC(block, statValues[49], FIELD_REAL),
    STATIC(block, statValues[50], FIELD_REAL),
    STATIC(block, statValues[51], FIELD_REAL),
    STATIC(block, statValues[52], FIELD_REAL),
    STATIC(block, statValues[53], FIELD_REAL),
    STATIC(block, statValues[54], FIELD_REAL),
    STATIC(block, statValues[55], FIELD_REAL),
    STATIC(block, statValues[56], FIELD_REAL),
    STATIC(block, statValues[57], FIELD_REAL),
    STATIC(block, statValues[58], FIELD_REAL),
    STATIC(block, statValues[59], FIELD_REAL),
    STATIC(block, statValues[60], FIELD_REAL),
    STATIC(block, statValues[61], FIELD_REAL),
    STATIC(block, statValues[62], FIELD_REAL),
    STATIC(block, statValues[63], FIELD_REAL),
    STATIC(block, statValues[64], FIELD_REAL),
    STATIC(block, statValues[65], FIELD_REAL),
    STATIC(block, statValues[66], FIELD_REAL),
    STATIC(block, statValues[67], FIELD_REAL),
    STATIC(block, statValues[68], FIELD_REAL),
    STATIC(block, statValues[69], FIELD_REAL),
    STATIC(block, statValues[70], FIELD_REAL),
    STATIC(block, statValues[71], FIELD_REAL),
    STATIC(block, statValues[72], FIELD_REAL),
    STATIC(block, statValues[73], FIELD_REAL),
    STATIC(block, statValues[74], FIELD_REAL),
    STATIC(block, statValues[75], FIELD_REAL),
    STATIC(block, statValues[76], FIELD_REAL),
    STATIC(block, statValues[77], FIELD_REAL),
    STATIC(block, statValues[78], FIELD_REAL),
    STATIC(block, statValues[79], FIELD_REAL),
    STATIC(block, statValues[80], FIELD_REAL),
    STATIC(block, statValues[81], FIELD_REAL),
    STATIC(block, statValues[82], FIELD_REAL),
    STATIC(block, statValues[83], FIELD_REAL),
    STATIC(block, statValues[84], FIELD_REAL),
    STATIC(block, statValues[85], FIELD_REAL),
    STATIC(block, statValues[86], FIELD_REAL),
    STATIC(block, statValues[87], FIELD_REAL),
    STATIC(block, statValues[88], FIELD_REAL),
    STATIC(block, statValues[89], FIELD_REAL),
    STATIC(block, statValues[90], FIELD_REAL),
    STATIC(block, statValues[91], FIELD_REAL),
    STATIC(block, statValues[92], FIELD_REAL),
    STATIC(block, statValues[93], FIELD_REAL),
    STATIC(block, statValues[94], FIELD_REAL),
    STATIC(block, statValues[95], FIELD_REAL),
    STATIC(block, statValues[96], FIELD_REAL),
    STATIC(block, statValues[97], FIELD_REAL),
    STATIC(block, statValues[98], FIELD_REAL),
    STATIC(block, statValues[99], FIELD_REAL),
    /* NaN after Inf - Inf (docs/behaviour.md §15.3) */
    STATIC(block, statSum, FIELD_RESULT),
    STATIC(block, statAverage, FIELD_RESULT),
    STATIC(block, statCount, FIELD_INT16),
    STATIC(block, statWindowSizeOld, FIELD_INT16),
    STATIC(block, statWindowSizeReached, FIELD_BOOL),
    STATIC(block, statTriggerOld, FIELD_BOOL),
};

BLOCK_MODEL("LGF_FloatingAverage", "{2cb5fdc3-8036-4b49-a4c8-4b5f6e3704cf}", 2,
            "Siemens LGF_FloatingAverage (LGF V5.1, block V3.0.2): the moving arithmetic "
            "mean of the last windowSize LREAL values, read in every call or at each "
            "rising edge of trigger, as the original's code computes it. One PLC call "
            "every cycleTime. Start values: value 1.0 read in every call into a window "
            "of 10.",
            BLOCK_STATICS, NO_CYCLE_CODES, .state_check = state_check, BLOCK_STATUS_FIELDS);
