/* libFuzzer target: the input bytes drive one instance of one LGF FMU, FMI 2.0 or FMI 3.0,
 * co-simulation or Model Exchange, through a sequence of calls of both interfaces, right and
 * wrong, and the target checks what docs/behaviour.md §1.7 promises. This file includes the
 * FMU's one translation unit (the core, one front-end, one block): tests/fuzz/CMakeLists.txt
 * compiles it twice per block, with units/fmi2/<Block>.c (LGF_FUZZ_FMI 2) and with
 * units/fmi3/<Block>.c (LGF_FUZZ_FMI 3), each as its own entry point (LGF_FUZZ_ENTRY), and
 * fuzz_main.c picks one by bit 6 of the input's second byte: fuzz_LGF_SawTooth,
 * fuzz_LGF_RampCI, ... The calls below go through the x_* layer, which is FMI 2.0 or FMI 3.0;
 * the checks are the same (FMI 3.0 adds its own: the out-pointers of fmi3DoStep, nValues, the
 * types without variables, the independent variable time, the functions it refuses).
 *
 * Besides the sanitizers (address, undefined: any crash, leak or undefined behaviour), the
 * target aborts when
 *   - a call on an instance returns fmi2Error or fmi2Warning without logging a problem, logs
 *     an error but returns fmi2OK, or returns a status other than OK, Warning and Error;
 *   - a call that returned fmi2Error changed the instance: the FMU state (serialized, byte for
 *     byte: clock, inputs, parameters, outputs, statics), the outputs read back with fmi2Get*
 *     and fmi2LastSuccessfulTime must be as before;
 *   - an fmi2Get*, a status query, fmi2GetFMUstate or a serialization changed the instance;
 *   - an input accepted by fmi2Set* does not read back as set (LREAL bit for bit, INT exactly,
 *     Boolean as 0/1, TIME to the ms, cycleTime to the µs);
 *   - after an accepted fmi2DoStep(t, h) the FMU's time is not t + h, or the FMU refuses its
 *     own state, serialized (FMI 3.0: also when fmi3DoStep asks for event handling, the end
 *     or an early return, or its lastSuccessfulTime is not the FMU's time);
 *   - a serialize / deserialize / fmi2SetFMUstate round trip does not reproduce the next
 *     step: the same inputs and doStep from the restored state must give the same status,
 *     the same outputs and the same state bytes;
 *   - deserialized bytes that were accepted do not serialize back to the same bytes;
 *   - the logger gets a format other than "%s", a NULL or empty message, an unknown category,
 *     or another componentEnvironment (FMI 3.0: instanceEnvironment; a message holding "##",
 *     FMI 2.0's escape of '#');
 *   - FMI 3.0: a get or set whose nValues differs from nValueReferences is accepted, a type
 *     this FMU has no variable of (Int8, Int32, Int64, UInt8, UInt64, String, Binary, Clock)
 *     accepts a value reference, a refused function (fmi3EnterStepMode, configuration mode,
 *     clocks, derivatives, dependencies) is accepted, fmi3GetFloat64 of time is not the FMU's
 *     time, or fmi3InstantiateScheduledExecution returns an instance;
 * and, for Model Exchange (the calls of the other interface must be refused, fmi2Error with a
 * message, changing nothing, like any other refused call), when
 *   - an accepted fmi2ExitInitializationMode, fmi2EnterEventMode, fmi2EnterContinuousTimeMode
 *     or fmi2Terminate leaves the instance in another mode than FMI 2.0 names;
 *   - an accepted fmi2SetTime(t) does not leave the FMU at time t, or the FMU then refuses its
 *     own state, serialized;
 *   - an accepted fmi2NewDiscreteStates returns another eventInfo than the contract's (no
 *     further iteration, no end, nothing continuous changed, nextEventTime defined and equal
 *     to t0 + (k·cycle_us)/1e6 of the next call k, after the FMU's time), leaves a call due,
 *     or a second one right after it changes anything;
 *   - fmi2CompletedIntegratorStep changes the instance or asks for an event or the end;
 *   - a function of continuous states or event indicators accepts nx (ni) != 0 or writes to
 *     an array of 0 elements;
 *   - an event iteration restored from a serialized state does not reproduce the original.
 *
 * Input format (bytes run out as zeros, so every input is valid):
 *   byte 0   instantiation (modulo 16): 0..8 correct, 9 no logger, 10 wrong GUID, 11 an fmuType
 *            that is neither interface, 12 NULL GUID, 13 empty instanceName, 14 NULL
 *            allocateMemory, 15 an allocation fails (next byte: which). A refused
 *            instantiation must return NULL with a log line (if there is a logger) and is
 *            followed by a correct one. FMI 3.0 (no allocator): 9 wrong token and no
 *            logMessage, 11 fmi3InstantiateScheduledExecution, 14 NULL instanceName, 15 a
 *            correct instance without logMessage, freed at once.
 *   byte 1   loggingOn (bit 0); FMI 3.0 (bit 6, read by fuzz_main.c); the interface (bit 7:
 *            1 Model Exchange, 0 co-simulation)
 *   then     operations: one byte (modulo OP_COUNT) and the operation's arguments; see the
 *            op_* functions. FMI 3.0 reads one byte more after OP_SET_REAL (Float64 or
 *            Float32), OP_SET_INTEGER (Int16, UInt16, UInt32, Int32, Int8 or UInt8) and
 *            OP_SET_BOOLEAN (where it changes nothing: set_kind), and OP_GET's
 *            kind byte picks one of its nine kinds; OP_SETUP keeps the experiment's times for the next
 *            OP_ENTER (fmi3EnterInitializationMode takes them) unless its flags have bit 2,
 *            which calls it at once. tests/fuzz/make_seeds.py writes seeds in this format.
 * Set LGF_FUZZ_TRACE=1 to print the calls and the FMU's log while replaying an input.
 * LGF_FUZZ_SKIP_KNOWN=1 reports a violation of an invariant that an open (found, not yet
 * fixed) bug of the FMU breaks (known_bug below; tests/fuzz/README.md, "Open findings") instead
 * of aborting, so that a run can look for other problems; without it every violation aborts.
 * While no bug is open, no check goes through known_bug and the variable changes nothing. */
#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The FMU's one translation unit (its binding, which includes the block and the FMI layer):
 * the target sees lgf_model (the variable table, GUID and identifier of this block) and the
 * layout of a serialized state. */
#include LGF_FMU_SOURCE

#ifndef LGF_FUZZ_FMI
#define LGF_FUZZ_FMI 2
#endif
#ifndef LGF_FUZZ_ENTRY
#define LGF_FUZZ_ENTRY LLVMFuzzerTestOneInput
#endif
#define FMI3 (LGF_FUZZ_FMI == 3)

/* Both versions number their statuses alike (fmi2Pending has no FMI 3.0 counterpart). */
typedef int fstatus;
enum { S_OK, S_WARNING, S_DISCARD, S_ERROR, S_FATAL, S_PENDING };
typedef uint32_t vref;
typedef void *fmu_state;

/* ---------------------------------------------------------------- failures, tracing ---- */

static bool trace;

static void fail(const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 1, 2), noreturn))
#endif
    ;

static void fail(const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    fprintf(stderr, "\nFUZZ INVARIANT VIOLATED (%s, FMI %d.0): ", lgf_model.identifier,
            LGF_FUZZ_FMI);
    vfprintf(stderr, fmt, args);
    fprintf(stderr, "\n");
    va_end(args);
    abort();
}

/* A violation that an open bug of the FMU causes (found, not yet fixed: tests/fuzz/README.md,
 * "Open findings"): it aborts like any other, unless LGF_FUZZ_SKIP_KNOWN is set; then it is
 * reported once. The check of such an invariant calls known_bug instead of fail until the fix,
 * which turns it back into a fail. None is open now, so nothing calls it. */
static bool skip_known;

__attribute__((unused)) static bool known_bug(const char *name, const char *what)
{
    if (!skip_known) fail("%s (known bug: %s)", what, name);
    static const char *reported[8];
    for (int i = 0; i < 8 && reported[i]; i++)
        if (!strcmp(reported[i], name)) return true;
    for (int i = 0; i < 8; i++) {
        if (!reported[i]) {
            reported[i] = name;
            break;
        }
    }
    fprintf(stderr, "KNOWN BUG %s: %s (LGF_FUZZ_SKIP_KNOWN: going on)\n", name, what);
    return true;
}

#define TRACE(...)                                                                                 \
    do {                                                                                           \
        if (trace) fprintf(stderr, __VA_ARGS__);                                                   \
    } while (0)

static const char *status_name(fstatus s)
{
    switch (s) {
    case S_OK: return FMI3 ? "fmi3OK" : "fmi2OK";
    case S_WARNING: return FMI3 ? "fmi3Warning" : "fmi2Warning";
    case S_DISCARD: return FMI3 ? "fmi3Discard" : "fmi2Discard";
    case S_ERROR: return FMI3 ? "fmi3Error" : "fmi2Error";
    case S_FATAL: return FMI3 ? "fmi3Fatal" : "fmi2Fatal";
    case S_PENDING: return FMI3 ? "(not an fmi3Status)" : "fmi2Pending";
    }
    return "(not a status)";
}

/* ---------------------------------------------------------------------- input bytes ---- */

typedef struct {
    const uint8_t *p;
    size_t n;
} input;

static uint8_t u8(input *in)
{
    if (!in->n) return 0;
    in->n--;
    return *in->p++;
}

static uint16_t u16(input *in)
{
    uint16_t lo = u8(in);
    return (uint16_t)(lo | (uint16_t)u8(in) << 8);
}

static uint32_t u32(input *in)
{
    uint32_t lo = u16(in);
    return lo | (uint32_t)u16(in) << 16;
}

static uint64_t u64(input *in)
{
    uint64_t lo = u32(in);
    return lo | (uint64_t)u32(in) << 32;
}

static double from_bits(uint64_t bits)
{
    double d;
    memcpy(&d, &bits, sizeof d);
    return d;
}

/* Values where the FMU's rules change: ranges of cycleTime, TIME, INT and WORD, the call
 * counter's limit, and every kind of NaN and infinity. */
static double special_real(unsigned index)
{
    static const double values[] = {0.0,          -0.0,
                                    1.0,          -1.0,
                                    0.5,          0.1,
                                    0.01,         0.001,
                                    0.0015,       0.0009999,
                                    1e-6,         1.4e-6,
                                    1.6e-6,       0.9e-6,
                                    60.0,         60.000001,
                                    61.0,         2147483.647,
                                    2147483.6474, 2147483.6476,
                                    2147483.648,  -2147483.647,
                                    -2147483.648, -2147483.6486,
                                    32767.0,      32767.5,
                                    32768.0,      -32768.0,
                                    -32768.5,     -32769.0,
                                    65535.0,      65536.0,
                                    1e300,        -1e300,
                                    DBL_MAX,      -DBL_MAX,
                                    DBL_MIN,      4.9e-324,
                                    1e15,         9e15,
                                    1e9,          5.0,
                                    10.0,         100.0,
                                    1e-9,         0.3,
                                    0.25,         0.2,
                                    2.0,          3.0,
                                    4.0,          63.0,
                                    64.0,         65.0,
                                    1e20,         -1e-300,
                                    0.1 + 1e-17,  4503599627370496.0};
    static const uint64_t nans[] = {
        0x7ff8000000000000u, /* quiet NaN */
        0xfff8000000000000u, /* negative quiet NaN */
        0x7ff0000000000001u, /* signalling NaN */
        0x7fffffffffffffffu, /* NaN with every payload bit */
        0x7ff0000000000000u, /* +Inf */
        0xfff0000000000000u, /* -Inf */
    };
    size_t n = sizeof values / sizeof values[0], m = sizeof nans / sizeof nans[0];
    index %= (unsigned)(n + m);
    return index < n ? values[index] : from_bits(nans[index - n]);
}

/* Any fmi2Real: a special value, a multiple of 1/16 in -2048 ... 2048, or any bit pattern. */
static double any_real(input *in)
{
    uint8_t tag = u8(in);
    if (tag < 0x40) return special_real(tag);
    if (tag < 0x80) return (int16_t)u16(in) / 16.0;
    return from_bits(u64(in));
}

static int32_t any_int(input *in)
{
    static const int32_t values[] = {0,     1,      -1,     2,     3,     4,         5,
                                     10,    63,     64,     65,    100,   1000,      32767,
                                     32768, -32768, -32769, 65535, 65536, INT32_MAX, INT32_MIN};
    uint8_t tag = u8(in);
    if (tag < 0x40) return values[tag % (sizeof values / sizeof values[0])];
    if (tag < 0x80) return (int16_t)u16(in);
    return (int32_t)u32(in);
}

/* -------------------------------------------------------------- the block's variables ---- */

/* The kinds of values the target sets and gets: FMI 2.0's fmi2Real, fmi2Integer and
 * fmi2Boolean; FMI 3.0's nine types that this FMU has variables of. The target holds a value
 * of any kind in a `value`, as a double, an int64_t or an int (its class). */
#if FMI3
typedef enum {
    K_FLOAT64,
    K_FLOAT32,
    K_INT16,
    K_UINT16,
    K_UINT32,
    K_BOOLEAN,
    K_INT32, /* after K_BOOLEAN: the committed seeds' kind bytes keep their meaning */
    K_INT8,
    K_UINT8,
    K_COUNT
} kind;
#define K_REAL K_FLOAT64  /* the kind of cycleTime and of every LREAL and TIME */
#define K_INTEGER K_INT16 /* OP_SET_INTEGER: any integer kind (set_kind) */
#else
typedef enum { K_REAL, K_INTEGER, K_BOOLEAN, K_COUNT } kind;
#endif

typedef enum { C_REAL, C_INTEGER, C_BOOLEAN } value_class;

static value_class class_of(kind k)
{
#if FMI3
    return k == K_FLOAT64 || k == K_FLOAT32 ? C_REAL : k == K_BOOLEAN ? C_BOOLEAN : C_INTEGER;
#else
    return k == K_REAL ? C_REAL : k == K_BOOLEAN ? C_BOOLEAN : C_INTEGER;
#endif
}

typedef union {
    double r;
    int64_t i;
    int b;
} value;

#define MAX_VARS 1024

typedef struct {
    uint32_t vr;
    const model_variable *var;
} known_var;

static known_var known[MAX_VARS];
static size_t known_count;
static uint32_t kind_vrs[K_COUNT][MAX_VARS], output_vrs[K_COUNT][MAX_VARS];
static size_t kind_count[K_COUNT], output_count[K_COUNT];
static uint32_t cycle_vr;

static kind fuzz_kind_of(var_type type)
{
#if FMI3
    switch (type) {
    case VAR_REAL: return K_FLOAT32;
    case VAR_INT: return K_INT16;
    case VAR_WORD: return K_UINT16;
    case VAR_UDINT:
    case VAR_DWORD: return K_UINT32;
    case VAR_DINT: return K_INT32;
    case VAR_UINT: return K_UINT16;
    case VAR_SINT: return K_INT8;
    case VAR_USINT:
    case VAR_BYTE: return K_UINT8;
    case VAR_BOOL: return K_BOOLEAN;
    default: return K_FLOAT64; /* VAR_CYCLE, VAR_LREAL, VAR_TIME */
    }
#else
    return type == VAR_BOOL ? K_BOOLEAN : var_is_integer(type) ? K_INTEGER : K_REAL;
#endif
}

static void learn_variables(void)
{
    if (known_count) return;
    for (size_t i = 0; i < lgf_model.variable_count; i++) {
        const model_variable *v = &lgf_model.variables[i];
        if (v->type == VAR_CYCLE) cycle_vr = v->vr;
        for (uint32_t k = 0; k < v->count && known_count < MAX_VARS; k++) {
            known[known_count++] = (known_var){v->vr + k, v};
            kind k_ = fuzz_kind_of(v->type);
            kind_vrs[k_][kind_count[k_]++] = v->vr + k;
            if (v->role == ROLE_OUTPUT) output_vrs[k_][output_count[k_]++] = v->vr + k;
        }
    }
}

static const model_variable *variable_of(uint32_t vr)
{
    for (size_t i = 0; i < known_count; i++)
        if (known[i].vr == vr) return known[i].var;
    return NULL;
}

/* A value reference: mostly one of this kind, sometimes one of another kind, one just past a
 * variable or array, (FMI 3.0) the independent variable's, or any number. */
static uint32_t pick_vr(input *in, kind k)
{
    uint8_t tag = u8(in);
    if (tag < 0x80 && kind_count[k]) return kind_vrs[k][u8(in) % kind_count[k]];
    if (FMI3 && tag >= 0xC0 && tag < 0xC8) return TIME_VR;
    if (tag < 0xC0) return known[u8(in) % known_count].vr;
    if (tag < 0xE0) {
        const model_variable *v = &lgf_model.variables[u8(in) % lgf_model.variable_count];
        return tag & 1 ? v->vr + v->count : UINT32_MAX - (tag & 7);
    }
    return u32(in);
}

/* ------------------------------------------------------------------ the environment ---- */

static int environment_tag; /* its address is the componentEnvironment */
static unsigned problems_logged, errors_logged;

static void check_message(const void *env, fstatus status, const char *category, const char *text)
{
    if (env != &environment_tag) fail("the logger got another componentEnvironment");
    if (!category || !text) fail("the logger got a NULL category or message");
    if (strcmp(category, "logAll") && strcmp(category, "logStatusWarning") &&
        strcmp(category, "logStatusDiscard") && strcmp(category, "logStatusError"))
        fail("the logger got the unknown category \"%s\"", category);
    if (strlen(text) == 0) fail("the logger got an empty message");
    if (status != S_OK) problems_logged++;
    if (status == S_ERROR || status == S_FATAL) errors_logged++;
}

#if FMI3
static void logger(fmi3InstanceEnvironment env, fmi3Status status, fmi3String category,
                   fmi3String message)
{
    check_message(env, (fstatus)status, category, message);
    /* FMI 3.0 passes plain text: FMI 2.0's escape of '#' must not leak into it */
    if (strstr(message, "##")) fail("an FMI 3.0 message holds \"##\": \"%s\"", message);
    TRACE("    [%s %s] %s\n", status_name((fstatus)status), category, message);
}
#else
static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    if (!name || !message) fail("the logger got a NULL instanceName or message");
    /* The FMU never passes its text as a format (src/core/log.c): the format is always "%s". */
    if (strcmp(message, "%s")) fail("the logger got the format \"%s\" instead of \"%%s\"", message);
    va_list args;
    va_start(args, message);
    const char *text = va_arg(args, const char *);
    va_end(args);
    if (!text) fail("the logger got a NULL message for \"%%s\"");
    check_message(env, (fstatus)status, category, text);
    TRACE("    [%s %s] %s: %s\n", status_name((fstatus)status), category, name, text);
}
#endif

/* Allocation failures are injected only into the calls under test, never into the target's
 * own bookkeeping calls (FMI 2.0: FMI 3.0 has no allocator callbacks). */
static bool injecting;
static int fail_countdown; /* > 0: that allocation (1 = the next one) returns NULL */

#if !FMI3
static void *allocate_memory(size_t count, size_t size)
{
    if (injecting && fail_countdown > 0 && --fail_countdown == 0) {
        TRACE("    (allocation of %zu x %zu bytes made to fail)\n", count, size);
        return NULL;
    }
    return calloc(count, size);
}

static void free_memory(void *p) { free(p); }

static const fmi2CallbackFunctions callbacks = {logger, allocate_memory, free_memory, NULL,
                                                &environment_tag};
#endif

/* ------------------------------------------- the calls, in FMI 2.0 or FMI 3.0 (x_*) ---- */

static void *inst;
static bool inst_me;            /* inst is a Model Exchange instance */
static const char *called = ""; /* the FMI function the last x_* call made, for the trace */
/* The FMI function f called with the arguments after it, its name kept in `called`. */
#define CALL(f, ...) (called = #f, f(__VA_ARGS__))

/* The event iteration's results as the FMU wrote them (fmi2EventInfo; the out-pointers of
 * fmi3UpdateDiscreteStates). */
typedef struct {
    int needed, terminate, nominals, values, defined;
    double next;
} event_flags;

#define MAX_VALUES MAX_VARS

#if FMI3
static fstatus x_set(void *c, kind k, const vref *vr, size_t nvr, const value *in, size_t n_values)
{
    static fmi3Float64 f64[MAX_VALUES];
    static fmi3Float32 f32[MAX_VALUES];
    static fmi3Int16 i16[MAX_VALUES];
    static fmi3UInt16 u16[MAX_VALUES];
    static fmi3UInt32 u32_[MAX_VALUES];
    static fmi3Int32 i32[MAX_VALUES];
    static fmi3Int8 i8[MAX_VALUES];
    static fmi3UInt8 u8_[MAX_VALUES];
    static fmi3Boolean b[MAX_VALUES];
    for (size_t i = 0; in && i < nvr && i < MAX_VALUES; i++) {
        f64[i] = in[i].r, f32[i] = (fmi3Float32)in[i].r;
        i16[i] = (fmi3Int16)in[i].i, u16[i] = (fmi3UInt16)in[i].i, u32_[i] = (fmi3UInt32)in[i].i;
        i32[i] = (fmi3Int32)in[i].i, i8[i] = (fmi3Int8)in[i].i, u8_[i] = (fmi3UInt8)in[i].i;
        b[i] = in[i].b != 0;
    }
    switch (k) {
    case K_FLOAT64: return CALL(fmi3SetFloat64, c, vr, nvr, in ? f64 : NULL, n_values);
    case K_FLOAT32: return CALL(fmi3SetFloat32, c, vr, nvr, in ? f32 : NULL, n_values);
    case K_INT16: return CALL(fmi3SetInt16, c, vr, nvr, in ? i16 : NULL, n_values);
    case K_UINT16: return CALL(fmi3SetUInt16, c, vr, nvr, in ? u16 : NULL, n_values);
    case K_UINT32: return CALL(fmi3SetUInt32, c, vr, nvr, in ? u32_ : NULL, n_values);
    case K_INT32: return CALL(fmi3SetInt32, c, vr, nvr, in ? i32 : NULL, n_values);
    case K_INT8: return CALL(fmi3SetInt8, c, vr, nvr, in ? i8 : NULL, n_values);
    case K_UINT8: return CALL(fmi3SetUInt8, c, vr, nvr, in ? u8_ : NULL, n_values);
    default: return CALL(fmi3SetBoolean, c, vr, nvr, in ? b : NULL, n_values);
    }
}

static fstatus x_get(void *c, kind k, const vref *vr, size_t nvr, value *out, size_t n_values)
{
    static fmi3Float64 f64[MAX_VALUES];
    static fmi3Float32 f32[MAX_VALUES];
    static fmi3Int16 i16[MAX_VALUES];
    static fmi3UInt16 u16[MAX_VALUES];
    static fmi3UInt32 u32_[MAX_VALUES];
    static fmi3Int32 i32[MAX_VALUES];
    static fmi3Int8 i8[MAX_VALUES];
    static fmi3UInt8 u8_[MAX_VALUES];
    static fmi3Boolean b[MAX_VALUES];
    fstatus s;
    switch (k) {
    case K_FLOAT64: s = CALL(fmi3GetFloat64, c, vr, nvr, out ? f64 : NULL, n_values); break;
    case K_FLOAT32: s = CALL(fmi3GetFloat32, c, vr, nvr, out ? f32 : NULL, n_values); break;
    case K_INT16: s = CALL(fmi3GetInt16, c, vr, nvr, out ? i16 : NULL, n_values); break;
    case K_UINT16: s = CALL(fmi3GetUInt16, c, vr, nvr, out ? u16 : NULL, n_values); break;
    case K_UINT32: s = CALL(fmi3GetUInt32, c, vr, nvr, out ? u32_ : NULL, n_values); break;
    case K_INT32: s = CALL(fmi3GetInt32, c, vr, nvr, out ? i32 : NULL, n_values); break;
    case K_INT8: s = CALL(fmi3GetInt8, c, vr, nvr, out ? i8 : NULL, n_values); break;
    case K_UINT8: s = CALL(fmi3GetUInt8, c, vr, nvr, out ? u8_ : NULL, n_values); break;
    default: s = CALL(fmi3GetBoolean, c, vr, nvr, out ? b : NULL, n_values); break;
    }
    for (size_t i = 0; out && s == S_OK && i < nvr && i < MAX_VALUES; i++) {
        memset(&out[i], 0, sizeof out[i]);
        switch (k) {
        case K_FLOAT64: out[i].r = f64[i]; break;
        case K_FLOAT32: out[i].r = f32[i]; break;
        case K_INT16: out[i].i = i16[i]; break;
        case K_UINT16: out[i].i = u16[i]; break;
        case K_UINT32: out[i].i = u32_[i]; break;
        case K_INT32: out[i].i = i32[i]; break;
        case K_INT8: out[i].i = i8[i]; break;
        case K_UINT8: out[i].i = u8_[i]; break;
        default: out[i].b = b[i]; break;
        }
    }
    return s;
}

static fstatus x_time(void *c, double *t)
{
    const fmi3ValueReference vr = TIME_VR;
    return CALL(fmi3GetFloat64, c, &vr, 1, t, 1);
}

static bool step_flags_ok; /* the last accepted fmi3DoStep asked for nothing */
static double last_successful;

static fstatus x_do_step(void *c, double t, double h, bool no_set_prior)
{
    fmi3Boolean event = fmi3True, stop = fmi3True, early = fmi3True;
    last_successful = NAN;
    fstatus s = CALL(fmi3DoStep, c, t, h, no_set_prior, &event, &stop, &early, &last_successful);
    step_flags_ok = !event && !stop && !early;
    return s;
}

static fstatus x_exit_init(void *c) { return CALL(fmi3ExitInitializationMode, c); }
static fstatus x_terminate(void *c) { return CALL(fmi3Terminate, c); }
static fstatus x_reset(void *c) { return CALL(fmi3Reset, c); }
static fstatus x_get_state(void *c, fmu_state *s) { return CALL(fmi3GetFMUState, c, s); }
static fstatus x_set_state(void *c, fmu_state s) { return CALL(fmi3SetFMUState, c, s); }
static fstatus x_free_state(void *c, fmu_state *s) { return CALL(fmi3FreeFMUState, c, s); }
static fstatus x_state_size(void *c, fmu_state s, size_t *n)
{
    return CALL(fmi3SerializedFMUStateSize, c, s, n);
}
static fstatus x_serialize(void *c, fmu_state s, unsigned char *b, size_t n)
{
    return CALL(fmi3SerializeFMUState, c, s, b, n);
}
static fstatus x_deserialize(void *c, const unsigned char *b, size_t n, fmu_state *s)
{
    return CALL(fmi3DeserializeFMUState, c, b, n, s);
}
static fstatus x_set_debug_logging(void *c, bool on, size_t n, const char *const *categories)
{
    return CALL(fmi3SetDebugLogging, c, on, n, categories);
}
static fstatus x_enter_event(void *c) { return CALL(fmi3EnterEventMode, c); }
static fstatus x_enter_continuous(void *c) { return CALL(fmi3EnterContinuousTimeMode, c); }
static fstatus x_set_time(void *c, double t) { return CALL(fmi3SetTime, c, t); }

/* info NULL: every out-pointer NULL; null_one 1..6: that out-pointer NULL */
static fstatus x_update(void *c, event_flags *info, int null_one)
{
    if (!info) return CALL(fmi3UpdateDiscreteStates, c, NULL, NULL, NULL, NULL, NULL, NULL);
    fmi3Boolean needed = fmi3True, stop = fmi3True, nominals = fmi3True, values = fmi3True,
                defined = fmi3False;
    fmi3Float64 next = -7.25e300;
    fstatus s = CALL(fmi3UpdateDiscreteStates, c, null_one == 1 ? NULL : &needed,
                     null_one == 2 ? NULL : &stop, null_one == 3 ? NULL : &nominals,
                     null_one == 4 ? NULL : &values, null_one == 5 ? NULL : &defined,
                     null_one == 6 ? NULL : &next);
    *info = (event_flags){needed, stop, nominals, values, defined, next};
    return s;
}

/* The flags come back 0 when the FMU wrote false, 7 when it did not write (or wrote true). */
static fstatus x_completed(void *c, bool no_set_prior, int *enter, int *terminate)
{
    fmi3Boolean e = fmi3True, t = fmi3True;
    fstatus s = CALL(fmi3CompletedIntegratorStep, c, no_set_prior, enter ? &e : NULL,
                     terminate ? &t : NULL);
    if (enter) *enter = e ? 7 : 0;
    if (terminate) *terminate = t ? 7 : 0;
    return s;
}

static fstatus x_no_states(void *c, int which, double *x, size_t n)
{
    switch (which) {
    case 0: return CALL(fmi3SetContinuousStates, c, x, n);
    case 1: return CALL(fmi3GetContinuousStateDerivatives, c, x, n);
    case 2: return CALL(fmi3GetEventIndicators, c, x, n);
    case 3: return CALL(fmi3GetContinuousStates, c, x, n);
    default: return CALL(fmi3GetNominalsOfContinuousStates, c, x, n);
    }
}
#else
static fstatus x_set(void *c, kind k, const vref *vr, size_t nvr, const value *in, size_t n_values)
{
    (void)n_values;
    static fmi2Real r[MAX_VALUES];
    static fmi2Integer i_[MAX_VALUES];
    static fmi2Boolean b[MAX_VALUES];
    for (size_t i = 0; in && i < nvr && i < MAX_VALUES; i++)
        r[i] = in[i].r, i_[i] = (fmi2Integer)in[i].i, b[i] = in[i].b;
    switch (k) {
    case K_REAL: return CALL(fmi2SetReal, c, vr, nvr, in ? r : NULL);
    case K_INTEGER: return CALL(fmi2SetInteger, c, vr, nvr, in ? i_ : NULL);
    default: return CALL(fmi2SetBoolean, c, vr, nvr, in ? b : NULL);
    }
}

static fstatus x_get(void *c, kind k, const vref *vr, size_t nvr, value *out, size_t n_values)
{
    (void)n_values;
    static fmi2Real r[MAX_VALUES];
    static fmi2Integer i_[MAX_VALUES];
    static fmi2Boolean b[MAX_VALUES];
    fstatus s;
    switch (k) {
    case K_REAL: s = CALL(fmi2GetReal, c, vr, nvr, out ? r : NULL); break;
    case K_INTEGER: s = CALL(fmi2GetInteger, c, vr, nvr, out ? i_ : NULL); break;
    default: s = CALL(fmi2GetBoolean, c, vr, nvr, out ? b : NULL); break;
    }
    for (size_t i = 0; out && s == S_OK && i < nvr && i < MAX_VALUES; i++) {
        memset(&out[i], 0, sizeof out[i]);
        if (k == K_REAL)
            out[i].r = r[i];
        else if (k == K_INTEGER)
            out[i].i = i_[i];
        else
            out[i].b = b[i];
    }
    return s;
}

static fstatus x_time(void *c, double *t)
{
    return CALL(fmi2GetRealStatus, c, fmi2LastSuccessfulTime, t);
}

static fstatus x_do_step(void *c, double t, double h, bool no_set_prior)
{
    return CALL(fmi2DoStep, c, t, h, no_set_prior);
}

static fstatus x_exit_init(void *c) { return CALL(fmi2ExitInitializationMode, c); }
static fstatus x_terminate(void *c) { return CALL(fmi2Terminate, c); }
static fstatus x_reset(void *c) { return CALL(fmi2Reset, c); }
static fstatus x_get_state(void *c, fmu_state *s) { return CALL(fmi2GetFMUstate, c, s); }
static fstatus x_set_state(void *c, fmu_state s) { return CALL(fmi2SetFMUstate, c, s); }
static fstatus x_free_state(void *c, fmu_state *s) { return CALL(fmi2FreeFMUstate, c, s); }
static fstatus x_state_size(void *c, fmu_state s, size_t *n)
{
    return CALL(fmi2SerializedFMUstateSize, c, s, n);
}
static fstatus x_serialize(void *c, fmu_state s, unsigned char *b, size_t n)
{
    return CALL(fmi2SerializeFMUstate, c, s, (fmi2Byte *)b, n);
}
static fstatus x_deserialize(void *c, const unsigned char *b, size_t n, fmu_state *s)
{
    return CALL(fmi2DeSerializeFMUstate, c, (const fmi2Byte *)b, n, s);
}
static fstatus x_set_debug_logging(void *c, bool on, size_t n, const char *const *categories)
{
    return CALL(fmi2SetDebugLogging, c, on, n, categories);
}
static fstatus x_enter_event(void *c) { return CALL(fmi2EnterEventMode, c); }
static fstatus x_enter_continuous(void *c) { return CALL(fmi2EnterContinuousTimeMode, c); }
static fstatus x_set_time(void *c, double t) { return CALL(fmi2SetTime, c, t); }

static fstatus x_update(void *c, event_flags *info, int null_one)
{
    (void)null_one;
    if (!info) return CALL(fmi2NewDiscreteStates, c, NULL);
    fmi2EventInfo e;
    memset(&e, 0xA5, sizeof e);
    fstatus s = CALL(fmi2NewDiscreteStates, c, &e);
    *info = (event_flags){e.newDiscreteStatesNeeded,
                          e.terminateSimulation,
                          e.nominalsOfContinuousStatesChanged,
                          e.valuesOfContinuousStatesChanged,
                          e.nextEventTimeDefined,
                          e.nextEventTime};
    return s;
}

static fstatus x_completed(void *c, bool no_set_prior, int *enter, int *terminate)
{
    fmi2Boolean e = 7, t = 7;
    fstatus s = CALL(fmi2CompletedIntegratorStep, c, no_set_prior, enter ? &e : NULL,
                     terminate ? &t : NULL);
    if (enter) *enter = e;
    if (terminate) *terminate = t;
    return s;
}

static fstatus x_no_states(void *c, int which, double *x, size_t n)
{
    switch (which) {
    case 0: return CALL(fmi2SetContinuousStates, c, x, n);
    case 1: return CALL(fmi2GetDerivatives, c, x, n);
    case 2: return CALL(fmi2GetEventIndicators, c, x, n);
    case 3: return CALL(fmi2GetContinuousStates, c, x, n);
    default: return CALL(fmi2GetNominalsOfContinuousStates, c, x, n);
    }
}
#endif

/* ------------------------------------------------------------- checking one call ---- */

static void begin_call(void)
{
    problems_logged = errors_logged = 0;
    injecting = true;
}

static fstatus end_call(const char *function, fstatus s, bool on_instance)
{
    injecting = false;
    if (!strncmp(function, "x_", 2)) function = called; /* the FMI function it made */
    TRACE("  %s -> %s\n", function, status_name(s));
    if (s != S_OK && s != S_WARNING && s != S_DISCARD && s != S_ERROR)
        fail("%s returned %s (%d)", function, status_name(s), (int)s);
    if (!on_instance) return s;
    if (s != S_OK && problems_logged == 0)
        fail("%s returned %s without logging why", function, status_name(s));
    if (s != S_ERROR && errors_logged)
        fail("%s logged an error but returned %s", function, status_name(s));
    return s;
}

/* The whole observable state of the instance: its FMU state serialized (every input,
 * parameter, output and static, and the clock), its time, and the outputs read back with
 * the gets (or the status of the refused get). */
#define MAX_SERIALIZED 65536

typedef struct {
    size_t size;
    unsigned char bytes[MAX_SERIALIZED];
    fstatus get_status[K_COUNT];
    value outputs[K_COUNT][MAX_VARS];
    fstatus time_status;
    double time;
} snapshot;

static snapshot snap_before, snap_after, snap_round[3];

/* The target's own calls: they must succeed, and they are not under test here. */
static void serialize_now(unsigned char *bytes, size_t *size)
{
    fmu_state state = NULL;
    if (x_get_state(inst, &state) != S_OK) fail("getting the FMU state failed");
    if (x_state_size(inst, state, size) != S_OK) fail("the serialized size failed");
    if (*size > MAX_SERIALIZED) fail("serialized state of %zu bytes", *size);
    if (x_serialize(inst, state, bytes, *size) != S_OK) fail("serializing the FMU state failed");
    if (x_free_state(inst, &state) != S_OK || state) fail("freeing the FMU state failed");
}

static void take(snapshot *s)
{
    bool was_tracing = trace;
    trace = false;
    memset(s, 0, sizeof *s);
    serialize_now(s->bytes, &s->size);
    for (int k = 0; k < K_COUNT; k++)
        s->get_status[k] =
            x_get(inst, (kind)k, output_vrs[k], output_count[k], s->outputs[k], output_count[k]);
    s->time_status = x_time(inst, &s->time);
    trace = was_tracing;
}

static void must_equal(const snapshot *a, const snapshot *b, const char *what)
{
    if (a->size != b->size || memcmp(a->bytes, b->bytes, a->size))
        fail("%s: the FMU state bytes differ", what);
    for (int k = 0; k < K_COUNT; k++) {
        if (a->get_status[k] != b->get_status[k]) fail("%s: a get's status differs", what);
        for (size_t i = 0; i < output_count[k]; i++)
            if (memcmp(&a->outputs[k][i], &b->outputs[k][i], sizeof a->outputs[k][i]))
                fail("%s: output vr %u differs", what, (unsigned)output_vrs[k][i]);
    }
    if (a->time_status != b->time_status || memcmp(&a->time, &b->time, sizeof a->time))
        fail("%s: the time (fmi2LastSuccessfulTime, fmi3GetFloat64 of time) differs", what);
}

/* A call that changes the instance only when it succeeds: CHECKED(call) compares the
 * instance before and after a call that returned an error. READ_ONLY(call) compares it
 * after any call that must never change it. */
static void before_call(void)
{
    take(&snap_before);
    begin_call();
}

static fstatus after_checked(const char *function, fstatus s)
{
    end_call(function, s, inst != NULL);
    if (s == S_ERROR) {
        take(&snap_after);
        must_equal(&snap_before, &snap_after, function);
    }
    return s;
}

static fstatus after_read_only(const char *function, fstatus s)
{
    end_call(function, s, inst != NULL);
    take(&snap_after);
    must_equal(&snap_before, &snap_after, function);
    return s;
}

#define CHECKED(call) after_checked(#call, (before_call(), (fstatus)(call)))
#define READ_ONLY(call) after_read_only(#call, (before_call(), (fstatus)(call)))

/* ------------------------------------------------------------------- time and steps ---- */

/* The FMU's time, where it tells it (FMI 2.0: step mode and terminated; FMI 3.0: whenever
 * the time variable may be read), else 0. */
static double now(void)
{
    double t = 0;
    bool was_tracing = trace;
    trace = false;
    if (x_time(inst, &t) != S_OK) t = 0;
    trace = was_tracing;
    return t;
}

static double cycle_time(void)
{
    value cycle = {.r = 0.1};
    bool was_tracing = trace;
    trace = false;
    if (x_get(inst, K_REAL, &cycle_vr, 1, &cycle, 1) != S_OK || !(cycle.r > 0)) cycle.r = 0.1;
    trace = was_tracing;
    return cycle.r;
}

/* PLC calls the doSteps of one input may ask for; past it, steps are one cycle at most. */
#define CALL_BUDGET 300000.0
static double calls_asked;

/* The FMU's grid tolerance (src/core/clock.c): points this close to a call time count as on it. */
static double tolerance_near(double t) { return 1e-9 * cycle_time() + 8 * DBL_EPSILON * fabs(t); }

static double pick_t(input *in)
{
    double t = now();
    uint8_t tag = u8(in);
    switch (tag % 8) {
    case 4: { /* up to twice the grid tolerance off: at the edge of "matches the FMU's time" */
        uint8_t off = u8(in);
        return t + (off & 0x80 ? -1 : 1) * (off & 0x7f) / 64.0 * tolerance_near(t);
    }
    case 5: return t + (int8_t)u8(in) * 1e-12 * fmax(1.0, fabs(t)); /* near: tolerance edge */
    case 6: {
        int steps = (int8_t)u8(in);
        for (int i = 0; i < abs(steps); i++) t = nextafter(t, steps < 0 ? -INFINITY : INFINITY);
        return t;
    }
    case 7: return any_real(in);
    default: return t;
    }
}

/* A step size: mostly whole or partial cycles, sometimes anything. One doStep stays below
 * 10^4 cycles; sizes beyond 10^19 s are far past the FMU's limit and refused by it. */
static double pick_h(input *in)
{
    double cycle = cycle_time(), h;
    uint8_t tag = u8(in);
    switch (tag % 16) {
    case 8: h = (u8(in) + 1) / 256.0 * cycle; break;
    case 9: h = cycle * (u16(in) % 4096 + 1) / 16.0; break;
    case 10: h = -1.0 + (u32(in) / 4294967295.0) * (1e4 * cycle + 1.0); break;
    case 11: h = any_real(in); break;
    case 12: h = (u8(in) + 1) / 128.0 * tolerance_near(now()); break; /* below the tolerance */
    case 13: {
        h = cycle * (u8(in) % 8 + 1);
        int steps = (int8_t)u8(in);
        for (int i = 0; i < abs(steps); i++) h = nextafter(h, steps < 0 ? 0 : INFINITY);
        break;
    }
    case 14: h = 0.1 * (u8(in) % 8 + 1); break; /* the importer's steps, whatever the cycle */
    case 15: { /* whole cycles, up to twice the grid tolerance short or long */
        h = cycle * (u8(in) % 4 + 1);
        uint8_t off = u8(in);
        h += (off & 0x80 ? -1 : 1) * (off & 0x7f) / 64.0 * tolerance_near(now() + h);
        break;
    }
    default: h = cycle * (tag % 16 + 1); break;
    }
    if (isfinite(h) && h > 1e4 * cycle && h < 1e19) h = fmod(h, 1e4 * cycle);
    if (isfinite(h) && h > cycle && h < 1e19 && calls_asked > CALL_BUDGET) h = cycle;
    if (isfinite(h) && h > 0 && h < 1e19) calls_asked += h / cycle + 1;
    return h;
}

/* ------------------------------------------------------------------------- the clock ---- */

/* The clock at the start of a serialized payload (core_walk() in src/core/state.c): mode and
 * cycle_us (4 bytes each), start_time, time, calls, stop_time (8 each), stop_defined (1). */
typedef struct {
    int32_t mode, cycle_us;
    double start, time, stop;
    int64_t calls;
    bool stop_defined;
} clock_view;

static clock_view clock_in(const unsigned char *bytes, size_t size)
{
    clock_view c;
    memset(&c, 0, sizeof c);
    if (size < STATE_HEADER_SIZE + STATE_CLOCK_SIZE) fail("a serialized state of %zu bytes", size);
    const unsigned char *p = bytes + STATE_HEADER_SIZE;
    memcpy(&c.mode, p, 4);
    memcpy(&c.cycle_us, p + 4, 4);
    memcpy(&c.start, p + 8, 8);
    memcpy(&c.time, p + 16, 8);
    memcpy(&c.calls, p + 24, 8);
    memcpy(&c.stop, p + 32, 8);
    c.stop_defined = p[40] != 0;
    return c;
}

static clock_view clock_now(void)
{
    static unsigned char bytes[MAX_SERIALIZED];
    size_t size;
    bool was_tracing = trace;
    trace = false;
    serialize_now(bytes, &size);
    trace = was_tracing;
    return clock_in(bytes, size);
}

/* The FMU's grid tolerance (core_grid_tolerance in src/core/clock.c). */
static double grid_tolerance_of(const clock_view *c, double t)
{
    return 1e-4 * (c->cycle_us / 1e6) + 8 * DBL_EPSILON * fmax(fabs(c->start), fabs(t));
}

/* The time of the next call, as fmi2NewDiscreteStates announces it. */
static double next_call_time(const clock_view *c)
{
    return c->start + (double)(c->calls * (int64_t)c->cycle_us) / 1e6;
}

/* Calls done minus the index of the last call due at the clock's time: 0 when the calls up to
 * the time are done, -1 when the call at the time is still due. */
static double calls_ahead(const clock_view *c)
{
    double cycle = c->cycle_us / 1e6;
    return (double)(c->calls - 1) -
           floor((c->time - c->start + grid_tolerance_of(c, c->time)) / cycle);
}

/* The FMU refused bytes it serialized itself: a bug, whatever its state. (A Model Exchange
 * clock that fmi2SetTime had moved past call times whose events were not handled was one, the
 * bug "ME clock after fmi2SetTime": fixed in src/core/clock.c, its inputs are the regressions
 * me-clock-skipped-time-events and me-clock-terminated-at-call-time, tests/fuzz/README.md.)
 * The message gives the clock of the refused bytes. */
static void own_state_refused(const char *when, const unsigned char *bytes, size_t size)
{
    clock_view c = clock_in(bytes, size);
    fail("%s: the FMU refused its own serialized state (%s, mode %d, t = %.17g, %lld calls "
         "done, %+.0f against the calls due)",
         when, inst_me ? "Model Exchange" : "co-simulation", (int)c.mode, c.time,
         (long long)c.calls, calls_ahead(&c));
}

/* Whatever state the FMU reached through its API, it takes back serialized. */
static void accepts_own_state(const char *when)
{
    static unsigned char bytes[MAX_SERIALIZED];
    size_t size;
    fmu_state state = NULL;
    serialize_now(bytes, &size);
    bool was_tracing = trace;
    trace = false;
    if (x_deserialize(inst, bytes, size, &state) != S_OK) own_state_refused(when, bytes, size);
    trace = was_tracing;
    if (x_free_state(inst, &state) != S_OK) fail("freeing a state failed");
}

static fstatus do_step(double t, double h, bool no_set_prior)
{
    TRACE("  doStep(t = %.17g, h = %.17g)\n", t, h);
    double before = now();
    fstatus s = CHECKED(x_do_step(inst, t, h, no_set_prior));
    if (s != S_ERROR) {
        /* t + h, unless a step from just before the FMU's time ends before it: the FMU's time
         * never goes back */
        double expected = t + h > before ? t + h : before, got = 0;
        if (x_time(inst, &got) != S_OK) fail("the time could not be read after a doStep");
        if (memcmp(&expected, &got, sizeof got))
            fail("after doStep(%.17g, %.17g) the time is %.17g", t, h, got);
#if FMI3
        if (!step_flags_ok)
            fail("fmi3DoStep(%.17g, %.17g) asked for event handling, the end or an early return", t,
                 h);
        if (memcmp(&last_successful, &got, sizeof got))
            fail("fmi3DoStep's lastSuccessfulTime %.17g is not the FMU's time %.17g",
                 last_successful, got);
#endif
        accepts_own_state("after a doStep");
    }
    return s;
}

/* ------------------------------------------------------------------------ setting ---- */

#define MAX_SET 4

typedef struct {
    kind k;
    size_t n, n_values; /* FMI 3.0: nValues, mostly n */
    bool null_arrays;
    vref vr[MAX_SET];
    value values[MAX_SET];
} set_request;

/* FMI 3.0: OP_SET_REAL sets a Float64 or a Float32, OP_SET_INTEGER an Int16, a UInt16, a UInt32,
 * an Int32, an Int8 or a UInt8 (one byte more; the first three as before the others existed, so
 * that the committed seeds keep their meaning) */
static kind set_kind(input *in, kind k)
{
#if FMI3
    uint8_t which = u8(in);
    if (k == K_FLOAT64) return which & 1 ? K_FLOAT32 : K_FLOAT64;
    static const kind integers[] = {K_INT16, K_UINT16, K_UINT32, K_INT32, K_INT8, K_UINT8};
    if (k == K_INT16) return integers[which % 6];
#else
    (void)in;
#endif
    return k;
}

static void read_set(input *in, kind k, set_request *r)
{
    memset(r, 0, sizeof *r);
    uint8_t n = u8(in);
    r->k = k;
    r->n = n % (MAX_SET + 1);
    r->n_values = r->n;
    if (FMI3 && (n & 0x70) == 0x70) r->n_values = r->n + 1; /* nValues must equal nvr */
    r->null_arrays = (n & 0x80) && r->n > 0;
    for (size_t i = 0; i < r->n; i++) {
        r->vr[i] = pick_vr(in, k);
        value_class c = class_of(k);
        if (c == C_REAL)
            r->values[i].r = any_real(in);
        else if (c == C_INTEGER)
            r->values[i].i = any_int(in);
        else
            r->values[i].b = u8(in) < 0xE0 ? (u8(in) & 1) : (FMI3 ? u8(in) & 1 : any_int(in));
    }
}

static fstatus apply_set(const set_request *r)
{
    if (trace)
        for (size_t i = 0; i < r->n; i++) {
            value_class c = class_of(r->k);
            fprintf(stderr, "  set vr %u = %.17g\n", (unsigned)r->vr[i],
                    c == C_REAL      ? r->values[i].r
                    : c == C_INTEGER ? (double)r->values[i].i
                                     : (double)r->values[i].b);
        }
    const vref *vr = r->null_arrays ? NULL : r->vr;
    return CHECKED(x_set(inst, r->k, vr, r->n, r->null_arrays ? NULL : r->values, r->n_values));
}

/* The value an accepted integer set stores: FMI 3.0 passes it in the kind's own width. */
static int64_t as_set(kind k, int64_t v)
{
#if FMI3
    if (k == K_INT16) return (int16_t)v;
    if (k == K_UINT16) return (uint16_t)v;
    if (k == K_UINT32) return (uint32_t)v;
    if (k == K_INT32) return (int32_t)v;
    if (k == K_INT8) return (int8_t)v;
    if (k == K_UINT8) return (uint8_t)v;
#else
    (void)k;
#endif
    return v;
}

/* An accepted value reads back as set, within the rounding docs/behaviour.md §1.1/§1.4 allows
 * (a REAL is the nearest float32). */
static void check_read_back(const set_request *r)
{
    if (r->n_values != r->n)
        fail("a set with nValues %zu for %zu value references was accepted", r->n_values, r->n);
    for (size_t i = 0; i < r->n; i++) {
        bool last = true; /* only the last of repeated value references counts */
        for (size_t j = i + 1; j < r->n; j++) last &= r->vr[j] != r->vr[i];
        if (!last) continue;
        const model_variable *v = variable_of(r->vr[i]);
        if (!v) fail("a set with unknown value reference %u was accepted", (unsigned)r->vr[i]);
        if (v->role == ROLE_OUTPUT) fail("a set of the output %s was accepted", v->name);
        value got;
        fstatus s = x_get(inst, r->k, &r->vr[i], 1, &got, 1);
        if (s != S_OK) continue;
        value_class c = class_of(r->k);
        if (c == C_REAL) {
            double set = r->values[i].r, tolerance = 0;
            if (v->type == VAR_REAL) set = (float)set; /* stored as the nearest float32 */
            if (v->type == VAR_TIME) tolerance = 0.0005 + 1e-12 * fabs(set);
            if (v->type == VAR_CYCLE) tolerance = 0.5e-6 + 1e-12 * fabs(set);
            if (isnan(set) || !(got.r == set || fabs(got.r - set) <= tolerance))
                fail("%s was set to %.17g and reads back as %.17g", v->name, r->values[i].r, got.r);
            if ((v->type == VAR_LREAL || v->type == VAR_REAL) && memcmp(&got.r, &set, sizeof set))
                fail("%s was set to %.17g and reads back as %.17g (bits)", v->name, set, got.r);
        } else if (c == C_INTEGER) {
            if (got.i != as_set(r->k, r->values[i].i))
                fail("%s was set to %lld and reads back as %lld", v->name,
                     (long long)as_set(r->k, r->values[i].i), (long long)got.i);
        } else if (got.b != (r->values[i].b != 0)) {
            fail("%s was set to %d and reads back as %d", v->name, r->values[i].b, got.b);
        }
    }
}

/* ----------------------------------------------------------------------- FMU states ---- */

#define SLOTS 3
static fmu_state slots[SLOTS];
static _Alignas(16) unsigned char foreign[256]; /* not a state of this FMU */
static unsigned char serialized[MAX_SERIALIZED];
static size_t serialized_size;

/* 0..2: a slot; 3: NULL; otherwise memory that is not an FMU state. */
static fmu_state pick_state(input *in)
{
    uint8_t tag = u8(in) % 8;
    if (tag < SLOTS) return slots[tag];
    if (tag == 3) return NULL;
    for (size_t i = 0; i < sizeof foreign; i++) foreign[i] = u8(in);
    return foreign;
}

static uint64_t fuzz_fnv1a(const unsigned char *bytes, size_t size)
{
    uint64_t hash = 0xcbf29ce484222325u;
    for (size_t i = 0; i < size; i++) hash = (hash ^ bytes[i]) * 0x100000001b3u;
    return hash;
}

/* The serialized format of src/core/state.c: a STATE_HEADER_SIZE-byte header, the FNV-1a
 * 64 of the payload at offset 88 and the payload size at offset 84. The target can rewrite
 * both, so that changed payloads get past the checksum and test the FMU's checks of their
 * contents. */
#define HEADER_SIZE STATE_HEADER_SIZE

static void fuzz_put_le(unsigned char *to, uint64_t value, int size)
{
    for (int i = 0; i < size; i++) to[i] = (unsigned char)(value >> (8 * i));
}

static void fix_header(unsigned char *bytes, size_t size, bool fix_size, bool fix_checksum)
{
    if (size < HEADER_SIZE) return;
    if (fix_size) fuzz_put_le(bytes + 84, size - HEADER_SIZE, 4);
    if (fix_checksum)
        fuzz_put_le(bytes + 88, fuzz_fnv1a(bytes + HEADER_SIZE, size - HEADER_SIZE), 8);
}

/* Deserializes into the given slot (or NULL, or foreign memory); accepted bytes must
 * serialize back to the same bytes. Returns the slot that holds the state, or -1. */
static int deserialize(const unsigned char *bytes, size_t size, input *in)
{
    uint8_t tag = u8(in);
    fmu_state *target, none = NULL, alien = foreign;
    target = tag % 8 < SLOTS ? &slots[tag % 8] : tag % 8 == 3 ? &alien : &none;
    fmu_state before = *target;
    const unsigned char *from = tag & 0x80 ? NULL : bytes;
    fstatus s = READ_ONLY(x_deserialize(inst, from, size, (tag & 0x40) ? NULL : target));
    if (s == S_ERROR) {
        if (*target != before) fail("a refused deserialization changed *FMUstate");
        return -1;
    }
    static unsigned char again[MAX_SERIALIZED];
    size_t again_size = 0;
    if (x_state_size(inst, *target, &again_size) != S_OK || again_size != size ||
        x_serialize(inst, *target, again, again_size) != S_OK || memcmp(again, bytes, size))
        fail("accepted serialized bytes do not serialize back to the same bytes");
    if (target == &none) {
        if (x_free_state(inst, &none) != S_OK) fail("freeing a state failed");
        return -1;
    }
    return (int)(target - slots);
}

/* ----------------------------------------------------------------------- operations ---- */

/* Start times are kept where one doStep stays a bounded number of calls: the FMU widens its
 * grid tolerance with |t| (8 ulp), which at 1e12 s is 1800 calls of 1 µs and at 1e18 s 1.8e9
 * (the FMU accepts such start times: see the report of tests/fuzz/README.md). Times of 1e300
 * and more stay: the FMU must refuse every step there. */
static double bounded_time(double t)
{
    return isfinite(t) && fabs(t) > 1e12 && fabs(t) < 1e300 ? fmod(t, 1e12) : t;
}

#if FMI3
/* fmi3EnterInitializationMode takes the experiment's times: OP_SETUP keeps them for the next
 * OP_ENTER, or (flags bit 2) calls it at once. */
static struct {
    bool tolerance_defined, stop_defined;
    double tolerance, start, stop;
} experiment;

static fstatus enter_initialization(void)
{
    TRACE("  enterInitializationMode(start = %.17g, stop = %.17g)\n", experiment.start,
          experiment.stop);
    return CHECKED(fmi3EnterInitializationMode(inst, experiment.tolerance_defined,
                                               experiment.tolerance, experiment.start,
                                               experiment.stop_defined, experiment.stop));
}
#endif

static void op_setup(input *in)
{
    uint8_t flags = u8(in);
    double tolerance = any_real(in), start = bounded_time(any_real(in)), stop = any_real(in);
#if FMI3
    experiment.tolerance_defined = flags & 1, experiment.stop_defined = (flags >> 1) & 1;
    experiment.tolerance = tolerance, experiment.start = start, experiment.stop = stop;
    if (flags & 4) enter_initialization();
#else
    TRACE("  setupExperiment(start = %.17g, stop = %.17g)\n", start, stop);
    CHECKED(fmi2SetupExperiment(inst, flags & 1, tolerance, start, (flags >> 1) & 1, stop));
#endif
}

static void op_set_kind(input *in, kind k)
{
    set_request r;
    read_set(in, k, &r);
    fstatus s = apply_set(&r);
    if (s != S_ERROR) check_read_back(&r);
}

/* OP_SET_REAL, OP_SET_INTEGER, OP_SET_BOOLEAN (FMI 3.0: one byte more picks the type) */
static void op_set(input *in, kind k) { op_set_kind(in, set_kind(in, k)); }

/* FMI 3.0: the time, read where the FMU's clock says (an accepted get of it is its time). */
static void check_time_read(const vref *vr, size_t count, const value *values)
{
#if FMI3
    for (size_t i = 0; i < count; i++) {
        if (vr[i] != TIME_VR) continue;
        clock_view c = clock_now();
        if (memcmp(&values[i].r, &c.time, sizeof c.time))
            fail("fmi3GetFloat64 of time gave %.17g, the FMU's time is %.17g", values[i].r, c.time);
    }
#else
    (void)vr, (void)count, (void)values;
#endif
}

static void op_get(input *in)
{
    kind k = (kind)(u8(in) % K_COUNT);
    uint8_t n = u8(in);
    size_t count = n % (MAX_SET + 1), n_values = count;
    if (FMI3 && (n & 0x38) == 0x38) n_values = count + 1; /* nValues must equal nvr */
    bool null_arrays = (n & 0x80) && count > 0;
    vref vr[MAX_SET];
    for (size_t i = 0; i < count; i++) vr[i] = pick_vr(in, k);
    value values[MAX_SET];
    const vref *v = null_arrays && (n & 0x40) ? NULL : vr;
    fstatus s = READ_ONLY(x_get(inst, k, v, count, null_arrays ? NULL : values, n_values));
    if (s != S_ERROR && n_values != count)
        fail("a get with nValues %zu for %zu value references was accepted", n_values, count);
    if (s == S_OK && !null_arrays) check_time_read(vr, count, values);
}

static void op_do_step(input *in)
{
    double t = pick_t(in), h = pick_h(in);
    do_step(t, h, u8(in) & 1);
}

static void op_simple_step(input *in)
{
    double h = cycle_time() * (u8(in) % 4 + 1);
    calls_asked += 5;
    do_step(now(), h, false);
}

static void op_get_state(input *in)
{
    uint8_t tag = u8(in);
    fmu_state *slot = &slots[tag % SLOTS];
    if (tag & 0x80) {
        READ_ONLY(x_get_state(inst, NULL));
        return;
    }
    if (tag & 0x40) {
        fmu_state alien = pick_state(in);
        if (alien == foreign) READ_ONLY(x_get_state(inst, &alien));
        return;
    }
    fmu_state before = *slot;
    fstatus s = READ_ONLY(x_get_state(inst, slot));
    if (s == S_OK && before && *slot != before)
        fail("fmi2GetFMUstate with an existing state returned another state");
    if (s == S_ERROR && *slot != before) fail("a refused fmi2GetFMUstate changed *FMUstate");
}

static void op_set_state(input *in)
{
    fmu_state state = pick_state(in);
    CHECKED(x_set_state(inst, state));
}

static void op_free_state(input *in)
{
    uint8_t tag = u8(in);
    if (tag & 0x80) {
        READ_ONLY(x_free_state(inst, NULL));
    } else if (tag & 0x40) {
        fmu_state alien = pick_state(in);
        if (alien == foreign) READ_ONLY(x_free_state(inst, &alien));
    } else {
        fmu_state *slot = &slots[tag % SLOTS];
        fstatus s = READ_ONLY(x_free_state(inst, slot));
        if (s != S_ERROR && *slot) fail("fmi2FreeFMUstate left *FMUstate set");
    }
}

static void op_serialize(input *in)
{
    fmu_state state = pick_state(in);
    uint8_t tag = u8(in);
    size_t size = 0;
    fstatus s = READ_ONLY(x_state_size(inst, state, tag & 0x80 ? NULL : &size));
    if (s == S_ERROR) return;
    if (size < HEADER_SIZE || size > MAX_SERIALIZED) fail("serialized size %zu", size);
    size_t offered = tag & 0x40 ? size - 1 - tag % 8 : size + tag % 4;
    if (offered > MAX_SERIALIZED) offered = MAX_SERIALIZED;
    s = READ_ONLY(x_serialize(inst, state, tag & 0x20 ? NULL : serialized, offered));
    if (s != S_ERROR) serialized_size = size;
}

/* The last serialized state (or the current one) with bytes changed, the buffer cut or
 * padded, and optionally the size field and checksum rewritten to match. */
static void op_deserialize_mutated(input *in)
{
    static unsigned char bytes[MAX_SERIALIZED];
    size_t size;
    bool fresh = u8(in) & 1;
    if (!serialized_size || fresh) serialize_now(serialized, &serialized_size);
    size = serialized_size;
    memcpy(bytes, serialized, size);
    uint8_t count = u8(in) % 8;
    for (uint8_t i = 0; i < count; i++) {
        uint8_t how = u8(in);
        size_t at = u16(in) % (size ? size : 1);
        switch (how % 4) {
        case 0: bytes[at] ^= (unsigned char)(1u << (how >> 5)); break;
        case 1: bytes[at] = u8(in); break;
        case 2: /* an aligned 8-byte field: a double or a 64-bit counter of the image */
            if (size < HEADER_SIZE + 8) break;
            at = HEADER_SIZE + ((at & ~(size_t)7) % (size - HEADER_SIZE) & ~(size_t)7);
            if (at + 8 <= size) {
                uint64_t value;
                if (how & 0x40)
                    memcpy(&value, &(double){any_real(in)}, 8);
                else
                    value = how & 0x80 ? (uint64_t)(int64_t)any_int(in) : u64(in);
                memcpy(bytes + at, &value, 8);
            }
            break;
        default: /* cut or pad */
            size = how & 0x80 ? at : size + u8(in) % 16;
            if (size > MAX_SERIALIZED) size = MAX_SERIALIZED;
            break;
        }
    }
    uint8_t fix = u8(in);
    fix_header(bytes, size, fix & 1, fix & 2);
    deserialize(bytes, size, in);
}

/* The current state with one to three fields of its payload overwritten by values at the
 * edges of their type, behind a valid header and checksum: a forged state, which the FMU must
 * check field by field (the clock, every variable and the block's statics) before it runs it. */
static void op_forge(input *in)
{
    static const int64_t integers[] = {0,
                                       1,
                                       -1,
                                       2,
                                       3,
                                       255,
                                       256,
                                       32767,
                                       -32768,
                                       65535,
                                       INT32_MAX,
                                       INT32_MIN,
                                       INT64_MAX,
                                       INT64_MIN,
                                       INT64_C(1) << 62,
                                       INT64_C(1) << 56,
                                       INT64_C(9000000000000000),
                                       INT64_C(100000),
                                       INT64_C(60000000),
                                       -(INT64_C(1) << 40)};
    static unsigned char bytes[MAX_SERIALIZED];
    size_t size;
    serialize_now(bytes, &size);
    size_t payload = size - HEADER_SIZE, data = STATE_CLOCK_SIZE;
    uint8_t count = u8(in) % 3 + 1;
    for (uint8_t i = 0; i < count; i++) {
        uint8_t field = u8(in), how = u8(in);
        size_t at, width;
        bool real_ = false;
        switch (field % 8) {
        case 0: at = 0, width = 4; break; /* the clock's fields (src/core/model.h) */
        case 1: at = 4, width = 4; break;
        case 2: at = 8, width = 8, real_ = true; break;
        case 3: at = 16, width = 8, real_ = true; break;
        case 4: at = 24, width = 8; break;
        default: /* the block's data, at any aligned place and width */
            width = (size_t)1 << (how >> 6);
            at = data + (u8(in) * width) % (payload - data);
            at -= at % width;
            real_ = width == 8 && (how & 0x20);
            break;
        }
        if (at + width > payload) continue;
        int64_t value;
        if (real_) {
            double d = any_real(in);
            if (field % 8 == 2 || field % 8 == 3) d = bounded_time(d); /* see op_setup */
            memcpy(&value, &d, 8);
        } else {
            value = how & 0x10 ? (int64_t)u64(in)
                               : integers[how % (sizeof integers / sizeof integers[0])];
        }
        memcpy(bytes + HEADER_SIZE + at, &value, width); /* little endian: the low bytes */
    }
    fix_header(bytes, size, false, true);
    uint8_t then = u8(in);
    int slot = deserialize(bytes, size, in);
    if (slot >= 0 && (then & 1)) CHECKED(x_set_state(inst, slots[slot]));
}

/* Bytes from the input: as they are, or behind a valid header, or as the payload of a header
 * that names another block, format version or size. */
static void op_deserialize_raw(input *in)
{
    static unsigned char bytes[MAX_SERIALIZED];
    uint8_t how = u8(in);
    size_t length = u16(in) % 4096;
    size_t size = 0;
    if (how % 4) {
        serialize_now(bytes, &size); /* a valid header */
        for (size_t i = 0; i < length && HEADER_SIZE + i < size; i++)
            bytes[HEADER_SIZE + i] = u8(in);
        if (how % 4 == 2) {
            static const char *const names[] = {"LGF_SawTooth", "LGF_RampCI",
                                                "LGF_LimRateOfChangeCI", "LGF_"};
            memset(bytes + 12, 0, 32);
            const char *name = names[u8(in) % 4];
            memcpy(bytes + 12, name, strlen(name));
        } else if (how % 4 == 3) {
            fuzz_put_le(bytes + 8, u8(in), 4); /* format version */
        }
        fix_header(bytes, size, false, true);
    } else {
        for (size = 0; size < length; size++) bytes[size] = u8(in);
    }
    deserialize(bytes, size, in);
}

/* The start of a round trip (`what`, for messages): the FMU's state taken (*a), serialized and
 * deserialized again (*b). False, *a freed, when the FMU refused its own bytes (own_state_refused
 * says so); a state that cannot be serialized fails. */
static bool round_trip_begin(const char *what, fmu_state *a, fmu_state *b)
{
    size_t size = 0;
    static unsigned char bytes[MAX_SERIALIZED];
    if (x_get_state(inst, a) != S_OK || x_state_size(inst, *a, &size) != S_OK ||
        size > MAX_SERIALIZED || x_serialize(inst, *a, bytes, size) != S_OK)
        fail("%s: the state could not be serialized", what);
    if (x_deserialize(inst, bytes, size, b) == S_OK) return true;
    own_state_refused(what, bytes, size);
    x_free_state(inst, a);
    return false;
}

/* The end of a round trip: both its states freed. */
static void round_trip_end(const char *what, fmu_state *a, fmu_state *b)
{
    if (x_free_state(inst, a) != S_OK || x_free_state(inst, b) != S_OK)
        fail("%s: freeing a state failed", what);
}

/* Serialize, deserialize and set back: the next step must come out the same, bit for bit,
 * whether it runs from the live state or the restored one. */
static void op_round_trip(input *in)
{
    set_request r;
    read_set(in, (kind)(u8(in) % K_COUNT), &r);
    double t = pick_t(in), h = pick_h(in);
    TRACE("  round trip: doStep(%.17g, %.17g) twice\n", t, h);
    bool was_tracing = trace;
    trace = false;
    fmu_state a = NULL, b = NULL;
    if (!round_trip_begin("round trip", &a, &b)) {
        trace = was_tracing;
        return;
    }
    take(&snap_round[0]);
    fstatus set1 = apply_set(&r), step1 = x_do_step(inst, t, h, false);
    take(&snap_round[1]);
    if (x_set_state(inst, b) != S_OK) fail("round trip: setting the state was refused");
    take(&snap_round[2]);
    must_equal(&snap_round[0], &snap_round[2], "round trip: the restored state");
    fstatus set2 = apply_set(&r), step2 = x_do_step(inst, t, h, false);
    take(&snap_round[2]);
    if (set1 != set2 || step1 != step2)
        fail("round trip: the replay returned %s/%s instead of %s/%s", status_name(set2),
             status_name(step2), status_name(set1), status_name(step1));
    must_equal(&snap_round[1], &snap_round[2], "round trip: the step after the restore");
    round_trip_end("round trip", &a, &b);
    trace = was_tracing;
}

static void op_debug_logging(input *in)
{
    static const char *const names[] = {
        "logAll", "logStatusWarning", "logStatusError", "logStatusDiscard", "logEvents", "", NULL};
    uint8_t tag = u8(in);
    size_t n = tag % 4;
    const char *categories[3];
    for (size_t i = 0; i < n && i < 3; i++) categories[i] = names[u8(in) % 7];
    READ_ONLY(x_set_debug_logging(inst, (tag >> 2) & 1, n, tag & 0x80 ? NULL : categories));
}

/* The NULL pointers of the state functions both versions' op_misc pass. */
static void misc_null_states(input *in)
{
    fmu_state state = pick_state(in);
    READ_ONLY(x_state_size(inst, state, NULL));
    CHECKED(x_deserialize(inst, NULL, 100, &state));
}

/* A case of op_null_component: the call with a NULL instance, its status into s and its text
 * into function. */
#define NULL_CASE(n, call)                                                                         \
    case n:                                                                                        \
        s = call;                                                                                  \
        function = #call;                                                                          \
        break

#if !FMI3
/* The functions an importer rarely calls, and NULL pointers. */
static void op_misc(input *in)
{
    fmi2ValueReference vr[2] = {pick_vr(in, K_REAL), pick_vr(in, K_REAL)};
    fmi2Integer order[2] = {1, 1};
    fmi2Real reals[2] = {0, 0};
    fmi2String strings[2] = {"x", NULL};
    fmi2StatusKind kind_ = (fmi2StatusKind)(u8(in) % 3);
    bool null = u8(in) & 1;
    size_t n = u8(in) % 3;
    fmi2Status status_value;
    fmi2Real real_value;
    fmi2Integer integer_value;
    fmi2Boolean boolean_value;
    fmi2String string_value;
    switch (u8(in) % 14) {
    case 0:
        if (strcmp(fmi2GetVersion(), fmi2Version) ||
            strcmp(fmi2GetTypesPlatform(), fmi2TypesPlatform))
            fail("fmi2GetVersion or fmi2GetTypesPlatform");
        break;
    case 1: READ_ONLY(fmi2CancelStep(inst)); break;
    case 2: READ_ONLY(fmi2GetStatus(inst, kind_, null ? NULL : &status_value)); break;
    case 3: READ_ONLY(fmi2GetRealStatus(inst, kind_, null ? NULL : &real_value)); break;
    case 4: READ_ONLY(fmi2GetIntegerStatus(inst, kind_, null ? NULL : &integer_value)); break;
    case 5: READ_ONLY(fmi2GetBooleanStatus(inst, kind_ + 1, null ? NULL : &boolean_value)); break;
    case 6: READ_ONLY(fmi2GetStringStatus(inst, kind_, null ? NULL : &string_value)); break;
    case 7:
        CHECKED(fmi2SetRealInputDerivatives(inst, null ? NULL : vr, n, null ? NULL : order,
                                            null ? NULL : reals));
        break;
    case 8:
        READ_ONLY(fmi2GetRealOutputDerivatives(inst, null ? NULL : vr, n, null ? NULL : order,
                                               null ? NULL : reals));
        break;
    case 9:
        READ_ONLY(fmi2GetDirectionalDerivative(inst, null ? NULL : vr, n, null ? NULL : vr + 1, n,
                                               null ? NULL : reals, null ? NULL : reals + 1));
        break;
    case 10: CHECKED(fmi2SetString(inst, null ? NULL : vr, n, null ? NULL : strings)); break;
    case 11: READ_ONLY(fmi2GetString(inst, null ? NULL : vr, n, null ? NULL : strings)); break;
    case 12: { /* nvr = 0 with NULL arrays is a legal no-op */
        CHECKED(fmi2SetReal(inst, NULL, 0, NULL));
        READ_ONLY(fmi2GetBoolean(inst, NULL, 0, NULL));
        break;
    }
    default: misc_null_states(in); break;
    }
}

/* Every function with a NULL instance: fmi2Error (nothing to log to), never a crash. */
static void op_null_component(input *in)
{
    fmi2ValueReference vr = 0;
    fmi2Real r = 0;
    fmi2Integer i = 0;
    fmi2Boolean b = 0;
    fmu_state state = NULL;
    size_t size = 0;
    unsigned char byte = 0;
    fstatus s = S_OK;
    const char *function = "";
    switch (u8(in) % 24) {
        NULL_CASE(0, fmi2SetupExperiment(NULL, 0, 0, 0, 0, 0));
        NULL_CASE(1, fmi2EnterInitializationMode(NULL));
        NULL_CASE(2, fmi2ExitInitializationMode(NULL));
        NULL_CASE(3, fmi2Terminate(NULL));
        NULL_CASE(4, fmi2Reset(NULL));
        NULL_CASE(5, fmi2DoStep(NULL, 0, 0.1, 0));
        NULL_CASE(6, fmi2SetReal(NULL, &vr, 1, &r));
        NULL_CASE(7, fmi2SetInteger(NULL, &vr, 1, &i));
        NULL_CASE(8, fmi2SetBoolean(NULL, &vr, 1, &b));
        NULL_CASE(9, fmi2GetReal(NULL, &vr, 1, &r));
        NULL_CASE(10, fmi2GetInteger(NULL, &vr, 1, &i));
        NULL_CASE(11, fmi2GetBoolean(NULL, &vr, 1, &b));
        NULL_CASE(12, x_get_state(NULL, &state));
        NULL_CASE(13, x_set_state(NULL, state));
        NULL_CASE(14, x_free_state(NULL, &state));
        NULL_CASE(15, x_state_size(NULL, state, &size));
        NULL_CASE(16, x_serialize(NULL, state, &byte, 1));
        NULL_CASE(17, x_deserialize(NULL, &byte, 1, &state));
        NULL_CASE(18, fmi2SetDebugLogging(NULL, 1, 0, NULL));
        NULL_CASE(19, fmi2GetRealStatus(NULL, fmi2LastSuccessfulTime, &r));
        NULL_CASE(20, fmi2GetBooleanStatus(NULL, fmi2Terminated, &b));
        NULL_CASE(21, fmi2CancelStep(NULL));
        NULL_CASE(22, fmi2SetString(NULL, &vr, 1, NULL));
    default: fmi2FreeInstance(NULL); return;
    }
#undef NULL_CASE
    TRACE("  %s -> %s\n", function, status_name(s));
    if (s != S_ERROR) fail("%s returned %s", function, status_name(s));
    if (state) fail("%s with a NULL instance returned a state", function);
}

#else /* FMI 3.0 */

/* The types this FMU has no variable of: any value reference is unknown to them (k: 0 Int8,
 * 1 UInt8, 2 Int32, 3 Int64, 4 UInt64, 5 String, 6 Binary, 7 Clock). */
static fstatus other_type(int k, bool set, const vref *vr, size_t nvr, bool null_values,
                          size_t n_values)
{
    static fmi3Int8 i8[4];
    static fmi3UInt8 u8_[4];
    static fmi3Int32 i32[4];
    static fmi3Int64 i64[4];
    static fmi3UInt64 u64_[4];
    static fmi3String strings[4] = {"x", "y", "z", ""};
    static fmi3Byte byte;
    static fmi3Binary binaries[4] = {&byte, &byte, &byte, &byte};
    static size_t sizes[4] = {1, 1, 1, 1};
    static fmi3Clock clocks[4];
    bool n = null_values;
    switch (k % 8) {
    case 0:
        return set ? fmi3SetInt8(inst, vr, nvr, n ? NULL : i8, n_values)
                   : fmi3GetInt8(inst, vr, nvr, n ? NULL : i8, n_values);
    case 1:
        return set ? fmi3SetUInt8(inst, vr, nvr, n ? NULL : u8_, n_values)
                   : fmi3GetUInt8(inst, vr, nvr, n ? NULL : u8_, n_values);
    case 2:
        return set ? fmi3SetInt32(inst, vr, nvr, n ? NULL : i32, n_values)
                   : fmi3GetInt32(inst, vr, nvr, n ? NULL : i32, n_values);
    case 3:
        return set ? fmi3SetInt64(inst, vr, nvr, n ? NULL : i64, n_values)
                   : fmi3GetInt64(inst, vr, nvr, n ? NULL : i64, n_values);
    case 4:
        return set ? fmi3SetUInt64(inst, vr, nvr, n ? NULL : u64_, n_values)
                   : fmi3GetUInt64(inst, vr, nvr, n ? NULL : u64_, n_values);
    case 5:
        return set ? fmi3SetString(inst, vr, nvr, n ? NULL : strings, n_values)
                   : fmi3GetString(inst, vr, nvr, n ? NULL : strings, n_values);
    case 6:
        return set ? fmi3SetBinary(inst, vr, nvr, n ? NULL : sizes, n ? NULL : binaries, n_values)
                   : fmi3GetBinary(inst, vr, nvr, n ? NULL : sizes, n ? NULL : binaries, n_values);
    default:
        return set ? fmi3SetClock(inst, vr, nvr, n ? NULL : clocks)
                   : fmi3GetClock(inst, vr, nvr, n ? NULL : clocks);
    }
}

/* The functions FMI 3.0 has and this FMU refuses, whatever the mode and arguments. */
static fstatus refused_function(int which, const vref *vr, bool null)
{
    fmi3Float64 reals[2] = {1, 0};
    fmi3UInt64 counters[2] = {1, 1};
    fmi3IntervalQualifier qualifiers[2];
    fmi3Int32 orders[2] = {1, 1};
    size_t n = 0, elements[2] = {0, 0};
    fmi3DependencyKind kinds[2];
    fmi3ValueReference refs[2] = {vr[0], vr[1]};
    fmi3ValueReference *r = null ? NULL : refs;
    switch (which % 17) {
    case 0: return fmi3EnterStepMode(inst);
    case 1: return fmi3EnterConfigurationMode(inst);
    case 2: return fmi3ExitConfigurationMode(inst);
    case 3: return fmi3GetDirectionalDerivative(inst, r, 1, r, 1, reals, 1, reals + 1, 1);
    case 4: return fmi3GetAdjointDerivative(inst, r, 1, r, 1, reals, 1, reals + 1, 1);
    case 5: return fmi3GetNumberOfVariableDependencies(inst, refs[0], null ? NULL : &n);
    case 6: return fmi3GetVariableDependencies(inst, refs[0], elements, r, elements, kinds, 1);
    case 7: return fmi3GetOutputDerivatives(inst, r, 1, orders, reals, 1);
    case 8: return fmi3ActivateModelPartition(inst, refs[0], reals[0]);
    case 9: return fmi3GetIntervalDecimal(inst, r, 1, reals, qualifiers);
    case 10: return fmi3GetIntervalFraction(inst, r, 1, counters, counters + 1, qualifiers);
    case 11: return fmi3GetShiftDecimal(inst, r, 1, reals);
    case 12: return fmi3GetShiftFraction(inst, r, 1, counters, counters + 1);
    case 13: return fmi3SetIntervalDecimal(inst, r, 1, reals);
    case 14: return fmi3SetIntervalFraction(inst, r, 1, counters, counters + 1);
    case 15: return fmi3SetShiftDecimal(inst, r, 1, reals);
    default: return fmi3SetShiftFraction(inst, r, 1, counters, counters + 1);
    }
}

/* The functions an importer rarely calls, what only FMI 3.0 has, and NULL pointers. */
static void op_misc(input *in)
{
    vref vr[2] = {pick_vr(in, K_REAL), pick_vr(in, K_REAL)};
    bool null = u8(in) & 1;
    size_t n = u8(in) % 3;
    uint8_t which = u8(in);
    switch (which % 14) {
    case 0:
        if (strcmp(fmi3GetVersion(), fmi3Version)) fail("fmi3GetVersion");
        break;
    case 1: {
        fstatus s = READ_ONLY(refused_function(u8(in), vr, null));
        if (s != S_ERROR) fail("a function the FMU does not support returned %s", status_name(s));
        break;
    }
    case 2: { /* a type without variables: nvr > 0 is refused, nvr = 0 a no-op */
        int k = u8(in);
        bool set = k & 0x80;
        size_t n_values = k & 0x40 ? n + 1 : n;
        fstatus s = set ? CHECKED(other_type(k, true, null ? NULL : vr, n, null, n_values))
                        : READ_ONLY(other_type(k, false, null ? NULL : vr, n, null, n_values));
        if (s != S_ERROR && n > 0) fail("a type without variables accepted a value reference");
        /* (a bug once, fixed in src/fmi3/fmi3.c: the regressions fmi3-nvalues-no-variables) */
        if (s != S_ERROR && n_values != n && k % 8 != 7)
            fail("a get or set of a type without variables with nvr = %zu and nValues = %zu was "
                 "accepted",
                 n, n_values);
        break;
    }
    case 3: { /* DoStep with NULL out-pointers */
        fmi3Boolean flags[3];
        fmi3Float64 last;
        uint8_t nulls = (uint8_t)(u8(in) % 15 + 1);
        double t = now(), h = cycle_time();
        calls_asked += 2;
        fstatus s = CHECKED(fmi3DoStep(inst, t, h, fmi3False, nulls & 1 ? NULL : &flags[0],
                                       nulls & 2 ? NULL : &flags[1], nulls & 4 ? NULL : &flags[2],
                                       nulls & 8 ? NULL : &last));
        if (s != S_ERROR) fail("fmi3DoStep with a NULL out-pointer returned %s", status_name(s));
        break;
    }
    case 4: { /* UpdateDiscreteStates with one NULL out-pointer */
        event_flags info;
        fstatus s = CHECKED(x_update(inst, &info, u8(in) % 6 + 1));
        if (s != S_ERROR)
            fail("fmi3UpdateDiscreteStates with a NULL out-pointer returned %s", status_name(s));
        break;
    }
    case 5:
    case 6: { /* the counts: 0 */
        size_t count = 7;
        fstatus s = which % 14 == 5
                        ? READ_ONLY(fmi3GetNumberOfEventIndicators(inst, null ? NULL : &count))
                        : READ_ONLY(fmi3GetNumberOfContinuousStates(inst, null ? NULL : &count));
        if (s != S_ERROR && (null || count != 0))
            fail("a count of continuous states or event indicators is %zu", count);
        if (s == S_ERROR && count != 7) fail("a refused count wrote to its argument");
        break;
    }
    case 7: READ_ONLY(fmi3EvaluateDiscreteStates(inst)); break;
    case 8: { /* time, alone or with other Float64 value references */
        vref refs[2] = {TIME_VR, vr[1]};
        value values[2];
        size_t count = n ? n : 1;
        fstatus s = READ_ONLY(x_get(inst, K_FLOAT64, refs, count, values, count));
        if (s == S_OK) check_time_read(refs, count, values);
        break;
    }
    case 9: { /* nothing sets the time */
        vref refs[1] = {TIME_VR};
        value v = {.r = any_real(in)};
        if (CHECKED(x_set(inst, K_FLOAT64, refs, 1, &v, 1)) != S_ERROR)
            fail("fmi3SetFloat64 of time was accepted");
        break;
    }
    case 10: { /* nvr = 0 with NULL arrays is a legal no-op */
        CHECKED(fmi3SetFloat64(inst, NULL, 0, NULL, 0));
        READ_ONLY(fmi3GetBoolean(inst, NULL, 0, NULL, 0));
        break;
    }
    case 11: {
        fmi3Instance other =
            fmi3InstantiateScheduledExecution("fuzz", lgf_model.guid, NULL, fmi3False, fmi3False,
                                              &environment_tag, logger, NULL, NULL, NULL);
        if (other) fail("fmi3InstantiateScheduledExecution returned an instance");
        break;
    }
    case 12: { /* a get or set of a kind with nValues != nvr */
        kind k = (kind)(u8(in) % K_COUNT);
        value values[3] = {{.i = 0}, {.i = 0}, {.i = 0}};
        size_t n_values = n + 1;
        fstatus s = u8(in) & 1 ? CHECKED(x_set(inst, k, vr, n, values, n_values))
                               : READ_ONLY(x_get(inst, k, vr, n, values, n_values));
        if (s != S_ERROR) fail("nValues %zu for %zu value references was accepted", n_values, n);
        break;
    }
    default: misc_null_states(in); break;
    }
}

/* Every function with a NULL instance: fmi3Error (nothing to log to), never a crash. */
static void op_null_component(input *in)
{
    fmi3ValueReference vr = 0;
    fmi3Float64 r = 0;
    fmi3Int16 i = 0;
    fmi3Boolean b = 0, flags[3];
    fmi3FMUState state = NULL;
    size_t size = 0;
    fmi3Byte byte = 0;
    fstatus s = S_OK;
    const char *function = "";
    switch (u8(in) % 26) {
        NULL_CASE(0, fmi3EnterInitializationMode(NULL, 0, 0, 0, 0, 0));
        NULL_CASE(1, fmi3EnterStepMode(NULL));
        NULL_CASE(2, fmi3ExitInitializationMode(NULL));
        NULL_CASE(3, fmi3Terminate(NULL));
        NULL_CASE(4, fmi3Reset(NULL));
        NULL_CASE(5, fmi3DoStep(NULL, 0, 0.1, 0, &flags[0], &flags[1], &flags[2], &r));
        NULL_CASE(6, fmi3SetFloat64(NULL, &vr, 1, &r, 1));
        NULL_CASE(7, fmi3SetInt16(NULL, &vr, 1, &i, 1));
        NULL_CASE(8, fmi3SetBoolean(NULL, &vr, 1, &b, 1));
        NULL_CASE(9, fmi3GetFloat64(NULL, &vr, 1, &r, 1));
        NULL_CASE(10, fmi3GetInt16(NULL, &vr, 1, &i, 1));
        NULL_CASE(11, fmi3GetBoolean(NULL, &vr, 1, &b, 1));
        NULL_CASE(12, fmi3GetFMUState(NULL, &state));
        NULL_CASE(13, fmi3SetFMUState(NULL, state));
        NULL_CASE(14, fmi3FreeFMUState(NULL, &state));
        NULL_CASE(15, fmi3SerializedFMUStateSize(NULL, state, &size));
        NULL_CASE(16, fmi3SerializeFMUState(NULL, state, &byte, 1));
        NULL_CASE(17, fmi3DeserializeFMUState(NULL, &byte, 1, &state));
        NULL_CASE(18, fmi3SetDebugLogging(NULL, 1, 0, NULL));
        NULL_CASE(19, fmi3GetInt8(NULL, &vr, 1, NULL, 1));
        NULL_CASE(20, fmi3SetClock(NULL, &vr, 1, &b));
        NULL_CASE(21, fmi3EvaluateDiscreteStates(NULL));
        NULL_CASE(22, fmi3GetNumberOfEventIndicators(NULL, &size));
        NULL_CASE(23, fmi3EnterConfigurationMode(NULL));
        NULL_CASE(24, fmi3GetUInt32(NULL, &vr, 1, NULL, 1));
    default: fmi3FreeInstance(NULL); return;
    }
#undef NULL_CASE
    TRACE("  %s -> %s\n", function, status_name(s));
    if (s != S_ERROR) fail("%s returned %s", function, status_name(s));
    if (state) fail("%s with a NULL instance returned a state", function);
}
#endif

/* --------------------------------------------------------------- Model Exchange ---- */

#define MODE_STEP_ 2 /* fmu_mode (src/core/core.h) as the serialized clock holds it */
#define MODE_EVENT_ 3
#define MODE_CONTINUOUS_ 4
#define MODE_TERMINATED_ 5

/* After an accepted call that changes the mode: the mode FMI 2.0 (3.0) names. */
static void must_be_in(int32_t mode, const char *after)
{
    clock_view c = clock_now();
    if (c.mode != mode)
        fail("after %s the FMU is in mode %d, not %d", after, (int)c.mode, (int)mode);
}

/* A time for fmi2SetTime: the next call's time, on it or up to twice the grid tolerance off,
 * between calls, the FMU's time or a little before it, some calls on (time events the importer
 * passes without stopping), the stopTime, anything. As with fmi2DoStep, one time stays within
 * 10^4 cycles of the FMU's and the calls the importer asks for within the budget. */
static double pick_me_time(input *in)
{
    clock_view c = clock_now();
    double cycle = c.cycle_us > 0 ? c.cycle_us / 1e6 : 0.1;
    double next = next_call_time(&c), t;
    uint8_t tag = u8(in);
    switch (tag % 10) {
    case 1: {
        uint8_t off = u8(in);
        t = next + (off & 0x80 ? -1 : 1) * (off & 0x7f) / 64.0 * grid_tolerance_of(&c, next);
        break;
    }
    case 2: t = c.time + (u8(in) + 1) / 257.0 * (next - c.time); break; /* before the next call */
    case 3: t = c.time; break;
    case 4: { /* back, up to twice the tolerance */
        uint8_t off = u8(in);
        t = c.time - (off & 0x7f) / 64.0 * grid_tolerance_of(&c, c.time);
        break;
    }
    case 5: t = next + cycle * (u8(in) % 8); break;
    case 6:
        t = c.stop_defined ? c.stop + (int8_t)u8(in) / 64.0 * grid_tolerance_of(&c, c.stop) : next;
        break;
    case 7: t = any_real(in); break;
    case 8: t = c.time + (int8_t)u8(in) * cycle; break;
    case 9: {
        t = next;
        int steps = (int8_t)u8(in);
        for (int i = 0; i < abs(steps); i++) t = nextafter(t, steps < 0 ? -INFINITY : INFINITY);
        break;
    }
    default: t = next; break;
    }
    if (isfinite(t) && t > c.time + 1e4 * cycle && t < 1e19)
        t = c.time + fmod(t - c.time, 1e4 * cycle);
    if (isfinite(t) && t > c.time + cycle && t < 1e19 && calls_asked > CALL_BUDGET) t = next;
    if (isfinite(t) && t > c.time && t < 1e19) calls_asked += (t - c.time) / cycle + 1;
    return t;
}

static fstatus me_set_time(double t)
{
    TRACE("  setTime(%.17g)\n", t);
    fstatus s = CHECKED(x_set_time(inst, t));
    if (s != S_ERROR) {
        clock_view c = clock_now();
        if (memcmp(&c.time, &t, sizeof t))
            fail("after setting the time to %.17g the FMU's time is %.17g", t, c.time);
#if FMI3
        double got = NAN;
        if (x_time(inst, &got) != S_OK || memcmp(&got, &t, sizeof t))
            fail("after fmi3SetTime(%.17g) fmi3GetFloat64 of time gives %.17g", t, got);
#endif
        accepts_own_state("after setting the time");
    }
    return s;
}

static fstatus me_enter_event_mode(void)
{
    fstatus s = CHECKED(x_enter_event(inst));
    if (s != S_ERROR) must_be_in(MODE_EVENT_, "entering event mode");
    return s;
}

static fstatus me_enter_continuous(void)
{
    fstatus s = CHECKED(x_enter_continuous(inst));
    if (s != S_ERROR) must_be_in(MODE_CONTINUOUS_, "entering continuous-time mode");
    return s;
}

static bool same_event_info(const event_flags *a, const event_flags *b)
{
    return a->needed == b->needed && a->terminate == b->terminate && a->nominals == b->nominals &&
           a->values == b->values && a->defined == b->defined &&
           !memcmp(&a->next, &b->next, sizeof a->next);
}

/* An event iteration, and its invariants; info gets the eventInfo (zeros if refused). */
static fstatus me_new_discrete_states(bool second, event_flags *info)
{
    fstatus s = CHECKED(x_update(inst, info, 0));
    if (s == S_ERROR) {
        memset(info, 0, sizeof *info);
        return s;
    }
    clock_view c = clock_now();
    double next = next_call_time(&c);
    if (info->needed != 0 || info->terminate != 0 || info->nominals != 0 || info->values != 0 ||
        info->defined != 1)
        fail("the event iteration: eventInfo {%d, %d, %d, %d, %d}, expected {0, 0, 0, 0, 1}",
             info->needed, info->terminate, info->nominals, info->values, info->defined);
    if (memcmp(&info->next, &next, sizeof next))
        fail("the event iteration: nextEventTime %.17g, but the next call (%lld) is at %.17g",
             info->next, (long long)c.calls, next);
    if (!(info->next > c.time) || calls_ahead(&c) < 0)
        fail("the event iteration at t = %.17g left a call due (nextEventTime %.17g)", c.time,
             info->next);
    accepts_own_state("after the event iteration");
    if (second) { /* at the same instant: nothing is due any more */
        event_flags again;
        if (READ_ONLY(x_update(inst, &again, 0)) != S_OK)
            fail("a second event iteration was refused");
        if (!same_event_info(&again, info)) fail("a second event iteration: another eventInfo");
    }
    return s;
}

static void op_me_new_discrete_states(input *in)
{
    uint8_t tag = u8(in);
    event_flags info;
    /* FMI 3.0: bits 2..4 pick one out-pointer NULL, or all */
    if (tag & 1)
        CHECKED(x_update(inst, FMI3 && (tag >> 2) % 7 ? &info : NULL, (tag >> 2) % 7));
    else
        me_new_discrete_states(tag & 2, &info);
}

static void op_me_completed_integrator_step(input *in)
{
    uint8_t tag = u8(in);
    int enter = 7, terminate = 7;
    fstatus s = READ_ONLY(
        x_completed(inst, (tag >> 2) & 1, tag & 1 ? NULL : &enter, tag & 2 ? NULL : &terminate));
    if (s != S_ERROR && ((!(tag & 1) && enter != 0) || (!(tag & 2) && terminate != 0)))
        fail("the integrator step done: enterEventMode %d, terminateSimulation %d", enter,
             terminate);
    if (s == S_ERROR && (enter != 7 || terminate != 7))
        fail("a refused fmi2CompletedIntegratorStep wrote its out-pointers");
}

/* The functions of continuous states and event indicators, with any count and NULL arrays. */
static void op_me_no_states(input *in)
{
    uint8_t tag = u8(in);
    static const size_t counts[] = {0, 1, 2, 0, SIZE_MAX};
    size_t n = counts[(tag >> 3) % 5];
    if ((tag >> 3) % 5 == 3) n = u32(in);
    double x[4] = {-7.25, -7.25, -7.25, -7.25};
    double *array = tag & 0x80 ? NULL : x;
    fstatus s = tag % 5 == 0 ? CHECKED(x_no_states(inst, 0, array, n))
                             : READ_ONLY(x_no_states(inst, tag % 5, array, n));
    if (s != S_ERROR && n != 0) fail("a function of continuous states accepted n = %zu", n);
    for (int i = 0; i < 4; i++)
        if (x[i] != -7.25) fail("a function of continuous states wrote to its array");
}

/* What an importer does at a time event: fmi2SetTime (in continuous-time or event mode, maybe
 * first to a time between calls with fmi2CompletedIntegratorStep there), fmi2EnterEventMode,
 * inputs, fmi2NewDiscreteStates (maybe twice), back to continuous-time mode or not. */
static void op_me_event(input *in)
{
    uint8_t how = u8(in);
    calls_asked += 5;
    clock_view c = clock_now();
    double cycle = c.cycle_us > 0 ? c.cycle_us / 1e6 : 0.1;
    double next = next_call_time(&c), t = next;
    if ((how & 3) == 1) {
        uint8_t off = u8(in);
        t += (off & 0x80 ? -1 : 1) * (off & 0x7f) / 64.0 * grid_tolerance_of(&c, next);
    } else if ((how & 3) == 2) {
        double mid = c.time + (u8(in) + 1) / 257.0 * (next - c.time);
        if (me_set_time(mid) != S_ERROR) op_me_completed_integrator_step(in);
    } else if ((how & 3) == 3) {
        t += cycle * (u8(in) % 3); /* passes call times without stopping */
        calls_asked += 3;
    }
    me_set_time(t);
    if (clock_now().mode != MODE_EVENT_) me_enter_event_mode();
    if (how & 4) op_set_kind(in, (kind)(u8(in) % K_COUNT));
    event_flags info;
    me_new_discrete_states(how & 8, &info);
    if (!(how & 0x10)) me_enter_continuous();
}

/* Serialize, deserialize and set back: the same event iteration from the restored state must
 * give the same statuses, eventInfo and instance, bit for bit. */
static void op_me_round_trip(input *in)
{
    set_request r;
    read_set(in, (kind)(u8(in) % K_COUNT), &r);
    double t = pick_me_time(in);
    TRACE("  Model Exchange round trip: setTime(%.17g), event iteration, twice\n", t);
    bool was_tracing = trace;
    trace = false;
    fmu_state a = NULL, b = NULL;
    if (!round_trip_begin("Model Exchange round trip", &a, &b)) {
        trace = was_tracing;
        return;
    }
    take(&snap_round[0]);
    event_flags info[2];
    fstatus status[2][4];
    for (int run = 0; run < 2; run++) {
        memset(&info[run], 0, sizeof info[run]);
        status[run][0] = x_set_time(inst, t);
        status[run][1] = x_enter_event(inst);
        status[run][2] = apply_set(&r);
        status[run][3] = x_update(inst, &info[run], 0);
        take(&snap_round[1 + run]);
        if (run == 0) {
            if (x_set_state(inst, b) != S_OK)
                fail("Model Exchange round trip: setting the state was refused");
            take(&snap_after);
            must_equal(&snap_round[0], &snap_after,
                       "Model Exchange round trip: the restored state");
        }
    }
    if (memcmp(status[0], status[1], sizeof status[0]))
        fail("Model Exchange round trip: the replay returned other statuses");
    if (!same_event_info(&info[0], &info[1]))
        fail("Model Exchange round trip: the replay returned another eventInfo");
    must_equal(&snap_round[1], &snap_round[2],
               "Model Exchange round trip: the event after the restore");
    round_trip_end("Model Exchange round trip", &a, &b);
    trace = was_tracing;
}

/* The Model Exchange functions with a NULL instance: an error, never a crash. */
static void op_me_null_component(input *in)
{
    event_flags info;
    int enter, terminate;
    double x = 0;
    fstatus s;
    uint8_t which = u8(in) % 10;
    switch (which) {
    case 0: s = x_enter_event(NULL); break;
    case 1: s = x_update(NULL, &info, 0); break;
    case 2: s = x_enter_continuous(NULL); break;
    case 3: s = x_completed(NULL, false, &enter, &terminate); break;
    case 4: s = x_set_time(NULL, 0.5); break;
    default: s = x_no_states(NULL, which - 5, &x, 0); break;
    }
    TRACE("  Model Exchange function %u with a NULL instance -> %s\n", which, status_name(s));
    if (s != S_ERROR)
        fail("Model Exchange function %u with a NULL instance returned %s", which, status_name(s));
}

enum {
    OP_SETUP,
    OP_ENTER,
    OP_EXIT,
    OP_SET_REAL,
    OP_SET_INTEGER,
    OP_SET_BOOLEAN,
    OP_GET,
    OP_DO_STEP,
    OP_SIMPLE_STEP,
    OP_GET_STATE,
    OP_SET_STATE,
    OP_FREE_STATE,
    OP_SERIALIZE,
    OP_DESERIALIZE_MUTATED,
    OP_DESERIALIZE_RAW,
    OP_ROUND_TRIP,
    OP_TERMINATE,
    OP_RESET,
    OP_DEBUG_LOGGING,
    OP_MISC,
    OP_NULL_COMPONENT,
    OP_FAIL_ALLOCATION,
    OP_FORGE,
    /* Model Exchange (on either interface: a co-simulation instance must refuse them) */
    OP_ME_ENTER_EVENT,
    OP_ME_NEW_DISCRETE_STATES,
    OP_ME_ENTER_CONTINUOUS,
    OP_ME_COMPLETED_INTEGRATOR_STEP,
    OP_ME_SET_TIME,
    OP_ME_NO_STATES,
    OP_ME_EVENT,
    OP_ME_ROUND_TRIP,
    OP_ME_NULL_COMPONENT,
    OP_COUNT
};

#define MAX_OPS 2000

static void run_op(input *in)
{
    uint8_t op = u8(in) % OP_COUNT;
    switch (op) {
    case OP_SETUP: op_setup(in); break;
#if FMI3
    case OP_ENTER: enter_initialization(); break;
#else
    case OP_ENTER: CHECKED(fmi2EnterInitializationMode(inst)); break;
#endif
    case OP_EXIT:
        if (CHECKED(x_exit_init(inst)) != S_ERROR)
            must_be_in(inst_me ? MODE_EVENT_ : MODE_STEP_, "leaving initialization mode");
        break;
    case OP_SET_REAL: op_set(in, K_REAL); break;
    case OP_SET_INTEGER: op_set(in, K_INTEGER); break;
    case OP_SET_BOOLEAN: op_set(in, K_BOOLEAN); break;
    case OP_GET: op_get(in); break;
    case OP_DO_STEP: op_do_step(in); break;
    case OP_SIMPLE_STEP: op_simple_step(in); break;
    case OP_GET_STATE: op_get_state(in); break;
    case OP_SET_STATE: op_set_state(in); break;
    case OP_FREE_STATE: op_free_state(in); break;
    case OP_SERIALIZE: op_serialize(in); break;
    case OP_DESERIALIZE_MUTATED: op_deserialize_mutated(in); break;
    case OP_DESERIALIZE_RAW: op_deserialize_raw(in); break;
    case OP_ROUND_TRIP: op_round_trip(in); break;
    case OP_TERMINATE:
        if (CHECKED(x_terminate(inst)) != S_ERROR) {
            must_be_in(MODE_TERMINATED_, "terminating");
            accepts_own_state("after terminating");
        }
        break;
    case OP_RESET: CHECKED(x_reset(inst)); break;
    case OP_DEBUG_LOGGING: op_debug_logging(in); break;
    case OP_MISC: op_misc(in); break;
    case OP_NULL_COMPONENT: op_null_component(in); break;
    case OP_FAIL_ALLOCATION: fail_countdown = u8(in) % 4 + 1; break;
    case OP_FORGE: op_forge(in); break;
    case OP_ME_ENTER_EVENT: me_enter_event_mode(); break;
    case OP_ME_NEW_DISCRETE_STATES: op_me_new_discrete_states(in); break;
    case OP_ME_ENTER_CONTINUOUS: me_enter_continuous(); break;
    case OP_ME_COMPLETED_INTEGRATOR_STEP: op_me_completed_integrator_step(in); break;
    case OP_ME_SET_TIME: me_set_time(pick_me_time(in)); break;
    case OP_ME_NO_STATES: op_me_no_states(in); break;
    case OP_ME_EVENT: op_me_event(in); break;
    case OP_ME_ROUND_TRIP: op_me_round_trip(in); break;
    case OP_ME_NULL_COMPONENT: op_me_null_component(in); break;
    }
}

/* ------------------------------------------------------------------- instantiation ---- */

#if FMI3
static void *fuzz_instantiate(input *in)
{
    uint8_t variant = u8(in) % 16, flags = u8(in);
    fmi3Boolean logging_on = flags & 1;
    inst_me = flags & 0x80;
    char token[128];
    snprintf(token, sizeof token, "%s", lgf_model.guid);
    const char *name = "fuzz", *token_arg = token;
    fmi3LogMessageCallback log = logger;
    switch (variant) {
    case 9:
        token[1 + u8(in) % (strlen(token) - 2)] ^= 1, log = NULL;
        break; /* nowhere to say why */
    case 10: token[1 + u8(in) % (strlen(token) - 2)] ^= 1; break;
    case 12: token_arg = NULL; break;
    case 13: name = ""; break;
    case 14: name = NULL; break;
    default: break;
    }
    if (variant >= 9) {
        TRACE("  instantiation, variant %u\n", variant);
        begin_call();
        fmi3Instance other;
        if (variant == 11)
            other = fmi3InstantiateScheduledExecution(name, token_arg, NULL, fmi3False, logging_on,
                                                      &environment_tag, log, NULL, NULL, NULL);
        else if (variant == 15) /* correct, without a logger */
            other = inst_me ? fmi3InstantiateModelExchange(name, token_arg, NULL, fmi3False,
                                                           logging_on, NULL, NULL)
                            : fmi3InstantiateCoSimulation(name, token_arg, NULL, fmi3False,
                                                          logging_on, fmi3False, fmi3False, NULL, 0,
                                                          NULL, NULL, NULL);
        else
            other = inst_me ? fmi3InstantiateModelExchange(name, token_arg, NULL, fmi3False,
                                                           logging_on, &environment_tag, log)
                            : fmi3InstantiateCoSimulation(name, token_arg, NULL, fmi3False,
                                                          logging_on, fmi3False, fmi3False, NULL, 0,
                                                          &environment_tag, log, NULL);
        injecting = false;
        if (variant == 15 && !other) fail("a correct instantiation without logMessage failed");
        if (variant != 15 && other) fail("instantiation variant %u was not refused", variant);
        if (!other && !problems_logged && log) fail("an instantiation refused without a log line");
        if (other) fmi3FreeInstance(other);
    }
    TRACE("  fmi3Instantiate%s\n", inst_me ? "ModelExchange" : "CoSimulation");
    void *c = inst_me ? fmi3InstantiateModelExchange("fuzz", lgf_model.guid, NULL, fmi3False,
                                                     logging_on, &environment_tag, logger)
                      : fmi3InstantiateCoSimulation("fuzz", lgf_model.guid, NULL, fmi3False,
                                                    logging_on, fmi3False, fmi3False, NULL, 0,
                                                    &environment_tag, logger, NULL);
    if (!c) fail("a correct instantiation failed");
    memset(&experiment, 0, sizeof experiment);
    return c;
}
#else
static void *fuzz_instantiate(input *in)
{
    uint8_t variant = u8(in) % 16, flags = u8(in);
    fmi2Boolean logging_on = flags & 1;
    inst_me = flags & 0x80;
    fmi2Type inst_type = inst_me ? fmi2ModelExchange : fmi2CoSimulation;
    char guid[128];
    snprintf(guid, sizeof guid, "%s", lgf_model.guid);
    fmi2CallbackFunctions functions = callbacks;
    const char *name = "fuzz", *guid_arg = guid;
    fmi2Type type = inst_type;
    switch (variant) {
    case 10: guid[1 + u8(in) % (strlen(guid) - 2)] ^= 1; break;
    case 11: type = (fmi2Type)(u8(in) & 1 ? 2 : -1); break; /* neither interface */
    case 12: guid_arg = NULL; break;
    case 13: name = ""; break;
    case 9: functions.logger = NULL; break; /* refused, and nowhere to say why */
    case 14: functions.allocateMemory = NULL; break;
    case 15: fail_countdown = u8(in) % 4 + 1; break;
    default: break;
    }
    if (variant >= 9) {
        TRACE("  fmi2Instantiate, variant %u (must be refused)\n", variant);
        begin_call();
        fmi2Component refused = fmi2Instantiate(name, type, guid_arg, "file:///nowhere", &functions,
                                                fmi2False, logging_on);
        injecting = false;
        if (variant != 15 && refused) fail("fmi2Instantiate variant %u was not refused", variant);
        if (!refused && !problems_logged && functions.logger)
            fail("fmi2Instantiate refused without a log line");
        if (refused) fmi2FreeInstance(refused); /* the failure hit a later allocation */
        fail_countdown = 0;
    }
    TRACE("  fmi2Instantiate(%s)\n", inst_me ? "fmi2ModelExchange" : "fmi2CoSimulation");
    fmi2Component c =
        fmi2Instantiate("fuzz", inst_type, lgf_model.guid, NULL, &callbacks, fmi2False, logging_on);
    if (!c) fail("a correct fmi2Instantiate failed");
    return c;
}
#endif

/* The entry point of this version (fuzz_main.c calls it; alone, it is libFuzzer's). */
int LGF_FUZZ_ENTRY(const uint8_t *data, size_t size);

int LGF_FUZZ_ENTRY(const uint8_t *data, size_t size)
{
    static bool started;
    if (!started) {
        started = true;
        const char *env = getenv("LGF_FUZZ_TRACE");
        trace = env && *env && strcmp(env, "0");
        env = getenv("LGF_FUZZ_SKIP_KNOWN");
        skip_known = env && *env && strcmp(env, "0");
        learn_variables();
    }
    input in = {data, size};
    calls_asked = 0;
    fail_countdown = 0;
    serialized_size = 0;
    inst = fuzz_instantiate(&in);
    for (int ops = 0; in.n > 0 && ops < MAX_OPS; ops++) run_op(&in);
    fail_countdown = 0;
    for (int i = 0; i < SLOTS; i++)
        if (x_free_state(inst, &slots[i]) != S_OK || slots[i])
            fail("freeing the state of a slot failed");
#if FMI3
    fmi3FreeInstance(inst);
#else
    fmi2FreeInstance(inst);
#endif
    inst = NULL;
    return 0;
}
