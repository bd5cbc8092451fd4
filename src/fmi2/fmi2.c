/* The FMI 2.0 front-end: the fmi2 entry points of co-simulation and Model Exchange, translated
 * onto the core, and the one table of which function may be called in which mode (FMI 2.0,
 * 3.2.3 and 4.2.4). */
#include <string.h>

#include "fmi2Functions.h"
#include "core/core.c"

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

/* ---- which function may be called in which mode ---- */

typedef enum {
    F_SETUP_EXPERIMENT,
    F_ENTER_INITIALIZATION,
    F_EXIT_INITIALIZATION,
    F_TERMINATE,
    F_SET_REAL,
    F_SET_INTEGER,
    F_SET_BOOLEAN,
    F_SET_STRING,
    F_GET_REAL,
    F_GET_INTEGER,
    F_GET_BOOLEAN,
    F_GET_STRING,
    F_GET_FMU_STATE,
    F_SET_FMU_STATE,
    F_FREE_FMU_STATE,
    F_SERIALIZED_SIZE,
    F_SERIALIZE,
    F_DESERIALIZE,
    F_DO_STEP,
    F_GET_STATUS,
    F_GET_REAL_STATUS,
    F_GET_INTEGER_STATUS,
    F_GET_BOOLEAN_STATUS,
    F_GET_STRING_STATUS,
    F_ENTER_EVENT_MODE,
    F_NEW_DISCRETE_STATES,
    F_ENTER_CONTINUOUS_TIME_MODE,
    F_COMPLETED_INTEGRATOR_STEP,
    F_SET_TIME,
    F_SET_CONTINUOUS_STATES,
    F_GET_DERIVATIVES,
    F_GET_EVENT_INDICATORS,
    F_GET_CONTINUOUS_STATES,
    F_GET_NOMINALS
} fmi2_function;

static const core_rule fmi2_rules[] = {
    [F_SETUP_EXPERIMENT] = {"fmi2SetupExperiment", FOR_BOTH, MODE_BIT(MODE_INSTANTIATED)},
    [F_ENTER_INITIALIZATION] = {"fmi2EnterInitializationMode", FOR_BOTH,
                                MODE_BIT(MODE_INSTANTIATED)},
    [F_EXIT_INITIALIZATION] = {"fmi2ExitInitializationMode", FOR_BOTH,
                               MODE_BIT(MODE_INITIALIZATION)},
    [F_TERMINATE] = {"fmi2Terminate", FOR_BOTH, MODES_RUNNING},
    [F_SET_REAL] = {"fmi2SetReal", FOR_BOTH, MODES_SETTABLE},
    [F_SET_INTEGER] = {"fmi2SetInteger", FOR_BOTH, MODES_SETTABLE},
    [F_SET_BOOLEAN] = {"fmi2SetBoolean", FOR_BOTH, MODES_SETTABLE},
    [F_SET_STRING] = {"fmi2SetString", FOR_BOTH, MODES_SETTABLE},
    [F_GET_REAL] = {"fmi2GetReal", FOR_BOTH, MODES_READABLE},
    [F_GET_INTEGER] = {"fmi2GetInteger", FOR_BOTH, MODES_READABLE},
    [F_GET_BOOLEAN] = {"fmi2GetBoolean", FOR_BOTH, MODES_READABLE},
    [F_GET_STRING] = {"fmi2GetString", FOR_BOTH, MODES_READABLE},
    [F_GET_FMU_STATE] = {"fmi2GetFMUstate", FOR_BOTH, MODES_ANY},
    [F_SET_FMU_STATE] = {"fmi2SetFMUstate", FOR_BOTH, MODES_ANY},
    [F_FREE_FMU_STATE] = {"fmi2FreeFMUstate", FOR_BOTH, MODES_ANY},
    [F_SERIALIZED_SIZE] = {"fmi2SerializedFMUstateSize", FOR_BOTH, MODES_ANY},
    [F_SERIALIZE] = {"fmi2SerializeFMUstate", FOR_BOTH, MODES_ANY},
    [F_DESERIALIZE] = {"fmi2DeSerializeFMUstate", FOR_BOTH, MODES_ANY},
    [F_DO_STEP] = {"fmi2DoStep", FOR_CS, MODE_BIT(MODE_STEP)},
    [F_GET_STATUS] = {"fmi2GetStatus", FOR_CS, MODE_BIT(MODE_STEP) | MODE_BIT(MODE_TERMINATED)},
    [F_GET_REAL_STATUS] = {"fmi2GetRealStatus", FOR_CS,
                           MODE_BIT(MODE_STEP) | MODE_BIT(MODE_TERMINATED)},
    [F_GET_INTEGER_STATUS] = {"fmi2GetIntegerStatus", FOR_CS,
                              MODE_BIT(MODE_STEP) | MODE_BIT(MODE_TERMINATED)},
    [F_GET_BOOLEAN_STATUS] = {"fmi2GetBooleanStatus", FOR_CS,
                              MODE_BIT(MODE_STEP) | MODE_BIT(MODE_TERMINATED)},
    [F_GET_STRING_STATUS] = {"fmi2GetStringStatus", FOR_CS,
                             MODE_BIT(MODE_STEP) | MODE_BIT(MODE_TERMINATED)},
    [F_ENTER_EVENT_MODE] = {"fmi2EnterEventMode", FOR_ME, MODES_EXCHANGE},
    [F_NEW_DISCRETE_STATES] = {"fmi2NewDiscreteStates", FOR_ME, MODE_BIT(MODE_EVENT)},
    [F_ENTER_CONTINUOUS_TIME_MODE] = {"fmi2EnterContinuousTimeMode", FOR_ME, MODE_BIT(MODE_EVENT)},
    [F_COMPLETED_INTEGRATOR_STEP] = {"fmi2CompletedIntegratorStep", FOR_ME,
                                     MODE_BIT(MODE_CONTINUOUS)},
    [F_SET_TIME] = {"fmi2SetTime", FOR_ME, MODES_EXCHANGE},
    [F_SET_CONTINUOUS_STATES] = {"fmi2SetContinuousStates", FOR_ME, MODE_BIT(MODE_CONTINUOUS)},
    [F_GET_DERIVATIVES] = {"fmi2GetDerivatives", FOR_ME, MODES_READABLE},
    [F_GET_EVENT_INDICATORS] = {"fmi2GetEventIndicators", FOR_ME, MODES_READABLE},
    [F_GET_CONTINUOUS_STATES] = {"fmi2GetContinuousStates", FOR_ME, MODES_READABLE},
    [F_GET_NOMINALS] = {"fmi2GetNominalsOfContinuousStates", FOR_ME, MODES_ANY},
};

static instance *fmi2_allowed(fmi2Component c, fmi2_function f)
{
    return core_allowed(c, &fmi2_rules[f]);
}

/* ---- instances and the mode machine ---- */

const char *fmi2GetTypesPlatform(void) { return fmi2TypesPlatform; }
const char *fmi2GetVersion(void) { return fmi2Version; }

fmi2Status fmi2SetDebugLogging(fmi2Component c, fmi2Boolean loggingOn, size_t nCategories,
                               const fmi2String categories[])
{
    instance *inst = c;
    return inst ? (fmi2Status)core_set_debug_logging(inst, "fmi2SetDebugLogging", loggingOn,
                                                     nCategories, categories)
                : fmi2Error;
}

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
    if (refusal) {
        core_log(&probe.core, STATUS_ERROR, "fmi2Instantiate: %s (%s).", refusal,
                 lgf_model.identifier);
        return NULL;
    }
    fmi2_instance *fi = functions->allocateMemory(1, sizeof *fi);
    if (fi) {
        *fi = probe;
        if (core_create(&fi->core, instanceName, loggingOn != fmi2False)) return fi;
        functions->freeMemory(fi);
    }
    core_log(&probe.core, STATUS_ERROR, "fmi2Instantiate: out of memory.");
    return NULL;
}

void fmi2FreeInstance(fmi2Component c)
{
    fmi2_instance *fi = c;
    if (!fi) return;
    core_destroy(&fi->core);
    fi->callbacks.freeMemory(fi);
}

fmi2Status fmi2SetupExperiment(fmi2Component c, fmi2Boolean toleranceDefined, fmi2Real tolerance,
                               fmi2Real startTime, fmi2Boolean stopTimeDefined, fmi2Real stopTime)
{
    (void)toleranceDefined;
    (void)tolerance; /* the block is discrete: there is nothing to integrate */
    instance *inst = fmi2_allowed(c, F_SETUP_EXPERIMENT);
    if (!inst) return fmi2Error;
    return (fmi2Status)core_setup(inst, fmi2_rules[F_SETUP_EXPERIMENT].name, startTime,
                                  stopTimeDefined != fmi2False, stopTime);
}

fmi2Status fmi2EnterInitializationMode(fmi2Component c)
{
    return (fmi2Status)core_enter_mode(c, &fmi2_rules[F_ENTER_INITIALIZATION], MODE_INITIALIZATION);
}

fmi2Status fmi2ExitInitializationMode(fmi2Component c)
{
    instance *inst = fmi2_allowed(c, F_EXIT_INITIALIZATION);
    return inst ? (fmi2Status)core_exit_initialization(inst, fmi2_rules[F_EXIT_INITIALIZATION].name)
                : fmi2Error;
}

fmi2Status fmi2DoStep(fmi2Component c, fmi2Real currentCommunicationPoint,
                      fmi2Real communicationStepSize, fmi2Boolean noSetFMUStatePriorToCurrentPoint)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    instance *inst = fmi2_allowed(c, F_DO_STEP);
    if (!inst) return fmi2Error;
    return (fmi2Status)core_do_step(inst, fmi2_rules[F_DO_STEP].name, currentCommunicationPoint,
                                    communicationStepSize);
}

fmi2Status fmi2Terminate(fmi2Component c)
{
    return (fmi2Status)core_enter_mode(c, &fmi2_rules[F_TERMINATE], MODE_TERMINATED);
}

fmi2Status fmi2Reset(fmi2Component c)
{
    instance *inst = c;
    if (!inst) return fmi2Error;
    core_image_reset(inst->image);
    return fmi2OK;
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

#define FMI2_SETTER(function, f, kind, carrier, type)                                              \
    fmi2Status function(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,                \
                        const type value[])                                                        \
    {                                                                                              \
        instance *inst = fmi2_allowed(c, f);                                                       \
        if (!inst) return fmi2Error;                                                               \
        return (fmi2Status)core_set(inst, fmi2_rules[f].name, &fmi2_types, kind, carrier,          \
                                    (const uint32_t *)vr, nvr, value);                             \
    }

#define FMI2_GETTER(function, f, kind, carrier, type)                                              \
    fmi2Status function(fmi2Component c, const fmi2ValueReference vr[], size_t nvr, type value[])  \
    {                                                                                              \
        instance *inst = fmi2_allowed(c, f);                                                       \
        if (!inst) return fmi2Error;                                                               \
        return (fmi2Status)core_get(inst, fmi2_rules[f].name, &fmi2_types, kind, carrier,          \
                                    (const uint32_t *)vr, nvr, value);                             \
    }

FMI2_SETTER(fmi2SetReal, F_SET_REAL, KIND_REAL, CARRIER_DOUBLE, fmi2Real)
FMI2_SETTER(fmi2SetInteger, F_SET_INTEGER, KIND_INTEGER, CARRIER_INT32, fmi2Integer)
FMI2_SETTER(fmi2SetBoolean, F_SET_BOOLEAN, KIND_BOOLEAN, CARRIER_INT_BOOL, fmi2Boolean)
FMI2_GETTER(fmi2GetReal, F_GET_REAL, KIND_REAL, CARRIER_DOUBLE, fmi2Real)
FMI2_GETTER(fmi2GetInteger, F_GET_INTEGER, KIND_INTEGER, CARRIER_INT32, fmi2Integer)
FMI2_GETTER(fmi2GetBoolean, F_GET_BOOLEAN, KIND_BOOLEAN, CARRIER_INT_BOOL, fmi2Boolean)

/* The String variables of compiled SCL (core/strings.c): UTF-8. */
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[])
{
    instance *inst = fmi2_allowed(c, F_SET_STRING);
    if (!inst) return fmi2Error;
    return (fmi2Status)core_set_strings(inst, fmi2_rules[F_SET_STRING].name, &fmi2_types,
                                        KIND_STRING, (const uint32_t *)vr, nvr, value);
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[])
{
    instance *inst = fmi2_allowed(c, F_GET_STRING);
    if (!inst) return fmi2Error;
    return (fmi2Status)core_get_strings(inst, fmi2_rules[F_GET_STRING].name, &fmi2_types,
                                        KIND_STRING, (const uint32_t *)vr, nvr, value);
}

/* ---- FMU states ---- */

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    instance *inst = fmi2_allowed(c, F_GET_FMU_STATE);
    return inst ? (fmi2Status)core_get_state(inst, fmi2_rules[F_GET_FMU_STATE].name, FMUstate)
                : fmi2Error;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate)
{
    instance *inst = fmi2_allowed(c, F_SET_FMU_STATE);
    return inst ? (fmi2Status)core_set_state(inst, fmi2_rules[F_SET_FMU_STATE].name, FMUstate,
                                             core_modes_of(c))
                : fmi2Error;
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    instance *inst = fmi2_allowed(c, F_FREE_FMU_STATE);
    return inst ? (fmi2Status)core_free_state(inst, fmi2_rules[F_FREE_FMU_STATE].name, FMUstate)
                : fmi2Error;
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size)
{
    instance *inst = fmi2_allowed(c, F_SERIALIZED_SIZE);
    return inst ? (fmi2Status)core_state_size(inst, fmi2_rules[F_SERIALIZED_SIZE].name, FMUstate,
                                              size)
                : fmi2Error;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                 size_t size)
{
    instance *inst = fmi2_allowed(c, F_SERIALIZE);
    return inst ? (fmi2Status)core_serialize(inst, fmi2_rules[F_SERIALIZE].name, FMUstate,
                                             (unsigned char *)serializedState, size)
                : fmi2Error;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate *FMUstate)
{
    instance *inst = fmi2_allowed(c, F_DESERIALIZE);
    return inst ? (fmi2Status)core_deserialize(inst, fmi2_rules[F_DESERIALIZE].name,
                                               (const unsigned char *)serializedState, size,
                                               FMUstate, core_modes_of(c))
                : fmi2Error;
}

/* ---- the status functions (FMI 2.0, 4.2.3) ----
 * A status kind the FMU cannot provide is answered with fmi2Discard; only a wrong mode or a
 * NULL pointer is an error. This FMU provides fmi2LastSuccessfulTime and fmi2Terminated;
 * fmi2DoStep never returns fmi2Pending, so fmi2DoStepStatus and fmi2PendingStatus have nothing
 * to tell. */

#define FMI2_NO_STATUS_KIND (-1)

static instance *fmi2_status_request(fmi2Component c, fmi2_function f, fmi2StatusKind kind,
                                     const void *value, int provided, fmi2Status *status)
{
    instance *inst = fmi2_allowed(c, f);
    *status = fmi2Error;
    if (!inst) return NULL;
    if (!value) {
        core_log(inst, STATUS_ERROR, "%s: value must not be NULL.", fmi2_rules[f].name);
        return NULL;
    }
    if (provided != FMI2_NO_STATUS_KIND && (int)kind == provided) {
        *status = fmi2OK;
        return inst;
    }
    core_log(inst, STATUS_DISCARD,
             "%s: status kind %d is not available (fmi2DoStep never returns fmi2Pending).",
             fmi2_rules[f].name, (int)kind);
    *status = fmi2Discard;
    return NULL;
}

fmi2Status fmi2GetStatus(fmi2Component c, const fmi2StatusKind s, fmi2Status *value)
{
    fmi2Status status;
    fmi2_status_request(c, F_GET_STATUS, s, value, FMI2_NO_STATUS_KIND, &status);
    return status;
}

fmi2Status fmi2GetRealStatus(fmi2Component c, const fmi2StatusKind s, fmi2Real *value)
{
    fmi2Status status;
    instance *inst =
        fmi2_status_request(c, F_GET_REAL_STATUS, s, value, fmi2LastSuccessfulTime, &status);
    if (inst) *value = inst->image->time;
    return status;
}

fmi2Status fmi2GetIntegerStatus(fmi2Component c, const fmi2StatusKind s, fmi2Integer *value)
{
    fmi2Status status;
    fmi2_status_request(c, F_GET_INTEGER_STATUS, s, value, FMI2_NO_STATUS_KIND, &status);
    return status;
}

fmi2Status fmi2GetBooleanStatus(fmi2Component c, const fmi2StatusKind s, fmi2Boolean *value)
{
    fmi2Status status;
    if (fmi2_status_request(c, F_GET_BOOLEAN_STATUS, s, value, fmi2Terminated, &status))
        *value = fmi2False; /* the block never asks to end the simulation */
    return status;
}

fmi2Status fmi2GetStringStatus(fmi2Component c, const fmi2StatusKind s, fmi2String *value)
{
    fmi2Status status;
    fmi2_status_request(c, F_GET_STRING_STATUS, s, value, FMI2_NO_STATUS_KIND, &status);
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

fmi2Status fmi2EnterEventMode(fmi2Component c)
{
    return (fmi2Status)core_enter_mode(c, &fmi2_rules[F_ENTER_EVENT_MODE], MODE_EVENT);
}

/* At the time event of call k the call runs once; any other event iteration runs none. */
fmi2Status fmi2NewDiscreteStates(fmi2Component c, fmi2EventInfo *eventInfo)
{
    const char *function = fmi2_rules[F_NEW_DISCRETE_STATES].name;
    instance *inst = fmi2_allowed(c, F_NEW_DISCRETE_STATES);
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

fmi2Status fmi2EnterContinuousTimeMode(fmi2Component c)
{
    return (fmi2Status)core_enter_mode(c, &fmi2_rules[F_ENTER_CONTINUOUS_TIME_MODE],
                                       MODE_CONTINUOUS);
}

/* Nothing happens between calls: no step event, no reason to stop. */
fmi2Status fmi2CompletedIntegratorStep(fmi2Component c,
                                       fmi2Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi2Boolean *enterEventMode,
                                       fmi2Boolean *terminateSimulation)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    instance *inst = fmi2_allowed(c, F_COMPLETED_INTEGRATOR_STEP);
    if (!inst || !core_given(inst, fmi2_rules[F_COMPLETED_INTEGRATOR_STEP].name,
                             enterEventMode && terminateSimulation,
                             "enterEventMode and terminateSimulation must not be NULL"))
        return fmi2Error;
    *enterEventMode = fmi2False;
    *terminateSimulation = fmi2False;
    return fmi2OK;
}

fmi2Status fmi2SetTime(fmi2Component c, fmi2Real time)
{
    instance *inst = fmi2_allowed(c, F_SET_TIME);
    return inst ? (fmi2Status)core_set_time(inst, fmi2_rules[F_SET_TIME].name, time) : fmi2Error;
}

/* No continuous states, no event indicators (nx = 0, numberOfEventIndicators = 0). */
static fmi2Status fmi2_no_states(fmi2Component c, fmi2_function f, size_t n, const char *what)
{
    instance *inst = fmi2_allowed(c, f);
    return inst ? (fmi2Status)core_none(inst, fmi2_rules[f].name, n, what) : fmi2Error;
}

fmi2Status fmi2SetContinuousStates(fmi2Component c, const fmi2Real x[], size_t nx)
{
    (void)x;
    return fmi2_no_states(c, F_SET_CONTINUOUS_STATES, nx, "nx");
}

fmi2Status fmi2GetDerivatives(fmi2Component c, fmi2Real derivatives[], size_t nx)
{
    (void)derivatives;
    return fmi2_no_states(c, F_GET_DERIVATIVES, nx, "nx");
}

fmi2Status fmi2GetEventIndicators(fmi2Component c, fmi2Real eventIndicators[], size_t ni)
{
    (void)eventIndicators;
    return fmi2_no_states(c, F_GET_EVENT_INDICATORS, ni, "ni");
}

fmi2Status fmi2GetContinuousStates(fmi2Component c, fmi2Real x[], size_t nx)
{
    (void)x;
    return fmi2_no_states(c, F_GET_CONTINUOUS_STATES, nx, "nx");
}

fmi2Status fmi2GetNominalsOfContinuousStates(fmi2Component c, fmi2Real x_nominal[], size_t nx)
{
    (void)x_nominal;
    return fmi2_no_states(c, F_GET_NOMINALS, nx, "nx");
}
