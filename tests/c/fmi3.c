/* FMI 3.0 in the harness: the fmi3 functions looked up with dlsym, the FMI 3.0 fmu_ops under
 * which every version-neutral scenario, case and group of harness.c and cases.c runs, and what
 * only FMI 3.0 has (docs/behaviour.md §1, §1.11; src/fmi3/fmi3.c): its mode tables, nValues,
 * the types this FMU has no variable of, the independent variable time, the out-pointers of
 * fmi3DoStep and fmi3UpdateDiscreteStates, the functions it refuses (step mode entry, clocks,
 * configuration mode, derivatives, dependencies), its instantiation functions, and the
 * comparison with the block's FMI 2.0 library: the same outputs call for call and bit for
 * bit, the same serialized states byte for byte, states that pass from one version to the
 * other, and the same messages. */
#define _POSIX_C_SOURCE 200809L
#include "harness.h"
#include "fmi3.h"

#include <dlfcn.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* ---- the library ---- */

static bool load(block *b, char *error, size_t size)
{
    struct fmi3_api *api = calloc(1, sizeof *api);
    b->api3 = api;
    if (!api) {
        snprintf(error, size, "out of memory");
        return false;
    }
    api->handle = dlopen(b->library, RTLD_NOW | RTLD_LOCAL);
    if (!api->handle) {
        snprintf(error, size, "dlopen(%s) failed: %s", b->library, dlerror());
        return false;
    }
    /* copied bytewise into the function pointer, the portable way POSIX allows */
#define FMI3_LOOK_UP(name)                                                                         \
    {                                                                                              \
        void *symbol = dlsym(api->handle, "fmi3" #name);                                           \
        if (!symbol) {                                                                             \
            snprintf(error, size, "%s does not export fmi3%s", b->library, #name);                 \
            return false;                                                                          \
        }                                                                                          \
        memcpy(&api->name, &symbol, sizeof symbol);                                                \
    }
    FMI3_FUNCTIONS(FMI3_LOOK_UP)
#undef FMI3_LOOK_UP
    return true;
}

static void unload(block *b)
{
    if (b->api3 && b->api3->handle) dlclose(b->api3->handle);
    free(b->api3);
    b->api3 = NULL;
}

void harness_logger3(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                     fmi3String message)
{
    log_store3(env, (int)status, category, message);
}

/* ---- the FMI 3.0 fmu_ops ---- */

static const char *const names[FN_COUNT] = {
    [FN_SETUP] = "fmi3EnterInitializationMode",
    [FN_ENTER_INIT] = "fmi3EnterInitializationMode",
    [FN_EXIT_INIT] = "fmi3ExitInitializationMode",
    [FN_TERMINATE] = "fmi3Terminate",
    [FN_RESET] = "fmi3Reset",
    [FN_DO_STEP] = "fmi3DoStep",
    [FN_SET_DEBUG_LOGGING] = "fmi3SetDebugLogging",
    [FN_GET_STATE] = "fmi3GetFMUState",
    [FN_SET_STATE] = "fmi3SetFMUState",
    [FN_FREE_STATE] = "fmi3FreeFMUState",
    [FN_STATE_SIZE] = "fmi3SerializedFMUStateSize",
    [FN_SERIALIZE] = "fmi3SerializeFMUState",
    [FN_DESERIALIZE] = "fmi3DeserializeFMUState",
    [FN_ENTER_EVENT] = "fmi3EnterEventMode",
    [FN_UPDATE_DISCRETE] = "fmi3UpdateDiscreteStates",
    [FN_ENTER_CONTINUOUS] = "fmi3EnterContinuousTimeMode",
    [FN_COMPLETED] = "fmi3CompletedIntegratorStep",
    [FN_SET_TIME] = "fmi3SetTime",
    [FN_SET_STATES] = "fmi3SetContinuousStates",
    [FN_GET_DERIVATIVES] = "fmi3GetContinuousStateDerivatives",
    [FN_GET_INDICATORS] = "fmi3GetEventIndicators",
    [FN_GET_STATES] = "fmi3GetContinuousStates",
    [FN_GET_NOMINALS] = "fmi3GetNominalsOfContinuousStates",
};

/* indexed by fmi3_type; has_table: the types of the front-end's kind table (a mismatch names
 * the variable), the others have no variable (any value reference is unknown to them) */
static const type_info types[T3_TYPES] = {
    [T3_FLOAT32] = {"fmi3SetFloat32", "fmi3GetFloat32", KIND_REAL, -INFINITY, INFINITY, true, true},
    [T3_FLOAT64] = {"fmi3SetFloat64", "fmi3GetFloat64", KIND_REAL, -INFINITY, INFINITY, false,
                    true},
    [T3_INT8] = {"fmi3SetInt8", "fmi3GetInt8", KIND_INTEGER, -128, 127, false, true},
    [T3_UINT8] = {"fmi3SetUInt8", "fmi3GetUInt8", KIND_INTEGER, 0, 255, false, true},
    [T3_INT16] = {"fmi3SetInt16", "fmi3GetInt16", KIND_INTEGER, -32768, 32767, false, true},
    [T3_UINT16] = {"fmi3SetUInt16", "fmi3GetUInt16", KIND_INTEGER, 0, 65535, false, true},
    [T3_INT32] = {"fmi3SetInt32", "fmi3GetInt32", KIND_INTEGER, -2147483648.0, 2147483647.0, false,
                  true},
    [T3_UINT32] = {"fmi3SetUInt32", "fmi3GetUInt32", KIND_INTEGER, 0, 4294967295.0, false, true},
    [T3_INT64] = {"fmi3SetInt64", "fmi3GetInt64", KIND_INTEGER, -9223372036854775808.0,
                  9223372036854774784.0, false, false},
    [T3_UINT64] = {"fmi3SetUInt64", "fmi3GetUInt64", KIND_INTEGER, 0, 18446744073709549568.0, false,
                   false},
    [T3_BOOLEAN] = {"fmi3SetBoolean", "fmi3GetBoolean", KIND_BOOLEAN, 0, 1, false, true},
    [T3_STRING] = {"fmi3SetString", "fmi3GetString", KIND_STRING, 0, 0, false, false},
    [T3_BINARY] = {"fmi3SetBinary", "fmi3GetBinary", KIND_OTHER, 0, 0, false, false},
    [T3_CLOCK] = {"fmi3SetClock", "fmi3GetClock", KIND_OTHER, 0, 0, false, false},
};

#define API(b) ((b)->api3)
#define MAX_VALUES 16

static const char *get_version(const block *b) { return API(b)->GetVersion(); }

static void *instantiate(const block *b, const char *name, fmi2Type type, log_record *log)
{
    if (type == fmi2ModelExchange)
        return API(b)->InstantiateModelExchange(name, b->guid, NULL, fmi3False, fmi3False, log,
                                                harness_logger3);
    return API(b)->InstantiateCoSimulation(name, b->guid, NULL, fmi3False, fmi3False, fmi3False,
                                           fmi3False, NULL, 0, log, harness_logger3, NULL);
}

static void free_instance(const block *b, void *c) { API(b)->FreeInstance(c); }

static int setup(const block *b, void *c, double start, bool stop_defined, double stop)
{
    return API(b)->EnterInitializationMode(c, fmi3False, 0.0, start, stop_defined, stop);
}

static int enter_init(const block *b, void *c) { return setup(b, c, 0.0, false, 0.0); }

static int exit_init(const block *b, void *c) { return API(b)->ExitInitializationMode(c); }
static int terminate(const block *b, void *c) { return API(b)->Terminate(c); }
static int reset(const block *b, void *c) { return API(b)->Reset(c); }

static int now(const block *b, void *c, double *t)
{
    const fmi3ValueReference time_vr = TIME_VR3;
    return API(b)->GetFloat64(c, &time_vr, 1, t, 1);
}

/* fmi3DoStep: an accepted step asks for nothing, ends early never, and its
 * lastSuccessfulTime is the FMU's time (docs/behaviour.md §1.3). */
static int do_step(const block *b, void *c, double t, double h)
{
    fmi3Boolean event = fmi3True, stop = fmi3True, early = fmi3True;
    fmi3Float64 last = NAN;
    int status = API(b)->DoStep(c, t, h, fmi3True, &event, &stop, &early, &last);
    if (status != fmi3OK || !c) return status;
    double time = NAN;
    if (event || stop || early || now(b, c, &time) != fmi3OK || memcmp(&time, &last, sizeof time))
        return OTHER_RESULT;
    return status;
}

/* The arrays set and get pass, of every type. */
typedef union {
    fmi3Float32 Float32[MAX_VALUES];
    fmi3Float64 Float64[MAX_VALUES];
    fmi3Int8 Int8[MAX_VALUES];
    fmi3UInt8 UInt8[MAX_VALUES];
    fmi3Int16 Int16[MAX_VALUES];
    fmi3UInt16 UInt16[MAX_VALUES];
    fmi3Int32 Int32[MAX_VALUES];
    fmi3UInt32 UInt32[MAX_VALUES];
    fmi3Int64 Int64[MAX_VALUES];
    fmi3UInt64 UInt64[MAX_VALUES];
    fmi3Boolean b[MAX_VALUES];
    fmi3String s[MAX_VALUES];
    fmi3Binary bin[MAX_VALUES];
    fmi3Clock clock[MAX_VALUES];
} arrays;

/* The numeric types whose values the harness converts from and to double (FMI 3.0's type
 * names); X(T3_ type, FMI type). Float64 is got as its bits, so it is the set's alone. */
#define NUMBERS(X)                                                                                 \
    X(T3_FLOAT32, Float32)                                                                         \
    X(T3_INT8, Int8)                                                                               \
    X(T3_UINT8, UInt8)                                                                             \
    X(T3_INT16, Int16)                                                                             \
    X(T3_UINT16, UInt16)                                                                           \
    X(T3_INT32, Int32)                                                                             \
    X(T3_UINT32, UInt32)                                                                           \
    X(T3_INT64, Int64)                                                                             \
    X(T3_UINT64, UInt64)
#define SET_CASE(type_, name_)                                                                     \
    case type_:                                                                                    \
        for (size_t i = 0; values && i < nvr; i++) a.name_[i] = (fmi3##name_)values[i];            \
        return api->Set##name_(c, vr, nvr, p, n_values);
#define GET_CASE(type_, name_)                                                                     \
    case type_:                                                                                    \
        status = api->Get##name_(c, vr, nvr, p, n_values);                                         \
        for (size_t i = 0; values && status == fmi3OK && i < nvr; i++)                             \
            values[i] = (double)a.name_[i];                                                        \
        break;

static int set(const block *b, void *c, int type, const uint32_t *vr, size_t nvr,
               const double *values, size_t n_values)
{
    const struct fmi3_api *api = API(b);
    arrays a;
    size_t sizes[MAX_VALUES];
    static const fmi3Byte byte = 0;
    if (values && nvr > MAX_VALUES) return -1;
    const void *p = values ? (const void *)&a : NULL;
    switch (type) {
        NUMBERS(SET_CASE)
        SET_CASE(T3_FLOAT64, Float64)
    case T3_BOOLEAN:
        for (size_t i = 0; values && i < nvr; i++) a.b[i] = values[i] != 0;
        return api->SetBoolean(c, vr, nvr, p, n_values);
    case T3_STRING:
        for (size_t i = 0; values && i < nvr; i++) a.s[i] = "x";
        return api->SetString(c, vr, nvr, p, n_values);
    case T3_BINARY:
        for (size_t i = 0; values && i < nvr; i++) a.bin[i] = &byte, sizes[i] = 1;
        return api->SetBinary(c, vr, nvr, values ? sizes : NULL, p, n_values);
    default:
        for (size_t i = 0; values && i < nvr; i++) a.clock[i] = values[i] != 0;
        return api->SetClock(c, vr, nvr, p);
    }
}

static int get(const block *b, void *c, int type, const uint32_t *vr, size_t nvr, double *values,
               size_t n_values)
{
    const struct fmi3_api *api = API(b);
    arrays a;
    size_t sizes[MAX_VALUES];
    if (values && nvr > MAX_VALUES) return -1;
    memset(&a, 0, sizeof a);
    void *p = values ? (void *)&a : NULL;
    int status;
    switch (type) {
        NUMBERS(GET_CASE)
    case T3_FLOAT64:
        status = api->GetFloat64(c, vr, nvr, p, n_values);
        for (size_t i = 0; values && status == fmi3OK && i < nvr; i++)
            memcpy(&values[i], &a.Float64[i], sizeof values[i]); /* the bits, NaN's too */
        break;
    case T3_BOOLEAN:
        status = api->GetBoolean(c, vr, nvr, p, n_values);
        for (size_t i = 0; values && status == fmi3OK && i < nvr; i++) values[i] = a.b[i];
        break;
    case T3_STRING: status = api->GetString(c, vr, nvr, p, n_values); break;
    case T3_BINARY: status = api->GetBinary(c, vr, nvr, values ? sizes : NULL, p, n_values); break;
    default: status = api->GetClock(c, vr, nvr, p); break;
    }
    return status;
}

static int set_debug_logging(const block *b, void *c, bool on, size_t n,
                             const char *const *categories)
{
    return API(b)->SetDebugLogging(c, on, n, categories);
}

static int get_state(const block *b, void *c, void **state)
{
    return API(b)->GetFMUState(c, state);
}
static int set_state(const block *b, void *c, void *state) { return API(b)->SetFMUState(c, state); }
static int free_state(const block *b, void *c, void **state)
{
    return API(b)->FreeFMUState(c, state);
}

static int state_size(const block *b, void *c, void *state, size_t *size)
{
    return API(b)->SerializedFMUStateSize(c, state, size);
}

static int serialize(const block *b, void *c, void *state, unsigned char *bytes, size_t size)
{
    return API(b)->SerializeFMUState(c, state, bytes, size);
}

static int deserialize(const block *b, void *c, const unsigned char *bytes, size_t size,
                       void **state)
{
    return API(b)->DeserializeFMUState(c, bytes, size, state);
}

static int enter_event(const block *b, void *c) { return API(b)->EnterEventMode(c); }

/* The flags start opposite to what the FMU must write, nextEventTime at a sentinel: what it
 * does not write shows. */
static int update_discrete(const block *b, void *c, event_info *info)
{
    if (!info) return API(b)->UpdateDiscreteStates(c, NULL, NULL, NULL, NULL, NULL, NULL);
    fmi3Boolean needed = fmi3True, stop = fmi3True, nominals = fmi3True, values = fmi3True,
                defined = fmi3False;
    fmi3Float64 next = -7.25e300;
    int status =
        API(b)->UpdateDiscreteStates(c, &needed, &stop, &nominals, &values, &defined, &next);
    *info = (event_info){needed, stop, nominals, values, defined, next};
    return status;
}

static int enter_continuous(const block *b, void *c) { return API(b)->EnterContinuousTimeMode(c); }

static int completed(const block *b, void *c, bool no_set_prior, int *enter, int *terminate_)
{
    fmi3Boolean e = enter ? *enter != 0 : 0, t = terminate_ ? *terminate_ != 0 : 0;
    int status =
        API(b)->CompletedIntegratorStep(c, no_set_prior, enter ? &e : NULL, terminate_ ? &t : NULL);
    if (enter) *enter = e;
    if (terminate_) *terminate_ = t;
    return status;
}

static int set_time(const block *b, void *c, double t) { return API(b)->SetTime(c, t); }

static int no_states(const block *b, void *c, int which, double *array, size_t n)
{
    const struct fmi3_api *api = API(b);
    switch (which + FN_SET_STATES) {
    case FN_SET_STATES: return api->SetContinuousStates(c, array, n);
    case FN_GET_DERIVATIVES: return api->GetContinuousStateDerivatives(c, array, n);
    case FN_GET_INDICATORS: return api->GetEventIndicators(c, array, n);
    case FN_GET_STATES: return api->GetContinuousStates(c, array, n);
    default: return api->GetNominalsOfContinuousStates(c, array, n);
    }
}

const fmu_ops fmi3_ops = {
    .version = 3,
    .version_string = "3.0",
    .names = names,
    .types = types,
    .n_types = T3_TYPES,
    .string_type = T3_STRING,
    .begin = setup, /* fmi3EnterInitializationMode takes the experiment's times */
    FMU_OPERATIONS,
};

/* ---- ops only FMI 3.0 has ---- */

/* i: the type; i2: 0 nvr 1 with nValues 0, 1 nvr 1 with nValues 2, 2 nvr 0 with nValues 1;
 * vr2: 1 a get, else a set */
static int op_n_values(sim *s, const misuse *m)
{
    static const size_t nvr[] = {1, 1, 0}, n_values[] = {0, 2, 1};
    uint32_t vr[2] = {m->vr, m->vr};
    double values[2] = {m->r, m->r};
    return m->vr2 ? FMU(s->b, get, s->c, (int)m->i, vr, nvr[m->i2], values, n_values[m->i2])
                  : FMU(s->b, set, s->c, (int)m->i, vr, nvr[m->i2], values, n_values[m->i2]);
}

/* fmi3GetFloat64 of time (i: 0 alone, 1 with the output vr2, 2 with the unknown vr2): the
 * value is the FMU's time; a refused call returns its status */
static int op_get_time(sim *s, const misuse *m)
{
    uint32_t vr[2] = {TIME_VR3, m->vr2};
    fmi3Float64 values[2] = {-1, -1};
    size_t n = m->i ? 2 : 1;
    int status = API(s->b)->GetFloat64(s->c, vr, n, values, n);
    double expected =
        s->phase == PHASE_INSTANTIATED || s->phase == PHASE_INITIALIZATION ? 0.0 : s->t;
    if (status == fmi3OK && memcmp(&values[0], &expected, sizeof expected)) return OTHER_RESULT;
    return status;
}

/* fmi3DoStep with out-pointer i2 NULL (4: all) */
static int op_do_step_null(sim *s, const misuse *m)
{
    fmi3Boolean event, stop, early;
    fmi3Float64 last;
    long k = m->i2;
    return API(s->b)->DoStep(s->c, s->t, s->b->cycle, fmi3True, k == 0 || k == 4 ? NULL : &event,
                             k == 1 || k == 4 ? NULL : &stop, k == 2 || k == 4 ? NULL : &early,
                             k == 3 || k == 4 ? NULL : &last);
}

/* fmi3UpdateDiscreteStates with out-pointer i2 NULL */
static int op_update_null(sim *s, const misuse *m)
{
    fmi3Boolean f[5] = {0};
    fmi3Float64 next = 0;
    long k = m->i2;
    return API(s->b)->UpdateDiscreteStates(s->c, k == 0 ? NULL : &f[0], k == 1 ? NULL : &f[1],
                                           k == 2 ? NULL : &f[2], k == 3 ? NULL : &f[3],
                                           k == 4 ? NULL : &f[4], k == 5 ? NULL : &next);
}

/* i: 0 fmi3EvaluateDiscreteStates, 1 fmi3GetNumberOfEventIndicators, 2
 * fmi3GetNumberOfContinuousStates; i2 = 1: the count NULL. A count must be 0. */
static int op_me3(sim *s, const misuse *m)
{
    const struct fmi3_api *api = API(s->b);
    size_t n = 7;
    int status;
    switch (m->i) {
    case 0: return api->EvaluateDiscreteStates(s->c);
    case 1: status = api->GetNumberOfEventIndicators(s->c, m->i2 ? NULL : &n); break;
    default: status = api->GetNumberOfContinuousStates(s->c, m->i2 ? NULL : &n); break;
    }
    if (status == fmi3OK && n != 0) return OTHER_RESULT;
    if (status != fmi3OK && n != 7) return OTHER_RESULT;
    return status;
}

/* The functions FMI 3.0 has and this FMU refuses (i): with plausible arguments. */
enum {
    U_ENTER_STEP_MODE,
    U_ENTER_CONFIGURATION,
    U_EXIT_CONFIGURATION,
    U_DIRECTIONAL,
    U_ADJOINT,
    U_N_DEPENDENCIES,
    U_DEPENDENCIES,
    U_OUTPUT_DERIVATIVES,
    U_ACTIVATE_PARTITION,
    U_GET_INTERVAL_DECIMAL,
    U_GET_INTERVAL_FRACTION,
    U_GET_SHIFT_DECIMAL,
    U_GET_SHIFT_FRACTION,
    U_SET_INTERVAL_DECIMAL,
    U_SET_INTERVAL_FRACTION,
    U_SET_SHIFT_DECIMAL,
    U_SET_SHIFT_FRACTION,
    UNSUPPORTED
};

static const char *const UNSUPPORTED_NAMES[UNSUPPORTED] = {
    "fmi3EnterStepMode",           "fmi3EnterConfigurationMode",
    "fmi3ExitConfigurationMode",   "fmi3GetDirectionalDerivative",
    "fmi3GetAdjointDerivative",    "fmi3GetNumberOfVariableDependencies",
    "fmi3GetVariableDependencies", "fmi3GetOutputDerivatives",
    "fmi3ActivateModelPartition",  "fmi3GetIntervalDecimal",
    "fmi3GetIntervalFraction",     "fmi3GetShiftDecimal",
    "fmi3GetShiftFraction",        "fmi3SetIntervalDecimal",
    "fmi3SetIntervalFraction",     "fmi3SetShiftDecimal",
    "fmi3SetShiftFraction"};

static int call_unsupported(const block *b, void *c, long which, uint32_t in, uint32_t out)
{
    const struct fmi3_api *api = API(b);
    fmi3ValueReference known[1] = {in}, unknown[1] = {out};
    fmi3Float64 seed[1] = {1}, sensitivity[1] = {-1}, interval[1] = {0.1};
    fmi3UInt64 counter[1] = {1}, resolution[1] = {10};
    fmi3IntervalQualifier qualifier[1];
    fmi3Int32 order[1] = {1};
    size_t n = 0, element[1] = {0};
    fmi3DependencyKind kind[1];
    switch (which) {
    case U_ENTER_STEP_MODE: return api->EnterStepMode(c);
    case U_ENTER_CONFIGURATION: return api->EnterConfigurationMode(c);
    case U_EXIT_CONFIGURATION: return api->ExitConfigurationMode(c);
    case U_DIRECTIONAL:
        return api->GetDirectionalDerivative(c, unknown, 1, known, 1, seed, 1, sensitivity, 1);
    case U_ADJOINT:
        return api->GetAdjointDerivative(c, unknown, 1, known, 1, seed, 1, sensitivity, 1);
    case U_N_DEPENDENCIES: return api->GetNumberOfVariableDependencies(c, out, &n);
    case U_DEPENDENCIES:
        return api->GetVariableDependencies(c, out, element, known, element, kind, 1);
    case U_OUTPUT_DERIVATIVES:
        return api->GetOutputDerivatives(c, unknown, 1, order, sensitivity, 1);
    case U_ACTIVATE_PARTITION: return api->ActivateModelPartition(c, in, 0.0);
    case U_GET_INTERVAL_DECIMAL: return api->GetIntervalDecimal(c, known, 1, interval, qualifier);
    case U_GET_INTERVAL_FRACTION:
        return api->GetIntervalFraction(c, known, 1, counter, resolution, qualifier);
    case U_GET_SHIFT_DECIMAL: return api->GetShiftDecimal(c, known, 1, interval);
    case U_GET_SHIFT_FRACTION: return api->GetShiftFraction(c, known, 1, counter, resolution);
    case U_SET_INTERVAL_DECIMAL: return api->SetIntervalDecimal(c, known, 1, interval);
    case U_SET_INTERVAL_FRACTION: return api->SetIntervalFraction(c, known, 1, counter, resolution);
    case U_SET_SHIFT_DECIMAL: return api->SetShiftDecimal(c, known, 1, interval);
    default: return api->SetShiftFraction(c, known, 1, counter, resolution);
    }
}

static int op_unsupported3(sim *s, const misuse *m)
{
    return call_unsupported(s->b, s->c, m->i, m->vr, m->vr2);
}

/* Every function with an instance, called with NULL and otherwise valid arguments: fmi3Error,
 * nothing logged (there is nowhere to), no crash; fmi3FreeInstance(NULL) does nothing. */
enum { NULL_CALLS = 2 * T3_TYPES + UNSUPPORTED + ME_FUNCTIONS + 16 };

static int op_null_instance(sim *s, const misuse *m)
{
    const block *b = s->b;
    const struct fmi3_api *api = API(b);
    fmi3ValueReference vr[1] = {m->vr};
    double d = 0;
    fmi3Boolean flag = 0, flags[6];
    fmi3Float64 real = 0;
    size_t size = 0;
    void *valid = NULL, *state = NULL;
    unsigned char *bytes = NULL;
    size_t n = 0;
    if (FMU(b, get_state, s->c, &valid) != fmi3OK || !sim_state_bytes(s, &bytes, &n)) return -1;
    long i = m->i;
    int result = -1;
    if (i < T3_TYPES)
        result = FMU(b, get, NULL, (int)i, vr, 1, &d, 1);
    else if (i < 2 * T3_TYPES)
        result = FMU(b, set, NULL, (int)(i - T3_TYPES), vr, 1, &d, 1);
    else if (i < 2 * T3_TYPES + UNSUPPORTED)
        result = call_unsupported(b, NULL, i - 2 * T3_TYPES, m->vr, m->vr);
    else if (i < 2 * T3_TYPES + UNSUPPORTED + ME_FUNCTIONS) {
        misuse me = *m;
        me.i = i - 2 * T3_TYPES - UNSUPPORTED;
        result = op_me_null_component(s, &me);
    } else {
        switch (i - (2 * T3_TYPES + UNSUPPORTED + ME_FUNCTIONS)) {
        case 0: result = api->SetDebugLogging(NULL, fmi3True, 0, NULL); break;
        case 1: result = api->EnterInitializationMode(NULL, fmi3False, 0, 0, fmi3False, 0); break;
        case 2: result = api->ExitInitializationMode(NULL); break;
        case 3: result = api->Terminate(NULL); break;
        case 4: result = api->Reset(NULL); break;
        case 5: result = api->GetFMUState(NULL, &state); break;
        case 6: result = api->SetFMUState(NULL, valid); break;
        case 7: /* must not free the state: it is freed below, a double free would show */
            state = valid;
            result = api->FreeFMUState(NULL, &state);
            if (state != valid) result = OTHER_RESULT;
            state = NULL;
            break;
        case 8: result = api->SerializedFMUStateSize(NULL, valid, &size); break;
        case 9: result = api->SerializeFMUState(NULL, valid, bytes, n); break;
        case 10: result = api->DeserializeFMUState(NULL, bytes, n, &state); break;
        case 11:
            result =
                api->DoStep(NULL, s->t, b->cycle, fmi3True, &flag, &flags[0], &flags[1], &real);
            break;
        case 12: result = api->EvaluateDiscreteStates(NULL); break;
        case 13: result = api->GetNumberOfEventIndicators(NULL, &size); break;
        case 14: result = api->GetNumberOfContinuousStates(NULL, &size); break;
        default:
            api->FreeInstance(NULL);
            result = fmi3OK;
            break;
        }
    }
    if (state) result = OTHER_RESULT; /* something was allocated for a NULL instance */
    FMU(b, free_state, s->c, &valid);
    free(bytes);
    return result;
}

static const char *null_call_name(long i, char *text, size_t size)
{
    static const char *const rest[] = {"fmi3SetDebugLogging",
                                       "fmi3EnterInitializationMode",
                                       "fmi3ExitInitializationMode",
                                       "fmi3Terminate",
                                       "fmi3Reset",
                                       "fmi3GetFMUState",
                                       "fmi3SetFMUState",
                                       "fmi3FreeFMUState",
                                       "fmi3SerializedFMUStateSize",
                                       "fmi3SerializeFMUState",
                                       "fmi3DeserializeFMUState",
                                       "fmi3DoStep",
                                       "fmi3EvaluateDiscreteStates",
                                       "fmi3GetNumberOfEventIndicators",
                                       "fmi3GetNumberOfContinuousStates",
                                       "fmi3FreeInstance"};
    if (i < T3_TYPES) return types[i].getter;
    if (i < 2 * T3_TYPES) return types[i - T3_TYPES].setter;
    i -= 2 * T3_TYPES;
    if (i < UNSUPPORTED) return UNSUPPORTED_NAMES[i];
    i -= UNSUPPORTED;
    if (i < ME_FUNCTIONS) return names[FN_ENTER_EVENT + i];
    i -= ME_FUNCTIONS;
    snprintf(text, size, "%s", rest[i]);
    return text;
}

/* ---- the cases only FMI 3.0 has ---- */

enum {
    I = 1 << PHASE_INSTANTIATED,
    N = 1 << PHASE_INITIALIZATION,
    S = 1 << PHASE_STEP,
    T = 1 << PHASE_TERMINATED,
    C = 1 << PHASE_CONTINUOUS,
    ALL = I | N | S | T | C
};

static const md_variable *input_of_type(const block *b, int type)
{
    for (size_t i = 0; i < b->md.count; i++)
        if (b->md.variables[i].type == type && b->md.variables[i].causality == CAUS_INPUT)
            return &b->md.variables[i];
    return NULL;
}

/* The rows of the get and set functions and of the types without variables, for a table of
 * calls in every mode: gets, sets of an input in `settable` (Float32 and Float64 also in
 * `settable_real`), the other types with nvr = 0 wherever. */
static size_t variable_rows(const block *b, mode_row *rows, unsigned readable, unsigned settable,
                            unsigned settable_real, unsigned any)
{
    size_t n = 0;
    for (int type = 0; type < T3_TYPES; type++) {
        if (!types[type].has_table) {
            /* Strings are values of the core (core/strings.c), so their calls keep the state
             * rules of every get and set, even with nvr = 0; the other types have none. */
            unsigned get_in = type == T3_STRING ? readable : any,
                     set_in = type == T3_STRING ? settable : any;
            rows[n++] = (mode_row){types[type].getter,
                                   " with nvr = 0",
                                   op_null_array,
                                   type,
                                   5,
                                   NULL,
                                   get_in,
                                   get_in,
                                   NULL,
                                   false};
            rows[n++] = (mode_row){types[type].setter,
                                   " with nvr = 0",
                                   op_null_array,
                                   type,
                                   4,
                                   NULL,
                                   set_in,
                                   set_in,
                                   NULL,
                                   false};
            continue;
        }
        const md_variable *v = first_of_type(b, type), *in = input_of_type(b, type);
        if (v)
            rows[n++] =
                (mode_row){types[type].getter,      "",   op_get, type, 0, v, readable, readable,
                           "must not be called in", false};
        if (in)
            rows[n++] = (mode_row){types[type].setter,
                                   " of an input",
                                   op_set,
                                   type,
                                   0,
                                   in,
                                   types[type].kind == KIND_REAL ? settable_real : settable,
                                   0,
                                   "must not be called in",
                                   false};
    }
    rows[n++] =
        (mode_row){"fmi3GetFloat64",        " of time", op_get_time, 0, 0, NULL, readable, readable,
                   "must not be called in", false};
    return n;
}

/* The modes of src/fmi3/fmi3.c's table (FMI 3.0, 3.2 and 4.2), for each interface. */
static void wrong_modes(const block *b, misuse_list *list)
{
    const char *mode = "must not be called in", *me = "Model Exchange function",
               *cs = "co-simulation function";
    mode_row rows[80];
    size_t n = variable_rows(b, rows, N | S | T, I | N | S, I | N | S, I | N | S | T);
    const mode_row cs_rows[] = {
        {"fmi3EnterInitializationMode", "", op_enter, 0, 0, NULL, I, 0, mode, false},
        {"fmi3ExitInitializationMode", "", op_exit, 0, 0, NULL, N, 0, mode, false},
        {"fmi3DoStep", "", op_dostep, 0, 0, NULL, S, 0, mode, false},
        {"fmi3Terminate", "", op_terminate, 0, 0, NULL, S, 0, mode, false},
        {"fmi3GetFMUState", " and fmi3FreeFMUState", op_get_free_state, 0, 0, NULL, ALL, ALL, mode,
         false},
        /* Model Exchange only: refused in every mode, naming the interface */
        {"fmi3EvaluateDiscreteStates", "", op_me3, 0, 0, NULL, 0, 0, me, false},
        {"fmi3GetNumberOfEventIndicators", "", op_me3, 1, 0, NULL, 0, 0, me, false},
        {"fmi3GetNumberOfContinuousStates", "", op_me3, 2, 0, NULL, 0, 0, me, false},
    };
    for (size_t i = 0; i < sizeof cs_rows / sizeof cs_rows[0]; i++) rows[n++] = cs_rows[i];
    static const int cs_phases[] = {PHASE_INSTANTIATED, PHASE_INITIALIZATION, PHASE_STEP,
                                    PHASE_TERMINATED};
    add_mode_cases(b, list, "calls in the wrong mode", fmi2CoSimulation, rows, n, cs_phases,
                   sizeof cs_phases / sizeof cs_phases[0]);

    /* Model Exchange: PHASE_STEP is event mode; inputs are set in event mode and, for the
     * importers that do so (OMSimulator), in continuous-time mode too, every type: the next PLC
     * call reads them (docs/behaviour.md §1.11) */
    n = variable_rows(b, rows, N | S | C | T, I | N | S | C, I | N | S | C, ALL);
    const mode_row me_rows[] = {
        {"fmi3EnterInitializationMode", "", op_enter, 0, 0, NULL, I, 0, mode, false},
        {"fmi3ExitInitializationMode", "", op_exit, 0, 0, NULL, N, 0, mode, false},
        {"fmi3Terminate", "", op_terminate, 0, 0, NULL, S | C, 0, mode, false},
        {"fmi3EnterEventMode", "", op_me, ME_ENTER_EVENT, 0, NULL, S | C, S, mode, false},
        {"fmi3UpdateDiscreteStates", "", op_me, ME_NEW_DISCRETE, 0, NULL, S, S, mode, false},
        {"fmi3EvaluateDiscreteStates", "", op_me3, 0, 0, NULL, S, S, mode, false},
        {"fmi3EnterContinuousTimeMode", "", op_me, ME_ENTER_CONTINUOUS, 0, NULL, S, 0, mode, false},
        {"fmi3CompletedIntegratorStep", "", op_me, ME_COMPLETED, 0, NULL, C, C, mode, false},
        {"fmi3SetTime", " (the FMU's time)", op_me, ME_SET_TIME, 0, NULL, S | C, S | C, mode,
         false},
        {"fmi3SetContinuousStates", " with nContinuousStates = 0", op_me, ME_SET_STATES, 0, NULL, C,
         C, mode, false},
        {"fmi3GetContinuousStateDerivatives", " with nContinuousStates = 0", op_me,
         ME_GET_DERIVATIVES, 0, NULL, N | S | C | T, N | S | C | T, mode, false},
        {"fmi3GetEventIndicators", " with nEventIndicators = 0", op_me, ME_GET_INDICATORS, 0, NULL,
         N | S | C | T, N | S | C | T, mode, false},
        {"fmi3GetContinuousStates", " with nContinuousStates = 0", op_me, ME_GET_STATES, 0, NULL,
         N | S | C | T, N | S | C | T, mode, false},
        {"fmi3GetNominalsOfContinuousStates", " with nContinuousStates = 0", op_me, ME_GET_NOMINALS,
         0, NULL, ALL, ALL, mode, false},
        {"fmi3GetNumberOfEventIndicators", "", op_me3, 1, 0, NULL, ALL, ALL, mode, false},
        {"fmi3GetNumberOfContinuousStates", "", op_me3, 2, 0, NULL, ALL, ALL, mode, false},
        {"fmi3GetFMUState", " and fmi3FreeFMUState", op_get_free_state, 0, 0, NULL, ALL, ALL, mode,
         false},
        /* co-simulation only: refused in every mode, naming the interface */
        {"fmi3DoStep", "", op_dostep, 0, 0, NULL, 0, 0, cs, false},
    };
    for (size_t i = 0; i < sizeof me_rows / sizeof me_rows[0]; i++) rows[n++] = me_rows[i];
    static const int me_phases[] = {PHASE_INSTANTIATED, PHASE_INITIALIZATION, PHASE_STEP,
                                    PHASE_CONTINUOUS, PHASE_TERMINATED};
    add_mode_cases(b, list, "ME: calls in the wrong mode", fmi2ModelExchange, rows, n, me_phases,
                   sizeof me_phases / sizeof me_phases[0]);
}

/* nValues must equal nValueReferences: every variable is a scalar. For a type the FMU has no
 * variable of, nvr = 0 with nValues = 1 breaks the rule just as well. */
static void n_values(const block *b, misuse_list *list)
{
    const md_variable *any = first_of(b, KIND_REAL, is_output);
    if (!any) any = &b->md.variables[0];
    static const char *const what[] = {"nvr = 1, nValues = 0", "nvr = 1, nValues = 2",
                                       "nvr = 0, nValues = 1"};
    for (int type = 0; type < T3_TYPES; type++) {
        if (type == T3_CLOCK) continue; /* fmi3Get/SetClock take no nValues */
        const md_variable *v = first_of_type(b, type);
        for (int get = 0; get <= 1; get++) {
            for (int k = 0; k < 3; k++) {
                misuse *m =
                    misuse_add(list, "nValues and nValueReferences", PHASE_STEP, op_n_values);
                misuse_label(m, "%s with %s", get ? types[type].getter : types[type].setter,
                             what[k]);
                m->i = type, m->i2 = k, m->vr2 = (uint32_t)get;
                m->vr = v ? v->vr : any->vr;
                m->r = v && v->has_start ? v->start : 0;
                m->function = get ? types[type].getter : types[type].setter;
                if (types[type].has_table) snprintf(m->contains, sizeof m->contains, "nValues");
            }
        }
    }
}

/* The independent variable: fmi3GetFloat64 reads it (in the tables of wrong_modes), nothing
 * sets it, and no other type knows its value reference. */
static void time_variable(const block *b, misuse_list *list)
{
    const char *group = "the independent variable time";
    const md_variable *out = first_of_type(b, T3_FLOAT64); /* cycleTime at least */
    uint32_t unknown = 0;
    while (known_vr(b, unknown)) unknown++;
    if (out) {
        misuse *m = misuse_add(list, group, PHASE_STEP, op_get_time);
        misuse_label(m, "fmi3GetFloat64 {time, %s} is allowed", out->name);
        m->i = 1, m->vr2 = out->vr, m->expect = fmi3OK, m->logs = 0, m->function = "fmi3GetFloat64";
    }
    misuse *m = misuse_add(list, group, PHASE_STEP, op_get_time);
    misuse_label(m, "fmi3GetFloat64 {time, unknown %u}", (unsigned)unknown);
    m->i = 2, m->vr2 = unknown, m->function = "fmi3GetFloat64";
    snprintf(m->contains, sizeof m->contains, "%u", (unsigned)unknown);
    static const int cs_phases[] = {PHASE_INSTANTIATED, PHASE_INITIALIZATION, PHASE_STEP,
                                    PHASE_TERMINATED};
    for (size_t p = 0; p < sizeof cs_phases / sizeof cs_phases[0]; p++) {
        m = misuse_add(list, group, cs_phases[p], op_set);
        misuse_label(m, "fmi3SetFloat64 of time");
        m->i = T3_FLOAT64, m->vr = TIME_VR3, m->r = 1.0, m->function = "fmi3SetFloat64";
        snprintf(m->contains, sizeof m->contains, "%s",
                 cs_phases[p] == PHASE_TERMINATED ? "must not be called in" : "1000000");
    }
    for (int type = 0; type < T3_TYPES; type++) {
        if (type == T3_FLOAT64) continue;
        for (int get = 0; get <= 1; get++) {
            m = misuse_add(list, group, PHASE_STEP, get ? op_get : op_set);
            misuse_label(m, "%s of time's value reference",
                         get ? types[type].getter : types[type].setter);
            m->i = type, m->vr = TIME_VR3, m->r = 0;
            m->function = get ? types[type].getter : types[type].setter;
            snprintf(m->contains, sizeof m->contains, "1000000");
        }
    }
}

static void out_pointers(const block *b, misuse_list *list)
{
    (void)b;
    static const char *const step[] = {"eventHandlingNeeded", "terminateSimulation", "earlyReturn",
                                       "lastSuccessfulTime", "every out-pointer"};
    for (int k = 0; k < 5; k++) {
        misuse *m = misuse_add(list, "fmi3DoStep arguments", PHASE_STEP, op_do_step_null);
        misuse_label(m, "fmi3DoStep with %s NULL", step[k]);
        m->i2 = k, m->function = "fmi3DoStep";
        snprintf(m->contains, sizeof m->contains, "NULL");
    }
    static const char *const update[] = {"discreteStatesNeedUpdate",
                                         "terminateSimulation",
                                         "nominalsOfContinuousStatesChanged",
                                         "valuesOfContinuousStatesChanged",
                                         "nextEventTimeDefined",
                                         "nextEventTime"};
    for (int k = 0; k < 6; k++) {
        misuse *m = misuse_add(list, "ME: arguments", PHASE_STEP, op_update_null);
        m->type = fmi2ModelExchange;
        misuse_label(m, "fmi3UpdateDiscreteStates with %s NULL", update[k]);
        m->i2 = k, m->function = "fmi3UpdateDiscreteStates";
        snprintf(m->contains, sizeof m->contains, "NULL");
    }
    for (int f = 1; f <= 2; f++) {
        misuse *m = misuse_add(list, "ME: arguments", PHASE_STEP, op_me3);
        m->type = fmi2ModelExchange;
        const char *name =
            f == 1 ? "fmi3GetNumberOfEventIndicators" : "fmi3GetNumberOfContinuousStates";
        misuse_label(m, "%s with the count NULL", name);
        m->i = f, m->i2 = 1, m->function = name;
        snprintf(m->contains, sizeof m->contains, "NULL");
    }
}

/* The functions this FMU refuses whatever the mode: fmi3Error, one message, nothing changed. */
static void refused_functions(const block *b, misuse_list *list)
{
    const md_variable *in = first_of(b, KIND_REAL, is_input),
                      *out = first_of(b, KIND_REAL, is_output);
    static const int phases[] = {PHASE_INSTANTIATED, PHASE_INITIALIZATION, PHASE_STEP,
                                 PHASE_CONTINUOUS, PHASE_TERMINATED};
    for (int type = fmi2ModelExchange; type <= fmi2CoSimulation; type++) {
        for (size_t p = 0; p < sizeof phases / sizeof phases[0]; p++) {
            if (phases[p] == PHASE_CONTINUOUS && type == fmi2CoSimulation) continue;
            for (int f = 0; f < UNSUPPORTED; f++) {
                misuse *m = misuse_add(list, "functions FMI 3.0 has and the FMU refuses", phases[p],
                                       op_unsupported3);
                m->type = (fmi2Type)type;
                misuse_label(m, "%s", UNSUPPORTED_NAMES[f]);
                m->i = f, m->vr = in ? in->vr : 0, m->vr2 = out ? out->vr : m->vr;
                m->function = UNSUPPORTED_NAMES[f];
                snprintf(m->contains, sizeof m->contains, "not supported");
            }
        }
    }
    const md_variable *any = first_of(b, KIND_REAL, is_any);
    for (long i = 0; i < NULL_CALLS; i++) {
        char text[64];
        misuse *m = misuse_add(list, "NULL instance", PHASE_STEP, op_null_instance);
        misuse_label(m, "%s(NULL, ...)", null_call_name(i, text, sizeof text));
        m->i = i, m->vr = any ? any->vr : 0, m->logs = 0;
        if (i == NULL_CALLS - 1) m->expect = fmi3OK; /* fmi3FreeInstance(NULL): a no-op */
    }
}

void build_fmi3_misuses(const block *b, misuse_list *list)
{
    wrong_modes(b, list);
    n_values(b, list);
    time_variable(b, list);
    out_pointers(b, list);
    refused_functions(b, list);
}

/* ---- groups ---- */

typedef struct {
    const char *label;
    int how; /* 0 co-simulation, 1 Model Exchange, 2 Scheduled Execution */
    const char *name, *token;
    bool logger, environment;
    bool succeeds;
    const char *contains;
} instantiation3;

/* The instance works: initialization, a step (co-simulation) or the time event of call 1. */
static bool works(const block *b, void *c, bool model_exchange)
{
    event_info info = {0};
    bool ok = FMU(b, begin, c, 0.0, false, 0.0) == fmi3OK && FMU(b, exit_init, c) == fmi3OK;
    if (model_exchange)
        return ok && FMU(b, update_discrete, c, &info) == fmi3OK &&
               FMU(b, enter_continuous, c) == fmi3OK && FMU(b, set_time, c, info.next) == fmi3OK &&
               FMU(b, enter_event, c) == fmi3OK && FMU(b, update_discrete, c, &info) == fmi3OK &&
               info.next == call_time(b, 2) && FMU(b, do_step, c, 0.0, b->cycle) == fmi3Error;
    return ok && FMU(b, do_step, c, 0.0, b->cycle) == fmi3OK;
}

/* fmi3InstantiateModelExchange, fmi3InstantiateCoSimulation and
 * fmi3InstantiateScheduledExecution refuse what they must, with one message through
 * logMessage, and the instances they make work. */
static void group_instantiate3(const block *b)
{
    group_begin("fmi3Instantiate*");
    const struct fmi3_api *api = API(b);
    wrong_guids wrong;
    make_wrong_guids(b, &wrong);
    const instantiation3 cases[] = {
        {"co-simulation", 0, "i", b->guid, true, true, true, NULL},
        {"Model Exchange", 1, "i", b->guid, true, true, true, NULL},
        {"co-simulation, no logMessage", 0, "i", b->guid, false, true, true, NULL},
        {"Model Exchange, no logMessage", 1, "i", b->guid, false, true, true, NULL},
        {"co-simulation, instanceEnvironment NULL", 0, "i", b->guid, true, false, true, NULL},
        {"zero token", 0, "i", "{00000000-0000-0000-0000-000000000000}", true, true, false,
         "instantiationToken"},
        {"token of another block", 0, "i", wrong.other, true, true, false, "instantiationToken"},
        {"token without its last character", 0, "i", wrong.prefix, true, true, false,
         "instantiationToken"},
        {"token with one character changed", 0, "i", wrong.changed, true, true, false,
         "instantiationToken"},
        {"empty token", 0, "i", "", true, true, false, "instantiationToken"},
        {"NULL token", 0, "i", NULL, true, true, false, "instantiationToken"},
        {"Model Exchange, wrong token", 1, "i", wrong.changed, true, true, false,
         "instantiationToken"},
        {"Model Exchange, NULL token", 1, "i", NULL, true, true, false, "instantiationToken"},
        {"NULL instanceName", 0, NULL, b->guid, true, true, false, "instanceName"},
        {"empty instanceName", 0, "", b->guid, true, true, false, "instanceName"},
        {"Model Exchange, NULL instanceName", 1, NULL, b->guid, true, true, false, "instanceName"},
        {"Model Exchange, empty instanceName", 1, "", b->guid, true, true, false, "instanceName"},
        {"wrong token, no logMessage", 0, "i", wrong.changed, false, true, false, NULL},
        {"Scheduled Execution", 2, "i", b->guid, true, true, false, "Scheduled Execution"},
        {"Scheduled Execution, no logMessage", 2, "i", b->guid, false, true, false, NULL},
    };
    static const fmi3ValueReference required[1] = {0};
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const instantiation3 *t = &cases[i];
        log_record log = {0};
        fmi3LogMessageCallback logger = t->logger ? harness_logger3 : NULL;
        fmi3InstanceEnvironment environment = t->environment ? &log : NULL;
        long messages = total_log_messages();
        fmi3Instance c;
        if (t->how == 0)
            c = api->InstantiateCoSimulation(t->name, t->token, "/tmp", fmi3True, fmi3True,
                                             fmi3False, fmi3True, required, 1, environment, logger,
                                             NULL);
        else if (t->how == 1)
            c = api->InstantiateModelExchange(t->name, t->token, "/tmp", fmi3True, fmi3True,
                                              environment, logger);
        else
            c = api->InstantiateScheduledExecution(t->name, t->token, "/tmp", fmi3False, fmi3False,
                                                   environment, logger, NULL, NULL, NULL);
        int expected_logs = t->succeeds || !t->logger ? 0 : 1;
        const log_entry *e = log_get(&log, 0);
        bool ok = (c != NULL) == t->succeeds && total_log_messages() - messages == expected_logs &&
                  (!t->environment || log.total == expected_logs);
        const char *function = t->how == 0   ? "fmi3InstantiateCoSimulation"
                               : t->how == 1 ? "fmi3InstantiateModelExchange"
                                             : "fmi3InstantiateScheduledExecution";
        if (ok && expected_logs && t->environment)
            ok = e && e->status == fmi2Error && !strcmp(e->category, "logStatusError") &&
                 !strncmp(e->text, function, strlen(function)) && strstr(e->text, t->contains);
        /* loggingOn was true: the instance's trace goes to its logger; fine either way */
        if (c) {
            ok = ok && works(b, c, t->how == 1);
            api->FreeInstance(c);
        }
        check(ok, "%s: returned %s, %ld messages (expected %d) \"%s\"", t->label,
              c ? "an instance" : "NULL", total_log_messages() - messages, expected_logs,
              e ? e->text : "");
    }
    /* Two instances of the same name are independent: one runs, the other stays where it was. */
    log_record l1 = {0}, l2 = {0};
    void *x = FMU(b, instantiate, "same", fmi2CoSimulation, &l1);
    void *y = FMU(b, instantiate, "same", fmi2CoSimulation, &l2);
    double t = -1;
    check(x && y && x != y && works(b, x, false) && FMU(b, begin, y, 0.0, false, 0.0) == fmi3OK &&
              FMU(b, now, y, &t) == fmi3OK && t == 0.0,
          "two instances of the same name are independent");
    if (x) FMU(b, free_instance, x);
    if (y) FMU(b, free_instance, y);
    /* The FMU copies instanceName: the importer's buffer may change afterwards; a long name */
    char name[1200];
    for (int variant = 0; variant < 2; variant++) {
        log_record log = {0};
        size_t length = variant ? sizeof name - 1 : 8;
        memset(name, 'n', length);
        name[length] = '\0';
        void *c = FMU(b, instantiate, name, variant ? fmi2ModelExchange : fmi2CoSimulation, &log);
        memset(name, 'x', length);
        check(c && works(b, c, variant == 1) && log.total == variant, /* ME: fmi3DoStep refused */
              "%s: the instance works",
              variant ? "an instanceName of 1199 characters"
                      : "instanceName buffer reused after instantiation");
        if (c) FMU(b, free_instance, c);
    }
    group_end();
}

/* The FMI 3.0 variables are the FMI 2.0 ones: the same names, value references, causalities
 * and start values, in the same order (so that both scenarios set the same inputs). */
static bool same_variables(const block *b3, const block *b2, char *why, size_t size)
{
    if (b3->md.count != b2->md.count) {
        snprintf(why, size, "%zu variables in FMI 3.0, %zu in FMI 2.0", b3->md.count, b2->md.count);
        return false;
    }
    for (size_t i = 0; i < b3->md.count; i++) {
        const md_variable *x = &b3->md.variables[i], *y = &b2->md.variables[i];
        if (strcmp(x->name, y->name) || x->vr != y->vr || x->causality != y->causality ||
            x->fixed != y->fixed || x->kind != y->kind || x->is_time != y->is_time ||
            x->has_start != y->has_start || (x->has_start && x->start != y->start)) {
            snprintf(why, size, "variable %zu: %s (vr %u) in FMI 3.0, %s (vr %u) in FMI 2.0", i,
                     x->name, (unsigned)x->vr, y->name, (unsigned)y->vr);
            return false;
        }
    }
    return true;
}

/* The same scenario (variants, interfaces, step patterns, inputs) on both libraries: the same
 * outputs after every doStep and every call, bit for bit (integers through the native widths,
 * a Float32 widened to double), and the same serialized states at every phase, byte for byte. */
static void group_versus_fmi2(const block *b, const reference *refs, const reference *me_refs)
{
    group_begin("FMI 3.0 against FMI 2.0");
    const block *b2 = b->fmi2;
    char why[256] = "";
    check(same_variables(b, b2, why, sizeof why), "the variables differ: %s", why);
    check(!strcmp(b->md.identifier, b2->md.identifier) && !strcmp(b->md.guid, b2->md.guid),
          "modelIdentifier %s and instantiationToken %s are FMI 2.0's %s and guid %s",
          b->md.identifier, b->md.guid, b2->md.identifier, b2->md.guid);
    for (int variant = 0; variant < THREADS; variant++) {
        for (int run = 0; run < 3; run++) {
            static const char *const runs[] = {"co-simulation (steps of 1, 2, 0.5, 1.5 cycles)",
                                               "co-simulation (steps of one cycle)",
                                               "Model Exchange"};
            fmi2Type type = run == 2 ? fmi2ModelExchange : fmi2CoSimulation;
            reference r2, r3;
            bool own = run == 1; /* the uniform co-simulation run has no reference yet */
            bool ok = reference_run_as(b2, variant, type, run == 1, &r2) &&
                      (!own || reference_run_as(b, variant, type, true, &r3));
            const reference *x = own ? &r3 : run == 2 ? &me_refs[variant] : &refs[variant];
            why[0] = '\0';
            check(ok && same_reference(b, x, &r2, why, sizeof why),
                  "variant %d, %s: FMI 3.0 and FMI 2.0 differ: %s", variant, runs[run], why);
            if (ok) reference_free(&r2);
            if (ok && own) reference_free(&r3);
        }
    }
    group_end();
}

/* Serialized states pass between the versions (the format is the same): a state of one
 * library, deserialized by an instance of the other, goes on as the original would. */
static void group_states_across_versions(const block *b, const reference *refs,
                                         const reference *me_refs)
{
    group_begin("states across versions");
    const block *versions[2] = {b, b->fmi2};
    for (int from = 0; from <= 1; from++) {
        const block *source_block = versions[from], *target_block = versions[1 - from];
        for (int type = fmi2ModelExchange; type <= fmi2CoSimulation; type++) {
            const reference *ref = type == fmi2ModelExchange ? &me_refs[0] : &refs[0];
            for (int phase = PHASE_INITIALIZATION; phase <= PHASE_STEP; phase++) {
                sim source, target;
                unsigned char *bytes = NULL;
                size_t size = 0;
                void *state = NULL;
                char why[256] = "";
                bool ok = sim_open_as(&source, source_block, 0, (fmi2Type)type) &&
                          sim_advance(&source, phase) && sim_state_bytes(&source, &bytes, &size) &&
                          sim_open_as(&target, target_block, 1, (fmi2Type)type) &&
                          FMU(target_block, deserialize, target.c, bytes, size, &state) == fmi3OK &&
                          FMU(target_block, set_state, target.c, state) == fmi3OK &&
                          FMU(target_block, free_state, target.c, &state) == fmi3OK;
                if (ok) { /* go on where the source was, with the reference's inputs */
                    target.variant = 0;
                    target.phase = source.phase;
                    target.k = source.k;
                    target.t = source.t;
                    target.next_event = source.next_event;
                    target.in_event = source.in_event;
                    target.rows = source.rows;
                    memcpy(target.trace, source.trace,
                           (size_t)source.rows * (size_t)b->n_outputs * sizeof *target.trace);
                    ok = sim_run_to_end(&target) && same_trace(&target, ref, 0, why, sizeof why);
                }
                check(ok,
                      "a %s state of FMI %s in %s, deserialized by FMI %s, goes on as FMI %s's "
                      "reference: %s %s %s",
                      interface_name((fmi2Type)type), source_block->ops->version_string,
                      phase_name((fmi2Type)type, phase), target_block->ops->version_string,
                      b->ops->version_string, source.failure, target.failure, why);
                free(bytes);
                sim_close(&source);
                sim_close(&target);
            }
        }
    }
    group_end();
}

/* A UDINT beyond what an fmi2Integer carries (FMI 3.0 sets it, its state serializes it; FMI
 * 2.0 declares max 2147483647): the FMI 2.0 library must refuse such a state, or read the value
 * back without undefined behaviour. Run in a child: a sanitizer's report ends it. */
typedef struct {
    const block *b;
    const md_variable *v;
} wide_job;

static bool wide_udint(void *argument, char *why, size_t why_size)
{
    wide_job *job = argument;
    const block *b = job->b, *b2 = b->fmi2;
    log_record l3 = {0}, l2 = {0};
    double wide = 4000000000.0, back = 0;
    void *c3 = FMU(b, instantiate, "wide", fmi2CoSimulation, &l3), *state = NULL;
    void *c2 = FMU(b2, instantiate, "wide", fmi2CoSimulation, &l2);
    unsigned char *bytes = NULL;
    size_t size = 0;
    bool ok = c3 && c2 && FMU(b, begin, c3, 0, false, 0) == fmi3OK &&
              FMU(b, set, c3, T3_UINT32, &job->v->vr, 1, &wide, 1) == fmi3OK &&
              FMU(b, exit_init, c3) == fmi3OK && FMU(b, get_state, c3, &state) == fmi3OK &&
              FMU(b, state_size, c3, state, &size) == fmi3OK && (bytes = malloc(size)) &&
              FMU(b, serialize, c3, state, bytes, size) == fmi3OK;
    void *state2 = NULL;
    int status = fmi2Fatal;
    bool refused = false;
    if (!ok) {
        snprintf(why, why_size, "FMI 3.0 did not set %s = 4000000000", job->v->name);
    } else {
        status = FMU(b2, deserialize, c2, bytes, size, &state2);
        refused = status == fmi2Error && l2.total == 1; /* refused, with a message: fine */
        if (!refused) {
            ok = status == fmi2OK && FMU(b2, set_state, c2, state2) == fmi2OK &&
                 FMU(b2, get, c2, KIND_INTEGER, &job->v->vr, 1, &back, 1) == fmi2OK;
            snprintf(
                why, why_size,
                "fmi2DeSerializeFMUstate accepted it (status %d) and fmi2GetInteger(%s) %s %.0f",
                status, job->v->name, ok ? "reads" : "fails, or reads", back);
        }
    }
    /* everything freed, so that valgrind's leak check in the child has nothing to report */
    if (state2) FMU(b2, free_state, c2, &state2);
    if (state) FMU(b, free_state, c3, &state);
    free(bytes);
    if (c2) FMU(b2, free_instance, c2);
    if (c3) FMU(b, free_instance, c3);
    return refused;
}

static void group_wide_values(const block *b)
{
    for (size_t i = 0; i < b->md.count; i++) {
        const md_variable *v = &b->md.variables[i];
        if (v->type != T3_UINT32 || v->causality != CAUS_INPUT ||
            (v->has_max && v->max < 2147483648.0))
            continue;
        group_begin("a UDINT beyond fmi2Integer");
        wide_job job = {b, v};
        char why[256] = "";
        bool ok = isolated(wide_udint, &job, why, sizeof why);
        check(ok,
              "an FMI 3.0 state with %s = 4000000000 (fmi2Integer carries at most 2147483647) "
              "into the FMI 2.0 library: must be refused or read back as it is: %s",
              v->name, why);
        group_end();
        return;
    }
}

/* The refusals of FMI 3.0 say what FMI 2.0's say, with the fmi3 function's name and without
 * FMI 2.0's '#' escape (the harness's FMI 2.0 logger undoes it): a cycleTime out of range names
 * the original's status codes 16#... in those blocks that have them. */
static void group_messages(const block *b)
{
    group_begin("FMI 3.0 messages");
    const md_variable *cycle = NULL, *cycle2 = NULL;
    for (size_t i = 0; i < b->md.count; i++)
        if (b->md.variables[i].is_cycle) cycle = &b->md.variables[i];
    for (size_t i = 0; b->fmi2 && i < b->fmi2->md.count; i++)
        if (b->fmi2->md.variables[i].is_cycle) cycle2 = &b->fmi2->md.variables[i];
    static const double bad[] = {0.0, 61.0, NAN};
    for (size_t k = 0; cycle && cycle2 && k < sizeof bad / sizeof bad[0]; k++) {
        sim s3, s2;
        bool ok = sim_open(&s3, b, 0) && sim_advance(&s3, PHASE_INITIALIZATION) &&
                  sim_open(&s2, b->fmi2, 0) && sim_advance(&s2, PHASE_INITIALIZATION);
        int mark3 = s3.log.total, mark2 = s2.log.total;
        ok = ok && FMU(b, set, s3.c, cycle->type, &cycle->vr, 1, &bad[k], 1) == fmi3Error &&
             FMU(b->fmi2, set, s2.c, cycle2->type, &cycle2->vr, 1, &bad[k], 1) == fmi2Error &&
             s3.log.total == mark3 + 1 && s2.log.total == mark2 + 1;
        const log_entry *e3 = log_get(&s3.log, mark3), *e2 = log_get(&s2.log, mark2);
        const char *t3 = e3 ? strchr(e3->text, ':') : NULL, *t2 = e2 ? strchr(e2->text, ':') : NULL;
        ok = ok && t3 && t2 && !strncmp(e3->text, "fmi3SetFloat64:", 15) && !strcmp(t3, t2) &&
             !strstr(e3->text, "##");
        check(ok, "cycleTime = %g: FMI 3.0 says \"%s\", FMI 2.0 \"%s\"", bad[k], e3 ? e3->text : "",
              e2 ? e2->text : "");
        sim_close(&s3);
        sim_close(&s2);
    }
    group_end();
}

/* fmi3GetFloat64 of time with values NULL: refused like any get with a NULL array (one
 * message, nothing changed). In a child: the known crash ends only it. */
typedef struct {
    const block *b;
    fmi2Type type;
} null_time_job;

static bool null_time(void *argument, char *why, size_t why_size)
{
    null_time_job *job = argument;
    sim s;
    unsigned char *before = NULL, *after = NULL;
    size_t nb = 0, na = 0;
    const fmi3ValueReference vr = TIME_VR3;
    bool ok = sim_open_as(&s, job->b, 0, job->type) && sim_advance(&s, PHASE_STEP) &&
              sim_state_bytes(&s, &before, &nb);
    int mark = s.log.total;
    int status = ok ? (int)API(job->b)->GetFloat64(s.c, &vr, 1, NULL, 1) : -1;
    ok = ok && status == fmi3Error && s.log.total == mark + 1 && sim_state_bytes(&s, &after, &na) &&
         same_bytes(before, nb, after, na, why, why_size, "the state changed");
    if (!ok && !why[0])
        snprintf(why, why_size, "returned %d, %d messages", status, s.log.total - mark);
    free(before);
    free(after);
    sim_close(&s);
    return ok;
}

static void group_null_time(const block *b)
{
    group_begin("time with values NULL");
    for (int type = fmi2ModelExchange; type <= fmi2CoSimulation; type++) {
        null_time_job job = {b, (fmi2Type)type};
        char why[256] = "";
        bool ok = isolated(null_time, &job, why, sizeof why);
        check(ok,
              "%s: fmi3GetFloat64(instance, {time}, 1, NULL, 1) must be refused (fmi3Error, one "
              "message): %s",
              interface_name((fmi2Type)type), why);
    }
    group_end();
}

void fmi3_groups_before_cases(const block *b, const reference *refs, const reference *me_refs)
{
    group_instantiate3(b);
    if (b->fmi2) {
        group_versus_fmi2(b, refs, me_refs);
        group_states_across_versions(b, refs, me_refs);
        group_messages(b);
    }
}

void fmi3_groups_after_cases(const block *b)
{
    group_null_time(b);
    if (b->fmi2) group_wide_values(b);
}
