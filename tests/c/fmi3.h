/* The FMI 3.0 side of the harness: every fmi3 function of the FMU, looked up with dlsym, and
 * the logMessage callback. fmi3.c implements the FMI 3.0 fmu_ops over them and the cases and
 * groups only FMI 3.0 has. */
#ifndef LGF_HARNESS_FMI3_H
#define LGF_HARNESS_FMI3_H

#include "fmi3FunctionTypes.h"

/* Every function an FMI 3.0 FMU exports (FMI 3.0, 2.3): common, Model Exchange, Co-Simulation
 * and Scheduled Execution. */
/* One X() per function, in the order of the standard; laid out by hand. */
/* clang-format off */
#define FMI3_FUNCTIONS(X)              \
    X(GetVersion)                      \
    X(SetDebugLogging)                 \
    X(InstantiateModelExchange)        \
    X(InstantiateCoSimulation)         \
    X(InstantiateScheduledExecution)   \
    X(FreeInstance)                    \
    X(EnterInitializationMode)         \
    X(ExitInitializationMode)          \
    X(EnterEventMode)                  \
    X(Terminate)                       \
    X(Reset)                           \
    X(GetFloat32)                      \
    X(GetFloat64)                      \
    X(GetInt8)                         \
    X(GetUInt8)                        \
    X(GetInt16)                        \
    X(GetUInt16)                       \
    X(GetInt32)                        \
    X(GetUInt32)                       \
    X(GetInt64)                        \
    X(GetUInt64)                       \
    X(GetBoolean)                      \
    X(GetString)                       \
    X(GetBinary)                       \
    X(GetClock)                        \
    X(SetFloat32)                      \
    X(SetFloat64)                      \
    X(SetInt8)                         \
    X(SetUInt8)                        \
    X(SetInt16)                        \
    X(SetUInt16)                       \
    X(SetInt32)                        \
    X(SetUInt32)                       \
    X(SetInt64)                        \
    X(SetUInt64)                       \
    X(SetBoolean)                      \
    X(SetString)                       \
    X(SetBinary)                       \
    X(SetClock)                        \
    X(GetNumberOfVariableDependencies) \
    X(GetVariableDependencies)         \
    X(GetFMUState)                     \
    X(SetFMUState)                     \
    X(FreeFMUState)                    \
    X(SerializedFMUStateSize)          \
    X(SerializeFMUState)               \
    X(DeserializeFMUState)             \
    X(GetDirectionalDerivative)        \
    X(GetAdjointDerivative)            \
    X(EnterConfigurationMode)          \
    X(ExitConfigurationMode)           \
    X(GetIntervalDecimal)              \
    X(GetIntervalFraction)             \
    X(GetShiftDecimal)                 \
    X(GetShiftFraction)                \
    X(SetIntervalDecimal)              \
    X(SetIntervalFraction)             \
    X(SetShiftDecimal)                 \
    X(SetShiftFraction)                \
    X(EvaluateDiscreteStates)          \
    X(UpdateDiscreteStates)            \
    X(EnterContinuousTimeMode)         \
    X(CompletedIntegratorStep)         \
    X(SetTime)                         \
    X(SetContinuousStates)             \
    X(GetContinuousStateDerivatives)   \
    X(GetEventIndicators)              \
    X(GetContinuousStates)             \
    X(GetNominalsOfContinuousStates)   \
    X(GetNumberOfEventIndicators)      \
    X(GetNumberOfContinuousStates)     \
    X(EnterStepMode)                   \
    X(GetOutputDerivatives)            \
    X(DoStep)                          \
    X(ActivateModelPartition)
/* clang-format on */

struct fmi3_api {
    void *handle;
#define FMI3_DECLARE_POINTER(name) fmi3##name##TYPE *name;
    FMI3_FUNCTIONS(FMI3_DECLARE_POINTER)
#undef FMI3_DECLARE_POINTER
};

/* The value reference of the independent variable, time (modelDescription/fmi3/<Block>.xml). */
#define TIME_VR3 1000000u

/* env: the instance's log_record (or NULL); records the message (log_store3 in importer.c). */
void harness_logger3(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                     fmi3String message);

#endif
