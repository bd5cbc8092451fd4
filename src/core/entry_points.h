/* The entry points that FMI 2.0 and FMI 3.0 have alike but for their names and types, written
 * once: a front-end (fmi2/, fmi3/) gives its status, instance and value types and the names of
 * its functions, in the order of each macro. Each function checks its kind of call (core_call),
 * then hands over to the core, whose status codes both versions number alike (lgf_status).
 * A macro names each function twice: as the definition, which the FMI headers turn into the
 * prefixed name where the importer compiles with a function prefix, and as the text of its log
 * lines (#name, never expanded), which is the standard's name. */
#ifndef LGF_CORE_ENTRY_POINTS_H
#define LGF_CORE_ENTRY_POINTS_H

#include "core/core.h"

/* SetDebugLogging, ExitInitializationMode, Terminate, Reset and FreeInstance. */
#define CORE_LIFECYCLE_ENTRY_POINTS(Status, Instance, Boolean, String, set_debug_logging,          \
                                    exit_initialization, terminate, reset, free_instance)          \
    Status set_debug_logging(Instance i, Boolean loggingOn, size_t nCategories,                    \
                             const String categories[])                                            \
    {                                                                                              \
        return i ? (Status)core_set_debug_logging(i, #set_debug_logging, loggingOn, nCategories,   \
                                                  categories)                                      \
                 : (Status)STATUS_ERROR;                                                           \
    }                                                                                              \
    Status exit_initialization(Instance i)                                                         \
    {                                                                                              \
        instance *inst = core_allowed(i, #exit_initialization, CALL_EXIT_INITIALIZATION);          \
        return inst ? (Status)core_exit_initialization(inst, #exit_initialization)                 \
                    : (Status)STATUS_ERROR;                                                        \
    }                                                                                              \
    Status terminate(Instance i)                                                                   \
    {                                                                                              \
        return (Status)core_enter_mode(i, #terminate, CALL_TERMINATE, MODE_TERMINATED);            \
    }                                                                                              \
    Status reset(Instance i)                                                                       \
    {                                                                                              \
        instance *inst = i;                                                                        \
        if (!inst) return (Status)STATUS_ERROR;                                                    \
        core_image_reset(inst->image);                                                             \
        return (Status)STATUS_OK;                                                                  \
    }                                                                                              \
    void free_instance(Instance i) { core_free_instance(i); }

/* GetFMUState, SetFMUState, FreeFMUState, SerializedFMUStateSize, SerializeFMUState and
 * DeserializeFMUState (FMI 2.0 spells FMUstate and DeSerialize). */
#define CORE_STATE_ENTRY_POINTS(Status, Instance, State, Byte, get_state, set_state, free_state,   \
                                state_size, serialize, deserialize)                                \
    Status get_state(Instance i, State *FMUState)                                                  \
    {                                                                                              \
        instance *inst = core_allowed(i, #get_state, CALL_ANY_MODE);                               \
        return inst ? (Status)core_get_state(inst, #get_state, FMUState) : (Status)STATUS_ERROR;   \
    }                                                                                              \
    Status set_state(Instance i, State FMUState)                                                   \
    {                                                                                              \
        instance *inst = core_allowed(i, #set_state, CALL_ANY_MODE);                               \
        return inst ? (Status)core_set_state(inst, #set_state, FMUState, core_modes_of(inst))      \
                    : (Status)STATUS_ERROR;                                                        \
    }                                                                                              \
    Status free_state(Instance i, State *FMUState)                                                 \
    {                                                                                              \
        instance *inst = core_allowed(i, #free_state, CALL_ANY_MODE);                              \
        return inst ? (Status)core_free_state(inst, #free_state, FMUState) : (Status)STATUS_ERROR; \
    }                                                                                              \
    Status state_size(Instance i, State FMUState, size_t *size)                                    \
    {                                                                                              \
        instance *inst = core_allowed(i, #state_size, CALL_ANY_MODE);                              \
        return inst ? (Status)core_state_size(inst, #state_size, FMUState, size)                   \
                    : (Status)STATUS_ERROR;                                                        \
    }                                                                                              \
    Status serialize(Instance i, State FMUState, Byte serializedState[], size_t size)              \
    {                                                                                              \
        instance *inst = core_allowed(i, #serialize, CALL_ANY_MODE);                               \
        return inst ? (Status)core_serialize(inst, #serialize, FMUState,                           \
                                             (unsigned char *)serializedState, size)               \
                    : (Status)STATUS_ERROR;                                                        \
    }                                                                                              \
    Status deserialize(Instance i, const Byte serializedState[], size_t size, State *FMUState)     \
    {                                                                                              \
        instance *inst = core_allowed(i, #deserialize, CALL_ANY_MODE);                             \
        return inst ? (Status)core_deserialize(inst, #deserialize,                                 \
                                               (const unsigned char *)serializedState, size,       \
                                               FMUState, core_modes_of(inst))                      \
                    : (Status)STATUS_ERROR;                                                        \
    }

/* Model Exchange (docs/behaviour.md §1.11), but for the event update: EnterEventMode,
 * EnterContinuousTimeMode, CompletedIntegratorStep, SetTime, and the functions of the continuous
 * states and event indicators, of which the FMU has none, so that their arrays have 0 elements
 * (states_count and indicators_count: how the version names their counts, for messages). */
#define CORE_MODEL_EXCHANGE_ENTRY_POINTS(                                                          \
    Status, Instance, Real, Boolean, enter_event_mode, enter_continuous_time_mode,                 \
    completed_integrator_step, set_time, set_states, get_derivatives, get_event_indicators,        \
    get_states, get_nominals, states_count, indicators_count)                                      \
    Status enter_event_mode(Instance i)                                                            \
    {                                                                                              \
        return (Status)core_enter_mode(i, #enter_event_mode, CALL_EXCHANGE, MODE_EVENT);           \
    }                                                                                              \
    Status enter_continuous_time_mode(Instance i)                                                  \
    {                                                                                              \
        return (Status)core_enter_mode(i, #enter_continuous_time_mode, CALL_EVENT,                 \
                                       MODE_CONTINUOUS);                                           \
    }                                                                                              \
    /* Nothing happens between calls: no step event, no reason to stop. */                         \
    Status completed_integrator_step(Instance i, Boolean noSetFMUStatePriorToCurrentPoint,         \
                                     Boolean *enterEventMode, Boolean *terminateSimulation)        \
    {                                                                                              \
        (void)noSetFMUStatePriorToCurrentPoint;                                                    \
        instance *inst = core_allowed(i, #completed_integrator_step, CALL_CONTINUOUS);             \
        if (!inst ||                                                                               \
            !core_given(inst, #completed_integrator_step, enterEventMode && terminateSimulation,   \
                        "enterEventMode and terminateSimulation must not be NULL"))                \
            return (Status)STATUS_ERROR;                                                           \
        *enterEventMode = *terminateSimulation = false;                                            \
        return (Status)STATUS_OK;                                                                  \
    }                                                                                              \
    Status set_time(Instance i, Real time)                                                         \
    {                                                                                              \
        instance *inst = core_allowed(i, #set_time, CALL_EXCHANGE);                                \
        return inst ? (Status)core_set_time(inst, #set_time, time) : (Status)STATUS_ERROR;         \
    }                                                                                              \
    CORE_NONE_ENTRY_POINT(Status, Instance, const Real, set_states, #set_states, CALL_CONTINUOUS,  \
                          states_count)                                                            \
    CORE_NONE_ENTRY_POINT(Status, Instance, Real, get_derivatives, #get_derivatives,               \
                          CALL_EXCHANGE_GET, states_count)                                         \
    CORE_NONE_ENTRY_POINT(Status, Instance, Real, get_event_indicators, #get_event_indicators,     \
                          CALL_EXCHANGE_GET, indicators_count)                                     \
    CORE_NONE_ENTRY_POINT(Status, Instance, Real, get_states, #get_states, CALL_EXCHANGE_GET,      \
                          states_count)                                                            \
    CORE_NONE_ENTRY_POINT(Status, Instance, Real, get_nominals, #get_nominals,                     \
                          CALL_EXCHANGE_ANY_MODE, states_count)

/* One function of the continuous states or event indicators, of which the FMU has none: its array
 * has 0 elements (core_none). `name` is the function's own name as text, which the macro above
 * takes before the FMI headers' prefix can change it. */
#define CORE_NONE_ENTRY_POINT(Status, Instance, Element, function, name, call, count)              \
    Status function(Instance i, Element values[], size_t n)                                        \
    {                                                                                              \
        (void)values;                                                                              \
        return (Status)core_none(i, name, call, n, count);                                         \
    }

#endif
