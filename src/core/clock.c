/* The PLC call clock (docs/behaviour.md §1.2, §1.3, §1.11): call k happens at t0 + k·cycleTime,
 * from an integer call counter; a co-simulation step executes every call in (t, t + h], a Model
 * Exchange time event the call due at its time. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "core/core.h"

static double core_cycle_seconds(const fmu_image *image) { return image->cycle_us / 1e6; }

/* How far a time may lie from a point of the call grid and still count as on it: 1e-4 of a
 * cycle, widened by a few ulps of the times involved. A master computes t + h in floating
 * point (0.1 arrives as 0.10000000000000003), and one that adds up its steps drifts: after
 * 10^6 steps of 1 ms, 10 ms or 100 ms the sum lies up to 1.7e-5 cycles off the grid. At large
 * t one ulp exceeds 1e-4 of a short cycle, hence the ulp term. */
static double core_grid_tolerance(const fmu_image *image, double t)
{
    return 1e-4 * core_cycle_seconds(image) +
           8 * DBL_EPSILON * fmax(fabs(image->start_time), fabs(t));
}

/* Far from 0, doubles cannot tell the call times of a short cycle apart (one ulp of 1e9 s is
 * 1.2e-7 s). Where the tolerance reaches a quarter cycle the grid is refused, instead of calls
 * being merged or skipped. */
static bool core_grid_resolvable(const instance *inst, const char *function, double t)
{
    const fmu_image *image = inst->image;
    if (core_grid_tolerance(image, t) < 0.25 * core_cycle_seconds(image)) return true;
    core_log(inst, STATUS_ERROR,
             "%s: at t = %g s double precision cannot resolve the call grid of cycleTime %g s; "
             "use a start time closer to 0 or a longer cycleTime.",
             function, t, core_cycle_seconds(image));
    return false;
}

/* A call the block failed (model.fault): logged, and the instance in the error state. */
static lgf_status core_call_failed(instance *inst, const plc_call *call, const char *why)
{
    core_log(inst, STATUS_ERROR, "%s: the PLC call at t = %.9g s failed: %s", lgf_model.identifier,
             inst->image->start_time + (double)call->now_us / 1e6, why);
    inst->image->mode = MODE_ERROR;
    return STATUS_ERROR;
}

/* The PLC calls up to call index `last`, each at its time from the integer counter. The
 * block's status is logged when it changes to an error code (docs/behaviour.md §1.6). A call
 * that fails ends them with STATUS_ERROR. */
static lgf_status core_run_calls(instance *inst, int64_t last)
{
    fmu_image *image = inst->image;
    plc_call call = {.cycle_us = image->cycle_us};
    iec_word status = lgf_model.status ? lgf_model.status(image->data) : 0;
    for (; image->calls <= last; image->calls++) {
        call.now_us = image->calls * image->cycle_us;
        lgf_model.call(image->data, &call);
        if (lgf_model.fault) { /* a constant: no test for the blocks whose calls cannot fail */
            char msg[256];
            const char *why = lgf_model.fault(image->data, msg, sizeof msg);
            if (why) {
                image->calls++;
                return core_call_failed(inst, &call, why);
            }
        }
        if (!lgf_model.status || lgf_model.status(image->data) == status) continue;
        status = lgf_model.status(image->data);
        const char *meaning = lgf_model.status_text(status);
        if (meaning)
            core_log(inst, STATUS_WARNING, "%s: status 16#%04X at t = %.9g s: %s",
                     lgf_model.identifier, (unsigned)status,
                     image->start_time + (double)call.now_us / 1e6, meaning);
    }
    return STATUS_OK;
}

static const fmu_image *core_preview_first_call(instance *inst)
{
    memcpy(inst->scratch, inst->image, inst->image_size);
    plc_call call = {.now_us = 0, .cycle_us = inst->image->cycle_us};
    lgf_model.call(inst->scratch->data, &call);
    return inst->scratch;
}

static lgf_status core_setup(instance *inst, const char *function, double start_time,
                             bool stop_defined, double stop_time)
{
    if (!isfinite(start_time)) {
        core_log(inst, STATUS_ERROR, "%s: startTime must be finite (got %g).", function,
                 start_time);
        return STATUS_ERROR;
    }
    if (stop_defined && !(stop_time >= start_time && isfinite(stop_time))) {
        core_log(inst, STATUS_ERROR,
                 "%s: stopTime (%g) must be finite and not before startTime (%g).", function,
                 stop_time, start_time);
        return STATUS_ERROR;
    }
    fmu_image *image = inst->image;
    image->start_time = start_time;
    image->time = start_time;
    image->stop_defined = stop_defined;
    image->stop_time = stop_defined ? stop_time : 0.0;
    return STATUS_OK;
}

static lgf_status core_first_call(instance *inst, const char *function)
{
    fmu_image *image = inst->image;
    if (!core_grid_resolvable(inst, function, image->start_time)) return STATUS_ERROR;
    image->time = image->start_time;
    /* with the inputs set during initialization */
    if (core_run_calls(inst, 0) != STATUS_OK) return STATUS_ERROR;
    if (core_trace_on(inst))
        core_log(inst, STATUS_OK, "%s: call 0 at t = %.17g s.", function, image->start_time);
    return STATUS_OK;
}

/* Calls k are executed while t0 + k·cycle <= t + h (within the grid tolerance). The bound
 * keeps k exactly representable and the loop finite whatever h a caller passes, and k·cycle
 * in µs below 2^62, so that plc_call.now_us and a block's now_us + TIME cannot overflow. */
#define CORE_MAX_CALL_INDEX 9.0e15

static double core_call_index_limit(const fmu_image *image)
{
    return fmin(CORE_MAX_CALL_INDEX, floor(4611686018427387904.0 /* 2^62 */ / image->cycle_us));
}

/* How many calls a Model Exchange state may lag behind its time (see core_clock_is_valid): about
 * 10 ms of catching up. */
#define CORE_MAX_PENDING_CALLS 1e6

/* The index of the last call at or before t (within the grid tolerance). */
static double core_last_call_until(const fmu_image *image, double t)
{
    return floor((t - image->start_time + core_grid_tolerance(image, t)) /
                 core_cycle_seconds(image));
}

static bool core_clock_is_valid(const fmu_image *image)
{
    if (image->mode < MODE_INSTANTIATED || image->mode > MODE_TERMINATED || image->cycle_us < 1 ||
        !isfinite(image->start_time) || !isfinite(image->time) ||
        !iec_bool_is_valid(&image->stop_defined))
        return false;
    if (image->stop_defined &&
        !(isfinite(image->stop_time) && image->stop_time >= image->start_time))
        return false;
    /* Co-simulation steps end at the stop time; Model Exchange time may look beyond it. */
    if (image->stop_defined && image->mode == MODE_STEP &&
        image->time > image->stop_time + core_grid_tolerance(image, image->stop_time))
        return false;
    if (!image->stop_defined && image->stop_time != 0.0) return false;
    if (image->mode == MODE_INSTANTIATED || image->mode == MODE_INITIALIZATION)
        return image->calls == 0 && image->time == image->start_time; /* no call yet */
    if (!(image->calls >= 1 && (double)image->calls <= core_call_index_limit(image))) return false;
    /* Calls 0 ... calls-1 are those up to the communication point (right after the first
     * call, the one call at t0). A counter behind its time would make the next step catch up,
     * up to ~1e15 calls; one far ahead would freeze the block. It may be one ahead: a step from
     * a communication point up to the grid tolerance before the FMU's time can end before the
     * call that was already executed. In Model Exchange the time may run ahead of the calls:
     * the call at it may still be due (the time is set, the event not yet handled), an
     * integrator may step past the next call time before it goes back to it, and an importer
     * may integrate past call times and terminate; up to CORE_MAX_PENDING_CALLS, which also
     * bounds what the event update (fmi2NewDiscreteStates, fmi3UpdateDiscreteStates) catches up
     * after a restore. */
    if (image->calls == 1 && image->time == image->start_time) return true;
    double last = core_last_call_until(image, image->time), done = (double)(image->calls - 1);
    bool exchange = image->mode == MODE_EVENT || image->mode == MODE_CONTINUOUS ||
                    image->mode == MODE_TERMINATED;
    return done >= last - (exchange ? CORE_MAX_PENDING_CALLS : 0) && done <= last + 1;
}

static lgf_status core_do_step(instance *inst, const char *function, double t, double h)
{
    fmu_image *image = inst->image;
    if (!(h > 0) || !isfinite(h)) {
        core_log(inst, STATUS_ERROR,
                 "%s: communicationStepSize must be a finite number > 0 (got %g).", function, h);
        return STATUS_ERROR;
    }
    if (!isfinite(t) || !(fabs(t - image->time) <= core_grid_tolerance(image, t))) {
        core_log(inst, STATUS_ERROR,
                 "%s: currentCommunicationPoint %.17g does not match the FMU's time %.17g.",
                 function, t, image->time);
        return STATUS_ERROR;
    }
    double end = t + h;
    if (image->stop_defined &&
        end > image->stop_time + core_grid_tolerance(image, image->stop_time)) {
        core_log(inst, STATUS_ERROR,
                 "%s: the step from %.17g s by %.17g s ends after the stopTime %.17g s of the "
                 "experiment.",
                 function, t, h, image->stop_time);
        return STATUS_ERROR;
    }
    double last = core_last_call_until(image, end);
    if (!(last < core_call_index_limit(image))) {
        core_log(inst, STATUS_ERROR,
                 "%s: communicationStepSize %g reaches beyond the last call this FMU can count "
                 "(%g calls of cycleTime).",
                 function, h, core_call_index_limit(image));
        return STATUS_ERROR;
    }
    if (!core_grid_resolvable(inst, function, end)) return STATUS_ERROR;
    int64_t first = image->calls;
    /* exact: last < call_index_limit <= 9e15 */
    if (core_run_calls(inst, (int64_t)last) != STATUS_OK) return STATUS_ERROR;
    /* A step from a point up to the tolerance before the FMU's time may end before it: the
     * FMU's time never goes back, so tiny steps cannot walk it backwards. */
    image->time = fmax(image->time, end);
    if (core_trace_on(inst)) {
        if (image->calls > first)
            core_log(inst, STATUS_OK, "%s: (%.17g s, %.17g s]: calls %lld to %lld.", function, t,
                     end, (long long)first, (long long)image->calls - 1);
        else
            core_log(inst, STATUS_OK, "%s: (%.17g s, %.17g s]: no call is due.", function, t, end);
    }
    return STATUS_OK;
}

/* An integrator may step past the next call time and go back to it (FMPy's CVODE does), so the
 * time may go back, but not before the last call executed: that call is history. The stop time
 * binds co-simulation steps; an integrator may look beyond it. */
static lgf_status core_set_time(instance *inst, const char *function, double t)
{
    fmu_image *image = inst->image;
    double last_call = image->start_time + (double)((image->calls - 1) * image->cycle_us) / 1e6;
    if (!isfinite(t) || t < last_call - core_grid_tolerance(image, t)) {
        core_log(inst, STATUS_ERROR,
                 "%s: time %.17g must be finite and not before the last PLC call, at %.17g s.",
                 function, t, last_call);
        return STATUS_ERROR;
    }
    double last_due =
        core_last_call_until(image, t); /* the index of the last call at or before t */
    if (!(last_due < core_call_index_limit(image))) {
        core_log(inst, STATUS_ERROR, "%s: time %.17g lies beyond the last call this FMU can count.",
                 function, t);
        return STATUS_ERROR;
    }
    /* The calls in between run at the next event: at most CORE_MAX_PENDING_CALLS of them, the
     * lag a state may have (core_clock_is_valid), so that no event catches up for hours. */
    if (last_due - (double)(image->calls - 1) > CORE_MAX_PENDING_CALLS) {
        core_log(inst, STATUS_ERROR,
                 "%s: time %.17g lies more than %.0f PLC calls past the last call, at %.17g s; "
                 "stop at the time events (the next call is at %.17g s).",
                 function, t, CORE_MAX_PENDING_CALLS, last_call, core_next_call_time(image));
        return STATUS_ERROR;
    }
    if (!core_grid_resolvable(inst, function, t)) return STATUS_ERROR;
    image->time = t;
    return STATUS_OK;
}

/* At a time event the importer has set the time of call k (within the grid tolerance): call k
 * runs once, with the inputs as they are now. Any other event iteration finds no call due. An
 * importer that passed a call time without stopping gets the calls it skipped. */
static lgf_status core_calls_due(instance *inst, const char *function)
{
    fmu_image *image = inst->image;
    int64_t first = image->calls;
    if (core_run_calls(inst, (int64_t)core_last_call_until(image, image->time)) != STATUS_OK)
        return STATUS_ERROR;
    if (core_trace_on(inst) && image->calls > first)
        core_log(inst, STATUS_OK, "%s: at t = %.17g s: calls %lld to %lld.", function, image->time,
                 (long long)first, (long long)image->calls - 1);
    return STATUS_OK;
}

/* t0 + k·cycle for the next call k, from the integer counter: no drift. */
static double core_next_call_time(const fmu_image *image)
{
    return image->start_time + (double)(image->calls * image->cycle_us) / 1e6;
}
