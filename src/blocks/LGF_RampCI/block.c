#include "blocks/LGF_RampCI/block.h"

#include <stdio.h>
#include <string.h>

static void lgf_ramp_ci_init(lgf_ramp_ci *block)
{
    /* Inputs, outputs and statics start at 0 / 0.0 / FALSE, the LGF defaults; the edge memories
     * FALSE, so an input that is TRUE in the first call is a rising edge (docs/behaviour.md §4.3). */
    memset(block, 0, sizeof *block);
    /* A table a user sees working at once (docs/behaviour.md §4.1): 0 -> 100 in 5 s, hold 100 for 10 s,
     * -> 0 in 5 s. Entries 4 ... 63 stay (0.0, 0 s). */
    block->numberOfSetpoints = 4;
    block->setpoints[0] = (lgf_ramp_ci_setpoint){0.0, 5000};
    block->setpoints[1] = (lgf_ramp_ci_setpoint){100.0, 10000};
    block->setpoints[2] = (lgf_ramp_ci_setpoint){100.0, 5000};
    block->setpoints[3] = (lgf_ramp_ci_setpoint){0.0, 0};
    /* start TRUE (LGF: FALSE), so that the table runs as soon as the FMU is dropped into a model:
     * the first call sees a rising edge, since the edge memory starts FALSE (docs/behaviour.md §4.1). */
    block->start = true;
}

/* The index of the last point of the table. numberOfSetpoints is checked to 2 ... 64 whenever
 * it is set or a state is restored; the clamps here only keep a call from indexing outside the
 * table whatever the data holds (the original would stop the PLC, docs/behaviour.md §4.6). */
static int last_index(const lgf_ramp_ci *block)
{
    int n = block->numberOfSetpoints;
    if (n < 1) n = 1;
    if (n > LGF_RAMP_CI_MAX_SETPOINTS) n = LGF_RAMP_CI_MAX_SETPOINTS;
    return n - 1;
}

static int in_table(const lgf_ramp_ci *block, int index)
{
    int last = last_index(block);
    return index < 0 ? 0 : index > last ? last : index;
}

/* Sum of the times of entries first ... last, in 64 bits: 64 TIMEs cannot overflow it; the
 * caller saturates the result to a TIME (docs/behaviour.md §4.3). */
static int64_t sum_times(const lgf_ramp_ci *block, int first)
{
    int64_t sum = 0;
    for (int i = in_table(block, first); i <= last_index(block); i++)
        sum += block->setpoints[i].time;
    return sum;
}

static void lgf_ramp_ci_call(lgf_ramp_ci *block, const plc_call *call)
{
    /* The original divides the µs of QRY_CINT by 1000 in integers (docs/behaviour.md §4.2, §4.3). */
    const iec_time ts = (iec_time)(call->cycle_us / 1000);
    const int last = last_index(block);
    const lgf_ramp_ci_setpoint *points = block->setpoints;
    iec_word status = LGF_RAMP_CI_STATUS_RUNNING;
    double out = 0.0;

    /* 1. Rising edge of start: a new run from point 0. */
    if (iec_rising_edge(&block->statStartOld, block->start)) {
        status = LGF_RAMP_CI_STATUS_START;
        block->statInitRun = true;
        block->totalTime = iec_time_saturate(sum_times(block, 0));
        block->remainTotalTime = block->totalTime;
        block->statBlocked = false;
    }

    /* 2. Rising edge of reset: back to 0.0 and blocked until the next rising edge of start. */
    if (iec_rising_edge(&block->statResetOld, block->reset)) {
        status = LGF_RAMP_CI_STATUS_IDLE_OR_END;
        block->totalTime = iec_time_saturate(sum_times(block, 0));
        out = 0.0;
        block->remainTotalTime = block->totalTime;
        block->statTargetValue = 0.0;
        block->stepNumber = 0;
        block->remainTime = 0;
        block->statInitRun = true;
        block->actTimeTable = false;
        block->statBlocked = true;
    }

    /* 3. Operation. */
    if (block->start && !block->statBlocked) {
        if (block->statInitRun) {
            /* a) Initialise the run: sit on point 0, head for point 1. */
            block->statInitRun = false;
            out = points[0].outputValue;
            block->statTargetValue = points[in_table(block, 1)].outputValue;
            block->remainTime = points[0].time;
            block->remainTotalTime = block->totalTime;
            block->stepNumber = 1;
            block->actTimeTable = true;
        } else if (block->hold) {
            /* b) Hold: output and times frozen; with continue, aim at point contStepNbr. */
            block->actTimeTable = false;
            out = block->statPrevOutValue;
            if (block->continue_) {
                int next = in_table(block, block->contStepNbr);
                block->statTargetValue = points[next].outputValue;
                block->remainTime = block->contStepTime;
                block->stepNumber = (iec_int)next;
                block->remainTotalTime =
                    iec_time_saturate((int64_t)block->contStepTime + sum_times(block, next));
            }
        } else if (block->remainTime > ts) {
            /* c) Interpolate towards the target over the remaining time, in this order; the
             * original converts the rest time and the cycle (ms) to REAL before the LREAL
             * arithmetic, which rounds a rest time above 2^24 ms (docs/behaviour.md §4.3). */
            out = block->statPrevOutValue + (block->statTargetValue - block->statPrevOutValue) /
                                                (double)iec_dint_to_real(block->remainTime) *
                                                (double)iec_dint_to_real(ts);
            block->remainTime -= ts;
            block->remainTotalTime = iec_time_saturate((int64_t)block->remainTotalTime - ts);
        } else if (in_table(block, block->stepNumber) < last) {
            /* d) Point stepNumber reached: snap onto it and head for the next one. */
            int reached = in_table(block, block->stepNumber);
            out = points[reached].outputValue;
            block->statTargetValue = points[reached + 1].outputValue;
            block->remainTime = points[reached].time;
            block->stepNumber = (iec_int)(reached + 1);
            block->actTimeTable = true;
            block->remainTotalTime = iec_time_saturate((int64_t)block->remainTotalTime - ts);
        } else {
            /* e) Last point reached: stay on it, or start again at point 0 in the next call
             * (no interpolation from the last point to the first). */
            status = LGF_RAMP_CI_STATUS_IDLE_OR_END;
            block->remainTotalTime = 0;
            block->remainTime = 0; /* as in the worked example of docs/behaviour.md §4.5 */
            out = points[last].outputValue;
            if (block->cyclicOP) {
                block->statInitRun = true;
                status = LGF_RAMP_CI_STATUS_CYCLIC;
            } else {
                block->actTimeTable = false;
            }
        }
    } else {
        out = 0.0;
        block->actTimeTable = false;
    }

    /* 4. Rising edge of updateTime: the times again from the (possibly changed) table. */
    if (iec_rising_edge(&block->statUpdateTimeOld, block->updateTime)) {
        block->totalTime = iec_time_saturate(sum_times(block, 0));
        block->remainTotalTime =
            iec_time_saturate((int64_t)block->remainTime + sum_times(block, block->stepNumber));
    }

    /* 5. Pre-assignment: the time processing above goes on underneath, and the ramp later runs
     * on from defaultOutValue because it becomes the previous output. */
    if (block->enDefaultOutValue) {
        out = block->defaultOutValue;
        block->actTimeTable = false;
    }

    /* 6. Outputs. QRY_CINT cannot fail in an FMU and invalid tables are refused when they are
     * set (docs/behaviour.md §1.6, §4.6), so error and subFunctionStatus stay clear. */
    block->outputValue = out;
    block->statPrevOutValue = out;
    block->error = false;
    block->status = status;
    block->subFunctionStatus = 0;
}

/* NULL when the block's data can be run; else one sentence naming the variable and the allowed
 * values, written into msg. */
static const char *lgf_ramp_ci_check(const lgf_ramp_ci *block, char *msg, size_t size)
{
    int n = block->numberOfSetpoints;
    if (n < 2 || n > LGF_RAMP_CI_MAX_SETPOINTS) {
        snprintf(msg, size, "numberOfSetpoints = %d is outside the allowed range (2 to %d)", n,
                 LGF_RAMP_CI_MAX_SETPOINTS);
        return msg;
    }
    if (block->contStepNbr < 0 || block->contStepNbr >= n) {
        snprintf(msg, size,
                 "contStepNbr = %d is outside the allowed range (0 to numberOfSetpoints - 1 = %d)",
                 (int)block->contStepNbr, n - 1);
        return msg;
    }
    if (block->stepNumber < 0 || block->stepNumber >= n) {
        snprintf(msg, size,
                 "stepNumber = %d is outside the allowed range (0 to numberOfSetpoints - 1 = %d)",
                 (int)block->stepNumber, n - 1);
        return msg;
    }
    return NULL;
}
