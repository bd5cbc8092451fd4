/* The FMI 2.0 front-end: the fmi2 entry points of co-simulation and Model Exchange, translated
 * onto the core; each names its kind of call, whose modes the core's table gives (core/modes.c:
 * FMI 2.0, 3.2.3 and 4.2.4), and those FMI 3.0 has alike are written once (core/entry_points.h). */
#include <string.h>

#include "fmi2Functions.h"
#include "core/core.c"
#include "core/entry_points.h"

/* An instance as the importer sees it: the core's and the importer's callbacks. */
typedef struct {
    instance core; /* first: an fmi2Component points at both */
    fmi2CallbackFunctions callbacks;
} fmi2_instance;

static void fmi2_log(const instance *inst, lgf_status status, const char *category,
                     const char *text)
{
    const fmi2_instance *fi = (const fmi2_instance *)inst;
    if (fi->callbacks.logger)
        fi->callbacks.logger(fi->callbacks.componentEnvironment, inst->name ? inst->name : "?",
                             (fmi2Status)status, category, "%s", text);
}

static void *fmi2_allocate(const instance *inst, size_t size)
{
    return ((const fmi2_instance *)inst)->callbacks.allocateMemory(1, size);
}

static void fmi2_release(const instance *inst, void *memory)
{
    ((const fmi2_instance *)inst)->callbacks.freeMemory(memory);
}

static const lgf_host fmi2_host = {fmi2_log, fmi2_allocate, fmi2_release, true, 2147483647.0};

/* ---- instances and the mode machine ---- */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Component fmi2Instantiate(fmi2String instanceName, fmi2Type fmuType, fmi2String fmuGUID,
                              fmi2String fmuResourceLocation,
                              const fmi2CallbackFunctions *functions, fmi2Boolean visible,
                              fmi2Boolean loggingOn)
{
    (void)fmuResourceLocation;
    (void)visible;
    if (!functions || !functions->logger) return NULL; /* nowhere to say why */
    fmi2_instance probe = {
        .core = {.host = &fmi2_host,
                 .name = (char *)instanceName,
                 .interface = fmuType == fmi2CoSimulation ? INTERFACE_CS : INTERFACE_ME},
        .callbacks = *functions};
    const char *refusal = NULL;
    if (!functions->allocateMemory || !functions->freeMemory)
        refusal = "allocateMemory and freeMemory must not be NULL";
    else if (!instanceName || !*instanceName)
        refusal = "instanceName must be a non-empty string";
    else if (fmuType != fmi2CoSimulation && fmuType != fmi2ModelExchange)
        refusal = "fmuType must be fmi2ModelExchange or fmi2CoSimulation";
    else if (!fmuGUID || strcmp(fmuGUID, lgf_model.guid))
        refusal = "fmuGUID does not match the guid of this FMU's modelDescription.xml";
    return core_instantiate(&probe.core, sizeof probe, "fmi2Instantiate", refusal,
                            loggingOn != fmi2False);
}

CORE_LIFECYCLE_ENTRY_POINTS(fmi2Status, fmi2Component, fmi2Boolean, fmi2String, fmi2SetDebugLogging,
                            fmi2ExitInitializationMode, fmi2Terminate, fmi2Reset, fmi2FreeInstance)

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    (void)toleranceDefined;
    (void)tolerance; /* the block is discrete: there is nothing to integrate */
    instance *inst = core_allowed(c, "fmi2SetupExperiment", CALL_SETUP);
    if (!inst) return fmi2Error;
    return (fmi2Status)core_setup(inst, "fmi2SetupExperiment", startTime,
                                  stopTimeDefined != fmi2False, stopTime);
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    return (fmi2Status)core_enter_mode(c, "fmi2EnterInitializationMode", CALL_SETUP,
                                       MODE_INITIALIZATION);
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    instance *inst = core_allowed(c, "fmi2DoStep", CALL_DO_STEP);
    if (!inst) return fmi2Error;
    return (fmi2Status)core_do_step(inst, "fmi2DoStep", currentCommunicationPoint,
                                    communicationStepSize);
}

/* ---- variables ---- */

enum { KIND_REAL, KIND_INTEGER, KIND_BOOLEAN, KIND_STRING };
static const char *const fmi2_kind_names[] = {"fmi2Real", "fmi2Integer", "fmi2Boolean",
                                              "fmi2String"};
static const fmi_types fmi2_types = {
    .kind_of = {[VAR_CYCLE] = KIND_REAL,
                [VAR_LREAL] = KIND_REAL,
                [VAR_TIME] = KIND_REAL,
                [VAR_INT] = KIND_INTEGER,
                [VAR_WORD] = KIND_INTEGER,
                [VAR_REAL] = KIND_REAL,
                [VAR_UDINT] = KIND_INTEGER,
                [VAR_DINT] = KIND_INTEGER,
                [VAR_UINT] = KIND_INTEGER,
                [VAR_SINT] = KIND_INTEGER,
                [VAR_USINT] = KIND_INTEGER,
                [VAR_BYTE] = KIND_INTEGER,
                [VAR_DWORD] = KIND_INTEGER,
                [VAR_STRING] = KIND_STRING,
                [VAR_WSTRING] = KIND_STRING,
                [VAR_BOOL] = KIND_BOOLEAN},
    .kind_names = fmi2_kind_names,
};

/* fmi2ValueReference is an unsigned int, the core's value references uint32_t: the same. */
typedef char value_references_are_32_bits[sizeof(fmi2ValueReference) == sizeof(uint32_t) ? 1 : -1];

#define FMI2_SETTER(function, kind, carrier, type)                                                 \
    fmi2Status function(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,                \
                        const type value[])                                                        \
    {                                                                                              \
        instance *inst = core_allowed(c, #function, CALL_SET);                                     \
        if (!inst) return fmi2Error;                                                               \
        return (fmi2Status)core_set(inst, #function, &fmi2_types, kind, carrier,                   \
                                    (const uint32_t *)vr, nvr, value);                             \
    }

#define FMI2_GETTER(function, kind, carrier, type)                                                 \
    fmi2Status function(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, type value[])  \
    {                                                                                              \
        instance *inst = core_allowed(c, #function, CALL_GET);                                     \
        if (!inst) return fmi2Error;                                                               \
        return (fmi2Status)core_get(inst, #function, &fmi2_types, kind, carrier,                   \
                                    (const uint32_t *)vr, nvr, value);                             \
    }

FMI2_SETTER(fmi2SetReal, KIND_REAL, CARRIER_DOUBLE, fmi2Real)
FMI2_SETTER(fmi2SetInteger, KIND_INTEGER, CARRIER_INT32, fmi2Integer)
FMI2_SETTER(fmi2SetBoolean, KIND_BOOLEAN, CARRIER_INT_BOOL, fmi2Boolean)
FMI2_GETTER(fmi2GetReal, KIND_REAL, CARRIER_DOUBLE, fmi2Real)
FMI2_GETTER(fmi2GetInteger, KIND_INTEGER, CARRIER_INT32, fmi2Integer)
FMI2_GETTER(fmi2GetBoolean, KIND_BOOLEAN, CARRIER_INT_BOOL, fmi2Boolean)

/* The String variables of compiled SCL (core/strings.c): UTF-8. */
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[])
{
    instance *inst = core_allowed(c, "fmi2SetString", CALL_SET);
    if (!inst) return fmi2Error;
    return (fmi2Status)core_set_strings(inst, "fmi2SetString", &fmi2_types, KIND_STRING,
                                        (const uint32_t *)vr, nvr, value);
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[])
{
    instance *inst = core_allowed(c, "fmi2GetString", CALL_GET);
    if (!inst) return fmi2Error;
    return (fmi2Status)core_get_strings(inst, "fmi2GetString", &fmi2_types, KIND_STRING,
                                        (const uint32_t *)vr, nvr, value);
}

/* ---- FMU states ---- */

CORE_STATE_ENTRY_POINTS(fmi2Status, fmi2Component, fmi2FMUstate, fmi2Byte, fmi2GetFMUstate,
                        fmi2SetFMUstate, fmi2FreeFMUstate, fmi2SerializedFMUstateSize,
                        fmi2SerializeFMUstate, fmi2DeSerializeFMUstate)

/* ---- the status functions (FMI 2.0, 4.2.3) ----
 * A status kind the FMU cannot provide is answered with fmi2Discard; only a wrong mode or a
 * NULL pointer is an error. This FMU provides fmi2LastSuccessfulTime and fmi2Terminated;
 * fmi2DoStep never returns fmi2Pending, so fmi2DoStepStatus and fmi2PendingStatus have nothing
 * to tell. */

#define FMI2_NO_STATUS_KIND (-1)

static instance *fmi2_status_request(fmi2Component c, const char *function, fmi2StatusKind kind,
                                     const void *value, int provided, fmi2Status *status)
{
    instance *inst = core_allowed(c, function, CALL_STATUS);
    *status = fmi2Error;
    if (!inst) return NULL;
    if (!value) {
        core_log(inst, STATUS_ERROR, "%s: value must not be NULL.", function);
        return NULL;
    }
    if (provided != FMI2_NO_STATUS_KIND && (int)kind == provided) {
        *status = fmi2OK;
        return inst;
    }
    core_log(inst, STATUS_DISCARD,
             "%s: status kind %d is not available (fmi2DoStep never returns fmi2Pending).",
             function, (int)kind);
    *status = fmi2Discard;
    return NULL;
}

/* The status functions of the types this FMU has no status kind of. */
#define FMI2_NO_STATUS(function, type)                                                             \
    fmi2Status function(fmi2Component c, const fmi2StatusKind s, type *value)                      \
    {                                                                                              \
        fmi2Status status;                                                                         \
        fmi2_status_request(c, #function, s, value, FMI2_NO_STATUS_KIND, &status);                 \
        return status;                                                                             \
    }

FMI2_NO_STATUS(fmi2GetStatus, fmi2Status)
FMI2_NO_STATUS(fmi2GetIntegerStatus, fmi2Integer)
FMI2_NO_STATUS(fmi2GetStringStatus, fmi2String)

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value)
{
    fmi2Status status;
    instance *inst =
        fmi2_status_request(c, "fmi2GetRealStatus", s, value, fmi2LastSuccessfulTime, &status);
    if (inst) *value = inst->image->time;
    return status;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value)
{
    fmi2Status status;
    if (fmi2_status_request(c, "fmi2GetBooleanStatus", s, value, fmi2Terminated, &status))
        *value = fmi2False; /* the block never asks to end the simulation */
    return status;
}

/* ---- what this FMU does not provide (see the capability flags in its XML) ---- */

static fmi2Status fmi2_unsupported(fmi2Component c, const char *function, const char *why)
{
    return (fmi2Status)core_unsupported(c, function, why);
}

fmi2Status fmi2CancelStep(fmi2Component c)
{
    return fmi2_unsupported(c, "fmi2CancelStep", "fmi2DoStep always completes synchronously");
}

fmi2Status fmi2SetRealInputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                       const fmi2Integer order[], const fmi2Real value[])
{
    (void)vr, (void)nvr, (void)order, (void)value;
    return fmi2_unsupported(
        c, "fmi2SetRealInputDerivatives",
        "canInterpolateInputs is false; a PLC samples its inputs once per call");
}

fmi2Status fmi2GetRealOutputDerivatives(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                                        const fmi2Integer order[], fmi2Real value[])
{
    (void)vr, (void)nvr, (void)order, (void)value;
    return fmi2_unsupported(c, "fmi2GetRealOutputDerivatives", "maxOutputDerivativeOrder is 0");
}

fmi2Status fmi2GetDirectionalDerivative(fmi2Component c, const fmi2ValueReference vUnknown[],
                                        size_t nUnknown, const fmi2ValueReference vKnown[],
                                        size_t nKnown, const fmi2Real dvKnown[],
                                        fmi2Real dvUnknown[])
{
    (void)vUnknown, (void)nUnknown, (void)vKnown, (void)nKnown, (void)dvKnown, (void)dvUnknown;
    return fmi2_unsupported(c, "fmi2GetDirectionalDerivative",
                            "providesDirectionalDerivative is false");
}

/* ---- Model Exchange (docs/behaviour.md §1.11): a sampled system, no continuous states ---- */

/* At the time event of call k the call runs once; any other event iteration runs none. */
fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *eventInfo)
{
    const char *function = "fmi2NewDiscreteStates";
    instance *inst = core_allowed(c, function, CALL_EVENT);
    if (!inst || !core_given(inst, function, eventInfo, "eventInfo must not be NULL"))
        return fmi2Error;
    if (core_update_discrete_states(inst, function, &eventInfo->nextEventTime) != STATUS_OK)
        return fmi2Error;
    eventInfo->newDiscreteStatesNeeded = fmi2False;
    eventInfo->terminateSimulation = fmi2False;
    eventInfo->nominalsOfContinuousStatesChanged = fmi2False;
    eventInfo->valuesOfContinuousStatesChanged = fmi2False;
    eventInfo->nextEventTimeDefined = fmi2True;
    return fmi2OK;
}

CORE_MODEL_EXCHANGE_ENTRY_POINTS(fmi2Status, fmi2Component, fmi2Real, fmi2Boolean,
                                 fmi2EnterEventMode, fmi2EnterContinuousTimeMode,
                                 fmi2CompletedIntegratorStep, fmi2SetTime, fmi2SetContinuousStates,
                                 fmi2GetDerivatives, fmi2GetEventIndicators,
                                 fmi2GetContinuousStates, fmi2GetNominalsOfContinuousStates, "nx",
                                 "ni")
