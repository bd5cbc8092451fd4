/* libFuzzer target: the input bytes drive one instance of one LGF FMU, co-simulation or Model
 * Exchange, through a sequence of FMI 2.0 calls of both interfaces, right and wrong, and the
 * target checks what docs/behaviour.md §1.7 promises. It links the FMU's sources directly
 * (the shared layer of src/fmi2/, one block and its binding), so it is built once per block:
 * fuzz_LGF_SawTooth, fuzz_LGF_RampCI, ...
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
 *     own state, serialized;
 *   - a serialize / deserialize / fmi2SetFMUstate round trip does not reproduce the next
 *     step: the same inputs and doStep from the restored state must give the same status,
 *     the same outputs and the same state bytes;
 *   - deserialized bytes that were accepted do not serialize back to the same bytes;
 *   - the logger gets a format other than "%s", a NULL or empty message, an unknown category,
 *     or another componentEnvironment;
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
 *            followed by a correct one.
 *   byte 1   loggingOn (bit 0); the interface (bit 7: 1 Model Exchange, 0 co-simulation)
 *   then     operations: one byte (modulo OP_COUNT) and the operation's arguments; see the
 *            op_* functions. tests/fuzz/make_seeds.py writes seeds in this format.
 * Set LGF_FUZZ_TRACE=1 to print the calls and the FMU's log while replaying an input.
 * LGF_FUZZ_SKIP_KNOWN=1 reports a violation of an invariant that a known, not yet fixed bug
 * of the FMU breaks (tests/fuzz/README.md, "Open findings") instead of aborting, so that a run
 * can look for other problems; without it every violation aborts. */
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
    fprintf(stderr, "\nFUZZ INVARIANT VIOLATED (%s): ", lgf_model.identifier);
    vfprintf(stderr, fmt, args);
    fprintf(stderr, "\n");
    va_end(args);
    abort();
}

/* A violation that a known, not yet fixed bug of the FMU causes (tests/fuzz/README.md): it
 * aborts like any other, unless LGF_FUZZ_SKIP_KNOWN is set; then it is reported once. */
static bool skip_known;

static bool known_bug(const char *name, const char *what)
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

#define TRACE(...)                                                                             \
    do {                                                                                       \
        if (trace) fprintf(stderr, __VA_ARGS__);                                               \
    } while (0)

static const char *status_name(fmi2Status s)
{
    switch (s) {
    case fmi2OK: return "fmi2OK";
    case fmi2Warning: return "fmi2Warning";
    case fmi2Discard: return "fmi2Discard";
    case fmi2Error: return "fmi2Error";
    case fmi2Fatal: return "fmi2Fatal";
    case fmi2Pending: return "fmi2Pending";
    }
    return "(not an fmi2Status)";
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
    static const double values[] = {
        0.0, -0.0, 1.0, -1.0, 0.5, 0.1, 0.01, 0.001, 0.0015, 0.0009999, 1e-6, 1.4e-6, 1.6e-6,
        0.9e-6, 60.0, 60.000001, 61.0, 2147483.647, 2147483.6474, 2147483.6476, 2147483.648,
        -2147483.647, -2147483.648, -2147483.6486, 32767.0, 32767.5, 32768.0, -32768.0,
        -32768.5, -32769.0, 65535.0, 65536.0, 1e300, -1e300, DBL_MAX, -DBL_MAX, DBL_MIN,
        4.9e-324, 1e15, 9e15, 1e9, 5.0, 10.0, 100.0, 1e-9, 0.3, 0.25, 0.2, 2.0, 3.0, 4.0,
        63.0, 64.0, 65.0, 1e20, -1e-300, 0.1 + 1e-17, 4503599627370496.0};
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
    static const int32_t values[] = {0,     1,      -1,    2,      3,         4,         5,
                                     10,    63,     64,    65,     100,       1000,      32767,
                                     32768, -32768, -32769, 65535, 65536, INT32_MAX, INT32_MIN};
    uint8_t tag = u8(in);
    if (tag < 0x40) return values[tag % (sizeof values / sizeof values[0])];
    if (tag < 0x80) return (int16_t)u16(in);
    return (int32_t)u32(in);
}

/* -------------------------------------------------------------- the block's variables ---- */

typedef enum { K_REAL, K_INTEGER, K_BOOLEAN } kind;

#define MAX_VARS 1024

typedef struct {
    uint32_t vr;
    const model_variable *var;
} known_var;

static known_var known[MAX_VARS];
static size_t known_count;
static uint32_t kind_vrs[3][MAX_VARS], output_vrs[3][MAX_VARS];
static size_t kind_count[3], output_count[3];
static uint32_t cycle_vr;

static kind fuzz_kind_of(var_type type)
{
    return type == VAR_BOOL ? K_BOOLEAN : type == VAR_INT || type == VAR_WORD ? K_INTEGER : K_REAL;
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
 * variable or array, or any number. */
static uint32_t pick_vr(input *in, kind k)
{
    uint8_t tag = u8(in);
    if (tag < 0x80 && kind_count[k]) return kind_vrs[k][u8(in) % kind_count[k]];
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

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    if (env != &environment_tag) fail("the logger got another componentEnvironment");
    if (!name || !category || !message) fail("the logger got a NULL instanceName, category or message");
    if (strcmp(category, "logAll") && strcmp(category, "logStatusWarning") &&
        strcmp(category, "logStatusDiscard") && strcmp(category, "logStatusError"))
        fail("the logger got the unknown category \"%s\"", category);
    /* The FMU never passes its text as a format (instance.h): the format is always "%s". */
    if (strcmp(message, "%s")) fail("the logger got the format \"%s\" instead of \"%%s\"", message);
    va_list args;
    va_start(args, message);
    const char *text = va_arg(args, const char *);
    va_end(args);
    if (!text) fail("the logger got a NULL message for \"%%s\"");
    size_t length = strlen(text);
    if (length == 0) fail("the logger got an empty message");
    if (status != fmi2OK) problems_logged++;
    if (status == fmi2Error || status == fmi2Fatal) errors_logged++;
    TRACE("    [%s %s] %s: %s\n", status_name(status), category, name, text);
}

/* Allocation failures are injected only into the calls under test, never into the target's
 * own bookkeeping calls. */
static bool injecting;
static int fail_countdown; /* > 0: that allocation (1 = the next one) returns NULL */

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

/* ------------------------------------------------------------- checking one call ---- */

static fmi2Component inst;
static fmi2Type inst_type; /* the interface of inst */

static void begin_call(void)
{
    problems_logged = errors_logged = 0;
    injecting = true;
}

static fmi2Status end_call(const char *function, fmi2Status s, bool on_instance)
{
    injecting = false;
    TRACE("  %s -> %s\n", function, status_name(s));
    if (s != fmi2OK && s != fmi2Warning && s != fmi2Discard && s != fmi2Error)
        fail("%s returned %s (%d)", function, status_name(s), (int)s);
    if (!on_instance) return s;
    if (s != fmi2OK && problems_logged == 0)
        fail("%s returned %s without logging why", function, status_name(s));
    if (s != fmi2Error && errors_logged)
        fail("%s logged an error but returned %s", function, status_name(s));
    return s;
}

/* The whole observable state of the instance: its FMU state serialized (every input,
 * parameter, output and static, and the clock), its time, and the outputs read back with
 * fmi2Get* (or the status of the refused fmi2Get*). */
#define MAX_SERIALIZED 65536

typedef struct {
    size_t size;
    unsigned char bytes[MAX_SERIALIZED];
    fmi2Status get_status[3];
    fmi2Real reals[MAX_VARS];
    fmi2Integer integers[MAX_VARS];
    fmi2Boolean booleans[MAX_VARS];
    fmi2Status time_status;
    fmi2Real time;
} snapshot;

static snapshot snap_before, snap_after, snap_round[3];

/* The target's own calls: they must succeed, and they are not under test here. */
static void serialize_now(unsigned char *bytes, size_t *size)
{
    fmi2FMUstate state = NULL;
    if (fmi2GetFMUstate(inst, &state) != fmi2OK) fail("fmi2GetFMUstate failed");
    if (fmi2SerializedFMUstateSize(inst, state, size) != fmi2OK)
        fail("fmi2SerializedFMUstateSize failed");
    if (*size > MAX_SERIALIZED) fail("serialized state of %zu bytes", *size);
    if (fmi2SerializeFMUstate(inst, state, (fmi2Byte *)bytes, *size) != fmi2OK)
        fail("fmi2SerializeFMUstate failed");
    if (fmi2FreeFMUstate(inst, &state) != fmi2OK || state) fail("fmi2FreeFMUstate failed");
}

static void take(snapshot *s)
{
    bool was_tracing = trace;
    trace = false;
    memset(s, 0, sizeof *s);
    serialize_now(s->bytes, &s->size);
    s->get_status[K_REAL] = fmi2GetReal(inst, output_vrs[K_REAL], output_count[K_REAL], s->reals);
    s->get_status[K_INTEGER] =
        fmi2GetInteger(inst, output_vrs[K_INTEGER], output_count[K_INTEGER], s->integers);
    s->get_status[K_BOOLEAN] =
        fmi2GetBoolean(inst, output_vrs[K_BOOLEAN], output_count[K_BOOLEAN], s->booleans);
    s->time_status = fmi2GetRealStatus(inst, fmi2LastSuccessfulTime, &s->time);
    trace = was_tracing;
}

static void must_equal(const snapshot *a, const snapshot *b, const char *what)
{
    if (a->size != b->size || memcmp(a->bytes, b->bytes, a->size))
        fail("%s: the FMU state bytes differ", what);
    for (int k = 0; k < 3; k++)
        if (a->get_status[k] != b->get_status[k]) fail("%s: an fmi2Get* status differs", what);
    for (size_t i = 0; i < output_count[K_REAL]; i++)
        if (memcmp(&a->reals[i], &b->reals[i], sizeof a->reals[i]))
            fail("%s: output vr %u differs: %.17g vs %.17g", what,
                 (unsigned)output_vrs[K_REAL][i], a->reals[i], b->reals[i]);
    for (size_t i = 0; i < output_count[K_INTEGER]; i++)
        if (a->integers[i] != b->integers[i])
            fail("%s: output vr %u differs: %d vs %d", what, (unsigned)output_vrs[K_INTEGER][i],
                 a->integers[i], b->integers[i]);
    for (size_t i = 0; i < output_count[K_BOOLEAN]; i++)
        if (a->booleans[i] != b->booleans[i])
            fail("%s: output vr %u differs", what, (unsigned)output_vrs[K_BOOLEAN][i]);
    if (a->time_status != b->time_status || memcmp(&a->time, &b->time, sizeof a->time))
        fail("%s: the time (fmi2LastSuccessfulTime) differs", what);
}

/* A call that changes the instance only when it succeeds: CHECKED(call) compares the
 * instance before and after a call that returned fmi2Error. READ_ONLY(call) compares it
 * after any call that must never change it. */
static void before_call(void)
{
    take(&snap_before);
    begin_call();
}

static fmi2Status after_checked(const char *function, fmi2Status s)
{
    end_call(function, s, inst != NULL);
    if (s == fmi2Error) {
        take(&snap_after);
        must_equal(&snap_before, &snap_after, function);
    }
    return s;
}

static fmi2Status after_read_only(const char *function, fmi2Status s)
{
    end_call(function, s, inst != NULL);
    take(&snap_after);
    must_equal(&snap_before, &snap_after, function);
    return s;
}

#define CHECKED(call) after_checked(#call, (before_call(), (call)))
#define READ_ONLY(call) after_read_only(#call, (before_call(), (call)))

/* ------------------------------------------------------------------- time and steps ---- */

/* The FMU's time, where it tells it (step mode and terminated), else 0. */
static double now(void)
{
    fmi2Real t = 0;
    bool was_tracing = trace;
    trace = false;
    if (fmi2GetRealStatus(inst, fmi2LastSuccessfulTime, &t) != fmi2OK) t = 0;
    trace = was_tracing;
    return t;
}

static double cycle_time(void)
{
    fmi2Real cycle = 0.1;
    bool was_tracing = trace;
    trace = false;
    if (fmi2GetReal(inst, &cycle_vr, 1, &cycle) != fmi2OK || !(cycle > 0)) cycle = 0.1;
    trace = was_tracing;
    return cycle;
}

/* PLC calls the doSteps of one input may ask for; past it, steps are one cycle at most. */
#define CALL_BUDGET 300000.0
static double calls_asked;

/* The FMU's grid tolerance (lifecycle.c): points this close to a call time count as on it. */
static double tolerance_near(double t)
{
    return 1e-9 * cycle_time() + 8 * DBL_EPSILON * fabs(t);
}

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

/* The clock at the start of a serialized payload (walk() in src/core/state.c): mode and
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

/* The FMU's grid tolerance (grid_tolerance in src/core/clock.c). */
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
    return (double)(c->calls - 1) - floor((c->time - c->start + grid_tolerance_of(c, c->time)) / cycle);
}

/* The FMU refused bytes it serialized itself. A Model Exchange clock that fmi2SetTime moved
 * away from the calls done further than the FMU's check of a restored clock allows (in event
 * and continuous-time mode one call may be due, when terminated none) is the known bug "ME
 * clock after fmi2SetTime" (README); anything else fails. */
static void own_state_refused(const char *when, const unsigned char *bytes, size_t size)
{
    clock_view c = clock_in(bytes, size);
    double ahead = calls_ahead(&c);
    bool exchange = c.mode == 3 || c.mode == 4;
    if (inst_type == fmi2ModelExchange && (exchange || c.mode == 5) &&
        (ahead < (exchange ? -1 : 0) || ahead > 1)) {
        char what[256];
        snprintf(what, sizeof what,
                 "%s: the FMU refused its own serialized state (Model Exchange, t = %.17g, %lld "
                 "calls done, %+.0f against the calls due)",
                 when, c.time, (long long)c.calls, ahead);
        known_bug("ME clock after fmi2SetTime", what);
        return;
    }
    fail("%s: the FMU refused its own serialized state", when);
}

/* Whatever state the FMU reached through its API, it takes back serialized. */
static void accepts_own_state(const char *when)
{
    static unsigned char bytes[MAX_SERIALIZED];
    size_t size;
    fmi2FMUstate state = NULL;
    serialize_now(bytes, &size);
    bool was_tracing = trace;
    trace = false;
    if (fmi2DeSerializeFMUstate(inst, (const fmi2Byte *)bytes, size, &state) != fmi2OK)
        own_state_refused(when, bytes, size);
    trace = was_tracing;
    if (fmi2FreeFMUstate(inst, &state) != fmi2OK) fail("fmi2FreeFMUstate failed");
}

static fmi2Status do_step(double t, double h, fmi2Boolean no_set_prior)
{
    TRACE("  doStep(t = %.17g, h = %.17g)\n", t, h);
    double before = now();
    fmi2Status s = CHECKED(fmi2DoStep(inst, t, h, no_set_prior));
    if (s != fmi2Error) {
        /* t + h, unless a step from just before the FMU's time ends before it: the FMU's time
         * never goes back */
        double expected = t + h > before ? t + h : before, got = 0;
        if (fmi2GetRealStatus(inst, fmi2LastSuccessfulTime, &got) != fmi2OK)
            fail("fmi2GetRealStatus(fmi2LastSuccessfulTime) failed after fmi2DoStep");
        if (memcmp(&expected, &got, sizeof got))
            fail("after fmi2DoStep(%.17g, %.17g) the time is %.17g", t, h, got);
        accepts_own_state("after fmi2DoStep");
    }
    return s;
}

/* ------------------------------------------------------------------------ setting ---- */

#define MAX_SET 4

typedef struct {
    kind k;
    size_t n;
    bool null_arrays;
    fmi2ValueReference vr[MAX_SET];
    fmi2Real reals[MAX_SET];
    fmi2Integer integers[MAX_SET];
    fmi2Boolean booleans[MAX_SET];
} set_request;

static void read_set(input *in, kind k, set_request *r)
{
    memset(r, 0, sizeof *r);
    uint8_t n = u8(in);
    r->k = k;
    r->n = n % (MAX_SET + 1);
    r->null_arrays = (n & 0x80) && r->n > 0;
    for (size_t i = 0; i < r->n; i++) {
        r->vr[i] = pick_vr(in, k);
        if (k == K_REAL) r->reals[i] = any_real(in);
        else if (k == K_INTEGER) r->integers[i] = any_int(in);
        else r->booleans[i] = u8(in) < 0xE0 ? (fmi2Boolean)(u8(in) & 1) : any_int(in);
    }
}

static fmi2Status apply_set(const set_request *r)
{
    if (trace)
        for (size_t i = 0; i < r->n; i++)
            fprintf(stderr, "  set vr %u = %.17g\n", (unsigned)r->vr[i],
                    r->k == K_REAL ? r->reals[i]
                    : r->k == K_INTEGER ? (double)r->integers[i] : (double)r->booleans[i]);
    const fmi2ValueReference *vr = r->null_arrays ? NULL : r->vr;
    switch (r->k) {
    case K_REAL: return CHECKED(fmi2SetReal(inst, vr, r->n, r->null_arrays ? NULL : r->reals));
    case K_INTEGER:
        return CHECKED(fmi2SetInteger(inst, vr, r->n, r->null_arrays ? NULL : r->integers));
    default: return CHECKED(fmi2SetBoolean(inst, vr, r->n, r->null_arrays ? NULL : r->booleans));
    }
}

/* An accepted value reads back as set, within the rounding docs/behaviour.md §1.1/§1.4 allows. */
static void check_read_back(const set_request *r)
{
    for (size_t i = 0; i < r->n; i++) {
        bool last = true; /* only the last of repeated value references counts */
        for (size_t j = i + 1; j < r->n; j++) last &= r->vr[j] != r->vr[i];
        if (!last) continue;
        const model_variable *v = variable_of(r->vr[i]);
        if (!v) fail("a set with unknown value reference %u was accepted", (unsigned)r->vr[i]);
        if (v->role == ROLE_OUTPUT) fail("a set of the output %s was accepted", v->name);
        fmi2Status s;
        if (r->k == K_REAL) {
            fmi2Real got;
            s = fmi2GetReal(inst, &r->vr[i], 1, &got);
            double set = r->reals[i], tolerance = 0;
            if (v->type == VAR_REAL) set = (float)set; /* stored as the nearest float32 */
            if (v->type == VAR_TIME) tolerance = 0.0005 + 1e-12 * fabs(set);
            if (v->type == VAR_CYCLE) tolerance = 0.5e-6 + 1e-12 * fabs(set);
            if (s == fmi2OK && (isnan(set) || !(got == set || fabs(got - set) <= tolerance)))
                fail("%s was set to %.17g and reads back as %.17g", v->name, set, got);
            if (s == fmi2OK && (v->type == VAR_LREAL || v->type == VAR_REAL) &&
                memcmp(&got, &set, sizeof got))
                fail("%s was set to %.17g and reads back as %.17g (bits)", v->name, set, got);
        } else if (r->k == K_INTEGER) {
            fmi2Integer got;
            s = fmi2GetInteger(inst, &r->vr[i], 1, &got);
            if (s == fmi2OK && got != r->integers[i])
                fail("%s was set to %d and reads back as %d", v->name, r->integers[i], got);
        } else {
            fmi2Boolean got;
            s = fmi2GetBoolean(inst, &r->vr[i], 1, &got);
            if (s == fmi2OK && got != (r->booleans[i] != fmi2False ? fmi2True : fmi2False))
                fail("%s was set to %d and reads back as %d", v->name, r->booleans[i], got);
        }
    }
}

/* ----------------------------------------------------------------------- FMU states ---- */

#define SLOTS 3
static fmi2FMUstate slots[SLOTS];
static _Alignas(16) unsigned char foreign[256]; /* not a state of this FMU */
static unsigned char serialized[MAX_SERIALIZED];
static size_t serialized_size;

/* 0..2: a slot; 3: NULL; otherwise memory that is not an FMU state. */
static fmi2FMUstate pick_state(input *in)
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

/* The serialized format of src/fmi2/fmu_state.c: a STATE_HEADER_SIZE-byte header, the FNV-1a
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
    if (fix_checksum) fuzz_put_le(bytes + 88, fuzz_fnv1a(bytes + HEADER_SIZE, size - HEADER_SIZE), 8);
}

/* Deserializes into the given slot (or NULL, or foreign memory); accepted bytes must
 * serialize back to the same bytes. Returns the slot that holds the state, or -1. */
static int deserialize(const unsigned char *bytes, size_t size, input *in)
{
    uint8_t tag = u8(in);
    fmi2FMUstate *target, none = NULL, alien = foreign;
    target = tag % 8 < SLOTS ? &slots[tag % 8] : tag % 8 == 3 ? &alien : &none;
    fmi2FMUstate before = *target;
    const fmi2Byte *from = tag & 0x80 ? NULL : (const fmi2Byte *)bytes;
    fmi2Status s = READ_ONLY(fmi2DeSerializeFMUstate(inst, from, size, (tag & 0x40) ? NULL : target));
    if (s == fmi2Error) {
        if (*target != before) fail("a refused fmi2DeSerializeFMUstate changed *FMUstate");
        return -1;
    }
    static unsigned char again[MAX_SERIALIZED];
    size_t again_size = 0;
    if (fmi2SerializedFMUstateSize(inst, *target, &again_size) != fmi2OK || again_size != size ||
        fmi2SerializeFMUstate(inst, *target, (fmi2Byte *)again, again_size) != fmi2OK ||
        memcmp(again, bytes, size))
        fail("accepted serialized bytes do not serialize back to the same bytes");
    if (target == &none) {
        if (fmi2FreeFMUstate(inst, &none) != fmi2OK) fail("fmi2FreeFMUstate failed");
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

static void op_setup(input *in)
{
    uint8_t flags = u8(in);
    double tolerance = any_real(in), start = bounded_time(any_real(in)), stop = any_real(in);
    TRACE("  setupExperiment(start = %.17g, stop = %.17g)\n", start, stop);
    CHECKED(fmi2SetupExperiment(inst, flags & 1, tolerance, start, (flags >> 1) & 1, stop));
}

static void op_set(input *in, kind k)
{
    set_request r;
    read_set(in, k, &r);
    fmi2Status s = apply_set(&r);
    if (s != fmi2Error) check_read_back(&r);
}

static void op_get(input *in)
{
    kind k = (kind)(u8(in) % 3);
    uint8_t n = u8(in);
    size_t count = n % (MAX_SET + 1);
    bool null_arrays = (n & 0x80) && count > 0;
    fmi2ValueReference vr[MAX_SET];
    for (size_t i = 0; i < count; i++) vr[i] = pick_vr(in, k);
    fmi2Real reals[MAX_SET];
    fmi2Integer integers[MAX_SET];
    fmi2Boolean booleans[MAX_SET];
    const fmi2ValueReference *v = null_arrays && (n & 0x40) ? NULL : vr;
    if (k == K_REAL) READ_ONLY(fmi2GetReal(inst, v, count, null_arrays ? NULL : reals));
    else if (k == K_INTEGER)
        READ_ONLY(fmi2GetInteger(inst, v, count, null_arrays ? NULL : integers));
    else READ_ONLY(fmi2GetBoolean(inst, v, count, null_arrays ? NULL : booleans));
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
    do_step(now(), h, fmi2False);
}

static void op_get_state(input *in)
{
    uint8_t tag = u8(in);
    fmi2FMUstate *slot = &slots[tag % SLOTS];
    if (tag & 0x80) {
        READ_ONLY(fmi2GetFMUstate(inst, NULL));
        return;
    }
    if (tag & 0x40) {
        fmi2FMUstate alien = pick_state(in);
        if (alien == foreign) READ_ONLY(fmi2GetFMUstate(inst, &alien));
        return;
    }
    fmi2FMUstate before = *slot;
    fmi2Status s = READ_ONLY(fmi2GetFMUstate(inst, slot));
    if (s == fmi2OK && before && *slot != before)
        fail("fmi2GetFMUstate with an existing state returned another state");
    if (s == fmi2Error && *slot != before) fail("a refused fmi2GetFMUstate changed *FMUstate");
}

static void op_set_state(input *in)
{
    fmi2FMUstate state = pick_state(in);
    CHECKED(fmi2SetFMUstate(inst, state));
}

static void op_free_state(input *in)
{
    uint8_t tag = u8(in);
    if (tag & 0x80) {
        READ_ONLY(fmi2FreeFMUstate(inst, NULL));
    } else if (tag & 0x40) {
        fmi2FMUstate alien = pick_state(in);
        if (alien == foreign) READ_ONLY(fmi2FreeFMUstate(inst, &alien));
    } else {
        fmi2FMUstate *slot = &slots[tag % SLOTS];
        fmi2Status s = READ_ONLY(fmi2FreeFMUstate(inst, slot));
        if (s != fmi2Error && *slot) fail("fmi2FreeFMUstate left *FMUstate set");
    }
}

static void op_serialize(input *in)
{
    fmi2FMUstate state = pick_state(in);
    uint8_t tag = u8(in);
    size_t size = 0;
    fmi2Status s = READ_ONLY(fmi2SerializedFMUstateSize(inst, state, tag & 0x80 ? NULL : &size));
    if (s == fmi2Error) return;
    if (size < HEADER_SIZE || size > MAX_SERIALIZED) fail("serialized size %zu", size);
    size_t offered = tag & 0x40 ? size - 1 - tag % 8 : size + tag % 4;
    if (offered > MAX_SERIALIZED) offered = MAX_SERIALIZED;
    s = READ_ONLY(fmi2SerializeFMUstate(inst, state, tag & 0x20 ? NULL : (fmi2Byte *)serialized,
                                        offered));
    if (s != fmi2Error) serialized_size = size;
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
                if (how & 0x40) memcpy(&value, &(double){any_real(in)}, 8);
                else value = how & 0x80 ? (uint64_t)(int64_t)any_int(in) : u64(in);
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
    static const int64_t integers[] = {0, 1, -1, 2, 3, 255, 256, 32767, -32768, 65535,
                                       INT32_MAX, INT32_MIN, INT64_MAX, INT64_MIN,
                                       INT64_C(1) << 62, INT64_C(1) << 56, INT64_C(9000000000000000),
                                       INT64_C(100000), INT64_C(60000000), -(INT64_C(1) << 40)};
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
        case 0: at = 0, width = 4; break; /* the clock's fields (fmi2/instance.h) */
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
            value = how & 0x10 ? (int64_t)u64(in) : integers[how % (sizeof integers / sizeof integers[0])];
        }
        memcpy(bytes + HEADER_SIZE + at, &value, width); /* little endian: the low bytes */
    }
    fix_header(bytes, size, false, true);
    uint8_t then = u8(in);
    int slot = deserialize(bytes, size, in);
    if (slot >= 0 && (then & 1)) CHECKED(fmi2SetFMUstate(inst, slots[slot]));
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
        for (size_t i = 0; i < length && HEADER_SIZE + i < size; i++) bytes[HEADER_SIZE + i] = u8(in);
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

/* Serialize, deserialize and set back: the next step must come out the same, bit for bit,
 * whether it runs from the live state or the restored one. */
static void op_round_trip(input *in)
{
    set_request r;
    read_set(in, (kind)(u8(in) % 3), &r);
    double t = pick_t(in), h = pick_h(in);
    TRACE("  round trip: doStep(%.17g, %.17g) twice\n", t, h);
    bool was_tracing = trace;
    trace = false;
    fmi2FMUstate a = NULL, b = NULL;
    size_t size = 0;
    static unsigned char bytes[MAX_SERIALIZED];
    if (fmi2GetFMUstate(inst, &a) != fmi2OK || fmi2SerializedFMUstateSize(inst, a, &size) != fmi2OK ||
        size > MAX_SERIALIZED || fmi2SerializeFMUstate(inst, a, (fmi2Byte *)bytes, size) != fmi2OK)
        fail("round trip: the state could not be serialized");
    if (fmi2DeSerializeFMUstate(inst, (const fmi2Byte *)bytes, size, &b) != fmi2OK) {
        own_state_refused("round trip", bytes, size);
        fmi2FreeFMUstate(inst, &a);
        trace = was_tracing;
        return;
    }
    take(&snap_round[0]);
    fmi2Status set1 = apply_set(&r), step1 = fmi2DoStep(inst, t, h, fmi2False);
    take(&snap_round[1]);
    if (fmi2SetFMUstate(inst, b) != fmi2OK) fail("round trip: fmi2SetFMUstate refused");
    take(&snap_round[2]);
    must_equal(&snap_round[0], &snap_round[2], "round trip: the restored state");
    fmi2Status set2 = apply_set(&r), step2 = fmi2DoStep(inst, t, h, fmi2False);
    take(&snap_round[2]);
    if (set1 != set2 || step1 != step2)
        fail("round trip: the replay returned %s/%s instead of %s/%s", status_name(set2),
             status_name(step2), status_name(set1), status_name(step1));
    must_equal(&snap_round[1], &snap_round[2], "round trip: the step after the restore");
    if (fmi2FreeFMUstate(inst, &a) != fmi2OK || fmi2FreeFMUstate(inst, &b) != fmi2OK)
        fail("round trip: fmi2FreeFMUstate failed");
    trace = was_tracing;
}

static void op_debug_logging(input *in)
{
    static const char *const names[] = {"logAll", "logStatusWarning", "logStatusError",
                                        "logStatusDiscard", "logEvents", "", NULL};
    uint8_t tag = u8(in);
    size_t n = tag % 4;
    fmi2String categories[3];
    for (size_t i = 0; i < n && i < 3; i++) categories[i] = names[u8(in) % 7];
    READ_ONLY(fmi2SetDebugLogging(inst, (tag >> 2) & 1, n, tag & 0x80 ? NULL : categories));
}

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
        if (strcmp(fmi2GetVersion(), fmi2Version) || strcmp(fmi2GetTypesPlatform(), fmi2TypesPlatform))
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
    default: {
        fmi2FMUstate state = pick_state(in);
        READ_ONLY(fmi2SerializedFMUstateSize(inst, state, NULL));
        CHECKED(fmi2DeSerializeFMUstate(inst, NULL, 100, &state));
        break;
    }
    }
}

/* Every function with a NULL instance: fmi2Error (nothing to log to), never a crash. */
static void op_null_component(input *in)
{
    fmi2ValueReference vr = 0;
    fmi2Real r = 0;
    fmi2Integer i = 0;
    fmi2Boolean b = 0;
    fmi2FMUstate state = NULL;
    size_t size = 0;
    fmi2Byte byte = 0;
    fmi2Status s = fmi2OK;
    const char *function = "";
#define NULL_CASE(n, call)                                                                     \
    case n:                                                                                    \
        s = call;                                                                              \
        function = #call;                                                                      \
        break
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
        NULL_CASE(12, fmi2GetFMUstate(NULL, &state));
        NULL_CASE(13, fmi2SetFMUstate(NULL, state));
        NULL_CASE(14, fmi2FreeFMUstate(NULL, &state));
        NULL_CASE(15, fmi2SerializedFMUstateSize(NULL, state, &size));
        NULL_CASE(16, fmi2SerializeFMUstate(NULL, state, &byte, 1));
        NULL_CASE(17, fmi2DeSerializeFMUstate(NULL, &byte, 1, &state));
        NULL_CASE(18, fmi2SetDebugLogging(NULL, 1, 0, NULL));
        NULL_CASE(19, fmi2GetRealStatus(NULL, fmi2LastSuccessfulTime, &r));
        NULL_CASE(20, fmi2GetBooleanStatus(NULL, fmi2Terminated, &b));
        NULL_CASE(21, fmi2CancelStep(NULL));
        NULL_CASE(22, fmi2SetString(NULL, &vr, 1, NULL));
    default: fmi2FreeInstance(NULL); return;
    }
#undef NULL_CASE
    TRACE("  %s -> %s\n", function, status_name(s));
    if (s != fmi2Error) fail("%s returned %s", function, status_name(s));
    if (state) fail("%s with a NULL instance returned a state", function);
}

/* --------------------------------------------------------------- Model Exchange ---- */

#define MODE_STEP_ 2 /* fmu_mode (src/core/core.h) as the serialized clock holds it */
#define MODE_EVENT_ 3
#define MODE_CONTINUOUS_ 4
#define MODE_TERMINATED_ 5

/* After an accepted call that changes the mode: the mode FMI 2.0 names. */
static void must_be_in(int32_t mode, const char *after)
{
    clock_view c = clock_now();
    if (c.mode != mode) fail("after %s the FMU is in mode %d, not %d", after, (int)c.mode, (int)mode);
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
    case 6: t = c.stop_defined ? c.stop + (int8_t)u8(in) / 64.0 * grid_tolerance_of(&c, c.stop) : next; break;
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
    if (isfinite(t) && t > c.time + 1e4 * cycle && t < 1e19) t = c.time + fmod(t - c.time, 1e4 * cycle);
    if (isfinite(t) && t > c.time + cycle && t < 1e19 && calls_asked > CALL_BUDGET) t = next;
    if (isfinite(t) && t > c.time && t < 1e19) calls_asked += (t - c.time) / cycle + 1;
    return t;
}

static fmi2Status me_set_time(double t)
{
    TRACE("  setTime(%.17g)\n", t);
    fmi2Status s = CHECKED(fmi2SetTime(inst, t));
    if (s != fmi2Error) {
        clock_view c = clock_now();
        if (memcmp(&c.time, &t, sizeof t))
            fail("after fmi2SetTime(%.17g) the FMU's time is %.17g", t, c.time);
        accepts_own_state("after fmi2SetTime");
    }
    return s;
}

static fmi2Status me_enter_event_mode(void)
{
    fmi2Status s = CHECKED(fmi2EnterEventMode(inst));
    if (s != fmi2Error) must_be_in(MODE_EVENT_, "fmi2EnterEventMode");
    return s;
}

static fmi2Status me_enter_continuous(void)
{
    fmi2Status s = CHECKED(fmi2EnterContinuousTimeMode(inst));
    if (s != fmi2Error) must_be_in(MODE_CONTINUOUS_, "fmi2EnterContinuousTimeMode");
    return s;
}

static bool same_event_info(const fmi2EventInfo *a, const fmi2EventInfo *b)
{
    return a->newDiscreteStatesNeeded == b->newDiscreteStatesNeeded &&
           a->terminateSimulation == b->terminateSimulation &&
           a->nominalsOfContinuousStatesChanged == b->nominalsOfContinuousStatesChanged &&
           a->valuesOfContinuousStatesChanged == b->valuesOfContinuousStatesChanged &&
           a->nextEventTimeDefined == b->nextEventTimeDefined &&
           !memcmp(&a->nextEventTime, &b->nextEventTime, sizeof a->nextEventTime);
}

/* An event iteration, and its invariants; info gets the eventInfo (zeros if refused). */
static fmi2Status me_new_discrete_states(bool second, fmi2EventInfo *info)
{
    memset(info, 0xA5, sizeof *info);
    fmi2Status s = CHECKED(fmi2NewDiscreteStates(inst, info));
    if (s == fmi2Error) {
        memset(info, 0, sizeof *info);
        return s;
    }
    clock_view c = clock_now();
    double next = next_call_time(&c);
    if (info->newDiscreteStatesNeeded != fmi2False || info->terminateSimulation != fmi2False ||
        info->nominalsOfContinuousStatesChanged != fmi2False ||
        info->valuesOfContinuousStatesChanged != fmi2False || info->nextEventTimeDefined != fmi2True)
        fail("fmi2NewDiscreteStates: eventInfo {%d, %d, %d, %d, %d}, expected {0, 0, 0, 0, 1}",
             info->newDiscreteStatesNeeded, info->terminateSimulation,
             info->nominalsOfContinuousStatesChanged, info->valuesOfContinuousStatesChanged,
             info->nextEventTimeDefined);
    if (memcmp(&info->nextEventTime, &next, sizeof next))
        fail("fmi2NewDiscreteStates: nextEventTime %.17g, but the next call (%lld) is at %.17g",
             info->nextEventTime, (long long)c.calls, next);
    if (!(info->nextEventTime > c.time) || calls_ahead(&c) < 0)
        fail("fmi2NewDiscreteStates at t = %.17g left a call due (nextEventTime %.17g)", c.time,
             info->nextEventTime);
    accepts_own_state("after fmi2NewDiscreteStates");
    if (second) { /* at the same instant: nothing is due any more */
        fmi2EventInfo again;
        memset(&again, 0x5A, sizeof again);
        if (READ_ONLY(fmi2NewDiscreteStates(inst, &again)) != fmi2OK)
            fail("a second fmi2NewDiscreteStates was refused");
        if (!same_event_info(&again, info)) fail("a second fmi2NewDiscreteStates: another eventInfo");
    }
    return s;
}

static void op_me_new_discrete_states(input *in)
{
    uint8_t tag = u8(in);
    fmi2EventInfo info;
    if (tag & 1) CHECKED(fmi2NewDiscreteStates(inst, NULL));
    else me_new_discrete_states(tag & 2, &info);
}

static void op_me_completed_integrator_step(input *in)
{
    uint8_t tag = u8(in);
    fmi2Boolean enter = 7, terminate = 7;
    fmi2Status s = READ_ONLY(fmi2CompletedIntegratorStep(inst, (tag >> 2) & 1, tag & 1 ? NULL : &enter,
                                                         tag & 2 ? NULL : &terminate));
    if (s != fmi2Error && (enter != fmi2False || terminate != fmi2False))
        fail("fmi2CompletedIntegratorStep: enterEventMode %d, terminateSimulation %d", enter, terminate);
    if (s == fmi2Error && (enter != 7 || terminate != 7))
        fail("a refused fmi2CompletedIntegratorStep wrote its out-pointers");
}

/* The functions of continuous states and event indicators, with any count and NULL arrays. */
static void op_me_no_states(input *in)
{
    uint8_t tag = u8(in);
    static const size_t counts[] = {0, 1, 2, 0, SIZE_MAX};
    size_t n = counts[(tag >> 3) % 5];
    if ((tag >> 3) % 5 == 3) n = u32(in);
    fmi2Real x[4] = {-7.25, -7.25, -7.25, -7.25};
    fmi2Real *array = tag & 0x80 ? NULL : x;
    fmi2Status s;
    switch (tag % 5) {
    case 0: s = CHECKED(fmi2SetContinuousStates(inst, array, n)); break;
    case 1: s = READ_ONLY(fmi2GetDerivatives(inst, array, n)); break;
    case 2: s = READ_ONLY(fmi2GetEventIndicators(inst, array, n)); break;
    case 3: s = READ_ONLY(fmi2GetContinuousStates(inst, array, n)); break;
    default: s = READ_ONLY(fmi2GetNominalsOfContinuousStates(inst, array, n)); break;
    }
    if (s != fmi2Error && n != 0) fail("a function of continuous states accepted n = %zu", n);
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
        if (me_set_time(mid) != fmi2Error) op_me_completed_integrator_step(in);
    } else if ((how & 3) == 3) {
        t += cycle * (u8(in) % 3); /* passes call times without stopping */
        calls_asked += 3;
    }
    me_set_time(t);
    if (clock_now().mode != MODE_EVENT_) me_enter_event_mode();
    if (how & 4) op_set(in, (kind)(u8(in) % 3));
    fmi2EventInfo info;
    me_new_discrete_states(how & 8, &info);
    if (!(how & 0x10)) me_enter_continuous();
}

/* Serialize, deserialize and set back: the same event iteration from the restored state must
 * give the same statuses, eventInfo and instance, bit for bit. */
static void op_me_round_trip(input *in)
{
    set_request r;
    read_set(in, (kind)(u8(in) % 3), &r);
    double t = pick_me_time(in);
    TRACE("  Model Exchange round trip: setTime(%.17g), event iteration, twice\n", t);
    bool was_tracing = trace;
    trace = false;
    fmi2FMUstate a = NULL, b = NULL;
    size_t size = 0;
    static unsigned char bytes[MAX_SERIALIZED];
    if (fmi2GetFMUstate(inst, &a) != fmi2OK || fmi2SerializedFMUstateSize(inst, a, &size) != fmi2OK ||
        size > MAX_SERIALIZED || fmi2SerializeFMUstate(inst, a, (fmi2Byte *)bytes, size) != fmi2OK)
        fail("Model Exchange round trip: the state could not be serialized");
    if (fmi2DeSerializeFMUstate(inst, (const fmi2Byte *)bytes, size, &b) != fmi2OK) {
        own_state_refused("Model Exchange round trip", bytes, size);
        fmi2FreeFMUstate(inst, &a);
        trace = was_tracing;
        return;
    }
    take(&snap_round[0]);
    fmi2EventInfo info[2];
    fmi2Status status[2][4];
    for (int run = 0; run < 2; run++) {
        memset(&info[run], 0, sizeof info[run]);
        status[run][0] = fmi2SetTime(inst, t);
        status[run][1] = fmi2EnterEventMode(inst);
        status[run][2] = apply_set(&r);
        status[run][3] = fmi2NewDiscreteStates(inst, &info[run]);
        take(&snap_round[1 + run]);
        if (run == 0) {
            if (fmi2SetFMUstate(inst, b) != fmi2OK) fail("Model Exchange round trip: fmi2SetFMUstate refused");
            take(&snap_after);
            must_equal(&snap_round[0], &snap_after, "Model Exchange round trip: the restored state");
        }
    }
    if (memcmp(status[0], status[1], sizeof status[0]))
        fail("Model Exchange round trip: the replay returned other statuses");
    if (!same_event_info(&info[0], &info[1]))
        fail("Model Exchange round trip: the replay returned another eventInfo");
    must_equal(&snap_round[1], &snap_round[2], "Model Exchange round trip: the event after the restore");
    if (fmi2FreeFMUstate(inst, &a) != fmi2OK || fmi2FreeFMUstate(inst, &b) != fmi2OK)
        fail("Model Exchange round trip: fmi2FreeFMUstate failed");
    trace = was_tracing;
}

/* The Model Exchange functions with a NULL instance: fmi2Error, never a crash. */
static void op_me_null_component(input *in)
{
    fmi2EventInfo info;
    fmi2Boolean enter, terminate;
    fmi2Real x = 0;
    fmi2Status s;
    const char *function;
#define NULL_ME(n, call)                                                                       \
    case n:                                                                                    \
        s = call;                                                                              \
        function = #call;                                                                      \
        break
    switch (u8(in) % 10) {
        NULL_ME(0, fmi2EnterEventMode(NULL));
        NULL_ME(1, fmi2NewDiscreteStates(NULL, &info));
        NULL_ME(2, fmi2EnterContinuousTimeMode(NULL));
        NULL_ME(3, fmi2CompletedIntegratorStep(NULL, 0, &enter, &terminate));
        NULL_ME(4, fmi2SetTime(NULL, 0.5));
        NULL_ME(5, fmi2SetContinuousStates(NULL, &x, 0));
        NULL_ME(6, fmi2GetDerivatives(NULL, &x, 0));
        NULL_ME(7, fmi2GetEventIndicators(NULL, &x, 0));
        NULL_ME(8, fmi2GetContinuousStates(NULL, &x, 0));
    default:
        s = fmi2GetNominalsOfContinuousStates(NULL, &x, 0);
        function = "fmi2GetNominalsOfContinuousStates(NULL, &x, 0)";
        break;
    }
#undef NULL_ME
    TRACE("  %s -> %s\n", function, status_name(s));
    if (s != fmi2Error) fail("%s returned %s", function, status_name(s));
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
    case OP_ENTER: CHECKED(fmi2EnterInitializationMode(inst)); break;
    case OP_EXIT:
        if (CHECKED(fmi2ExitInitializationMode(inst)) != fmi2Error)
            must_be_in(inst_type == fmi2ModelExchange ? MODE_EVENT_ : MODE_STEP_,
                       "fmi2ExitInitializationMode");
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
        if (CHECKED(fmi2Terminate(inst)) != fmi2Error) {
            must_be_in(MODE_TERMINATED_, "fmi2Terminate");
            accepts_own_state("after fmi2Terminate");
        }
        break;
    case OP_RESET: CHECKED(fmi2Reset(inst)); break;
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

static fmi2Component instantiate(input *in)
{
    uint8_t variant = u8(in) % 16, flags = u8(in);
    fmi2Boolean logging_on = flags & 1;
    inst_type = flags & 0x80 ? fmi2ModelExchange : fmi2CoSimulation;
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
        fmi2Component refused =
            fmi2Instantiate(name, type, guid_arg, "file:///nowhere", &functions, fmi2False, logging_on);
        injecting = false;
        if (variant != 15 && refused) fail("fmi2Instantiate variant %u was not refused", variant);
        if (!refused && !problems_logged && functions.logger)
            fail("fmi2Instantiate refused without a log line");
        if (refused) fmi2FreeInstance(refused); /* the failure hit a later allocation */
        fail_countdown = 0;
    }
    TRACE("  fmi2Instantiate(%s)\n", inst_type == fmi2ModelExchange ? "fmi2ModelExchange" : "fmi2CoSimulation");
    fmi2Component c = fmi2Instantiate("fuzz", inst_type, lgf_model.guid, NULL, &callbacks,
                                      fmi2False, logging_on);
    if (!c) fail("a correct fmi2Instantiate failed");
    return c;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
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
    inst = instantiate(&in);
    for (int ops = 0; in.n > 0 && ops < MAX_OPS; ops++) run_op(&in);
    fail_countdown = 0;
    for (int i = 0; i < SLOTS; i++)
        if (fmi2FreeFMUstate(inst, &slots[i]) != fmi2OK || slots[i])
            fail("fmi2FreeFMUstate of a slot failed");
    fmi2FreeInstance(inst);
    inst = NULL;
    return 0;
}
