/* The call of the blocks that keep the last n values read in at a rising edge of insert while
 * enabled, LGF_SimpleSmoothingFB (n = 3) and LGF_DifferenceQuotientFB (n = 5): their originals
 * share it but for what they compute from a full buffer (docs/behaviour.md §16.2, §17.2). The
 * status codes are theirs alike; lgf_history_check checks what it leaves. */
#ifndef LGF_IEC_HISTORY_H
#define LGF_IEC_HISTORY_H

#include <stdio.h>
#include <string.h>

#include "iec/iec.h"

#define LGF_HISTORY_STATUS_NO_CALL 0x7000           /* disabled */
#define LGF_HISTORY_STATUS_FIRST_CALL 0x7001        /* the rising edge of enable */
#define LGF_HISTORY_STATUS_SUBSEQUENT_CALL 0x7002   /* a result from a full buffer */
#define LGF_HISTORY_STATUS_NOT_ENOUGH_VALUES 0x7010 /* fewer than n read in */

/* The original's order: both edge memories in every call, then one of three branches on enable.
 * A rising edge of enable starts again with an empty buffer and does nothing else (an edge of
 * insert in the same call is not read in; the output is left alone, already 0.0 as the call
 * before was disabled or this is the first call). Enabled, a rising edge of insert shifts value
 * in; the first n only count (*count 0 -> n), from the next on the buffer is full: true, and the
 * block computes its *output from values[0 .. n-1] (the newest last) and sets *status.
 * Disabled, *output is 0.0 and the buffer stays until the next rising edge of enable. */
static bool lgf_history_call(double values[], int n, iec_int *count, iec_word *status,
                             bool *enable_old, bool *insert_old, bool enable, bool insert,
                             double value, double *output)
{
    bool enable_edge = iec_rising_edge(enable_old, enable);
    bool insert_edge = iec_rising_edge(insert_old, insert);
    if (enable_edge) {
        memset(values, 0, (size_t)n * sizeof values[0]);
        *count = 0;
        *status = LGF_HISTORY_STATUS_FIRST_CALL;
        return false;
    }
    if (!enable) {
        *output = 0.0;
        *status = LGF_HISTORY_STATUS_NO_CALL;
        return false;
    }
    if (!insert_edge) return false;
    for (int i = 0; i < n - 1; i++) values[i] = values[i + 1];
    values[n - 1] = value;
    if (*count < n) {
        *count = (iec_int)(*count + 1);
        *status = LGF_HISTORY_STATUS_NOT_ENOUGH_VALUES;
        return false;
    }
    return true;
}

/* The outputs of every call: status the kept status, error its bit 15 (an error code 16#8xxx). */
static inline void lgf_history_outputs(iec_word kept, iec_word *status, bool *error)
{
    *status = kept;
    *error = (kept & 0x8000u) != 0;
}

/* The check (model.check) of these blocks, their values in statValues[0 .. n-1] counted in
 * statCount, the slots not read in yet holding 0.0 (docs/behaviour.md §16.2, §17.2): what every
 * call leaves behind, so that a restored state is one a run can produce. Their statStatus is
 * 16#7000 (enable FALSE: 0 to n values kept), 16#7001 (enabled, none read in), 16#7010 (1 to n
 * read in), 16#7002 (a result output: n), or the block's error code error (n; 0: none). */
static inline const char *lgf_history_check(iec_word status, iec_int count, iec_word error,
                                            const double values[], int n, char *msg, size_t size)
{
    bool fits = status == 0x7000                                      ? count >= 0 && count <= n
                : status == 0x7001                                    ? count == 0
                : status == 0x7010                                    ? count >= 1 && count <= n
                : status == 0x7002 || (error != 0 && status == error) ? count == n
                                                                      : false;
    if (!fits) {
        snprintf(msg, size, "statStatus 16#%04X and statCount %d are no state of the block",
                 (unsigned)status, count);
        return msg;
    }
    for (int i = 0; i < n - count; i++) {
        if (values[i] != 0.0) {
            snprintf(msg, size, "statValues[%d] holds a value with only %d read in", i, count);
            return msg;
        }
    }
    return NULL;
}

#endif
