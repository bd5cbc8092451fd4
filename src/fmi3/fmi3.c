/* The FMI 3.0 front-end: the fmi3 entry points of Co-Simulation and Model Exchange, translated
 * onto the same core as FMI 2.0, with the PLC's own widths (docs/behaviour.md §7): INT is Int16,
 * WORD UInt16, UDINT UInt32, REAL Float32, LREAL and TIME Float64, BOOL Boolean. One table says which function
 * may be called in which mode (FMI 3.0, 3.2 and 4.2). */
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "core/core.c"

/* An instance as the importer sees it: the core's, the importer's logger and the interface. */
typedef struct {
    instance core; /* first: an fmi3Instance points at both */
    fmi3InstanceEnvironment environment;
    fmi3LogMessageCallback log;
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

typedef enum {
    F_ENTER_INITIALIZATION,
    F_EXIT_INITIALIZATION,
    F_TERMINATE,
    F_SET_FLOAT64,
    F_SET_INT16,
    F_SET_UINT16,
    F_SET_BOOLEAN,
    F_SET_FLOAT32,
    F_SET_UINT32,
    F_SET_INT32,
    F_SET_INT8,
    F_SET_UINT8,
    F_SET_STRING,
    F_GET_FLOAT64,
    F_GET_INT16,
    F_GET_UINT16,
    F_GET_BOOLEAN,
    F_GET_FLOAT32,
    F_GET_UINT32,
    F_GET_INT32,
    F_GET_INT8,
    F_GET_UINT8,
    F_GET_STRING,
    F_OTHER_TYPES,
    F_GET_FMU_STATE,
    F_SET_FMU_STATE,
    F_FREE_FMU_STATE,
    F_SERIALIZED_SIZE,
    F_SERIALIZE,
    F_DESERIALIZE,
    F_DO_STEP,
    F_ENTER_EVENT_MODE,
    F_UPDATE_DISCRETE_STATES,
    F_EVALUATE_DISCRETE_STATES,
    F_ENTER_CONTINUOUS_TIME_MODE,
    F_COMPLETED_INTEGRATOR_STEP,
    F_SET_TIME,
    F_SET_CONTINUOUS_STATES,
    F_GET_DERIVATIVES,
    F_GET_EVENT_INDICATORS,
    F_GET_CONTINUOUS_STATES,
    F_GET_NOMINALS,
    F_NUMBER_OF_EVENT_INDICATORS,
    F_NUMBER_OF_CONTINUOUS_STATES
} fmi3_function;

static const core_rule fmi3_rules[] = {
    [F_ENTER_INITIALIZATION] = {"fmi3EnterInitializationMode", FOR_BOTH,
                                MODE_BIT(MODE_INSTANTIATED)},
    [F_EXIT_INITIALIZATION] = {"fmi3ExitInitializationMode", FOR_BOTH,
                               MODE_BIT(MODE_INITIALIZATION)},
    [F_TERMINATE] = {"fmi3Terminate", FOR_BOTH, MODES_RUNNING},
    [F_SET_FLOAT64] = {"fmi3SetFloat64", FOR_BOTH, MODES_SETTABLE},
    [F_SET_INT16] = {"fmi3SetInt16", FOR_BOTH, MODES_SETTABLE},
    [F_SET_UINT16] = {"fmi3SetUInt16", FOR_BOTH, MODES_SETTABLE},
    [F_SET_BOOLEAN] = {"fmi3SetBoolean", FOR_BOTH, MODES_SETTABLE},
    [F_SET_FLOAT32] = {"fmi3SetFloat32", FOR_BOTH, MODES_SETTABLE},
    [F_SET_UINT32] = {"fmi3SetUInt32", FOR_BOTH, MODES_SETTABLE},
    [F_SET_INT32] = {"fmi3SetInt32", FOR_BOTH, MODES_SETTABLE},
    [F_SET_INT8] = {"fmi3SetInt8", FOR_BOTH, MODES_SETTABLE},
    [F_SET_UINT8] = {"fmi3SetUInt8", FOR_BOTH, MODES_SETTABLE},
    [F_SET_STRING] = {"fmi3SetString", FOR_BOTH, MODES_SETTABLE},
    [F_GET_FLOAT64] = {"fmi3GetFloat64", FOR_BOTH, MODES_READABLE},
    [F_GET_INT16] = {"fmi3GetInt16", FOR_BOTH, MODES_READABLE},
    [F_GET_UINT16] = {"fmi3GetUInt16", FOR_BOTH, MODES_READABLE},
    [F_GET_BOOLEAN] = {"fmi3GetBoolean", FOR_BOTH, MODES_READABLE},
    [F_GET_FLOAT32] = {"fmi3GetFloat32", FOR_BOTH, MODES_READABLE},
    [F_GET_UINT32] = {"fmi3GetUInt32", FOR_BOTH, MODES_READABLE},
    [F_GET_INT32] = {"fmi3GetInt32", FOR_BOTH, MODES_READABLE},
    [F_GET_INT8] = {"fmi3GetInt8", FOR_BOTH, MODES_READABLE},
    [F_GET_UINT8] = {"fmi3GetUInt8", FOR_BOTH, MODES_READABLE},
    [F_GET_STRING] = {"fmi3GetString", FOR_BOTH, MODES_READABLE},
    [F_OTHER_TYPES] = {"fmi3Get/Set", FOR_BOTH, MODES_ANY},
    [F_GET_FMU_STATE] = {"fmi3GetFMUState", FOR_BOTH, MODES_ANY},
    [F_SET_FMU_STATE] = {"fmi3SetFMUState", FOR_BOTH, MODES_ANY},
    [F_FREE_FMU_STATE] = {"fmi3FreeFMUState", FOR_BOTH, MODES_ANY},
    [F_SERIALIZED_SIZE] = {"fmi3SerializedFMUStateSize", FOR_BOTH, MODES_ANY},
    [F_SERIALIZE] = {"fmi3SerializeFMUState", FOR_BOTH, MODES_ANY},
    [F_DESERIALIZE] = {"fmi3DeserializeFMUState", FOR_BOTH, MODES_ANY},
    [F_DO_STEP] = {"fmi3DoStep", FOR_CS, MODE_BIT(MODE_STEP)},
    [F_ENTER_EVENT_MODE] = {"fmi3EnterEventMode", FOR_ME, MODES_EXCHANGE},
    [F_UPDATE_DISCRETE_STATES] = {"fmi3UpdateDiscreteStates", FOR_ME, MODE_BIT(MODE_EVENT)},
    [F_EVALUATE_DISCRETE_STATES] = {"fmi3EvaluateDiscreteStates", FOR_ME, MODE_BIT(MODE_EVENT)},
    [F_ENTER_CONTINUOUS_TIME_MODE] = {"fmi3EnterContinuousTimeMode", FOR_ME, MODE_BIT(MODE_EVENT)},
    [F_COMPLETED_INTEGRATOR_STEP] = {"fmi3CompletedIntegratorStep", FOR_ME,
                                     MODE_BIT(MODE_CONTINUOUS)},
    [F_SET_TIME] = {"fmi3SetTime", FOR_ME, MODES_EXCHANGE},
    [F_SET_CONTINUOUS_STATES] = {"fmi3SetContinuousStates", FOR_ME, MODE_BIT(MODE_CONTINUOUS)},
    [F_GET_DERIVATIVES] = {"fmi3GetContinuousStateDerivatives", FOR_ME, MODES_READABLE},
    [F_GET_EVENT_INDICATORS] = {"fmi3GetEventIndicators", FOR_ME, MODES_READABLE},
    [F_GET_CONTINUOUS_STATES] = {"fmi3GetContinuousStates", FOR_ME, MODES_READABLE},
    [F_GET_NOMINALS] = {"fmi3GetNominalsOfContinuousStates", FOR_ME, MODES_ANY},
    [F_NUMBER_OF_EVENT_INDICATORS] = {"fmi3GetNumberOfEventIndicators", FOR_ME, MODES_ANY},
    [F_NUMBER_OF_CONTINUOUS_STATES] = {"fmi3GetNumberOfContinuousStates", FOR_ME, MODES_ANY},
};

static instance *fmi3_allowed(fmi3Instance i, fmi3_function f)
{
    return core_allowed(i, &fmi3_rules[f]);
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

static fmi3Instance fmi3_instantiate(const char *function, lgf_interface type, fmi3String name,
                                     fmi3String token, fmi3Boolean loggingOn,
                                     fmi3InstanceEnvironment environment,
                                     fmi3LogMessageCallback log)
{
    fmi3_instance probe = {.core = {.host = &fmi3_host, .name = (char *)name, .interface = type},
                           .environment = environment,
                           .log = log};
    const char *refusal = NULL;
    if (!name || !*name)
        refusal = "instanceName must be a non-empty string";
    else if (!token || strcmp(token, lgf_model.guid))
        refusal = "instantiationToken does not match the one of this FMU's modelDescription.xml";
    if (refusal) {
        core_log(&probe.core, STATUS_ERROR, "%s: %s (%s).", function, refusal,
                 lgf_model.identifier);
        return NULL;
    }
    fmi3_instance *fi = calloc(1, sizeof *fi);
    if (fi) {
        *fi = probe;
        if (core_create(&fi->core, name, loggingOn)) return fi;
        free(fi);
    }
    core_log(&probe.core, STATUS_ERROR, "%s: out of memory.", function);
    return NULL;
}

fmi3Instance fmi3InstantiateModelExchange(fmi3String instanceName, fmi3String instantiationToken,
                                          fmi3String resourcePath, fmi3Boolean visible,
                                          fmi3Boolean loggingOn,
                                          fmi3InstanceEnvironment instanceEnvironment,
                                          fmi3LogMessageCallback logMessage)
{
    (void)resourcePath, (void)visible;
    return fmi3_instantiate("fmi3InstantiateModelExchange", INTERFACE_ME, instanceName,
                            instantiationToken, loggingOn, instanceEnvironment, logMessage);
}

/* The block never needs event mode nor returns early: eventModeUsed and earlyReturnAllowed are
 * honoured by not using them (docs/behaviour.md §7). */
fmi3Instance fmi3InstantiateCoSimulation(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3Boolean eventModeUsed,
    fmi3Boolean earlyReturnAllowed, const fmi3ValueReference requiredIntermediateVariables[],
    size_t nRequiredIntermediateVariables, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3IntermediateUpdateCallback intermediateUpdate)
{
    (void)resourcePath, (void)visible, (void)eventModeUsed, (void)earlyReturnAllowed;
    (void)requiredIntermediateVariables, (void)nRequiredIntermediateVariables;
    (void)intermediateUpdate;
    return fmi3_instantiate("fmi3InstantiateCoSimulation", INTERFACE_CS, instanceName,
                            instantiationToken, loggingOn, instanceEnvironment, logMessage);
}

fmi3Instance fmi3InstantiateScheduledExecution(
    fmi3String instanceName, fmi3String instantiationToken, fmi3String resourcePath,
    fmi3Boolean visible, fmi3Boolean loggingOn, fmi3InstanceEnvironment instanceEnvironment,
    fmi3LogMessageCallback logMessage, fmi3ClockUpdateCallback clockUpdate,
    fmi3LockPreemptionCallback lockPreemption, fmi3UnlockPreemptionCallback unlockPreemption)
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
    instance *inst = fmi3_allowed(i, F_ENTER_INITIALIZATION);
    if (!inst) return fmi3Error;
    lgf_status status = core_setup(inst, fmi3_rules[F_ENTER_INITIALIZATION].name, startTime,
                                   stopTimeDefined, stopTime);
    if (status == STATUS_OK) inst->image->mode = MODE_INITIALIZATION;
    return (fmi3Status)status;
}

fmi3Status fmi3ExitInitializationMode(fmi3Instance i)
{
    instance *inst = fmi3_allowed(i, F_EXIT_INITIALIZATION);
    return inst ? (fmi3Status)core_exit_initialization(inst, fmi3_rules[F_EXIT_INITIALIZATION].name)
                : fmi3Error;
}

fmi3Status fmi3Terminate(fmi3Instance i)
{
    return (fmi3Status)core_enter_mode(i, &fmi3_rules[F_TERMINATE], MODE_TERMINATED);
}

fmi3Status fmi3Reset(fmi3Instance i)
{
    instance *inst = i;
    if (!inst) return fmi3Error;
    core_image_reset(inst->image);
    return fmi3OK;
}

/* ---- variables ---- */

enum {
    KIND_FLOAT64,
    KIND_INT16,
    KIND_UINT16,
    KIND_BOOLEAN,
    KIND_FLOAT32,
    KIND_UINT32,
    KIND_INT32,
    KIND_INT8,
    KIND_UINT8,
    KIND_STRING
};
static const char *const fmi3_kind_names[] = {"Float64", "Int16", "UInt16", "Boolean", "Float32",
                                              "UInt32",  "Int32", "Int8",   "UInt8",   "String"};
static const fmi_types fmi3_types = {
    .kind_of = {[VAR_CYCLE] = KIND_FLOAT64,
                [VAR_LREAL] = KIND_FLOAT64,
                [VAR_TIME] = KIND_FLOAT64,
                [VAR_INT] = KIND_INT16,
                [VAR_WORD] = KIND_UINT16,
                [VAR_REAL] = KIND_FLOAT32,
                [VAR_UDINT] = KIND_UINT32,
                [VAR_DINT] = KIND_INT32,
                [VAR_UINT] = KIND_UINT16,
                [VAR_SINT] = KIND_INT8,
                [VAR_USINT] = KIND_UINT8,
                [VAR_BYTE] = KIND_UINT8,
                [VAR_DWORD] = KIND_UINT32,
                [VAR_STRING] = KIND_STRING,
                [VAR_WSTRING] = KIND_STRING,
                [VAR_BOOL] = KIND_BOOLEAN},
    .kind_names = fmi3_kind_names,
};

/* Every variable is a scalar: one value per value reference. */
static bool fmi3_scalars(instance *inst, const char *function, size_t nvr, size_t nValues)
{
    if (nValues == nvr) return true;
    core_log(inst, STATUS_ERROR,
             "%s: nValues is %llu but nValueReferences is %llu; every variable of %s is a "
             "scalar.",
             function, (unsigned long long)nValues, (unsigned long long)nvr, lgf_model.identifier);
    return false;
}

#define FMI3_SETTER(function, f, kind, carrier, type)                                              \
    fmi3Status function(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,                 \
                        const type values[], size_t nValues)                                       \
    {                                                                                              \
        instance *inst = fmi3_allowed(i, f);                                                       \
        if (!inst || !fmi3_scalars(inst, fmi3_rules[f].name, nvr, nValues)) return fmi3Error;      \
        return (fmi3Status)core_set(inst, fmi3_rules[f].name, &fmi3_types, kind, carrier, vr, nvr, \
                                    values);                                                       \
    }

#define FMI3_GETTER(function, f, kind, carrier, type)                                              \
    fmi3Status function(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, type values[],  \
                        size_t nValues)                                                            \
    {                                                                                              \
        instance *inst = fmi3_allowed(i, f);                                                       \
        if (!inst || !fmi3_scalars(inst, fmi3_rules[f].name, nvr, nValues)) return fmi3Error;      \
        return (fmi3Status)core_get(inst, fmi3_rules[f].name, &fmi3_types, kind, carrier, vr, nvr, \
                                    values);                                                       \
    }

FMI3_SETTER(fmi3SetFloat64, F_SET_FLOAT64, KIND_FLOAT64, CARRIER_DOUBLE, fmi3Float64)
FMI3_SETTER(fmi3SetInt16, F_SET_INT16, KIND_INT16, CARRIER_INT16, fmi3Int16)
FMI3_SETTER(fmi3SetUInt16, F_SET_UINT16, KIND_UINT16, CARRIER_UINT16, fmi3UInt16)
FMI3_SETTER(fmi3SetBoolean, F_SET_BOOLEAN, KIND_BOOLEAN, CARRIER_BOOL, fmi3Boolean)
FMI3_SETTER(fmi3SetFloat32, F_SET_FLOAT32, KIND_FLOAT32, CARRIER_FLOAT, fmi3Float32)
FMI3_SETTER(fmi3SetUInt32, F_SET_UINT32, KIND_UINT32, CARRIER_UINT32, fmi3UInt32)
FMI3_SETTER(fmi3SetInt32, F_SET_INT32, KIND_INT32, CARRIER_INT32, fmi3Int32)
FMI3_SETTER(fmi3SetInt8, F_SET_INT8, KIND_INT8, CARRIER_INT8, fmi3Int8)
FMI3_SETTER(fmi3SetUInt8, F_SET_UINT8, KIND_UINT8, CARRIER_UINT8, fmi3UInt8)

/* Float64 also reads the independent variable, time (TIME_VR), one value at a time. */
fmi3Status fmi3GetFloat64(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float64 values[], size_t nValues)
{
    instance *inst = fmi3_allowed(i, F_GET_FLOAT64);
    const char *function = fmi3_rules[F_GET_FLOAT64].name;
    if (!inst || !fmi3_scalars(inst, function, nvr, nValues)) return fmi3Error;
    bool time = false;
    for (size_t k = 0; k < nvr && vr; k++) time |= vr[k] == TIME_VR;
    if (!time || !values) /* core_get refuses NULL arrays */
        return (fmi3Status)core_get(inst, function, &fmi3_types, KIND_FLOAT64, CARRIER_DOUBLE, vr,
                                    nvr, values);
    for (size_t k = 0; k < nvr; k++) {
        if (vr[k] == TIME_VR)
            values[k] = inst->image->time;
        else if (core_get(inst, function, &fmi3_types, KIND_FLOAT64, CARRIER_DOUBLE, vr + k, 1,
                          values + k) != STATUS_OK)
            return fmi3Error;
    }
    return fmi3OK;
}
FMI3_GETTER(fmi3GetInt16, F_GET_INT16, KIND_INT16, CARRIER_INT16, fmi3Int16)
FMI3_GETTER(fmi3GetUInt16, F_GET_UINT16, KIND_UINT16, CARRIER_UINT16, fmi3UInt16)
FMI3_GETTER(fmi3GetBoolean, F_GET_BOOLEAN, KIND_BOOLEAN, CARRIER_BOOL, fmi3Boolean)
FMI3_GETTER(fmi3GetFloat32, F_GET_FLOAT32, KIND_FLOAT32, CARRIER_FLOAT, fmi3Float32)
FMI3_GETTER(fmi3GetUInt32, F_GET_UINT32, KIND_UINT32, CARRIER_UINT32, fmi3UInt32)
FMI3_GETTER(fmi3GetInt32, F_GET_INT32, KIND_INT32, CARRIER_INT32, fmi3Int32)
FMI3_GETTER(fmi3GetInt8, F_GET_INT8, KIND_INT8, CARRIER_INT8, fmi3Int8)
FMI3_GETTER(fmi3GetUInt8, F_GET_UINT8, KIND_UINT8, CARRIER_UINT8, fmi3UInt8)

/* The types this FMU has no variable of: any value reference is unknown to them. */
static fmi3Status no_such_type(fmi3Instance i, const char *function, const fmi3ValueReference vr[],
                               size_t nvr, size_t nValues)
{
    instance *inst = fmi3_allowed(i, F_OTHER_TYPES);
    if (!inst || !fmi3_scalars(inst, function, nvr, nValues)) return fmi3Error;
    if (nvr == 0) return fmi3OK;
    core_log(inst, STATUS_ERROR, "%s: %s has no variable of this type (value reference %u).",
             function, lgf_model.identifier, vr ? (unsigned)vr[0] : 0u);
    return fmi3Error;
}

#define NO_GETTER(function, type)                                                                  \
    fmi3Status function(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, type values[],  \
                        size_t nValues)                                                            \
    {                                                                                              \
        (void)values;                                                                              \
        return no_such_type(i, #function, vr, nvr, nValues);                                       \
    }
#define NO_SETTER(function, type)                                                                  \
    fmi3Status function(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,                 \
                        const type values[], size_t nValues)                                       \
    {                                                                                              \
        (void)values;                                                                              \
        return no_such_type(i, #function, vr, nvr, nValues);                                       \
    }

NO_GETTER(fmi3GetInt64, fmi3Int64)
NO_GETTER(fmi3GetUInt64, fmi3UInt64)
NO_SETTER(fmi3SetInt64, fmi3Int64)
NO_SETTER(fmi3SetUInt64, fmi3UInt64)

/* The String variables of compiled SCL (core/strings.c): UTF-8. */
fmi3Status fmi3SetString(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                         const fmi3String values[], size_t nValues)
{
    instance *inst = fmi3_allowed(i, F_SET_STRING);
    const char *function = fmi3_rules[F_SET_STRING].name;
    if (!inst || !fmi3_scalars(inst, function, nvr, nValues)) return fmi3Error;
    return (fmi3Status)core_set_strings(inst, function, &fmi3_types, KIND_STRING, vr, nvr, values);
}

fmi3Status fmi3GetString(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                         fmi3String values[], size_t nValues)
{
    instance *inst = fmi3_allowed(i, F_GET_STRING);
    const char *function = fmi3_rules[F_GET_STRING].name;
    if (!inst || !fmi3_scalars(inst, function, nvr, nValues)) return fmi3Error;
    return (fmi3Status)core_get_strings(inst, function, &fmi3_types, KIND_STRING, vr, nvr, values);
}

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
    instance *inst = fmi3_allowed(i, F_GET_FMU_STATE);
    return inst ? (fmi3Status)core_get_state(inst, fmi3_rules[F_GET_FMU_STATE].name, FMUState)
                : fmi3Error;
}

fmi3Status fmi3SetFMUState(fmi3Instance i, fmi3FMUState FMUState)
{
    instance *inst = fmi3_allowed(i, F_SET_FMU_STATE);
    return inst ? (fmi3Status)core_set_state(inst, fmi3_rules[F_SET_FMU_STATE].name, FMUState,
                                             core_modes_of(i))
                : fmi3Error;
}

fmi3Status fmi3FreeFMUState(fmi3Instance i, fmi3FMUState *FMUState)
{
    instance *inst = fmi3_allowed(i, F_FREE_FMU_STATE);
    return inst ? (fmi3Status)core_free_state(inst, fmi3_rules[F_FREE_FMU_STATE].name, FMUState)
                : fmi3Error;
}

fmi3Status fmi3SerializedFMUStateSize(fmi3Instance i, fmi3FMUState FMUState, size_t *size)
{
    instance *inst = fmi3_allowed(i, F_SERIALIZED_SIZE);
    return inst ? (fmi3Status)core_state_size(inst, fmi3_rules[F_SERIALIZED_SIZE].name, FMUState,
                                              size)
                : fmi3Error;
}

fmi3Status fmi3SerializeFMUState(fmi3Instance i, fmi3FMUState FMUState, fmi3Byte serializedState[],
                                 size_t size)
{
    instance *inst = fmi3_allowed(i, F_SERIALIZE);
    return inst ? (fmi3Status)core_serialize(inst, fmi3_rules[F_SERIALIZE].name, FMUState,
                                             serializedState, size)
                : fmi3Error;
}

fmi3Status fmi3DeserializeFMUState(fmi3Instance i, const fmi3Byte serializedState[], size_t size,
                                   fmi3FMUState *FMUState)
{
    instance *inst = fmi3_allowed(i, F_DESERIALIZE);
    return inst ? (fmi3Status)core_deserialize(inst, fmi3_rules[F_DESERIALIZE].name,
                                               serializedState, size, FMUState, core_modes_of(i))
                : fmi3Error;
}

/* ---- Co-Simulation ---- */

fmi3Status fmi3DoStep(fmi3Instance i, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,
                      fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    instance *inst = fmi3_allowed(i, F_DO_STEP);
    if (!inst) return fmi3Error;
    if (!eventHandlingNeeded || !terminateSimulation || !earlyReturn || !lastSuccessfulTime) {
        core_log(inst, STATUS_ERROR,
                 "fmi3DoStep: eventHandlingNeeded, terminateSimulation, earlyReturn and "
                 "lastSuccessfulTime must not be NULL.");
        return fmi3Error;
    }
    lgf_status status = core_do_step(inst, fmi3_rules[F_DO_STEP].name, currentCommunicationPoint,
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
    return (fmi3Status)core_enter_mode(i, &fmi3_rules[F_ENTER_EVENT_MODE], MODE_EVENT);
}

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance i, fmi3Boolean *discreteStatesNeedUpdate,
                                    fmi3Boolean *terminateSimulation,
                                    fmi3Boolean *nominalsOfContinuousStatesChanged,
                                    fmi3Boolean *valuesOfContinuousStatesChanged,
                                    fmi3Boolean *nextEventTimeDefined, fmi3Float64 *nextEventTime)
{
    const char *function = fmi3_rules[F_UPDATE_DISCRETE_STATES].name;
    instance *inst = fmi3_allowed(i, F_UPDATE_DISCRETE_STATES);
    if (!inst ||
        !core_given(inst, function,
                    discreteStatesNeedUpdate && terminateSimulation &&
                        nominalsOfContinuousStatesChanged && valuesOfContinuousStatesChanged &&
                        nextEventTimeDefined && nextEventTime,
                    "no argument may be NULL"))
        return fmi3Error;
    if (core_update_discrete_states(inst, function, nextEventTime) != STATUS_OK) return fmi3Error;
    *discreteStatesNeedUpdate = fmi3False;
    *terminateSimulation = fmi3False;
    *nominalsOfContinuousStatesChanged = fmi3False;
    *valuesOfContinuousStatesChanged = fmi3False;
    *nextEventTimeDefined = fmi3True;
    return fmi3OK;
}

/* The outputs are those of the last call: there is nothing to evaluate. */
fmi3Status fmi3EvaluateDiscreteStates(fmi3Instance i)
{
    return fmi3_allowed(i, F_EVALUATE_DISCRETE_STATES) ? fmi3OK : fmi3Error;
}

fmi3Status fmi3EnterContinuousTimeMode(fmi3Instance i)
{
    return (fmi3Status)core_enter_mode(i, &fmi3_rules[F_ENTER_CONTINUOUS_TIME_MODE],
                                       MODE_CONTINUOUS);
}

fmi3Status fmi3CompletedIntegratorStep(fmi3Instance i, fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                                       fmi3Boolean *enterEventMode,
                                       fmi3Boolean *terminateSimulation)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    instance *inst = fmi3_allowed(i, F_COMPLETED_INTEGRATOR_STEP);
    if (!inst || !core_given(inst, fmi3_rules[F_COMPLETED_INTEGRATOR_STEP].name,
                             enterEventMode && terminateSimulation,
                             "enterEventMode and terminateSimulation must not be NULL"))
        return fmi3Error;
    *enterEventMode = fmi3False;
    *terminateSimulation = fmi3False;
    return fmi3OK;
}

fmi3Status fmi3SetTime(fmi3Instance i, fmi3Float64 time)
{
    instance *inst = fmi3_allowed(i, F_SET_TIME);
    return inst ? (fmi3Status)core_set_time(inst, fmi3_rules[F_SET_TIME].name, time) : fmi3Error;
}

/* No continuous states, no event indicators. */
static fmi3Status fmi3_none_of_them(fmi3Instance i, fmi3_function f, size_t n, const char *what)
{
    instance *inst = fmi3_allowed(i, f);
    return inst ? (fmi3Status)core_none(inst, fmi3_rules[f].name, n, what) : fmi3Error;
}

fmi3Status fmi3SetContinuousStates(fmi3Instance i, const fmi3Float64 x[], size_t nx)
{
    (void)x;
    return fmi3_none_of_them(i, F_SET_CONTINUOUS_STATES, nx, "nContinuousStates");
}

fmi3Status fmi3GetContinuousStateDerivatives(fmi3Instance i, fmi3Float64 derivatives[], size_t nx)
{
    (void)derivatives;
    return fmi3_none_of_them(i, F_GET_DERIVATIVES, nx, "nContinuousStates");
}

fmi3Status fmi3GetEventIndicators(fmi3Instance i, fmi3Float64 eventIndicators[], size_t ni)
{
    (void)eventIndicators;
    return fmi3_none_of_them(i, F_GET_EVENT_INDICATORS, ni, "nEventIndicators");
}

fmi3Status fmi3GetContinuousStates(fmi3Instance i, fmi3Float64 x[], size_t nx)
{
    (void)x;
    return fmi3_none_of_them(i, F_GET_CONTINUOUS_STATES, nx, "nContinuousStates");
}

fmi3Status fmi3GetNominalsOfContinuousStates(fmi3Instance i, fmi3Float64 nominals[], size_t nx)
{
    (void)nominals;
    return fmi3_none_of_them(i, F_GET_NOMINALS, nx, "nContinuousStates");
}

static fmi3Status fmi3_count_none(fmi3Instance i, fmi3_function f, size_t *n)
{
    instance *inst = fmi3_allowed(i, f);
    if (!inst) return fmi3Error;
    if (!n) {
        core_log(inst, STATUS_ERROR, "%s: the count must not be NULL.", fmi3_rules[f].name);
        return fmi3Error;
    }
    *n = 0;
    return fmi3OK;
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance i, size_t *nEventIndicators)
{
    return fmi3_count_none(i, F_NUMBER_OF_EVENT_INDICATORS, nEventIndicators);
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance i, size_t *nContinuousStates)
{
    return fmi3_count_none(i, F_NUMBER_OF_CONTINUOUS_STATES, nContinuousStates);
}

/* ---- what this FMU does not provide (see the capability flags in its XML) ---- */

static fmi3Status fmi3_unsupported(fmi3Instance i, const char *function, const char *why)
{
    return (fmi3Status)core_unsupported(i, function, why);
}

fmi3Status fmi3GetNumberOfVariableDependencies(fmi3Instance i, fmi3ValueReference valueReference,
                                               size_t *nDependencies)
{
    (void)valueReference, (void)nDependencies;
    return fmi3_unsupported(i, "fmi3GetNumberOfVariableDependencies",
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
    return fmi3_unsupported(i, "fmi3GetVariableDependencies",
                            "providesPerElementDependencies is false; see the ModelStructure");
}

fmi3Status fmi3GetDirectionalDerivative(fmi3Instance i, const fmi3ValueReference unknowns[],
                                        size_t nUnknowns, const fmi3ValueReference knowns[],
                                        size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                        fmi3Float64 sensitivity[], size_t nSensitivity)
{
    (void)unknowns, (void)nUnknowns, (void)knowns, (void)nKnowns, (void)seed, (void)nSeed;
    (void)sensitivity, (void)nSensitivity;
    return fmi3_unsupported(i, "fmi3GetDirectionalDerivative",
                            "providesDirectionalDerivatives is false");
}

fmi3Status fmi3GetAdjointDerivative(fmi3Instance i, const fmi3ValueReference unknowns[],
                                    size_t nUnknowns, const fmi3ValueReference knowns[],
                                    size_t nKnowns, const fmi3Float64 seed[], size_t nSeed,
                                    fmi3Float64 sensitivity[], size_t nSensitivity)
{
    (void)unknowns, (void)nUnknowns, (void)knowns, (void)nKnowns, (void)seed, (void)nSeed;
    (void)sensitivity, (void)nSensitivity;
    return fmi3_unsupported(i, "fmi3GetAdjointDerivative", "providesAdjointDerivatives is false");
}

fmi3Status fmi3EnterConfigurationMode(fmi3Instance i)
{
    return fmi3_unsupported(i, "fmi3EnterConfigurationMode",
                            "the FMU has no structural parameters");
}

fmi3Status fmi3ExitConfigurationMode(fmi3Instance i)
{
    return fmi3_unsupported(i, "fmi3ExitConfigurationMode", "the FMU has no structural parameters");
}

fmi3Status fmi3EnterStepMode(fmi3Instance i)
{
    return fmi3_unsupported(
        i, "fmi3EnterStepMode",
        "the FMU does not use event mode in co-simulation (hasEventMode is false)");
}

fmi3Status fmi3GetOutputDerivatives(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                    const fmi3Int32 orders[], fmi3Float64 values[], size_t nValues)
{
    (void)vr, (void)nvr, (void)orders, (void)values, (void)nValues;
    return fmi3_unsupported(i, "fmi3GetOutputDerivatives", "maxOutputDerivativeOrder is 0");
}

fmi3Status fmi3ActivateModelPartition(fmi3Instance i, fmi3ValueReference clockReference,
                                      fmi3Float64 activationTime)
{
    (void)clockReference, (void)activationTime;
    return fmi3_unsupported(i, "fmi3ActivateModelPartition", "the FMU has no clocks");
}

fmi3Status fmi3GetIntervalDecimal(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                  fmi3Float64 intervals[], fmi3IntervalQualifier qualifiers[])
{
    (void)vr, (void)nvr, (void)intervals, (void)qualifiers;
    return fmi3_unsupported(i, "fmi3GetIntervalDecimal", "the FMU has no clocks");
}

fmi3Status fmi3GetIntervalFraction(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                   fmi3UInt64 counters[], fmi3UInt64 resolutions[],
                                   fmi3IntervalQualifier qualifiers[])
{
    (void)vr, (void)nvr, (void)counters, (void)resolutions, (void)qualifiers;
    return fmi3_unsupported(i, "fmi3GetIntervalFraction", "the FMU has no clocks");
}

fmi3Status fmi3GetShiftDecimal(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                               fmi3Float64 shifts[])
{
    (void)vr, (void)nvr, (void)shifts;
    return fmi3_unsupported(i, "fmi3GetShiftDecimal", "the FMU has no clocks");
}

fmi3Status fmi3GetShiftFraction(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                fmi3UInt64 counters[], fmi3UInt64 resolutions[])
{
    (void)vr, (void)nvr, (void)counters, (void)resolutions;
    return fmi3_unsupported(i, "fmi3GetShiftFraction", "the FMU has no clocks");
}

fmi3Status fmi3SetIntervalDecimal(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                  const fmi3Float64 intervals[])
{
    (void)vr, (void)nvr, (void)intervals;
    return fmi3_unsupported(i, "fmi3SetIntervalDecimal", "the FMU has no clocks");
}

fmi3Status fmi3SetIntervalFraction(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                   const fmi3UInt64 counters[], const fmi3UInt64 resolutions[])
{
    (void)vr, (void)nvr, (void)counters, (void)resolutions;
    return fmi3_unsupported(i, "fmi3SetIntervalFraction", "the FMU has no clocks");
}

fmi3Status fmi3SetShiftDecimal(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                               const fmi3Float64 shifts[])
{
    (void)vr, (void)nvr, (void)shifts;
    return fmi3_unsupported(i, "fmi3SetShiftDecimal", "the FMU has no clocks");
}

fmi3Status fmi3SetShiftFraction(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                                const fmi3UInt64 counters[], const fmi3UInt64 resolutions[])
{
    (void)vr, (void)nvr, (void)counters, (void)resolutions;
    return fmi3_unsupported(i, "fmi3SetShiftFraction", "the FMU has no clocks");
}
