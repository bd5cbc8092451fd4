/* The FMI 3.0 front-end: the fmi3 entry points of Co-Simulation and Model Exchange, translated
 * onto the same core as FMI 2.0, with the PLC's own widths (docs/behaviour.md §7): INT is Int16,
 * WORD UInt16, UDINT UInt32, REAL Float32, LREAL and TIME Float64, BOOL Boolean. One table says which function
 * may be called in which mode (FMI 3.0, 3.2 and 4.2). */
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "core/core.c"

typedef enum { INTERFACE_ME, INTERFACE_CS } fmi3_interface;

/* An instance as the importer sees it: the core's, the importer's logger and the interface. */
typedef struct {
    instance core; /* first: an fmi3Instance points at both */
    fmi3InstanceEnvironment environment;
    fmi3LogMessageCallback log;
    fmi3_interface type;
} fmi3_instance;

static void fmi3_log(const instance *inst, lgf_status status, const char *category,
                     const char *text)
{
    const fmi3_instance *fi = (const fmi3_instance *)inst;
    if (fi->log) fi->log(fi->environment, (fmi3Status)status, category, text);
}

/* FMI 3.0 has no memory callbacks: the FMU allocates for itself. */
static void *fmi3_allocate(const instance *inst, size_t size)
{
    (void)inst;
    return calloc(1, size);
}

static void fmi3_release(const instance *inst, void *memory)
{
    (void)inst;
    free(memory);
}

static const lgf_host fmi3_host = {fmi3_log, fmi3_allocate, fmi3_release, false, 4294967295.0};

/* ---- which function may be called in which mode ---- */

#define CS (1u << INTERFACE_CS)
#define ME (1u << INTERFACE_ME)
#define BOTH (CS | ME)
#define BEFORE_INIT (IN(MODE_INSTANTIATED) | IN(MODE_INITIALIZATION))
#define RUNNING (IN(MODE_STEP) | IN(MODE_EVENT) | IN(MODE_CONTINUOUS))
#define READABLE (IN(MODE_INITIALIZATION) | RUNNING | IN(MODE_TERMINATED))
#define ANY_MODE (IN(MODE_INSTANTIATED) | READABLE)
#define EXCHANGE (IN(MODE_EVENT) | IN(MODE_CONTINUOUS))
/* Discrete inputs are set in event mode, not in continuous-time mode; as in FMI 2.0 (and the
 * Reference FMUs), Float64 is let through there. */
#define SETTABLE (BEFORE_INIT | IN(MODE_STEP) | IN(MODE_EVENT))

typedef enum {
    F_ENTER_INITIALIZATION, F_EXIT_INITIALIZATION, F_TERMINATE, F_SET_FLOAT64, F_SET_INT16,
    F_SET_UINT16, F_SET_BOOLEAN, F_SET_FLOAT32, F_SET_UINT32, F_GET_FLOAT64, F_GET_INT16,
    F_GET_UINT16, F_GET_BOOLEAN, F_GET_FLOAT32, F_GET_UINT32,
    F_OTHER_TYPES, F_GET_FMU_STATE, F_SET_FMU_STATE, F_FREE_FMU_STATE, F_SERIALIZED_SIZE,
    F_SERIALIZE, F_DESERIALIZE, F_DO_STEP, F_ENTER_EVENT_MODE, F_UPDATE_DISCRETE_STATES,
    F_EVALUATE_DISCRETE_STATES, F_ENTER_CONTINUOUS_TIME_MODE, F_COMPLETED_INTEGRATOR_STEP,
    F_SET_TIME, F_SET_CONTINUOUS_STATES, F_GET_DERIVATIVES, F_GET_EVENT_INDICATORS,
    F_GET_CONTINUOUS_STATES, F_GET_NOMINALS, F_NUMBER_OF_EVENT_INDICATORS,
    F_NUMBER_OF_CONTINUOUS_STATES
} fmi_function;

static const struct {
    const char *name;
    unsigned interfaces;
    unsigned modes;
} rules[] = {
    [F_ENTER_INITIALIZATION] = {"fmi3EnterInitializationMode", BOTH, IN(MODE_INSTANTIATED)},
    [F_EXIT_INITIALIZATION] = {"fmi3ExitInitializationMode", BOTH, IN(MODE_INITIALIZATION)},
    [F_TERMINATE] = {"fmi3Terminate", BOTH, RUNNING},
    [F_SET_FLOAT64] = {"fmi3SetFloat64", BOTH, SETTABLE | IN(MODE_CONTINUOUS)},
    [F_SET_INT16] = {"fmi3SetInt16", BOTH, SETTABLE},
    [F_SET_UINT16] = {"fmi3SetUInt16", BOTH, SETTABLE},
    [F_SET_BOOLEAN] = {"fmi3SetBoolean", BOTH, SETTABLE},
    [F_SET_FLOAT32] = {"fmi3SetFloat32", BOTH, SETTABLE | IN(MODE_CONTINUOUS)},
    [F_SET_UINT32] = {"fmi3SetUInt32", BOTH, SETTABLE},
    [F_GET_FLOAT64] = {"fmi3GetFloat64", BOTH, READABLE},
    [F_GET_INT16] = {"fmi3GetInt16", BOTH, READABLE},
    [F_GET_UINT16] = {"fmi3GetUInt16", BOTH, READABLE},
    [F_GET_BOOLEAN] = {"fmi3GetBoolean", BOTH, READABLE},
    [F_GET_FLOAT32] = {"fmi3GetFloat32", BOTH, READABLE},
    [F_GET_UINT32] = {"fmi3GetUInt32", BOTH, READABLE},
    [F_OTHER_TYPES] = {"fmi3Get/Set", BOTH, ANY_MODE},
    [F_GET_FMU_STATE] = {"fmi3GetFMUState", BOTH, ANY_MODE},
    [F_SET_FMU_STATE] = {"fmi3SetFMUState", BOTH, ANY_MODE},
    [F_FREE_FMU_STATE] = {"fmi3FreeFMUState", BOTH, ANY_MODE},
    [F_SERIALIZED_SIZE] = {"fmi3SerializedFMUStateSize", BOTH, ANY_MODE},
    [F_SERIALIZE] = {"fmi3SerializeFMUState", BOTH, ANY_MODE},
    [F_DESERIALIZE] = {"fmi3DeserializeFMUState", BOTH, ANY_MODE},
    [F_DO_STEP] = {"fmi3DoStep", CS, IN(MODE_STEP)},
    [F_ENTER_EVENT_MODE] = {"fmi3EnterEventMode", ME, EXCHANGE},
    [F_UPDATE_DISCRETE_STATES] = {"fmi3UpdateDiscreteStates", ME, IN(MODE_EVENT)},
    [F_EVALUATE_DISCRETE_STATES] = {"fmi3EvaluateDiscreteStates", ME, IN(MODE_EVENT)},
    [F_ENTER_CONTINUOUS_TIME_MODE] = {"fmi3EnterContinuousTimeMode", ME, IN(MODE_EVENT)},
    [F_COMPLETED_INTEGRATOR_STEP] = {"fmi3CompletedIntegratorStep", ME, IN(MODE_CONTINUOUS)},
    [F_SET_TIME] = {"fmi3SetTime", ME, EXCHANGE},
    [F_SET_CONTINUOUS_STATES] = {"fmi3SetContinuousStates", ME, IN(MODE_CONTINUOUS)},
    [F_GET_DERIVATIVES] = {"fmi3GetContinuousStateDerivatives", ME, READABLE},
    [F_GET_EVENT_INDICATORS] = {"fmi3GetEventIndicators", ME, READABLE},
    [F_GET_CONTINUOUS_STATES] = {"fmi3GetContinuousStates", ME, READABLE},
    [F_GET_NOMINALS] = {"fmi3GetNominalsOfContinuousStates", ME, ANY_MODE},
    [F_NUMBER_OF_EVENT_INDICATORS] = {"fmi3GetNumberOfEventIndicators", ME, ANY_MODE},
    [F_NUMBER_OF_CONTINUOUS_STATES] = {"fmi3GetNumberOfContinuousStates", ME, ANY_MODE},
};

/* The instance behind i, unless i is NULL, or the function belongs to the other interface or
 * may not be called in the instance's mode: then NULL, with a log line naming the function. */
static instance *allowed(fmi3Instance i, fmi_function f)
{
    fmi3_instance *fi = i;
    if (!fi) return NULL;
    if (!(rules[f].interfaces & (1u << fi->type))) {
        log_message(&fi->core, STATUS_ERROR, "%s is a %s function; this instance is for %s.",
                    rules[f].name, rules[f].interfaces == CS ? "co-simulation" : "Model Exchange",
                    fi->type == INTERFACE_CS ? "co-simulation" : "Model Exchange");
        return NULL;
    }
    return mode_allows(&fi->core, rules[f].name, rules[f].modes) ? &fi->core : NULL;
}

static unsigned modes_of(fmi3Instance i)
{
    unsigned common = BEFORE_INIT | IN(MODE_TERMINATED);
    return ((fmi3_instance *)i)->type == INTERFACE_CS ? common | IN(MODE_STEP) : common | EXCHANGE;
}

/* ---- instances and the mode machine ---- */

const char *fmi3GetVersion(void) { return fmi3Version; }

fmi3Status fmi3SetDebugLogging(fmi3Instance i, fmi3Boolean loggingOn, size_t nCategories,
                               const fmi3String categories[])
{
    instance *inst = i;
    return inst ? (fmi3Status)core_set_debug_logging(inst, "fmi3SetDebugLogging", loggingOn,
                                                     nCategories, categories)
                : fmi3Error;
}

static fmi3Instance instantiate(const char *function, fmi3_interface type, fmi3String name,
                                fmi3String token, fmi3Boolean loggingOn,
                                fmi3InstanceEnvironment environment, fmi3LogMessageCallback log)
{
    fmi3_instance probe = {.core = {.host = &fmi3_host, .name = (char *)name},
                           .environment = environment, .log = log, .type = type};
    const char *refusal = NULL;
    if (!name || !*name) refusal = "instanceName must be a non-empty string";
    else if (!token || strcmp(token, lgf_model.guid))
        refusal = "instantiationToken does not match the one of this FMU's modelDescription.xml";
    if (refusal) {
        log_message(&probe.core, STATUS_ERROR, "%s: %s (%s).", function, refusal,
                    lgf_model.identifier);
        return NULL;
    }
    fmi3_instance *fi = calloc(1, sizeof *fi);
    if (fi) {
        *fi = probe;
        if (core_create(&fi->core, name, loggingOn)) return fi;
        free(fi);
    }
    log_message(&probe.core, STATUS_ERROR, "%s: out of memory.", function);
    return NULL;
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken,
                                          fmi3String resourcePath, fmi3Boolean visible,
                                          fmi3Boolean loggingOn,
                                          fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage)
{
    (void)resourcePath, (void)visible;
    return instantiate("fmi3InstantiateModelExchange", INTERFACE_ME, instanceName,
                       instantiationToken, loggingOn, instanceEnvironment, logMessage);
}

/* The block never needs event mode nor returns early: eventModeUsed and earlyReturnAllowed are
 * honoured by not using them (docs/behaviour.md §7). */
fmi3Instance fmi3InstantiateCoSimulation(fmi3String instanceName, fmi3String instantiationToken,
                                         fmi3String resourcePath, fmi3Boolean visible,
                                         fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
                                         fmi3Boolean earlyReturnAllowed,
                                         const fmi3ValueReference requiredIntermediateVariables[],
                                         size_t nRequiredIntermediateVariables,
                                         fmi3InstanceEnvironment instanceEnvironment,
                                         fmi3LogMessageCallback logMessage,
                                         fmi3IntermediateUpdateCallback intermediateUpdate)
{
    (void)resourcePath, (void)visible, (void)eventModeUsed, (void)earlyReturnAllowed;
    (void)requiredIntermediateVariables, (void)nRequiredIntermediateVariables;
    (void)intermediateUpdate;
    return instantiate("fmi3InstantiateCoSimulation", INTERFACE_CS, instanceName,
                       instantiationToken, loggingOn, instanceEnvironment, logMessage);
}

fmi3Instance fmi3InstantiateScheduledExecution(fmi3String instanceName,
                                               fmi3String instantiationToken,
                                               fmi3String resourcePath, fmi3Boolean visible,
                                               fmi3Boolean loggingOn,
                                               fmi3InstanceEnvironment instanceEnvironment,
                                               fmi3LogMessageCallback logMessage,
                                               fmi3ClockUpdateCallback clockUpdate,
                                               fmi3LockPreemptionCallback lockPreemption,
                                               fmi3UnlockPreemptionCallback unlockPreemption)
{
    (void)instantiationToken, (void)resourcePath, (void)visible, (void)loggingOn;
    (void)clockUpdate, (void)lockPreemption, (void)unlockPreemption;
    if (logMessage)
        logMessage(instanceEnvironment, fmi3Error, "logStatusError",
                   "fmi3InstantiateScheduledExecution: this FMU offers Model Exchange and "
                   "Co-Simulation, not Scheduled Execution.");
    (void)instanceName;
    return NULL;
}

void fmi3FreeInstance(fmi3Instance i)
{
    fmi3_instance *fi = i;
    if (!fi) return;
    core_destroy(&fi->core);
    free(fi);
}

fmi3Status fmi3EnterInitializationMode(fmi3Instance i, fmi3Boolean toleranceDefined,
                                       fmi3Float64 tolerance, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime)
{
    (void)toleranceDefined, (void)tolerance; /* the block is discrete: nothing to integrate */
    instance *inst = allowed(i, F_ENTER_INITIALIZATION);
    if (!inst) return fmi3Error;
    lgf_status status =
        core_setup(inst, rules[F_ENTER_INITIALIZATION].name, startTime, stopTimeDefined, stopTime);
    if (status == STATUS_OK) inst->image->mode = MODE_INITIALIZATION;
    return (fmi3Status)status;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance i)
{
    instance *inst = allowed(i, F_EXIT_INITIALIZATION);
    if (!inst) return fmi3Error;
    int32_t mode = inst->image->mode;
    inst->image->mode = ((fmi3_instance *)i)->type == INTERFACE_CS ? MODE_STEP : MODE_EVENT;
    lgf_status status = core_first_call(inst, rules[F_EXIT_INITIALIZATION].name);
    if (status == STATUS_ERROR) inst->image->mode = mode;
    return (fmi3Status)status;
}

fmi3Status fmi3Terminate(fmi3Instance i)
{
    instance *inst = allowed(i, F_TERMINATE);
    if (!inst) return fmi3Error;
    inst->image->mode = MODE_TERMINATED;
    return fmi3OK;
}

fmi3Status fmi3Reset(fmi3Instance i)
{
    instance *inst = i;
    if (!inst) return fmi3Error;
    image_reset(inst->image);
    return fmi3OK;
}

/* ---- variables ---- */

enum { KIND_FLOAT64, KIND_INT16, KIND_UINT16, KIND_BOOLEAN, KIND_FLOAT32, KIND_UINT32 };
static const char *const kind_names[] = {"Float64", "Int16", "UInt16", "Boolean", "Float32",
                                         "UInt32"};
static const fmi_types fmi3_types = {
    .kind_of = {[VAR_CYCLE] = KIND_FLOAT64, [VAR_LREAL] = KIND_FLOAT64, [VAR_TIME] = KIND_FLOAT64,
                [VAR_INT] = KIND_INT16, [VAR_WORD] = KIND_UINT16, [VAR_REAL] = KIND_FLOAT32,
                [VAR_UDINT] = KIND_UINT32, [VAR_BOOL] = KIND_BOOLEAN},
    .kind_names = kind_names,
};

/* Every variable is a scalar: one value per value reference. */
static bool scalars(instance *inst, const char *function, size_t nvr, size_t nValues)
{
    if (nValues == nvr) return true;
    log_message(inst, STATUS_ERROR,
                "%s: nValues is %llu but nValueReferences is %llu; every variable of %s is a "
                "scalar.",
                function, (unsigned long long)nValues, (unsigned long long)nvr,
                lgf_model.identifier);
    return false;
}

#define SETTER(function, f, kind, carrier, type)                                               \
    fmi3Status function(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,             \
                        const type values[], size_t nValues)                                   \
    {                                                                                          \
        instance *inst = allowed(i, f);                                                        \
        if (!inst || !scalars(inst, rules[f].name, nvr, nValues)) return fmi3Error;            \
        return (fmi3Status)core_set(inst, rules[f].name, &fmi3_types, kind, carrier, vr, nvr,  \
                                    values);                                                   \
    }

#define GETTER(function, f, kind, carrier, type)                                               \
    fmi3Status function(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,             \
                        type values[], size_t nValues)                                         \
    {                                                                                          \
        instance *inst = allowed(i, f);                                                        \
        if (!inst || !scalars(inst, rules[f].name, nvr, nValues)) return fmi3Error;            \
        return (fmi3Status)core_get(inst, rules[f].name, &fmi3_types, kind, carrier, vr, nvr,  \
                                    values);                                                   \
    }

SETTER(fmi3SetFloat64, F_SET_FLOAT64, KIND_FLOAT64, CARRIER_DOUBLE, fmi3Float64)
SETTER(fmi3SetInt16, F_SET_INT16, KIND_INT16, CARRIER_INT16, fmi3Int16)
SETTER(fmi3SetUInt16, F_SET_UINT16, KIND_UINT16, CARRIER_UINT16, fmi3UInt16)
SETTER(fmi3SetBoolean, F_SET_BOOLEAN, KIND_BOOLEAN, CARRIER_BOOL, fmi3Boolean)
SETTER(fmi3SetFloat32, F_SET_FLOAT32, KIND_FLOAT32, CARRIER_FLOAT, fmi3Float32)
SETTER(fmi3SetUInt32, F_SET_UINT32, KIND_UINT32, CARRIER_UINT32, fmi3UInt32)

/* Float64 also reads the independent variable, time (TIME_VR), one value at a time. */
fmi3Status fmi3GetFloat64(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float64 values[], size_t nValues)
{
    instance *inst = allowed(i, F_GET_FLOAT64);
    const char *function = rules[F_GET_FLOAT64].name;
    if (!inst || !scalars(inst, function, nvr, nValues)) return fmi3Error;
    bool time = false;
    for (size_t k = 0; k < nvr && vr; k++) time |= vr[k] == TIME_VR;
    if (!time || !values) /* core_get refuses NULL arrays */
        return (fmi3Status)core_get(inst, function, &fmi3_types, KIND_FLOAT64, CARRIER_DOUBLE, vr,
                                    nvr, values);
    for (size_t k = 0; k < nvr; k++) {
        if (vr[k] == TIME_VR) values[k] = inst->image->time;
        else if (core_get(inst, function, &fmi3_types, KIND_FLOAT64, CARRIER_DOUBLE, vr + k, 1,
                          values + k) != STATUS_OK)
            return fmi3Error;
    }
    return fmi3OK;
}
GETTER(fmi3GetInt16, F_GET_INT16, KIND_INT16, CARRIER_INT16, fmi3Int16)
GETTER(fmi3GetUInt16, F_GET_UINT16, KIND_UINT16, CARRIER_UINT16, fmi3UInt16)
GETTER(fmi3GetBoolean, F_GET_BOOLEAN, KIND_BOOLEAN, CARRIER_BOOL, fmi3Boolean)
GETTER(fmi3GetFloat32, F_GET_FLOAT32, KIND_FLOAT32, CARRIER_FLOAT, fmi3Float32)
GETTER(fmi3GetUInt32, F_GET_UINT32, KIND_UINT32, CARRIER_UINT32, fmi3UInt32)

/* The types this FMU has no variable of: any value reference is unknown to them. */
static fmi3Status no_such_type(fmi3Instance i, const char *function, const fmi3ValueReference vr[],
                               size_t nvr, size_t nValues)
{
    instance *inst = allowed(i, F_OTHER_TYPES);
    if (!inst || !scalars(inst, function, nvr, nValues)) return fmi3Error;
    if (nvr == 0) return fmi3OK;
    log_message(inst, STATUS_ERROR, "%s: %s has no variable of this type (value reference %u).",
                function, lgf_model.identifier, vr ? (unsigned)vr[0] : 0u);
    return fmi3Error;
}

#define NO_GETTER(function, type)                                                              \
    fmi3Status function(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,             \
                        type values[], size_t nValues)                                         \
    {                                                                                          \
        (void)values;                                                                          \
        return no_such_type(i, #function, vr, nvr, nValues);                                   \
    }
#define NO_SETTER(function, type)                                                              \
    fmi3Status function(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,             \
                        const type values[], size_t nValues)                                   \
    {                                                                                          \
        (void)values;                                                                          \
        return no_such_type(i, #function, vr, nvr, nValues);                                   \
    }

NO_GETTER(fmi3GetInt8, fmi3Int8)
NO_GETTER(fmi3GetUInt8, fmi3UInt8)
NO_GETTER(fmi3GetInt32, fmi3Int32)
NO_GETTER(fmi3GetInt64, fmi3Int64)
NO_GETTER(fmi3GetUInt64, fmi3UInt64)
NO_GETTER(fmi3GetString, fmi3String)
NO_SETTER(fmi3SetInt8, fmi3Int8)
NO_SETTER(fmi3SetUInt8, fmi3UInt8)
NO_SETTER(fmi3SetInt32, fmi3Int32)
NO_SETTER(fmi3SetInt64, fmi3Int64)
NO_SETTER(fmi3SetUInt64, fmi3UInt64)
NO_SETTER(fmi3SetString, fmi3String)

fmi3Status fmi3GetBinary(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                         size_t valueSizes[], fmi3Binary values[], size_t nValues)
{
    (void)valueSizes, (void)values;
    return no_such_type(i, "fmi3GetBinary", vr, nvr, nValues);
}

fmi3Status fmi3SetBinary(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                         const size_t valueSizes[], const fmi3Binary values[], size_t nValues)
{
    (void)valueSizes, (void)values;
    return no_such_type(i, "fmi3SetBinary", vr, nvr, nValues);
}

fmi3Status fmi3GetClock(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                        fmi3Clock values[])
{
    (void)values;
    return no_such_type(i, "fmi3GetClock", vr, nvr, nvr);
}

fmi3Status fmi3SetClock(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                        const fmi3Clock values[])
{
    (void)values;
    return no_such_type(i, "fmi3SetClock", vr, nvr, nvr);
}

/* ---- FMU states ---- */

fmi3Status fmi3GetFMUState(fmi3Instance i, fmi3FMUState *FMUState)
{
    instance *inst = allowed(i, F_GET_FMU_STATE);
    return inst ? (fmi3Status)core_get_state(inst, rules[F_GET_FMU_STATE].name, FMUState)
                : fmi3Error;
}

fmi3Status fmi3SetFMUState(fmi3Instance i, fmi3FMUState FMUState)
{
    instance *inst = allowed(i, F_SET_FMU_STATE);
    return inst ? (fmi3Status)core_set_state(inst, rules[F_SET_FMU_STATE].name, FMUState,
                                             modes_of(i))
                : fmi3Error;
}

fmi3Status fmi3FreeFMUState(fmi3Instance i, fmi3FMUState *FMUState)
{
    instance *inst = allowed(i, F_FREE_FMU_STATE);
    return inst ? (fmi3Status)core_free_state(inst, rules[F_FREE_FMU_STATE].name, FMUState)
                : fmi3Error;
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance i, fmi3FMUState FMUState, size_t *size)
{
    instance *inst = allowed(i, F_SERIALIZED_SIZE);
    return inst ? (fmi3Status)core_state_size(inst, rules[F_SERIALIZED_SIZE].name, FMUState, size)
                : fmi3Error;
}

fmi3Status fmi3SerializeFMUState(fmi3Instance i, fmi3FMUState FMUState, fmi3Byte serializedState[],
                                 size_t size)
{
    instance *inst = allowed(i, F_SERIALIZE);
    return inst ? (fmi3Status)core_serialize(inst, rules[F_SERIALIZE].name, FMUState,
                                             serializedState, size)
                : fmi3Error;
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance i, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState *FMUState)
{
    instance *inst = allowed(i, F_DESERIALIZE);
    return inst ? (fmi3Status)core_deserialize(inst, rules[F_DESERIALIZE].name, serializedState,
                                               size, FMUState, modes_of(i))
                : fmi3Error;
}

/* ---- Co-Simulation ---- */

fmi3Status fmi3DoStep(fmi3Instance i, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,
                      fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    instance *inst = allowed(i, F_DO_STEP);
    if (!inst) return fmi3Error;
    if (!eventHandlingNeeded || !terminateSimulation || !earlyReturn || !lastSuccessfulTime) {
        log_message(inst, STATUS_ERROR,
                    "fmi3DoStep: eventHandlingNeeded, terminateSimulation, earlyReturn and "
                    "lastSuccessfulTime must not be NULL.");
        return fmi3Error;
    }
    lgf_status status = core_do_step(inst, rules[F_DO_STEP].name, currentCommunicationPoint,
                                     communicationStepSize);
    *eventHandlingNeeded = fmi3False;
    *terminateSimulation = fmi3False;
    *earlyReturn = fmi3False;
    *lastSuccessfulTime = inst->image->time;
    return (fmi3Status)status;
}

/* ---- Model Exchange (docs/behaviour.md §1.11) ---- */

fmi3Status fmi3EnterEventMode(fmi3Instance i)
{
    instance *inst = allowed(i, F_ENTER_EVENT_MODE);
    if (!inst) return fmi3Error;
    inst->image->mode = MODE_EVENT;
    return fmi3OK;
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance i, fmi3Boolean *discreteStatesNeedUpdate,
                                    fmi3Boolean *terminateSimulation,
                                    fmi3Boolean *nominalsOfContinuousStatesChanged,
                                    fmi3Boolean *valuesOfContinuousStatesChanged,
                                    fmi3Boolean *nextEventTimeDefined, fmi3Float64 *nextEventTime)
{
    instance *inst = allowed(i, F_UPDATE_DISCRETE_STATES);
    if (!inst) return fmi3Error;
    if (!discreteStatesNeedUpdate || !terminateSimulation || !nominalsOfContinuousStatesChanged ||
        !valuesOfContinuousStatesChanged || !nextEventTimeDefined || !nextEventTime) {
        log_message(inst, STATUS_ERROR, "fmi3UpdateDiscreteStates: no argument may be NULL.");
        return fmi3Error;
    }
    core_calls_due(inst, rules[F_UPDATE_DISCRETE_STATES].name);
    *discreteStatesNeedUpdate = fmi3False;
    *terminateSimulation = fmi3False;
    *nominalsOfContinuousStatesChanged = fmi3False;
    *valuesOfContinuousStatesChanged = fmi3False;
    *nextEventTimeDefined = fmi3True;
    *nextEventTime = core_next_call_time(inst->image);
    return fmi3OK;
}

/* The outputs are those of the last call: there is nothing to evaluate. */
fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance i)
{
    return allowed(i, F_EVALUATE_DISCRETE_STATES) ? fmi3OK : fmi3Error;
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance i)
{
    instance *inst = allowed(i, F_ENTER_CONTINUOUS_TIME_MODE);
    if (!inst) return fmi3Error;
    inst->image->mode = MODE_CONTINUOUS;
    return fmi3OK;
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance i, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean *enterEventMode, fmi3Boolean *terminateSimulation)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    instance *inst = allowed(i, F_COMPLETED_INTEGRATOR_STEP);
    if (!inst) return fmi3Error;
    if (!enterEventMode || !terminateSimulation) {
        log_message(inst, STATUS_ERROR,
                    "fmi3CompletedIntegratorStep: enterEventMode and terminateSimulation must not "
                    "be NULL.");
        return fmi3Error;
    }
    *enterEventMode = fmi3False;
    *terminateSimulation = fmi3False;
    return fmi3OK;
}

fmi3Status fmi3SetTime(fmi3Instance i, fmi3Float64 time)
{
    instance *inst = allowed(i, F_SET_TIME);
    return inst ? (fmi3Status)core_set_time(inst, rules[F_SET_TIME].name, time) : fmi3Error;
}

/* No continuous states, no event indicators. */
static fmi3Status none_of_them(fmi3Instance i, fmi_function f, size_t n, const char *what)
{
    instance *inst = allowed(i, f);
    return inst ? (fmi3Status)core_none(inst, rules[f].name, n, what) : fmi3Error;
}

fmi3Status fmi3SetContinuousStates(fmi3Instance i, const fmi3Float64 x[], size_t nx)
{
    (void)x;
    return none_of_them(i, F_SET_CONTINUOUS_STATES, nx, "nContinuousStates");
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance i, fmi3Float64 derivatives[], size_t nx)
{
    (void)derivatives;
    return none_of_them(i, F_GET_DERIVATIVES, nx, "nContinuousStates");
}

fmi3Status fmi3GetEventIndicators(fmi3Instance i, fmi3Float64 eventIndicators[], size_t ni)
{
    (void)eventIndicators;
    return none_of_them(i, F_GET_EVENT_INDICATORS, ni, "nEventIndicators");
}

fmi3Status fmi3GetContinuousStates(fmi3Instance i, fmi3Float64 x[], size_t nx)
{
    (void)x;
    return none_of_them(i, F_GET_CONTINUOUS_STATES, nx, "nContinuousStates");
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance i, fmi3Float64 nominals[], size_t nx)
{
    (void)nominals;
    return none_of_them(i, F_GET_NOMINALS, nx, "nContinuousStates");
}

static fmi3Status count_none(fmi3Instance i, fmi_function f, size_t *n)
{
    instance *inst = allowed(i, f);
    if (!inst) return fmi3Error;
    if (!n) {
        log_message(inst, STATUS_ERROR, "%s: the count must not be NULL.", rules[f].name);
        return fmi3Error;
    }
    *n = 0;
    return fmi3OK;
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance i, size_t *nEventIndicators)
{
    return count_none(i, F_NUMBER_OF_EVENT_INDICATORS, nEventIndicators);
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance i, size_t *nContinuousStates)
{
    return count_none(i, F_NUMBER_OF_CONTINUOUS_STATES, nContinuousStates);
}

/* ---- what this FMU does not provide (see the capability flags in its XML) ---- */

static fmi3Status unsupported(fmi3Instance i, const char *function, const char *why)
{
    if (i) log_message(i, STATUS_ERROR, "%s is not supported: %s.", function, why);
    return fmi3Error;
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance i, fmi3ValueReference valueReference,
                                               size_t *nDependencies)
{
    (void)valueReference, (void)nDependencies;
    return unsupported(i, "fmi3GetNumberOfVariableDependencies",
                       "providesPerElementDependencies is false; see the ModelStructure");
}

fmi3Status fmi3GetVariableDependencies(fmi3Instance i, fmi3ValueReference dependent,
                                       size_t elementIndicesOfDependent[],
                                       fmi3ValueReference independents[],
                                       size_t elementIndicesOfIndependents[],
                                       fmi3DependencyKind dependencyKinds[], size_t nDependencies)
{
    (void)dependent, (void)elementIndicesOfDependent, (void)independents;
    (void)elementIndicesOfIndependents, (void)dependencyKinds, (void)nDependencies;
    return unsupported(i, "fmi3GetVariableDependencies",
                       "providesPerElementDependencies is false; see the ModelStructure");
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance i, const fmi3ValueReference unknowns[],
                                        size_t nUnknowns, const fmi3ValueReference knowns[],
                                        size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                        fmi3Float64 sensitivity[], size_t nSensitivity)
{
    (void)unknowns, (void)nUnknowns, (void)knowns, (void)nKnowns, (void)seed, (void)nSeed;
    (void)sensitivity, (void)nSensitivity;
    return unsupported(i, "fmi3GetDirectionalDerivative", "providesDirectionalDerivatives is false");
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance i, const fmi3ValueReference unknowns[],
                                    size_t nUnknowns, const fmi3ValueReference knowns[],
                                    size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                    fmi3Float64 sensitivity[], size_t nSensitivity)
{
    (void)unknowns, (void)nUnknowns, (void)knowns, (void)nKnowns, (void)seed, (void)nSeed;
    (void)sensitivity, (void)nSensitivity;
    return unsupported(i, "fmi3GetAdjointDerivative", "providesAdjointDerivatives is false");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance i)
{
    return unsupported(i, "fmi3EnterConfigurationMode", "the FMU has no structural parameters");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance i)
{
    return unsupported(i, "fmi3ExitConfigurationMode", "the FMU has no structural parameters");
}

fmi3Status fmi3EnterStepMode(fmi3Instance i)
{
    return unsupported(i, "fmi3EnterStepMode",
                       "the FMU does not use event mode in co-simulation (hasEventMode is false)");
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                    const fmi3Int32 orders[], fmi3Float64 values[], size_t nValues)
{
    (void)vr, (void)nvr, (void)orders, (void)values, (void)nValues;
    return unsupported(i, "fmi3GetOutputDerivatives", "maxOutputDerivativeOrder is 0");
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance i, fmi3ValueReference clockReference,
                                      fmi3Float64 activationTime)
{
    (void)clockReference, (void)activationTime;
    return unsupported(i, "fmi3ActivateModelPartition", "the FMU has no clocks");
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                  fmi3Float64 intervals[], fmi3IntervalQualifier qualifiers[])
{
    (void)vr, (void)nvr, (void)intervals, (void)qualifiers;
    return unsupported(i, "fmi3GetIntervalDecimal", "the FMU has no clocks");
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                   fmi3UInt64 counters[], fmi3UInt64 resolutions[],
                                   fmi3IntervalQualifier qualifiers[])
{
    (void)vr, (void)nvr, (void)counters, (void)resolutions, (void)qualifiers;
    return unsupported(i, "fmi3GetIntervalFraction", "the FMU has no clocks");
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                               fmi3Float64 shifts[])
{
    (void)vr, (void)nvr, (void)shifts;
    return unsupported(i, "fmi3GetShiftDecimal", "the FMU has no clocks");
}

fmi3Status fmi3GetShiftFraction(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                fmi3UInt64 counters[], fmi3UInt64 resolutions[])
{
    (void)vr, (void)nvr, (void)counters, (void)resolutions;
    return unsupported(i, "fmi3GetShiftFraction", "the FMU has no clocks");
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                  const fmi3Float64 intervals[])
{
    (void)vr, (void)nvr, (void)intervals;
    return unsupported(i, "fmi3SetIntervalDecimal", "the FMU has no clocks");
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                   const fmi3UInt64 counters[], const fmi3UInt64 resolutions[])
{
    (void)vr, (void)nvr, (void)counters, (void)resolutions;
    return unsupported(i, "fmi3SetIntervalFraction", "the FMU has no clocks");
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                               const fmi3Float64 shifts[])
{
    (void)vr, (void)nvr, (void)shifts;
    return unsupported(i, "fmi3SetShiftDecimal", "the FMU has no clocks");
}

fmi3Status fmi3SetShiftFraction(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                const fmi3UInt64 counters[], const fmi3UInt64 resolutions[])
{
    (void)vr, (void)nvr, (void)counters, (void)resolutions;
    return unsupported(i, "fmi3SetShiftFraction", "the FMU has no clocks");
}
