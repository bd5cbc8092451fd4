/* FMI 2.0 co-simulation: instantiation, the mode machine, the PLC call clock and the
 * functions this FMU does not support. Variables live in variables.c, FMU states in
 * fmu_state.c. */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "fmi2/instance.h"

#define DEFAULT_CYCLE_US 100000 /* 100 ms, a default OB35 (BLOCKS.md 1.1) */

static const char *const mode_names[] = {"instantiated", "initialization mode", "step mode",
                                         "terminated"};

void log_message(const instance *inst, fmi2Status status, const char *fmt, ...)
{
    if (!inst->callbacks.logger) return;
    char text[512];
    va_list args;
    va_start(args, fmt);
    vsnprintf(text, sizeof text, fmt, args);
    va_end(args);
    const char *category = status == fmi2OK       ? "logAll"
                           : status == fmi2Warning ? "logStatusWarning"
                                                   : "logStatusError";
    if (status == fmi2OK && !inst->debug_logging) return;
    inst->callbacks.logger(inst->callbacks.componentEnvironment, inst->name, status, category,
                           "%s", text);
}

bool mode_allows(const instance *inst, const char *function, unsigned mask)
{
    if (mask & IN(inst->image->mode)) return true;
    log_message(inst, fmi2Error, "%s must not be called in %s.", function,
                mode_names[inst->image->mode]);
    return false;
}

void *allocate(const instance *inst, size_t size)
{
    return inst->callbacks.allocateMemory(1, size);
}

void release(const instance *inst, void *memory)
{
    if (memory) inst->callbacks.freeMemory(memory);
}

size_t image_size(void)
{
    return sizeof(fmu_image) + lgf_model.data_size;
}

void image_reset(fmu_image *image)
{
    memset(image, 0, image_size());
    image->mode = MODE_INSTANTIATED;
    image->cycle_us = DEFAULT_CYCLE_US;
    lgf_model.init(image->data);
}

/* ---- common functions ---- */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[])
{
    instance *inst = c;
    if (!inst) return fmi2Error;
    if (nCategories > 0 && !categories) {
        log_message(inst, fmi2Error, "fmi2SetDebugLogging: categories is NULL but nCategories is %llu.",
                    (unsigned long long)nCategories);
        return fmi2Error;
    }
    for (size_t i = 0; i < nCategories; i++) {
        const char *category = categories[i];
        if (!category || (strcmp(category, "logAll") && strcmp(category, "logStatusWarning") &&
                          strcmp(category, "logStatusError"))) {
            log_message(inst, fmi2Error,
                        "fmi2SetDebugLogging: unknown log category \"%s\"; allowed are logAll, "
                        "logStatusWarning and logStatusError.",
                        category ? category : "(null)");
            return fmi2Error;
        }
    }
    /* Warnings and errors are always logged; the switch only concerns the logAll trace. */
    inst->debug_logging = loggingOn != fmi2False;
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
    inst->debug_logging = loggingOn != fmi2False;
    inst->image_size = image_size();
    inst->name = allocate(inst, strlen(instanceName) + 1);
    inst->image = allocate(inst, inst->image_size);
    inst->scratch = allocate(inst, inst->image_size);
    if (!inst->name || !inst->image || !inst->scratch) {
        log_message(&probe, fmi2Error, "fmi2Instantiate: out of memory.");
        release(inst, inst->name);
        release(inst, inst->image);
        release(inst, inst->scratch);
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
    release(inst, inst->name);
    inst->callbacks.freeMemory(inst);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    (void)toleranceDefined;
    (void)tolerance; /* the block is discrete: there is nothing to integrate */
    instance *inst = c;
    if (!inst || !mode_allows(inst, "fmi2SetupExperiment", IN(MODE_INSTANTIATED))) return fmi2Error;
    if (!isfinite(startTime)) {
        log_message(inst, fmi2Error, "fmi2SetupExperiment: startTime must be finite (got %g).",
                    startTime);
        return fmi2Error;
    }
    if (stopTimeDefined && !(stopTime >= startTime)) {
        log_message(inst, fmi2Error,
                    "fmi2SetupExperiment: stopTime (%g) must not be before startTime (%g).",
                    stopTime, startTime);
        return fmi2Error;
    }
    inst->image->start_time = startTime;
    inst->image->time = startTime;
    return fmi2OK;
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    instance *inst = c;
    if (!inst || !mode_allows(inst, "fmi2EnterInitializationMode", IN(MODE_INSTANTIATED)))
        return fmi2Error;
    inst->image->mode = MODE_INITIALIZATION;
    return fmi2OK;
}

/* ---- the PLC call clock (BLOCKS.md 1.1) ---- */

/* How far a time may lie from a point of the call grid and still count as on it: 1e-9 of a
 * cycle, widened by a few ulps of the times involved, because an importer computes t + h in
 * floating point (0.1 arrives as 0.10000000000000003) and at large t one ulp exceeds 1e-9 of
 * a short cycle. */
static double grid_tolerance(const fmu_image *image, double t)
{
    double cycle_s = image->cycle_us / 1e6;
    return 1e-9 * cycle_s + 8 * DBL_EPSILON * fmax(fabs(image->start_time), fabs(t));
}

/* Far from 0, doubles cannot tell the call times of a short cycle apart (one ulp of 1e9 s is
 * 1.2e-7 s). Where the tolerance reaches a quarter cycle the grid is refused, instead of calls
 * being merged or skipped. */
static bool grid_resolvable(const instance *inst, const char *function, double t)
{
    const fmu_image *image = inst->image;
    if (grid_tolerance(image, t) < 0.25 * (image->cycle_us / 1e6)) return true;
    log_message(inst, fmi2Error,
                "%s: at t = %g s double precision cannot resolve the call grid of cycleTime %g s; "
                "use a start time closer to 0 or a longer cycleTime.",
                function, t, image->cycle_us / 1e6);
    return false;
}

static void call_block(instance *inst)
{
    fmu_image *image = inst->image;
    iec_word before = lgf_model.status ? lgf_model.status(image->data) : 0;
    plc_call call = {.now_us = image->calls * image->cycle_us, .cycle_us = image->cycle_us};
    lgf_model.call(image->data, &call);
    image->calls++;
    if (!lgf_model.status) return;
    iec_word after = lgf_model.status(image->data);
    const char *meaning = lgf_model.status_text(after);
    if (after != before && meaning)
        log_message(inst, fmi2Warning, "%s: status 16#%04X at t = %.9g s: %s", lgf_model.identifier,
                    (unsigned)after, image->start_time + (double)call.now_us / 1e6, meaning);
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    instance *inst = c;
    if (!inst || !mode_allows(inst, "fmi2ExitInitializationMode", IN(MODE_INITIALIZATION)) ||
        !grid_resolvable(inst, "fmi2ExitInitializationMode", inst->image->start_time))
        return fmi2Error;
    inst->image->mode = MODE_STEP;
    inst->image->time = inst->image->start_time;
    call_block(inst); /* the first call happens at t0 with the inputs of initialization */
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
    return floor((t - image->start_time + grid_tolerance(image, t)) / (image->cycle_us / 1e6));
}

bool clock_is_valid(const fmu_image *image)
{
    if (image->mode < MODE_INSTANTIATED || image->mode > MODE_TERMINATED || image->cycle_us < 1 ||
        !isfinite(image->start_time) || !isfinite(image->time))
        return false;
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
    if (!inst || !mode_allows(inst, "fmi2DoStep", IN(MODE_STEP))) return fmi2Error;
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
    double last = last_call_until(image, end);
    if (!(last < call_index_limit(image))) {
        log_message(inst, fmi2Error,
                    "fmi2DoStep: communicationStepSize %g reaches beyond the last call this FMU "
                    "can count (%g calls of cycleTime).",
                    h, call_index_limit(image));
        return fmi2Error;
    }
    if (!grid_resolvable(inst, "fmi2DoStep", end)) return fmi2Error;
    while ((double)image->calls <= last) call_block(inst);
    image->time = end;
    return fmi2OK;
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    instance *inst = c;
    if (!inst || !mode_allows(inst, "fmi2Terminate", IN(MODE_STEP))) return fmi2Error;
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

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value)
{
    (void)s;
    (void)value;
    return unsupported(c, "fmi2GetStatus", "fmi2DoStep never returns fmi2Pending");
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value)
{
    instance *inst = c;
    if (inst && s == fmi2LastSuccessfulTime && value) {
        /* FMI 2.0 4.2.4: the status functions belong to step mode and terminated */
        if (!mode_allows(inst, "fmi2GetRealStatus", IN(MODE_STEP) | IN(MODE_TERMINATED)))
            return fmi2Error;
        *value = inst->image->time;
        return fmi2OK;
    }
    return unsupported(c, "fmi2GetRealStatus", "only fmi2LastSuccessfulTime is available");
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value)
{
    (void)s;
    (void)value;
    return unsupported(c, "fmi2GetIntegerStatus", "there is no integer status");
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value)
{
    if (c && s == fmi2Terminated && value) {
        if (!mode_allows(c, "fmi2GetBooleanStatus", IN(MODE_STEP) | IN(MODE_TERMINATED)))
            return fmi2Error;
        *value = fmi2False; /* the block never asks to end the simulation */
        return fmi2OK;
    }
    return unsupported(c, "fmi2GetBooleanStatus", "only fmi2Terminated is available");
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value)
{
    (void)s;
    (void)value;
    return unsupported(c, "fmi2GetStringStatus", "fmi2DoStep never returns fmi2Pending");
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
