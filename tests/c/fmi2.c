/* The FMI 2.0 behind the version-neutral harness (fmu_ops in harness.h): each operation is the
 * fmi2 call an importer makes, through the functions importer.c looked up. */
#define _POSIX_C_SOURCE 200809L
#include "harness.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

static const char *const names[FN_COUNT] = {
    [FN_SETUP] = "fmi2SetupExperiment",
    [FN_ENTER_INIT] = "fmi2EnterInitializationMode",
    [FN_EXIT_INIT] = "fmi2ExitInitializationMode",
    [FN_TERMINATE] = "fmi2Terminate",
    [FN_RESET] = "fmi2Reset",
    [FN_DO_STEP] = "fmi2DoStep",
    [FN_SET_DEBUG_LOGGING] = "fmi2SetDebugLogging",
    [FN_GET_STATE] = "fmi2GetFMUstate",
    [FN_SET_STATE] = "fmi2SetFMUstate",
    [FN_FREE_STATE] = "fmi2FreeFMUstate",
    [FN_STATE_SIZE] = "fmi2SerializedFMUstateSize",
    [FN_SERIALIZE] = "fmi2SerializeFMUstate",
    [FN_DESERIALIZE] = "fmi2DeSerializeFMUstate",
    [FN_ENTER_EVENT] = "fmi2EnterEventMode",
    [FN_UPDATE_DISCRETE] = "fmi2NewDiscreteStates",
    [FN_ENTER_CONTINUOUS] = "fmi2EnterContinuousTimeMode",
    [FN_COMPLETED] = "fmi2CompletedIntegratorStep",
    [FN_SET_TIME] = "fmi2SetTime",
    [FN_SET_STATES] = "fmi2SetContinuousStates",
    [FN_GET_DERIVATIVES] = "fmi2GetDerivatives",
    [FN_GET_INDICATORS] = "fmi2GetEventIndicators",
    [FN_GET_STATES] = "fmi2GetContinuousStates",
    [FN_GET_NOMINALS] = "fmi2GetNominalsOfContinuousStates",
};

/* indexed by var_kind */
static const type_info types[] = {
    {"fmi2SetReal", "fmi2GetReal", KIND_REAL, -INFINITY, INFINITY, false, true},
    {"fmi2SetInteger", "fmi2GetInteger", KIND_INTEGER, -2147483648.0, 2147483647.0, false, true},
    {"fmi2SetBoolean", "fmi2GetBoolean", KIND_BOOLEAN, 0, 1, false, true},
    {"fmi2SetString", "fmi2GetString", KIND_STRING, 0, 0, false, false},
};

#define MAX_VALUES 16 /* values of one set or get through the driver */

static bool load(block *b, char *error, size_t size)
{
    return api_load(&b->api, b->library, error, size);
}
static void unload(block *b) { api_unload(&b->api); }
static const char *get_version(const block *b) { return b->api.GetVersion(); }

static void *instantiate(const block *b, const char *name, fmi2Type type, log_record *log)
{
    /* The FMU keeps a copy of the callbacks (FMI 2.0 2.1.5 allows the struct to go away). */
    fmi2CallbackFunctions callbacks = harness_callbacks(log);
    return b->api.Instantiate(name, type, b->guid, "file:///tmp", &callbacks, fmi2False, fmi2False);
}

static void free_instance(const block *b, void *c) { b->api.FreeInstance(c); }

static int setup(const block *b, void *c, double start, bool stop_defined, double stop)
{
    return b->api.SetupExperiment(c, fmi2False, 0.0, start, stop_defined ? fmi2True : fmi2False,
                                  stop);
}

static int enter_init(const block *b, void *c) { return b->api.EnterInitializationMode(c); }

static int begin(const block *b, void *c, double start, bool stop_defined, double stop)
{
    int status = setup(b, c, start, stop_defined, stop);
    return status == fmi2OK ? enter_init(b, c) : status;
}

static int exit_init(const block *b, void *c) { return b->api.ExitInitializationMode(c); }
static int terminate(const block *b, void *c) { return b->api.Terminate(c); }
static int reset(const block *b, void *c) { return b->api.Reset(c); }

static int do_step(const block *b, void *c, double t, double h)
{
    return b->api.DoStep(c, t, h, fmi2True);
}

static int now(const block *b, void *c, double *t)
{
    return b->api.GetRealStatus(c, fmi2LastSuccessfulTime, t);
}

/* The arrays set and get pass, of every type. */
typedef struct {
    fmi2Real reals[MAX_VALUES];
    fmi2Integer integers[MAX_VALUES];
    fmi2Boolean booleans[MAX_VALUES];
    fmi2String strings[MAX_VALUES];
} arrays;

static int set(const block *b, void *c, int type, const uint32_t *vr, size_t nvr,
               const double *values, size_t n_values)
{
    (void)n_values;
    const fmi2_api *api = &b->api;
    arrays a;
    if (values && nvr > MAX_VALUES) return -1;
    for (size_t i = 0; values && i < nvr; i++) { /* only the type's own conversion */
        if (type == KIND_REAL)
            a.reals[i] = values[i];
        else if (type == KIND_INTEGER)
            a.integers[i] = (fmi2Integer)values[i];
        else if (type == KIND_BOOLEAN)
            a.booleans[i] = (fmi2Boolean)values[i];
        else
            a.strings[i] = "x";
    }
    switch (type) {
    case KIND_REAL: return api->SetReal(c, vr, nvr, values ? a.reals : NULL);
    case KIND_INTEGER: return api->SetInteger(c, vr, nvr, values ? a.integers : NULL);
    case KIND_BOOLEAN: return api->SetBoolean(c, vr, nvr, values ? a.booleans : NULL);
    default: return api->SetString(c, vr, nvr, values ? a.strings : NULL);
    }
}

static int get(const block *b, void *c, int type, const uint32_t *vr, size_t nvr, double *values,
               size_t n_values)
{
    (void)n_values;
    const fmi2_api *api = &b->api;
    arrays a;
    if (values && nvr > MAX_VALUES) return -1;
    int status;
    switch (type) {
    case KIND_REAL: status = api->GetReal(c, vr, nvr, values ? a.reals : NULL); break;
    case KIND_INTEGER: status = api->GetInteger(c, vr, nvr, values ? a.integers : NULL); break;
    case KIND_BOOLEAN: status = api->GetBoolean(c, vr, nvr, values ? a.booleans : NULL); break;
    default: status = api->GetString(c, vr, nvr, values ? a.strings : NULL); break;
    }
    for (size_t i = 0; values && status == fmi2OK && i < nvr; i++) {
        if (type == KIND_REAL)
            memcpy(&values[i], &a.reals[i], sizeof values[i]);
        else if (type == KIND_INTEGER)
            values[i] = a.integers[i];
        else if (type == KIND_BOOLEAN)
            values[i] = a.booleans[i];
        else
            values[i] = 0;
    }
    return status;
}

static int set_debug_logging(const block *b, void *c, bool on, size_t n,
                             const char *const *categories)
{
    return b->api.SetDebugLogging(c, on ? fmi2True : fmi2False, n, categories);
}

static int get_state(const block *b, void *c, void **state) { return b->api.GetFMUstate(c, state); }
static int set_state(const block *b, void *c, void *state) { return b->api.SetFMUstate(c, state); }
static int free_state(const block *b, void *c, void **state)
{
    return b->api.FreeFMUstate(c, state);
}

static int state_size(const block *b, void *c, void *state, size_t *size)
{
    return b->api.SerializedFMUstateSize(c, state, size);
}

static int serialize(const block *b, void *c, void *state, unsigned char *bytes, size_t size)
{
    return b->api.SerializeFMUstate(c, state, (fmi2Byte *)bytes, size);
}

static int deserialize(const block *b, void *c, const unsigned char *bytes, size_t size,
                       void **state)
{
    return b->api.DeSerializeFMUstate(c, (const fmi2Byte *)bytes, size, state);
}

static int enter_event(const block *b, void *c) { return b->api.EnterEventMode(c); }

static int update_discrete(const block *b, void *c, event_info *info)
{
    if (!info) return b->api.NewDiscreteStates(c, NULL);
    fmi2EventInfo native;
    memset(&native, 0xA5, sizeof native);
    int status = b->api.NewDiscreteStates(c, &native);
    *info = (event_info){native.newDiscreteStatesNeeded,
                         native.terminateSimulation,
                         native.nominalsOfContinuousStatesChanged,
                         native.valuesOfContinuousStatesChanged,
                         native.nextEventTimeDefined,
                         native.nextEventTime};
    return status;
}

static int enter_continuous(const block *b, void *c) { return b->api.EnterContinuousTimeMode(c); }

static int completed(const block *b, void *c, bool no_set_prior, int *enter, int *terminate_)
{
    fmi2Boolean e = enter ? *enter : 0, t = terminate_ ? *terminate_ : 0;
    int status = b->api.CompletedIntegratorStep(c, no_set_prior ? fmi2True : fmi2False,
                                                enter ? &e : NULL, terminate_ ? &t : NULL);
    if (enter) *enter = e;
    if (terminate_) *terminate_ = t;
    return status;
}

static int set_time(const block *b, void *c, double t) { return b->api.SetTime(c, t); }

static int no_states(const block *b, void *c, int which, double *array, size_t n)
{
    const fmi2_api *api = &b->api;
    switch (which + FN_SET_STATES) {
    case FN_SET_STATES: return api->SetContinuousStates(c, array, n);
    case FN_GET_DERIVATIVES: return api->GetDerivatives(c, array, n);
    case FN_GET_INDICATORS: return api->GetEventIndicators(c, array, n);
    case FN_GET_STATES: return api->GetContinuousStates(c, array, n);
    default: return api->GetNominalsOfContinuousStates(c, array, n);
    }
}

const fmu_ops fmi2_ops = {
    .version = 2,
    .version_string = "2.0",
    .names = names,
    .types = types,
    .n_types = (int)(sizeof types / sizeof types[0]),
    .string_type = KIND_STRING,
    .begin = begin,
    FMU_OPERATIONS,
};
