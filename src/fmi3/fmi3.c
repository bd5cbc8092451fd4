/* The FMI 3.0 front-end: the fmi3 entry points of Co-Simulation and Model Exchange, translated
 * onto the same core as FMI 2.0, with the PLC's own widths (docs/behaviour.md §7): INT is Int16,
 * WORD UInt16, UDINT UInt32, REAL Float32, LREAL and TIME Float64, BOOL Boolean. Each entry point
 * names its kind of call, whose modes the core's table gives (core/modes.c: FMI 3.0, 3.2 and
 * 4.2), and those FMI 2.0 has alike are written once (core/entry_points.h). */
#include <stdlib.h>
#include <string.h>

#include "fmi3Functions.h"
#include "core/core.c"
#include "core/entry_points.h"

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

/* ---- instances and the mode machine ---- */

const char *fmi3GetVersion(void) { return fmi3Version; }

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
    return core_instantiate(&probe.core, sizeof probe, function, refusal, loggingOn);
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

CORE_LIFECYCLE_ENTRY_POINTS(fmi3Status, fmi3Instance, fmi3Boolean, fmi3String, fmi3SetDebugLogging,
                            fmi3ExitInitializationMode, fmi3Terminate, fmi3Reset, fmi3FreeInstance)

fmi3Status fmi3EnterInitializationMode(fmi3Instance i, fmi3Boolean toleranceDefined,
                                       fmi3Float64 tolerance, fmi3Float64 startTime,
                                       fmi3Boolean stopTimeDefined, fmi3Float64 stopTime)
{
    (void)toleranceDefined, (void)tolerance; /* the block is discrete: nothing to integrate */
    instance *inst = core_allowed(i, "fmi3EnterInitializationMode", CALL_SETUP);
    if (!inst) return fmi3Error;
    lgf_status status =
        core_setup(inst, "fmi3EnterInitializationMode", startTime, stopTimeDefined, stopTime);
    if (status == STATUS_OK) inst->image->mode = MODE_INITIALIZATION;
    return (fmi3Status)status;
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

#define FMI3_SETTER(function, kind, carrier, type)                                                 \
    fmi3Status function(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,                 \
                        const type values[], size_t nValues)                                       \
    {                                                                                              \
        instance *inst = core_allowed(i, #function, CALL_SET);                                     \
        if (!inst || !fmi3_scalars(inst, #function, nvr, nValues)) return fmi3Error;               \
        return (fmi3Status)core_set(inst, #function, &fmi3_types, kind, carrier, vr, nvr, values); \
    }

#define FMI3_GETTER(function, kind, carrier, type)                                                 \
    fmi3Status function(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr, type values[],  \
                        size_t nValues)                                                            \
    {                                                                                              \
        instance *inst = core_allowed(i, #function, CALL_GET);                                     \
        if (!inst || !fmi3_scalars(inst, #function, nvr, nValues)) return fmi3Error;               \
        return (fmi3Status)core_get(inst, #function, &fmi3_types, kind, carrier, vr, nvr, values); \
    }

FMI3_SETTER(fmi3SetFloat64, KIND_FLOAT64, CARRIER_DOUBLE, fmi3Float64)
FMI3_SETTER(fmi3SetInt16, KIND_INT16, CARRIER_INT16, fmi3Int16)
FMI3_SETTER(fmi3SetUInt16, KIND_UINT16, CARRIER_UINT16, fmi3UInt16)
FMI3_SETTER(fmi3SetBoolean, KIND_BOOLEAN, CARRIER_BOOL, fmi3Boolean)
FMI3_SETTER(fmi3SetFloat32, KIND_FLOAT32, CARRIER_FLOAT, fmi3Float32)
FMI3_SETTER(fmi3SetUInt32, KIND_UINT32, CARRIER_UINT32, fmi3UInt32)
FMI3_SETTER(fmi3SetInt32, KIND_INT32, CARRIER_INT32, fmi3Int32)
FMI3_SETTER(fmi3SetInt8, KIND_INT8, CARRIER_INT8, fmi3Int8)
FMI3_SETTER(fmi3SetUInt8, KIND_UINT8, CARRIER_UINT8, fmi3UInt8)

/* Float64 also reads the independent variable, time (TIME_VR), one value at a time. */
fmi3Status fmi3GetFloat64(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                          fmi3Float64 values[], size_t nValues)
{
    const char *function = "fmi3GetFloat64";
    instance *inst = core_allowed(i, function, CALL_GET);
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
FMI3_GETTER(fmi3GetInt16, KIND_INT16, CARRIER_INT16, fmi3Int16)
FMI3_GETTER(fmi3GetUInt16, KIND_UINT16, CARRIER_UINT16, fmi3UInt16)
FMI3_GETTER(fmi3GetBoolean, KIND_BOOLEAN, CARRIER_BOOL, fmi3Boolean)
FMI3_GETTER(fmi3GetFloat32, KIND_FLOAT32, CARRIER_FLOAT, fmi3Float32)
FMI3_GETTER(fmi3GetUInt32, KIND_UINT32, CARRIER_UINT32, fmi3UInt32)
FMI3_GETTER(fmi3GetInt32, KIND_INT32, CARRIER_INT32, fmi3Int32)
FMI3_GETTER(fmi3GetInt8, KIND_INT8, CARRIER_INT8, fmi3Int8)
FMI3_GETTER(fmi3GetUInt8, KIND_UINT8, CARRIER_UINT8, fmi3UInt8)

/* The types this FMU has no variable of: any value reference is unknown to them. */
static fmi3Status no_such_type(fmi3Instance i, const char *function, const fmi3ValueReference vr[],
                               size_t nvr, size_t nValues)
{
    instance *inst = core_allowed(i, function, CALL_ANY_MODE);
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
    const char *function = "fmi3SetString";
    instance *inst = core_allowed(i, function, CALL_SET);
    if (!inst || !fmi3_scalars(inst, function, nvr, nValues)) return fmi3Error;
    return (fmi3Status)core_set_strings(inst, function, &fmi3_types, KIND_STRING, vr, nvr, values);
}

fmi3Status fmi3GetString(fmi3Instance i, const fmi3ValueReference vr[], size_t nvr,
                         fmi3String values[], size_t nValues)
{
    const char *function = "fmi3GetString";
    instance *inst = core_allowed(i, function, CALL_GET);
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

CORE_STATE_ENTRY_POINTS(fmi3Status, fmi3Instance, fmi3FMUState, fmi3Byte, fmi3GetFMUState,
                        fmi3SetFMUState, fmi3FreeFMUState, fmi3SerializedFMUStateSize,
                        fmi3SerializeFMUState, fmi3DeserializeFMUState)

/* ---- Co-Simulation ---- */

fmi3Status fmi3DoStep(fmi3Instance i, fmi3Float64 currentCommunicationPoint,
                      fmi3Float64 communicationStepSize,
                      fmi3Boolean noSetFMUStatePriorToCurrentPoint,
                      fmi3Boolean *eventHandlingNeeded, fmi3Boolean *terminateSimulation,
                      fmi3Boolean *earlyReturn, fmi3Float64 *lastSuccessfulTime)
{
    (void)noSetFMUStatePriorToCurrentPoint;
    instance *inst = core_allowed(i, "fmi3DoStep", CALL_DO_STEP);
    if (!inst) return fmi3Error;
    if (!eventHandlingNeeded || !terminateSimulation || !earlyReturn || !lastSuccessfulTime) {
        core_log(inst, STATUS_ERROR,
                 "fmi3DoStep: eventHandlingNeeded, terminateSimulation, earlyReturn and "
                 "lastSuccessfulTime must not be NULL.");
        return fmi3Error;
    }
    lgf_status status =
        core_do_step(inst, "fmi3DoStep", currentCommunicationPoint, communicationStepSize);
    *eventHandlingNeeded = fmi3False;
    *terminateSimulation = fmi3False;
    *earlyReturn = fmi3False;
    *lastSuccessfulTime = inst->image->time;
    return (fmi3Status)status;
}

/* ---- Model Exchange (docs/behaviour.md §1.11) ---- */

fmi3Status fmi3UpdateDiscreteStates(fmi3Instance i, fmi3Boolean *discreteStatesNeedUpdate,
                                    fmi3Boolean *terminateSimulation,
                                    fmi3Boolean *nominalsOfContinuousStatesChanged,
                                    fmi3Boolean *valuesOfContinuousStatesChanged,
                                    fmi3Boolean *nextEventTimeDefined, fmi3Float64 *nextEventTime)
{
    const char *function = "fmi3UpdateDiscreteStates";
    instance *inst = core_allowed(i, function, CALL_EVENT);
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
    return core_allowed(i, "fmi3EvaluateDiscreteStates", CALL_EVENT) ? fmi3OK : fmi3Error;
}

CORE_MODEL_EXCHANGE_ENTRY_POINTS(fmi3Status, fmi3Instance, fmi3Float64, fmi3Boolean,
                                 fmi3EnterEventMode, fmi3EnterContinuousTimeMode,
                                 fmi3CompletedIntegratorStep, fmi3SetTime, fmi3SetContinuousStates,
                                 fmi3GetContinuousStateDerivatives, fmi3GetEventIndicators,
                                 fmi3GetContinuousStates, fmi3GetNominalsOfContinuousStates,
                                 "nContinuousStates", "nEventIndicators")

static fmi3Status fmi3_count_none(fmi3Instance i, const char *function, size_t *n)
{
    instance *inst = core_allowed(i, function, CALL_EXCHANGE_ANY_MODE);
    if (!inst) return fmi3Error;
    if (!n) {
        core_log(inst, STATUS_ERROR, "%s: the count must not be NULL.", function);
        return fmi3Error;
    }
    *n = 0;
    return fmi3OK;
}

fmi3Status fmi3GetNumberOfEventIndicators(fmi3Instance i, size_t *nEventIndicators)
{
    return fmi3_count_none(i, "fmi3GetNumberOfEventIndicators", nEventIndicators);
}

fmi3Status fmi3GetNumberOfContinuousStates(fmi3Instance i, size_t *nContinuousStates)
{
    return fmi3_count_none(i, "fmi3GetNumberOfContinuousStates", nContinuousStates);
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
