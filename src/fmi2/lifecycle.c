/* FMI 2.0 co-simulation: instantiation, the mode machine, the PLC call clock and the
 * functions this FMU does not support. Variables live in variables.c, FMU states in
 * fmu_state.c. */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "fmi2/instance.h"

#define DEFAULT_CYCLE_US 100000 /* 100 ms, a default OB35 (docs/behaviour.md §1.1) */

static const char *const mode_names[] = {"instantiated", "initialization mode", "step mode",
                                         "terminated"};

/* ---- which function may be called in which mode: the one table (FMI 2.0, 4.2.4) ---- */

#define IN(mode) (1u << (mode))
#define SETTABLE (IN(MODE_INSTANTIATED) | IN(MODE_INITIALIZATION) | IN(MODE_STEP))
#define READABLE (IN(MODE_INITIALIZATION) | IN(MODE_STEP) | IN(MODE_TERMINATED))
#define ANY_MODE (IN(MODE_INSTANTIATED) | READABLE)

typedef enum {
    F_SETUP_EXPERIMENT, F_ENTER_INITIALIZATION, F_EXIT_INITIALIZATION, F_DO_STEP, F_TERMINATE,
    F_SET_REAL, F_SET_INTEGER, F_SET_BOOLEAN, F_SET_STRING,
    F_GET_REAL, F_GET_INTEGER, F_GET_BOOLEAN, F_GET_STRING,
    F_GET_STATUS, F_GET_REAL_STATUS, F_GET_INTEGER_STATUS, F_GET_BOOLEAN_STATUS,
    F_GET_STRING_STATUS,
    F_GET_FMU_STATE, F_SET_FMU_STATE, F_FREE_FMU_STATE, F_SERIALIZED_SIZE, F_SERIALIZE,
    F_DESERIALIZE
} fmi_function;

static const struct {
    const char *name;
    unsigned modes;
} rules[] = {
    [F_SETUP_EXPERIMENT] = {"fmi2SetupExperiment", IN(MODE_INSTANTIATED)},
    [F_ENTER_INITIALIZATION] = {"fmi2EnterInitializationMode", IN(MODE_INSTANTIATED)},
    [F_EXIT_INITIALIZATION] = {"fmi2ExitInitializationMode", IN(MODE_INITIALIZATION)},
    [F_DO_STEP] = {"fmi2DoStep", IN(MODE_STEP)},
    [F_TERMINATE] = {"fmi2Terminate", IN(MODE_STEP)},
    [F_SET_REAL] = {"fmi2SetReal", SETTABLE},
    [F_SET_INTEGER] = {"fmi2SetInteger", SETTABLE},
    [F_SET_BOOLEAN] = {"fmi2SetBoolean", SETTABLE},
    [F_SET_STRING] = {"fmi2SetString", SETTABLE},
    [F_GET_REAL] = {"fmi2GetReal", READABLE},
    [F_GET_INTEGER] = {"fmi2GetInteger", READABLE},
    [F_GET_BOOLEAN] = {"fmi2GetBoolean", READABLE},
    [F_GET_STRING] = {"fmi2GetString", READABLE},
    [F_GET_STATUS] = {"fmi2GetStatus", IN(MODE_STEP) | IN(MODE_TERMINATED)},
    [F_GET_REAL_STATUS] = {"fmi2GetRealStatus", IN(MODE_STEP) | IN(MODE_TERMINATED)},
    [F_GET_INTEGER_STATUS] = {"fmi2GetIntegerStatus", IN(MODE_STEP) | IN(MODE_TERMINATED)},
    [F_GET_BOOLEAN_STATUS] = {"fmi2GetBooleanStatus", IN(MODE_STEP) | IN(MODE_TERMINATED)},
    [F_GET_STRING_STATUS] = {"fmi2GetStringStatus", IN(MODE_STEP) | IN(MODE_TERMINATED)},
    [F_GET_FMU_STATE] = {"fmi2GetFMUstate", ANY_MODE},
    [F_SET_FMU_STATE] = {"fmi2SetFMUstate", ANY_MODE},
    [F_FREE_FMU_STATE] = {"fmi2FreeFMUstate", ANY_MODE},
    [F_SERIALIZED_SIZE] = {"fmi2SerializedFMUstateSize", ANY_MODE},
    [F_SERIALIZE] = {"fmi2SerializeFMUstate", ANY_MODE},
    [F_DESERIALIZE] = {"fmi2DeSerializeFMUstate", ANY_MODE},
};

/* fmi2Error plus a log line naming the function, unless the instance is in a mode the
 * function may be called in. */
static bool allowed(const instance *inst, fmi_function f)
{
    if (!inst) return false;
    if (rules[f].modes & IN(inst->image->mode)) return true;
    log_message(inst, fmi2Error, "%s must not be called in %s.", rules[f].name,
                mode_names[inst->image->mode]);
    return false;
}

/* ---- logging ---- */

static void log_message(const instance *inst, fmi2Status status, const char *fmt, ...)
{
    if (!inst->callbacks.logger) return;
    unsigned category = status == fmi2OK        ? LOG_ALL
                        : status == fmi2Warning ? LOG_STATUS_WARNING
                        : status == fmi2Discard ? LOG_STATUS_DISCARD
                                                : LOG_STATUS_ERROR;
    if (category == LOG_ALL && !(inst->categories & LOG_ALL)) return;
    char text[512], escaped[2 * sizeof text];
    va_list args;
    va_start(args, fmt);
    vsnprintf(text, sizeof text, fmt, args);
    va_end(args);
    size_t n = 0;
    for (const char *c = text; *c; c++) {
        if (*c == '#') escaped[n++] = '#';
        escaped[n++] = *c;
    }
    escaped[n] = '\0';
    const char *name = category == LOG_ALL              ? "logAll"
                       : category == LOG_STATUS_WARNING ? "logStatusWarning"
                       : category == LOG_STATUS_DISCARD ? "logStatusDiscard"
                                                        : "logStatusError";
    inst->callbacks.logger(inst->callbacks.componentEnvironment, inst->name, status, name, "%s",
                           escaped);
}

static void *allocate(const instance *inst, size_t size)
{
    return inst->callbacks.allocateMemory(1, size);
}

static void release(const instance *inst, void *memory)
{
    if (memory) inst->callbacks.freeMemory(memory);
}

static size_t image_size(void)
{
    return sizeof(fmu_image) + lgf_model.data_size;
}

static void image_reset(fmu_image *image)
{
    memset(image, 0, image_size());
    image->mode = MODE_INSTANTIATED;
    image->cycle_us = DEFAULT_CYCLE_US;
    lgf_model.init(image->data);
}

/* ---- common functions ---- */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

static unsigned category_bit(const char *category)
{
    static const char *const names[] = {"logAll", "logStatusWarning", "logStatusDiscard",
                                        "logStatusError"};
    for (unsigned i = 0; category && i < sizeof names / sizeof names[0]; i++)
        if (!strcmp(category, names[i])) return 1u << i;
    return 0;
}

/* FMI 2.0, 2.1.5: without categories, loggingOn switches every category; with categories,
 * loggingOn = true logs only those, false switches those off. Warnings, discards and errors
 * are logged whatever the switches say, as the standard allows: only the logAll trace is
 * optional. */
fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[])
{
    instance *inst = c;
    if (!inst) return fmi2Error;
    if (nCategories > 0 && !categories) {
        log_message(inst, fmi2Error,
                    "fmi2SetDebugLogging: categories is NULL but nCategories is %llu.",
                    (unsigned long long)nCategories);
        return fmi2Error;
    }
    unsigned listed = nCategories ? 0 : LOG_EVERY;
    for (size_t i = 0; i < nCategories; i++) {
        unsigned bit = category_bit(categories[i]);
        if (!bit) {
            log_message(inst, fmi2Error,
                        "fmi2SetDebugLogging: unknown log category \"%s\"; allowed are logAll, "
                        "logStatusWarning, logStatusDiscard and logStatusError.",
                        categories[i] ? categories[i] : "(null)");
            return fmi2Error;
        }
        listed |= bit;
    }
    if (loggingOn) inst->categories = listed;
    else inst->categories &= ~listed;
    return fmi2OK;
}

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions *functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn)
{
    (void)fmuResourceLocation;
    (void)visible;
    if (!functions || !functions->logger) return NULL; /* nowhere to say why */
    instance probe = {.callbacks = *functions, .name = (char *)(instanceName ? instanceName : "?")};
    const char *refusal = NULL;
    if (!functions->allocateMemory || !functions->freeMemory)
        refusal = "allocateMemory and freeMemory must not be NULL";
    else if (!instanceName || !*instanceName)
        refusal = "instanceName must be a non-empty string";
    else if (fmuType != fmi2CoSimulation)
        refusal = "this FMU supports co-simulation only, not Model Exchange";
    else if (!fmuGUID || strcmp(fmuGUID, lgf_model.guid))
        refusal = "fmuGUID does not match the guid of this FMU's modelDescription.xml";
    if (refusal) {
        log_message(&probe, fmi2Error, "fmi2Instantiate: %s (%s).", refusal, lgf_model.identifier);
        return NULL;
    }

    instance *inst = functions->allocateMemory(1, sizeof *inst);
    if (!inst) {
        log_message(&probe, fmi2Error, "fmi2Instantiate: out of memory.");
        return NULL;
    }
    inst->callbacks = *functions;
    inst->categories = loggingOn ? LOG_EVERY : 0;
    inst->image_size = image_size();
    inst->name = allocate(inst, strlen(instanceName) + 1);
    inst->image = allocate(inst, inst->image_size);
    inst->scratch = allocate(inst, inst->image_size);
    if (!inst->name || !inst->image || !inst->scratch || !index_variables(inst)) {
        log_message(&probe, fmi2Error, "fmi2Instantiate: out of memory.");
        release(inst, inst->name);
        release(inst, inst->image);
        release(inst, inst->scratch);
        release(inst, inst->vr_index);
        functions->freeMemory(inst);
        return NULL;
    }
    strcpy(inst->name, instanceName);
    image_reset(inst->image);
    return inst;
}

void fmi2FreeInstance(fmi2Component c)
{
    instance *inst = c;
    if (!inst) return;
    release(inst, inst->image);
    release(inst, inst->scratch);
    release(inst, inst->vr_index);
    release(inst, inst->name);
    inst->callbacks.freeMemory(inst);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    (void)toleranceDefined;
    (void)tolerance; /* the block is discrete: there is nothing to integrate */
    instance *inst = c;
    if (!allowed(inst, F_SETUP_EXPERIMENT)) return fmi2Error;
    if (!isfinite(startTime)) {
        log_message(inst, fmi2Error, "fmi2SetupExperiment: startTime must be finite (got %g).",
                    startTime);
        return fmi2Error;
    }
    if (stopTimeDefined && !(stopTime >= startTime && isfinite(stopTime))) {
        log_message(inst, fmi2Error,
                    "fmi2SetupExperiment: stopTime (%g) must be finite and not before startTime "
                    "(%g).",
                    stopTime, startTime);
        return fmi2Error;
    }
    fmu_image *image = inst->image;
    image->start_time = startTime;
    image->time = startTime;
    image->stop_defined = stopTimeDefined != fmi2False;
    image->stop_time = image->stop_defined ? stopTime : 0.0;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    instance *inst = c;
    if (!allowed(inst, F_ENTER_INITIALIZATION)) return fmi2Error;
    inst->image->mode = MODE_INITIALIZATION;
    return fmi2OK;
}

/* ---- the PLC call clock (docs/behaviour.md §1.2, §1.3) ---- */

static double cycle_seconds(const fmu_image *image) { return image->cycle_us / 1e6; }

/* How far a time may lie from a point of the call grid and still count as on it: 1e-4 of a
 * cycle, widened by a few ulps of the times involved. A master computes t + h in floating
 * point (0.1 arrives as 0.10000000000000003), and one that adds up its steps drifts: after
 * 10^6 steps of 1 ms, 10 ms or 100 ms the sum lies up to 1.7e-5 cycles off the grid. At large
 * t one ulp exceeds 1e-4 of a short cycle, hence the ulp term. */
static double grid_tolerance(const fmu_image *image, double t)
{
    return 1e-4 * cycle_seconds(image) +
           8 * DBL_EPSILON * fmax(fabs(image->start_time), fabs(t));
}

/* Far from 0, doubles cannot tell the call times of a short cycle apart (one ulp of 1e9 s is
 * 1.2e-7 s). Where the tolerance reaches a quarter cycle the grid is refused, instead of calls
 * being merged or skipped. */
static bool grid_resolvable(const instance *inst, const char *function, double t)
{
    const fmu_image *image = inst->image;
    if (grid_tolerance(image, t) < 0.25 * cycle_seconds(image)) return true;
    log_message(inst, fmi2Error,
                "%s: at t = %g s double precision cannot resolve the call grid of cycleTime %g s; "
                "use a start time closer to 0 or a longer cycleTime.",
                function, t, cycle_seconds(image));
    return false;
}

/* The PLC calls up to call index `last`, each at its time from the integer counter. The
 * block's status is logged when it changes to an error code (docs/behaviour.md §1.6). */
static void run_calls(instance *inst, int64_t last)
{
    fmu_image *image = inst->image;
    plc_call call = {.cycle_us = image->cycle_us, .cycle_s = cycle_seconds(image)};
    iec_word status = lgf_model.status ? lgf_model.status(image->data) : 0;
    for (; image->calls <= last; image->calls++) {
        call.now_us = image->calls * image->cycle_us;
        lgf_model.call(image->data, &call);
        if (!lgf_model.status || lgf_model.status(image->data) == status) continue;
        status = lgf_model.status(image->data);
        const char *meaning = lgf_model.status_text(status);
        if (meaning)
            log_message(inst, fmi2Warning, "%s: status 16#%04X at t = %.9g s: %s",
                        lgf_model.identifier, (unsigned)status,
                        image->start_time + (double)call.now_us / 1e6, meaning);
    }
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    instance *inst = c;
    if (!allowed(inst, F_EXIT_INITIALIZATION) ||
        !grid_resolvable(inst, "fmi2ExitInitializationMode", inst->image->start_time))
        return fmi2Error;
    fmu_image *image = inst->image;
    image->mode = MODE_STEP;
    image->time = image->start_time;
    run_calls(inst, 0); /* the first call happens at t0 with the inputs of initialization */
    if (trace_on(inst))
        log_message(inst, fmi2OK, "fmi2ExitInitializationMode: call 0 at t = %.17g s.",
                    image->start_time);
    return fmi2OK;
}

/* Calls k are executed while t0 + k·cycle <= t + h (within the grid tolerance). The bound
 * keeps k exactly representable and the loop finite whatever h a caller passes, and k·cycle
 * in µs below 2^62, so that plc_call.now_us and a block's now_us + TIME cannot overflow. */
#define MAX_CALL_INDEX 9.0e15

static double call_index_limit(const fmu_image *image)
{
    return fmin(MAX_CALL_INDEX, floor(4611686018427387904.0 /* 2^62 */ / image->cycle_us));
}

/* The index of the last call at or before t (within the grid tolerance). */
static double last_call_until(const fmu_image *image, double t)
{
    return floor((t - image->start_time + grid_tolerance(image, t)) / cycle_seconds(image));
}

static bool clock_is_valid(const fmu_image *image)
{
    if (image->mode < MODE_INSTANTIATED || image->mode > MODE_TERMINATED || image->cycle_us < 1 ||
        !isfinite(image->start_time) || !isfinite(image->time) ||
        !iec_bool_is_valid(&image->stop_defined))
        return false;
    if (image->stop_defined &&
        !(isfinite(image->stop_time) && image->stop_time >= image->start_time &&
          image->time <= image->stop_time + grid_tolerance(image, image->stop_time)))
        return false;
    if (!image->stop_defined && image->stop_time != 0.0) return false;
    if (image->mode == MODE_INSTANTIATED || image->mode == MODE_INITIALIZATION)
        return image->calls == 0 && image->time == image->start_time; /* no call yet */
    if (!(image->calls >= 1 && (double)image->calls <= call_index_limit(image))) return false;
    /* Calls 0 ... calls-1 are those up to the communication point (right after
     * fmi2ExitInitializationMode, the one call at t0). A counter behind its time would make the
     * next fmi2DoStep catch up, up to ~1e15 calls; one far ahead would freeze the block. It may
     * be one ahead: a doStep from a currentCommunicationPoint up to the grid tolerance before
     * the FMU's time can end before the call that was already executed. */
    if (image->calls == 1 && image->time == image->start_time) return true;
    double last = last_call_until(image, image->time);
    return (double)(image->calls - 1) >= last && (double)(image->calls - 1) <= last + 1;
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    instance *inst = c;
    if (!allowed(inst, F_DO_STEP)) return fmi2Error;
    fmu_image *image = inst->image;
    double t = currentCommunicationPoint, h = communicationStepSize;
    if (!(h > 0) || !isfinite(h)) {
        log_message(inst, fmi2Error,
                    "fmi2DoStep: communicationStepSize must be a finite number > 0 (got %g).", h);
        return fmi2Error;
    }
    if (!isfinite(t) || !(fabs(t - image->time) <= grid_tolerance(image, t))) {
        log_message(inst, fmi2Error,
                    "fmi2DoStep: currentCommunicationPoint %.17g does not match the FMU's time "
                    "%.17g.",
                    t, image->time);
        return fmi2Error;
    }
    double end = t + h;
    if (image->stop_defined && end > image->stop_time + grid_tolerance(image, image->stop_time)) {
        log_message(inst, fmi2Error,
                    "fmi2DoStep: the step from %.17g s by %.17g s ends after the stopTime "
                    "%.17g s of fmi2SetupExperiment.",
                    t, h, image->stop_time);
        return fmi2Error;
    }
    double last = last_call_until(image, end);
    if (!(last < call_index_limit(image))) {
        log_message(inst, fmi2Error,
                    "fmi2DoStep: communicationStepSize %g reaches beyond the last call this FMU "
                    "can count (%g calls of cycleTime).",
                    h, call_index_limit(image));
        return fmi2Error;
    }
    if (!grid_resolvable(inst, "fmi2DoStep", end)) return fmi2Error;
    int64_t first = image->calls;
    run_calls(inst, (int64_t)last); /* exact: last < call_index_limit <= 9e15 */
    image->time = end;
    if (trace_on(inst)) {
        if (image->calls > first)
            log_message(inst, fmi2OK, "fmi2DoStep: (%.17g s, %.17g s]: calls %lld to %lld.", t,
                        end, (long long)first, (long long)image->calls - 1);
        else
            log_message(inst, fmi2OK, "fmi2DoStep: (%.17g s, %.17g s]: no call is due.", t, end);
    }
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    instance *inst = c;
    if (!allowed(inst, F_TERMINATE)) return fmi2Error;
    inst->image->mode = MODE_TERMINATED;
    return fmi2OK;
}

fmi2Status fmi2Reset(fmi2Component c)
{
    instance *inst = c;
    if (!inst) return fmi2Error;
    image_reset(inst->image);
    return fmi2OK;
}

/* ---- what this FMU does not provide (see the capability flags in its XML) ---- */

static fmi2Status unsupported(fmi2Component c, const char *function, const char *why)
{
    if (c) log_message(c, fmi2Error, "%s is not supported: %s.", function, why);
    return fmi2Error;
}

fmi2Status fmi2CancelStep(fmi2Component c)
{
    return unsupported(c, "fmi2CancelStep", "fmi2DoStep always completes synchronously");
}

/* The status functions (FMI 2.0, 4.2.3): a status kind the FMU cannot provide is answered
 * with fmi2Discard; only a wrong mode or a NULL pointer is an error. This FMU provides
 * fmi2LastSuccessfulTime and fmi2Terminated; fmi2DoStep never returns fmi2Pending, so
 * fmi2DoStepStatus and fmi2PendingStatus have nothing to tell. */
#define NO_STATUS_KIND (-1)

static fmi2Status status_request(instance *inst, fmi_function f, fmi2StatusKind kind,
                                 const void *value, int provided)
{
    if (!allowed(inst, f)) return fmi2Error;
    if (!value) {
        log_message(inst, fmi2Error, "%s: value must not be NULL.", rules[f].name);
        return fmi2Error;
    }
    if (provided != NO_STATUS_KIND && (int)kind == provided) return fmi2OK;
    log_message(inst, fmi2Discard,
                "%s: status kind %d is not available (fmi2DoStep never returns fmi2Pending).",
                rules[f].name, (int)kind);
    return fmi2Discard;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value)
{
    return status_request(c, F_GET_STATUS, s, value, NO_STATUS_KIND);
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value)
{
    instance *inst = c;
    fmi2Status status = status_request(inst, F_GET_REAL_STATUS, s, value, fmi2LastSuccessfulTime);
    if (status == fmi2OK) *value = inst->image->time;
    return status;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value)
{
    return status_request(c, F_GET_INTEGER_STATUS, s, value, NO_STATUS_KIND);
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value)
{
    fmi2Status status = status_request(c, F_GET_BOOLEAN_STATUS, s, value, fmi2Terminated);
    if (status == fmi2OK) *value = fmi2False; /* the block never asks to end the simulation */
    return status;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value)
{
    return status_request(c, F_GET_STRING_STATUS, s, value, NO_STATUS_KIND);
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[])
{
    (void)vr, (void)nvr, (void)order, (void)value;
    return unsupported(c, "fmi2SetRealInputDerivatives",
                       "canInterpolateInputs is false; a PLC samples its inputs once per call");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[],
                                        size_t nvr, const fmi2Integer order[], fmi2Real value[])
{
    (void)vr, (void)nvr, (void)order, (void)value;
    return unsupported(c, "fmi2GetRealOutputDerivatives", "maxOutputDerivativeOrder is 0");
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown[],
                                        size_t nUnknown, const fmi2ValueReference vKnown[],
                                        size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[])
{
    (void)vUnknown, (void)nUnknown, (void)vKnown, (void)nKnown, (void)dvKnown, (void)dvUnknown;
    return unsupported(c, "fmi2GetDirectionalDerivative", "providesDirectionalDerivative is false");
}
