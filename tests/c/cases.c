/* The misuse cases of docs/behaviour.md §1.7, generated from the block's modelDescription.xml: each is a
 * call that must be refused (fmi2Error, or fmi2Warning where the FMU can go on) with exactly
 * the expected log message and no effect on the instance (run_misuse checks all that). The
 * cases both versions have go through the block's fmu_ops and take the function names from
 * FN(); what only FMI 2.0 has is build_fmi2_misuses, what only FMI 3.0 has is in fmi3.c. */
#define _POSIX_C_SOURCE 200809L
#define _DEFAULT_SOURCE /* MAP_ANONYMOUS */
#include "harness.h"

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>

#define SETTER(b, type) ((b)->ops->types[type].setter)
#define GETTER(b, type) ((b)->ops->types[type].getter)

misuse *misuse_add(misuse_list *list, const char *group, int phase, op_fn *op)
{
    if (list->count == list->capacity) {
        size_t capacity = list->capacity ? 2 * list->capacity : 256;
        misuse *bigger = realloc(list->items, capacity * sizeof *bigger);
        if (!bigger) {
            fprintf(stderr, "out of memory\n");
            exit(2);
        }
        list->items = bigger;
        list->capacity = capacity;
    }
    misuse *m = &list->items[list->count++];
    memset(m, 0, sizeof *m);
    m->group = group;
    m->phase = phase;
    m->op = op;
    m->expect = fmi2Error;
    m->logs = 1;
    m->log_status = fmi2Error;
    m->function = "fmi";
    m->type = fmi2CoSimulation;
    return m;
}

void misuse_label(misuse *m, const char *fmt, ...)
{
    va_list args;
    va_start(args, fmt);
    vsnprintf(m->label, sizeof m->label, fmt, args);
    va_end(args);
}

#define label misuse_label

static void put_le(unsigned char *to, uint64_t value, int width)
{
    for (int i = 0; i < width; i++) to[i] = (unsigned char)(value >> (8 * i));
}

static uint64_t bits_of(double value)
{
    uint64_t bits;
    memcpy(&bits, &value, sizeof bits);
    return bits;
}

static double double_of(uint64_t bits)
{
    double value;
    memcpy(&value, &bits, sizeof value);
    return value;
}

/* ---- ops: each performs one call (or a few, to set it up) and returns its status ---- */

/* m->i: the type; vr with r */
int op_set(sim *s, const misuse *m)
{
    uint32_t vr = m->vr;
    double value = m->r;
    return FMU(s->b, set, s->c, (int)m->i, &vr, 1, &value, 1);
}

int op_get(sim *s, const misuse *m)
{
    uint32_t vr = m->vr;
    double value;
    return FMU(s->b, get, s->c, (int)m->i, &vr, 1, &value, 1);
}

/* two value references in one call: vr with r, vr2 with r2 */
static int op_set2(sim *s, const misuse *m)
{
    uint32_t vr[2] = {m->vr, m->vr2};
    double values[2] = {m->r, m->r2};
    return FMU(s->b, set, s->c, (int)m->i, vr, 2, values, 2);
}

static int op_get2(sim *s, const misuse *m)
{
    uint32_t vr[2] = {m->vr, m->vr2};
    double values[2];
    return FMU(s->b, get, s->c, (int)m->i, vr, 2, values, 2);
}

/* i: type; i2: 0 set with vr NULL, 1 set with value NULL, 2 get with vr NULL, 3 get with
 * value NULL, 4 set with nvr = 0 and both NULL, 5 get likewise */
int op_null_array(sim *s, const misuse *m)
{
    uint32_t vr = m->vr;
    double value = 0;
    const uint32_t *vrs = m->i2 == 0 || m->i2 == 2 || m->i2 >= 4 ? NULL : &vr;
    bool values = m->i2 == 1 || m->i2 == 3 || m->i2 >= 4 ? false : true;
    size_t count = m->i2 >= 4 ? 0 : 1;
    bool set = m->i2 == 0 || m->i2 == 1 || m->i2 == 4;
    return set ? FMU(s->b, set, s->c, (int)m->i, vrs, count, values ? &value : NULL, count)
               : FMU(s->b, get, s->c, (int)m->i, vrs, count, values ? &value : NULL, count);
}

/* FN_SETUP: startTime r, stopTime r2 if i */
int op_setup(sim *s, const misuse *m) { return FMU(s->b, setup, s->c, m->r, m->i != 0, m->r2); }

int op_enter(sim *s, const misuse *m)
{
    (void)m;
    return FMU(s->b, enter_init, s->c);
}

int op_exit(sim *s, const misuse *m)
{
    (void)m;
    return FMU(s->b, exit_init, s->c);
}

int op_terminate(sim *s, const misuse *m)
{
    (void)m;
    return FMU(s->b, terminate, s->c);
}

/* i: 0 at the sim's time + r, 1 at r; step r2 */
int op_dostep(sim *s, const misuse *m)
{
    double t = m->i ? m->r : s->t + m->r;
    return FMU(s->b, do_step, s->c, t, m->r2);
}

int op_debug_logging(sim *s, const misuse *m)
{
    static const char *const unknown[] = {"logNothing"};
    static const char *const null_entry[] = {NULL};
    static const char *const format[] = {"%s%n%s%s%p%%"};
    static const char *const mixed[] = {"logAll", "logBogus"};
    static const char *const valid[] = {"logAll", "logStatusWarning", "logStatusError"};
    const block *b = s->b;
    switch (m->i) {
    case 0: return FMU(b, set_debug_logging, s->c, true, 1, unknown);
    case 1: return FMU(b, set_debug_logging, s->c, true, 1, null_entry);
    case 2: return FMU(b, set_debug_logging, s->c, true, 2, NULL);
    case 3: return FMU(b, set_debug_logging, s->c, true, 1, format);
    case 4: return FMU(b, set_debug_logging, s->c, true, 2, mixed);
    case 5: return FMU(b, set_debug_logging, s->c, true, 0, NULL);
    case 6: return FMU(b, set_debug_logging, s->c, false, 3, valid);
    default: return -1;
    }
}

/* NULL where a state, a size or a buffer must be given (i selects the call). */
static int op_state_null(sim *s, const misuse *m)
{
    const block *b = s->b;
    void *valid = NULL, *state = NULL;
    unsigned char *bytes = NULL;
    size_t n = 0, size = 0;
    if (FMU(b, get_state, s->c, &valid) != fmi2OK || !sim_state_bytes(s, &bytes, &n)) return -1;
    int result = -1;
    switch (m->i) {
    case 0: result = FMU(b, get_state, s->c, NULL); break;
    case 1: result = FMU(b, set_state, s->c, NULL); break;
    case 2: result = FMU(b, free_state, s->c, NULL); break;
    case 3: result = FMU(b, state_size, s->c, NULL, &size); break;
    case 4: result = FMU(b, state_size, s->c, valid, NULL); break;
    case 5: result = FMU(b, serialize, s->c, NULL, bytes, n); break;
    case 6: result = FMU(b, serialize, s->c, valid, NULL, n); break;
    case 7: result = FMU(b, serialize, s->c, valid, bytes, n - 1); break;
    case 8: result = FMU(b, serialize, s->c, valid, bytes, 0); break;
    case 9: result = FMU(b, deserialize, s->c, NULL, n, &state); break;
    case 10: result = FMU(b, deserialize, s->c, bytes, n, NULL); break;
    case 11: result = FMU(b, free_state, s->c, &state); break; /* *FMUstate NULL: nothing to do */
    }
    if (state) result = OTHER_RESULT;
    FMU(b, free_state, s->c, &valid);
    free(bytes);
    return result;
}

/* One page that faults when read (made once, never unmapped). */
static void *unreadable_page(void)
{
    static void *page;
    if (!page) {
        void *p = mmap(NULL, 4096, PROT_NONE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
        page = p == MAP_FAILED ? NULL : p;
    }
    return page;
}

/* A pointer that is not a state: readable memory holding zeros (i2 = 0) or 0xFF bytes
 * (i2 = 1), a state of the other block (i2 = 2), a state this instance made and freed (i2 = 3:
 * ASan and valgrind see a read of it), or an address that cannot be read at all (i2 = 4: a
 * read faults). The FMU must refuse each without reading it. i selects the call. */
static int op_state_foreign(sim *s, const misuse *m)
{
    const block *b = s->b;
    static _Alignas(64) unsigned char memory[4096];
    unsigned char pattern = m->i2 == 1 ? 0xFF : 0x00;
    memset(memory, pattern, sizeof memory);
    void *foreign = (void *)memory;
    if (m->i2 == 2) foreign = FOREIGN.other_state;
    if (m->i2 == 3) {
        foreign = NULL;
        if (FMU(b, get_state, s->c, &foreign) != fmi2OK || !foreign) return -1;
        void *copy = foreign;
        if (FMU(b, free_state, s->c, &copy) != fmi2OK) return -1;
    }
    if (m->i2 == 4 && !(foreign = unreadable_page())) return -1;
    void *state = foreign;
    unsigned char *bytes = NULL, *buffer = NULL;
    size_t n = 0, size = 0;
    if (!sim_state_bytes(s, &bytes, &n) || !(buffer = calloc(1, n + 4096))) return -1;
    int result = -1;
    switch (m->i) {
    case 0: result = FMU(b, get_state, s->c, &state); break;
    case 1: result = FMU(b, set_state, s->c, foreign); break;
    case 2: result = FMU(b, free_state, s->c, &state); break;
    case 3: result = FMU(b, state_size, s->c, foreign, &size); break;
    case 4: result = FMU(b, serialize, s->c, foreign, buffer, n + 4096); break;
    case 5: result = FMU(b, deserialize, s->c, bytes, n, &state); break;
    }
    /* The foreign object must be left as it was. */
    if (state != foreign) result = OTHER_RESULT;
    if (m->i2 == 2) {
        unsigned char *now = malloc(FOREIGN.other_size);
        size_t other_size = 0;
        if (!now ||
            FMU(FOREIGN.other, state_size, FOREIGN.other_instance, foreign, &other_size) !=
                fmi2OK ||
            other_size != FOREIGN.other_size ||
            FMU(FOREIGN.other, serialize, FOREIGN.other_instance, foreign, now, other_size) !=
                fmi2OK ||
            memcmp(now, FOREIGN.other_bytes, other_size))
            result = OTHER_RESULT;
        free(now);
    } else if (m->i2 < 2) {
        for (size_t i = 0; i < sizeof memory; i++)
            if (memory[i] != pattern) result = OTHER_RESULT;
    }
    free(bytes);
    free(buffer);
    return result;
}

/* ---- serialized states ---- */

enum {
    MUT_LENGTH,       /* i2 bytes (i2 < 0: size + i2); beyond the size zeros follow */
    MUT_FLIP,         /* one bit of byte i2 */
    MUT_VERSION,      /* format version i2 */
    MUT_IDENTIFIER,   /* the other block's modelIdentifier (or a made-up one) */
    MUT_GUID,         /* the other block's guid (or zeros) */
    MUT_SIZE_FIELD,   /* payload size field + i2, the bytes as they are */
    MUT_SIZE_BOTH,    /* payload size field and bytes + i2 (zeros), checksum made to match */
    MUT_PATCH,        /* the patches, checksum made to match */
    MUT_OTHER_BYTES,  /* the other block's serialized state */
    MUT_INTO_EXISTING /* flip a payload bit, deserialize into an existing state */
};

static int op_deserialize(sim *s, const misuse *m)
{
    const block *b = s->b;
    unsigned char *bytes = NULL, *buffer = NULL;
    size_t n = 0;
    if (!sim_state_bytes(s, &bytes, &n) || !(buffer = calloc(1, n + 4096))) {
        free(bytes);
        return -1;
    }
    memcpy(buffer, bytes, n);
    size_t length = n;
    const unsigned char *input = buffer;
    void *state = NULL;
    switch (m->i) {
    case MUT_LENGTH: length = m->i2 >= 0 ? (size_t)m->i2 : n - (size_t)(-m->i2); break;
    case MUT_FLIP: buffer[m->i2] ^= (unsigned char)(1u << (m->i2 % 8)); break;
    case MUT_VERSION: put_le(buffer + 8, (uint64_t)m->i2, 4); break;
    case MUT_IDENTIFIER:
        memset(buffer + 12, 0, 32);
        memcpy(buffer + 12, FOREIGN.other ? FOREIGN.other->md.identifier : "LGF_Other",
               strlen(FOREIGN.other ? FOREIGN.other->md.identifier : "LGF_Other"));
        break;
    case MUT_GUID:
        memset(buffer + 44, 0, 40);
        if (FOREIGN.other) memcpy(buffer + 44, FOREIGN.other->guid, strlen(FOREIGN.other->guid));
        break;
    case MUT_SIZE_FIELD: put_le(buffer + 84, (uint64_t)((long)(n - HEADER_SIZE) + m->i2), 4); break;
    case MUT_SIZE_BOTH:
        length = (size_t)((long)n + m->i2);
        put_le(buffer + 84, length - HEADER_SIZE, 4);
        put_le(buffer + 88, fnv1a64(buffer + HEADER_SIZE, length - HEADER_SIZE), 8);
        break;
    case MUT_PATCH:
        for (int p = 0; p < m->n_patches; p++)
            put_le(buffer + HEADER_SIZE + m->patches[p].offset, m->patches[p].bits,
                   m->patches[p].width);
        put_le(buffer + 88, fnv1a64(buffer + HEADER_SIZE, n - HEADER_SIZE), 8);
        break;
    case MUT_OTHER_BYTES:
        input = FOREIGN.other_bytes;
        length = FOREIGN.other_size;
        break;
    case MUT_INTO_EXISTING:
        buffer[n - 1] ^= 0x10;
        if (FMU(b, get_state, s->c, &state) != fmi2OK) {
            free(bytes);
            free(buffer);
            return -1;
        }
        break;
    }
    void *existing = state;
    int result = FMU(b, deserialize, s->c, input, length, &state);
    if (m->i == MUT_INTO_EXISTING) {
        /* refused: the existing state is the same object with the same content */
        unsigned char *now = malloc(n);
        size_t size = 0;
        if (state != existing || !now || FMU(b, state_size, s->c, state, &size) != fmi2OK ||
            size != n || FMU(b, serialize, s->c, state, now, n) != fmi2OK || memcmp(now, bytes, n))
            result = OTHER_RESULT;
        free(now);
        FMU(b, free_state, s->c, &existing);
    } else if (result == fmi2OK) {
        if (!state || FMU(b, free_state, s->c, &state) != fmi2OK) result = OTHER_RESULT;
    } else if (state) {
        result = OTHER_RESULT; /* a refused deserialization allocated a state */
    }
    free(bytes);
    free(buffer);
    return result;
}

/* The state functions when the importer's allocateMemory returns NULL. */
static int op_out_of_memory(sim *s, const misuse *m)
{
    const block *b = s->b;
    void *state = NULL;
    unsigned char *bytes = NULL;
    size_t n = 0;
    if (!sim_state_bytes(s, &bytes, &n)) return -1;
    fail_allocation_after(1);
    int result =
        m->i == 0 ? FMU(b, get_state, s->c, &state) : FMU(b, deserialize, s->c, bytes, n, &state);
    fail_allocation_after(0);
    if (state) {
        FMU(b, free_state, s->c, &state);
        result = OTHER_RESULT;
    }
    free(bytes);
    return result;
}

/* ---- ops only FMI 2.0 has ---- */

static int op_unsupported(sim *s, const misuse *m)
{
    const fmi2_api *api = &s->b->api;
    fmi2Status status = fmi2OK;
    fmi2Real real = -1;
    fmi2Integer integer = 0, order = 1;
    fmi2Boolean boolean = fmi2True;
    fmi2String text = NULL;
    fmi2ValueReference in = m->vr, out = m->vr2;
    fmi2Real dv = 1.0, result = 0.0;
    switch (m->i) {
    case 0: return api->CancelStep(s->c);
    case 1: return api->GetStatus(s->c, fmi2DoStepStatus, &status);
    case 2: return api->GetRealStatus(s->c, fmi2DoStepStatus, &real);
    case 3: return api->GetRealStatus(s->c, fmi2LastSuccessfulTime, NULL);
    case 4: return api->GetIntegerStatus(s->c, fmi2DoStepStatus, &integer);
    case 5: return api->GetBooleanStatus(s->c, fmi2DoStepStatus, &boolean);
    case 6: return api->GetBooleanStatus(s->c, fmi2Terminated, NULL);
    case 7: return api->GetStringStatus(s->c, fmi2PendingStatus, &text);
    case 8: return api->SetRealInputDerivatives(s->c, &in, 1, &order, &dv);
    case 9: return api->GetRealOutputDerivatives(s->c, &out, 1, &order, &result);
    case 10: return api->GetDirectionalDerivative(s->c, &out, 1, &in, 1, &dv, &result);
    case 11: { /* what is supported: the last successful time, and "not terminated" */
        int got = api->GetRealStatus(s->c, fmi2LastSuccessfulTime, &real);
        return got == fmi2OK && real != s->t ? OTHER_RESULT : got;
    }
    case 12: {
        int got = api->GetBooleanStatus(s->c, fmi2Terminated, &boolean);
        return got == fmi2OK && boolean != fmi2False ? OTHER_RESULT : got;
    }
    case 13: return api->SetRealInputDerivatives(s->c, NULL, 1, NULL, NULL);
    case 14: return api->GetDirectionalDerivative(s->c, NULL, 1, NULL, 1, NULL, NULL);
    default: return -1;
    }
}

/* Every function with an fmi2Component, called with NULL and otherwise valid arguments. */
#define NULL_COMPONENT_CALLS 31
static const char *const NULL_COMPONENT_NAMES[NULL_COMPONENT_CALLS] = {
    "fmi2SetDebugLogging",
    "fmi2SetupExperiment",
    "fmi2EnterInitializationMode",
    "fmi2ExitInitializationMode",
    "fmi2Terminate",
    "fmi2Reset",
    "fmi2GetReal",
    "fmi2GetInteger",
    "fmi2GetBoolean",
    "fmi2GetString",
    "fmi2SetReal",
    "fmi2SetInteger",
    "fmi2SetBoolean",
    "fmi2SetString",
    "fmi2GetFMUstate",
    "fmi2SetFMUstate",
    "fmi2FreeFMUstate",
    "fmi2SerializedFMUstateSize",
    "fmi2SerializeFMUstate",
    "fmi2DeSerializeFMUstate",
    "fmi2GetDirectionalDerivative",
    "fmi2SetRealInputDerivatives",
    "fmi2GetRealOutputDerivatives",
    "fmi2DoStep",
    "fmi2CancelStep",
    "fmi2GetStatus",
    "fmi2GetRealStatus",
    "fmi2GetIntegerStatus",
    "fmi2GetBooleanStatus",
    "fmi2GetStringStatus",
    "fmi2FreeInstance"};

static int op_null_component(sim *s, const misuse *m)
{
    const fmi2_api *api = &s->b->api;
    fmi2ValueReference vr = m->vr;
    fmi2Real r = 0;
    fmi2Integer n = 0, order = 1;
    fmi2Boolean b = 0;
    fmi2String text = "x";
    fmi2Status status;
    size_t size = 0;
    unsigned char *bytes = NULL;
    size_t nbytes = 0;
    fmi2FMUstate state = NULL, valid = NULL;
    if (api->GetFMUstate(s->c, &valid) != fmi2OK || !sim_state_bytes(s, &bytes, &nbytes)) return -1;
    int result = -1;
    switch (m->i) {
    case 0: result = api->SetDebugLogging(NULL, fmi2True, 0, NULL); break;
    case 1: result = api->SetupExperiment(NULL, fmi2False, 0, 0, fmi2False, 0); break;
    case 2: result = api->EnterInitializationMode(NULL); break;
    case 3: result = api->ExitInitializationMode(NULL); break;
    case 4: result = api->Terminate(NULL); break;
    case 5: result = api->Reset(NULL); break;
    case 6: result = api->GetReal(NULL, &vr, 1, &r); break;
    case 7: result = api->GetInteger(NULL, &vr, 1, &n); break;
    case 8: result = api->GetBoolean(NULL, &vr, 1, &b); break;
    case 9: result = api->GetString(NULL, &vr, 1, &text); break;
    case 10: result = api->SetReal(NULL, &vr, 1, &r); break;
    case 11: result = api->SetInteger(NULL, &vr, 1, &n); break;
    case 12: result = api->SetBoolean(NULL, &vr, 1, &b); break;
    case 13: result = api->SetString(NULL, &vr, 1, &text); break;
    case 14: result = api->GetFMUstate(NULL, &state); break;
    case 15: result = api->SetFMUstate(NULL, valid); break;
    case 16: /* must not free the state: it is freed below, a double free would show */
        state = valid;
        result = api->FreeFMUstate(NULL, &state);
        if (state != valid) result = OTHER_RESULT;
        state = NULL;
        break;
    case 17: result = api->SerializedFMUstateSize(NULL, valid, &size); break;
    case 18: result = api->SerializeFMUstate(NULL, valid, (fmi2Byte *)bytes, nbytes); break;
    case 19:
        result = api->DeSerializeFMUstate(NULL, (const fmi2Byte *)bytes, nbytes, &state);
        break;
    case 20: result = api->GetDirectionalDerivative(NULL, &vr, 1, &vr, 1, &r, &r); break;
    case 21: result = api->SetRealInputDerivatives(NULL, &vr, 1, &order, &r); break;
    case 22: result = api->GetRealOutputDerivatives(NULL, &vr, 1, &order, &r); break;
    case 23: result = api->DoStep(NULL, s->t, s->b->cycle, fmi2True); break;
    case 24: result = api->CancelStep(NULL); break;
    case 25: result = api->GetStatus(NULL, fmi2DoStepStatus, &status); break;
    case 26: result = api->GetRealStatus(NULL, fmi2LastSuccessfulTime, &r); break;
    case 27: result = api->GetIntegerStatus(NULL, fmi2DoStepStatus, &n); break;
    case 28: result = api->GetBooleanStatus(NULL, fmi2Terminated, &b); break;
    case 29: result = api->GetStringStatus(NULL, fmi2PendingStatus, &text); break;
    case 30:
        api->FreeInstance(NULL);
        result = fmi2OK;
        break; /* returns nothing: must not crash */
    }
    if (state) result = OTHER_RESULT; /* something was allocated for a NULL instance */
    api->FreeFMUstate(s->c, &valid);
    free(bytes);
    return result;
}

/* ---- the cases ---- */

const md_variable *first_of(const block *b, var_kind kind, bool (*fits)(const md_variable *))
{
    for (size_t i = 0; i < b->md.count; i++)
        if (b->md.variables[i].kind == kind && fits(&b->md.variables[i]))
            return &b->md.variables[i];
    return NULL;
}

const md_variable *first_of_type(const block *b, int type)
{
    for (size_t i = 0; i < b->md.count; i++)
        if (b->md.variables[i].type == type) return &b->md.variables[i];
    return NULL;
}

bool is_input(const md_variable *v) { return v->causality == CAUS_INPUT; }
bool is_output(const md_variable *v) { return v->causality == CAUS_OUTPUT; }
bool is_settable(const md_variable *v)
{
    return v->causality == CAUS_INPUT || v->causality == CAUS_PARAMETER;
}
bool is_any(const md_variable *v) { return v != NULL; }

bool known_vr(const block *b, uint32_t vr)
{
    for (size_t i = 0; i < b->md.count; i++)
        if (b->md.variables[i].vr == vr) return true;
    return false;
}

/* NaN of every kind, beyond min and max, and for a Float32 beyond the float range; integers
 * beyond min and max as far as their C type carries them. */
static void out_of_range(const block *b, misuse_list *list)
{
    const char *group = "values out of range";
    for (size_t i = 0; i < b->md.count; i++) {
        const md_variable *v = &b->md.variables[i];
        if (!is_settable(v)) continue;
        const type_info *t = &b->ops->types[v->type];
        int phase = v->fixed ? PHASE_INITIALIZATION : PHASE_STEP;
        double bad[12];
        const char *names[12];
        int n = 0;
        if (v->kind == KIND_REAL && t->single) { /* what a float carries */
            bad[n] = NAN, names[n++] = "NaN";
            bad[n] = -NAN, names[n++] = "-NaN";
            if (v->has_min) {
                bad[n] = nextafterf((float)v->min, -INFINITY), names[n++] = "just below min";
                bad[n] = -INFINITY, names[n++] = "-Inf";
            }
            if (v->has_max) {
                bad[n] = nextafterf((float)v->max, INFINITY), names[n++] = "just above max";
                bad[n] = INFINITY, names[n++] = "+Inf";
            }
        } else if (v->kind == KIND_REAL) {
            bad[n] = NAN, names[n++] = "NaN";
            bad[n] = -NAN, names[n++] = "-NaN";
            bad[n] = double_of(0x7FF0000000000001u), names[n++] = "signalling NaN";
            bad[n] = double_of(0xFFFFFFFFFFFFFFFFu), names[n++] = "NaN with all bits set";
            if (v->has_min) {
                bad[n] = nextafter(v->min, -INFINITY), names[n++] = "just below min";
                bad[n] = v->min - fabs(v->min) * 1e-3 - 1e-3, names[n++] = "below min";
                bad[n] = -1e300, names[n++] = "-1e300";
                bad[n] = -INFINITY, names[n++] = "-Inf";
            }
            if (v->has_max) {
                bad[n] = nextafter(v->max, INFINITY), names[n++] = "just above max";
                bad[n] = v->max + fabs(v->max) * 1e-3 + 1e-3, names[n++] = "above max";
                bad[n] = 1e300, names[n++] = "1e300";
                bad[n] = INFINITY, names[n++] = "+Inf";
            }
        } else if (v->kind == KIND_INTEGER) {
            if (v->has_min && v->min > t->lo) {
                bad[n] = v->min - 1, names[n++] = "min - 1";
                if (v->min - 1 > t->lo) bad[n] = t->lo, names[n++] = "the type's least value";
            }
            if (v->has_max && v->max < t->hi) {
                bad[n] = v->max + 1, names[n++] = "max + 1";
                if (v->max + 1 < t->hi) bad[n] = t->hi, names[n++] = "the type's largest value";
            }
        }
        for (int k = 0; k < n; k++) {
            /* a Float32 that rounds onto min or max is no case */
            if (t->single && isfinite(bad[k]) && (float)bad[k] >= v->min && (float)bad[k] <= v->max)
                continue;
            misuse *m = misuse_add(list, group, phase, op_set);
            label(m, "%s = %.17g (%s)", v->name, bad[k], names[k]);
            m->i = v->type;
            m->vr = v->vr;
            m->r = bad[k];
            m->function = SETTER(b, v->type);
            snprintf(m->contains, sizeof m->contains, "%s", v->name);
        }
    }
}

static void wrong_variables(const block *b, misuse_list *list)
{
    for (size_t i = 0; i < b->md.count; i++) {
        const md_variable *v = &b->md.variables[i];
        double value = v->has_start ? v->start : 1;
        if (v->fixed && is_settable(v)) {
            for (int phase = PHASE_STEP; phase <= PHASE_TERMINATED; phase++) {
                misuse *m = misuse_add(list, "fixed parameters after init", phase, op_set);
                label(m, "set fixed %s to its start value", v->name);
                m->i = v->type, m->vr = v->vr, m->r = value;
                m->function = SETTER(b, v->type);
                if (phase == PHASE_STEP) snprintf(m->contains, sizeof m->contains, "%s", v->name);
            }
        }
        if (is_output(v)) {
            for (int phase = PHASE_INSTANTIATED; phase <= PHASE_STEP; phase++) {
                misuse *m = misuse_add(list, "setting outputs", phase, op_set);
                label(m, "set output %s", v->name);
                m->i = v->type, m->vr = v->vr, m->r = 1;
                m->function = SETTER(b, v->type);
                snprintf(m->contains, sizeof m->contains, "%s", v->name);
            }
        }
        for (int type = 0; type < b->ops->n_types; type++) {
            if (type == v->type) continue;
            for (int get = 0; get <= 1; get++) {
                misuse *m = misuse_add(list, "type mismatch", PHASE_STEP, get ? op_get : op_set);
                label(m, "%s on %s", get ? GETTER(b, type) : SETTER(b, type), v->name);
                m->i = type, m->vr = v->vr, m->r = 0;
                m->function = get ? GETTER(b, type) : SETTER(b, type);
                if (!b->ops->types[type].has_table)
                    snprintf(m->contains, sizeof m->contains, "%u", (unsigned)v->vr);
                else
                    snprintf(m->contains, sizeof m->contains, "%s", v->name);
            }
        }
    }
}

static void unknown_references(const block *b, misuse_list *list)
{
    uint32_t highest = 0, gap = 0;
    for (size_t i = 0; i < b->md.count; i++)
        if (b->md.variables[i].vr > highest) highest = b->md.variables[i].vr;
    for (uint32_t vr = 0; vr < highest && !gap; vr++)
        if (!known_vr(b, vr)) gap = vr;
    uint32_t unknown[] = {highest + 1, gap ? gap : highest + 2, 0x7FFFFFFFu, 0x80000000u,
                          0xFFFFFFFFu};
    for (size_t u = 0; u < sizeof unknown / sizeof unknown[0]; u++) {
        for (int type = 0; type < b->ops->n_types; type++) {
            for (int get = 0; get <= 1; get++) {
                misuse *m =
                    misuse_add(list, "unknown value references", PHASE_STEP, get ? op_get : op_set);
                label(m, "%s of value reference %u", get ? GETTER(b, type) : SETTER(b, type),
                      (unsigned)unknown[u]);
                m->i = type, m->vr = unknown[u], m->r = 0;
                m->function = get ? GETTER(b, type) : SETTER(b, type);
                snprintf(m->contains, sizeof m->contains, "%u", (unsigned)unknown[u]);
            }
        }
    }
    /* in initialization mode as well */
    const md_variable *real = first_of(b, KIND_REAL, is_any);
    int type = real ? real->type : 0;
    misuse *m = misuse_add(list, "unknown value references", PHASE_INITIALIZATION, op_set);
    label(m, "%s of value reference %u", SETTER(b, type), (unsigned)(highest + 1));
    m->i = type, m->vr = highest + 1;
    m->function = SETTER(b, type);
    snprintf(m->contains, sizeof m->contains, "%u", (unsigned)(highest + 1));
}

/* A call with a good value and a bad one applies neither. */
static void multiple_values(const block *b, misuse_list *list)
{
    const char *group = "multiple values in one call";
    uint32_t unknown = 0;
    while (known_vr(b, unknown)) unknown++;
    const md_variable *real = first_of(b, KIND_REAL, is_input);
    const md_variable *integer = first_of(b, KIND_INTEGER, is_input);
    const md_variable *boolean = first_of(b, KIND_BOOLEAN, is_input);
    const md_variable *out_bool = first_of(b, KIND_BOOLEAN, is_output);
    if (real) {
        double good = real->has_max ? real->min : real->start + 1;
        const char *set = SETTER(b, real->type), *get = GETTER(b, real->type);
        misuse *m = misuse_add(list, group, PHASE_STEP, op_set2);
        label(m, "%s {%s = %g, %s = NaN}", set, real->name, good, real->name);
        m->i = real->type, m->vr = m->vr2 = real->vr, m->r = good, m->r2 = NAN;
        m->function = set;
        snprintf(m->contains, sizeof m->contains, "%s", real->name);
        m = misuse_add(list, group, PHASE_STEP, op_set2);
        label(m, "%s {%s = %g, unknown %u}", set, real->name, good, (unsigned)unknown);
        m->i = real->type, m->vr = real->vr, m->vr2 = unknown, m->r = good;
        m->function = set;
        snprintf(m->contains, sizeof m->contains, "%u", (unsigned)unknown);
        m = misuse_add(list, group, PHASE_STEP, op_get2);
        label(m, "%s {%s, unknown %u}", get, real->name, (unsigned)unknown);
        m->i = real->type, m->vr = real->vr, m->vr2 = unknown;
        m->function = get;
    }
    if (integer && integer->has_max && integer->max < b->ops->types[integer->type].hi) {
        const char *set = SETTER(b, integer->type);
        misuse *m = misuse_add(list, group, PHASE_STEP, op_set2);
        label(m, "%s {%s = %g, %s = %g}", set, integer->name, integer->start + 1, integer->name,
              integer->max + 1);
        m->i = integer->type, m->vr = m->vr2 = integer->vr, m->r = integer->start + 1,
        m->r2 = integer->max + 1;
        m->function = set;
        snprintf(m->contains, sizeof m->contains, "%s", integer->name);
    }
    if (boolean && out_bool) {
        const char *set = SETTER(b, boolean->type);
        misuse *m = misuse_add(list, group, PHASE_STEP, op_set2);
        label(m, "%s {%s = %d, output %s}", set, boolean->name, !boolean->start, out_bool->name);
        m->i = boolean->type, m->vr = boolean->vr, m->vr2 = out_bool->vr, m->r = !boolean->start,
        m->r2 = 1;
        m->function = set;
        snprintf(m->contains, sizeof m->contains, "%s", out_bool->name);
    }
}

void add_mode_cases(const block *b, misuse_list *list, const char *group, fmi2Type type,
                    const mode_row *rows, size_t n_rows, const int *phases, size_t n_phases)
{
    const md_variable *real_in = first_of(b, KIND_REAL, is_input);
    const md_variable *real_out = first_of(b, KIND_REAL, is_output);
    for (size_t i = 0; i < n_rows; i++) {
        const mode_row *row = &rows[i];
        if ((row->op == op_get || row->op == op_set) && !row->v) continue;
        for (size_t p = 0; p < n_phases; p++) {
            int phase = phases[p];
            bool allowed = row->allowed & (1u << phase);
            bool made = row->made & (1u << phase);
            if (allowed && !made) continue;
            misuse *m = misuse_add(list, group, phase, row->op);
            m->type = type;
            label(m, "%s%s%s", row->function, row->what, allowed ? " is allowed" : "");
            m->i = row->i, m->i2 = row->i2;
            m->vr = row->v ? row->v->vr : real_in ? real_in->vr : 0;
            m->vr2 = real_out ? real_out->vr : m->vr;
            m->r = row->v && row->v->has_start ? row->v->start : 0;
            if (row->op == op_dostep) m->r = 0, m->r2 = b->cycle; /* doStep(t, cycle) */
            m->function = row->function;
            if (allowed && row->discard)
                m->expect = m->log_status = fmi2Discard, m->logs = 1;
            else if (allowed)
                m->expect = fmi2OK, m->logs = 0;
            else if (row->contains)
                snprintf(m->contains, sizeof m->contains, "%s", row->contains);
        }
    }
}

/* A misuse of an argument of `function`: labelled "<function> with <what>", its message naming
 * `contains`. */
static misuse *argument_misuse(misuse_list *list, const char *group, int phase, op_fn *op,
                               const char *function, const char *what, const char *contains)
{
    misuse *m = misuse_add(list, group, phase, op);
    label(m, "%s with %s", function, what);
    m->function = function;
    snprintf(m->contains, sizeof m->contains, "%s", contains);
    return m;
}

static void step_arguments(const block *b, misuse_list *list)
{
    const char *group = b->ops->version == 3 ? "fmi3DoStep arguments" : "fmi2DoStep arguments";
    double c = b->cycle;
    struct {
        const char *what;
        int absolute;
        double t, h;
        const char *contains;
    } steps[] = {
        {"h = 0", 0, 0, 0.0, "communicationStepSize"},
        {"h = -0", 0, 0, -0.0, "communicationStepSize"},
        {"h = -cycleTime", 0, 0, -c, "communicationStepSize"},
        {"h = -DBL_MIN", 0, 0, -DBL_MIN, "communicationStepSize"},
        {"h = NaN", 0, 0, NAN, "communicationStepSize"},
        {"h = +Inf", 0, 0, INFINITY, "communicationStepSize"},
        {"h = -Inf", 0, 0, -INFINITY, "communicationStepSize"},
        {"h = 1e300", 0, 0, 1e300, "communicationStepSize"},
        {"h = DBL_MAX", 0, 0, DBL_MAX, "communicationStepSize"},
        {"t half a cycle ahead", 0, c / 2, c, "currentCommunicationPoint"},
        {"t a cycle back", 0, -c, c, "currentCommunicationPoint"},
        {"t 1e-3 cycles ahead (the tolerance is 1e-4)", 0, c * 1e-3, c,
         "currentCommunicationPoint"},
        {"t = 0 (the start)", 1, 0, c, "currentCommunicationPoint"},
        {"t = NaN", 1, NAN, c, "currentCommunicationPoint"},
        {"t = +Inf", 1, INFINITY, c, "currentCommunicationPoint"},
        {"t = -Inf", 1, -INFINITY, c, "currentCommunicationPoint"},
        {"t = NaN and h = NaN", 1, NAN, NAN, ""},
    };
    for (size_t i = 0; i < sizeof steps / sizeof steps[0]; i++) {
        misuse *m = argument_misuse(list, group, PHASE_STEP, op_dostep, FN(b, FN_DO_STEP),
                                    steps[i].what, steps[i].contains);
        m->i = steps[i].absolute, m->r = steps[i].t, m->r2 = steps[i].h;
    }
    group = b->ops->version == 3 ? "fmi3EnterInitializationMode arguments"
                                 : "fmi2SetupExperiment arguments";
    struct {
        const char *what;
        double start;
        int stop_defined;
        double stop;
        const char *contains;
    } setups[] = {
        {"startTime = NaN", NAN, 0, 0, "startTime"},
        {"startTime = +Inf", INFINITY, 0, 0, "startTime"},
        {"startTime = -Inf", -INFINITY, 0, 0, "startTime"},
        {"stopTime before startTime", 1.0, 1, 0.5, "stopTime"},
        {"stopTime = NaN", 0.0, 1, NAN, "stopTime"},
    };
    for (size_t i = 0; i < sizeof setups / sizeof setups[0]; i++) {
        misuse *m = argument_misuse(list, group, PHASE_INSTANTIATED, op_setup, FN(b, FN_SETUP),
                                    setups[i].what, setups[i].contains);
        m->r = setups[i].start, m->i = setups[i].stop_defined, m->r2 = setups[i].stop;
    }
}

static void null_arrays_and_logging(const block *b, misuse_list *list)
{
    for (int type = 0; type < b->ops->n_types; type++) {
        const md_variable *v = first_of_type(b, type);
        uint32_t vr = v ? v->vr : 0;
        static const char *const what[] = {
            "vr NULL",    "value NULL",         "vr NULL",
            "value NULL", "nvr = 0, both NULL", "nvr = 0, both NULL"};
        for (int variant = 0; variant < 6; variant++) {
            bool set = variant == 0 || variant == 1 || variant == 4;
            misuse *m = misuse_add(list, "NULL arrays", PHASE_STEP, op_null_array);
            label(m, "%s with %s", set ? SETTER(b, type) : GETTER(b, type), what[variant]);
            m->i = type, m->i2 = variant, m->vr = vr;
            m->function = set ? SETTER(b, type) : GETTER(b, type);
            if (variant >= 4)
                m->expect = fmi2OK, m->logs = 0;
            else if (b->ops->types[type].has_table)
                snprintf(m->contains, sizeof m->contains, "NULL");
        }
    }
    static const char *const logging[] = {"unknown category",
                                          "NULL category",
                                          "categories NULL with nCategories 2",
                                          "a category full of format directives",
                                          "a valid and an unknown category",
                                          "no categories",
                                          "the three categories"};
    const char *group = b->ops->version == 3 ? "fmi3SetDebugLogging" : "fmi2SetDebugLogging";
    for (int i = 0; i < 7; i++) {
        misuse *m = misuse_add(list, group, PHASE_STEP, op_debug_logging);
        label(m, "%s with %s", FN(b, FN_SET_DEBUG_LOGGING), logging[i]);
        m->i = i;
        m->function = FN(b, FN_SET_DEBUG_LOGGING);
        if (i == 0) snprintf(m->contains, sizeof m->contains, "logNothing");
        if (i == 3) snprintf(m->contains, sizeof m->contains, "%%s%%n%%s%%s%%p%%%%");
        if (i == 4) snprintf(m->contains, sizeof m->contains, "logBogus");
        if (i >= 5) m->expect = fmi2OK, m->logs = 0;
    }
}

static void warnings(const block *b, misuse_list *list)
{
    for (size_t i = 0; i < b->md.count; i++) {
        const md_variable *v = &b->md.variables[i];
        if (!v->is_cycle) continue;
        /* not a whole number of µs: rounded to the start value, so nothing else changes */
        misuse *m = misuse_add(list, "rounded values (warnings)", PHASE_INITIALIZATION, op_set);
        label(m, "cycleTime = start + 0.4 µs");
        m->i = v->type, m->vr = v->vr, m->r = v->start + 0.4e-6;
        m->expect = fmi2Warning, m->log_status = fmi2Warning;
        m->function = SETTER(b, v->type);
        snprintf(m->contains, sizeof m->contains, "cycleTime");
    }
}

static void state_pointers(const block *b, const block *other, misuse_list *list)
{
    const char *get = FN(b, FN_GET_STATE), *set = FN(b, FN_SET_STATE),
               *free_ = FN(b, FN_FREE_STATE), *size = FN(b, FN_STATE_SIZE),
               *serialize = FN(b, FN_SERIALIZE), *deserialize = FN(b, FN_DESERIALIZE);
    static const char *const null_calls[] = {"(c, NULL)",
                                             "(c, NULL)",
                                             "(c, NULL)",
                                             "(c, NULL, &size)",
                                             "(c, s, NULL)",
                                             "(c, NULL, bytes, size)",
                                             "(c, s, NULL, size)",
                                             "(c, s, bytes, size - 1)",
                                             "(c, s, bytes, 0)",
                                             "(c, NULL, size, &s)",
                                             "(c, bytes, size, NULL)",
                                             "(c, &NULL) is allowed"};
    const char *null_functions[] = {get,       set,         free_,       size,
                                    size,      serialize,   serialize,   serialize,
                                    serialize, deserialize, deserialize, free_};
    for (int i = 0; i < 12; i++) {
        misuse *m = misuse_add(list, "FMU state pointers", PHASE_STEP, op_state_null);
        label(m, "%s%s", null_functions[i], null_calls[i]);
        m->i = i;
        m->function = null_functions[i];
        if (i == 11) m->expect = fmi2OK, m->logs = 0;
    }
    static const char *const foreign_calls[] = {" into", " of", " of", " of", " of", " into"};
    const char *foreign_functions[] = {get, set, free_, size, serialize, deserialize};
    static const char *const kinds[] = {"memory of zeros", "memory of 0xFF bytes",
                                        "a state of another FMU", "a state it freed",
                                        "an unreadable address"};
    for (int kind = 0; kind < 5; kind++) {
        if (kind == 2 && !other) continue;
        for (int i = 0; i < 6; i++) {
            misuse *m = misuse_add(list, "FMU state pointers", PHASE_STEP, op_state_foreign);
            label(m, "%s%s %s", foreign_functions[i], foreign_calls[i], kinds[kind]);
            m->i = i, m->i2 = kind;
            m->function = foreign_functions[i];
        }
    }
}

static void serialized(const block *b, const block *other, misuse_list *list)
{
    const char *group = "serialized state: header", *deserialize = FN(b, FN_DESERIALIZE);
    size_t size = 0;
    {
        /* the serialized size, for the bit sweep */
        sim s;
        unsigned char *bytes = NULL;
        if (sim_open(&s, b, 0) && sim_advance(&s, PHASE_STEP) && sim_state_bytes(&s, &bytes, &size))
            free(bytes);
        sim_close(&s);
    }
    long lengths[] = {0,
                      1,
                      8,
                      HEADER_SIZE - 1,
                      HEADER_SIZE,
                      HEADER_SIZE + 1,
                      -(long)(size / 2),
                      -8,
                      -1,
                      (long)size + 1,
                      (long)size + 8,
                      (long)size + 4000};
    for (size_t i = 0; i < sizeof lengths / sizeof lengths[0]; i++) {
        misuse *m = misuse_add(list, group, PHASE_STEP, op_deserialize);
        long n = lengths[i] >= 0 ? lengths[i] : (long)size + lengths[i];
        label(m, "%s to %ld of %zu bytes", n < (long)size ? "truncated" : "padded", n, size);
        m->i = MUT_LENGTH, m->i2 = lengths[i];
        m->function = deserialize;
    }
    long versions[] = {0, 1, 3, 0x01000000, 0xFFFFFFFF}; /* the format is version 2 */
    for (size_t i = 0; i < sizeof versions / sizeof versions[0]; i++) {
        misuse *m = misuse_add(list, group, PHASE_STEP, op_deserialize);
        label(m, "format version %ld", versions[i]);
        m->i = MUT_VERSION, m->i2 = versions[i];
        m->function = deserialize;
    }
    misuse *m = misuse_add(list, group, PHASE_STEP, op_deserialize);
    label(m, "header naming another block (%s)", other ? other->md.identifier : "LGF_Other");
    m->i = MUT_IDENTIFIER, m->function = deserialize;
    m = misuse_add(list, group, PHASE_STEP, op_deserialize);
    label(m, "header with another guid");
    m->i = MUT_GUID, m->function = deserialize;
    long deltas[] = {-8, -1, 1, 8, 0x7FFFFFFF};
    for (size_t i = 0; i < sizeof deltas / sizeof deltas[0]; i++) {
        m = misuse_add(list, group, PHASE_STEP, op_deserialize);
        label(m, "payload size field %+ld", deltas[i]);
        m->i = MUT_SIZE_FIELD, m->i2 = deltas[i], m->function = deserialize;
    }
    long both[] = {-8, 8, 64};
    for (size_t i = 0; i < sizeof both / sizeof both[0]; i++) {
        m = misuse_add(list, group, PHASE_STEP, op_deserialize);
        label(m, "payload %+ld bytes, size field and checksum matching", both[i]);
        m->i = MUT_SIZE_BOTH, m->i2 = both[i], m->function = deserialize;
    }
    if (other) {
        m = misuse_add(list, group, PHASE_STEP, op_deserialize);
        label(m, "a serialized state of %s", other->md.identifier);
        m->i = MUT_OTHER_BYTES, m->function = deserialize;
    }
    m = misuse_add(list, group, PHASE_STEP, op_deserialize);
    label(m, "a corrupt state into an existing state object");
    m->i = MUT_INTO_EXISTING, m->function = deserialize;

    for (size_t byte = 0; byte < size; byte++) {
        m = misuse_add(list, "serialized state: every byte", PHASE_STEP, op_deserialize);
        label(m, "bit %zu of byte %zu flipped", byte % 8, byte);
        m->i = MUT_FLIP, m->i2 = (long)byte, m->function = deserialize;
    }
}

/* States with a valid header and checksum whose content no instance can have: made by an
 * importer that writes bytes itself, or by a defect. Needs the layout found by experiment. */
static misuse *crafted(const block *b, misuse_list *list, const char *what, int expect)
{
    misuse *m = misuse_add(list, "serialized state: crafted", PHASE_STEP, op_deserialize);
    label(m, "%s", what);
    m->i = MUT_PATCH;
    m->function = FN(b, FN_DESERIALIZE);
    if (expect == fmi2OK) m->expect = fmi2OK, m->logs = 0;
    return m;
}

static void add_patch(misuse *m, size_t offset, int width, uint64_t bits)
{
    m->patches[m->n_patches++] = (patch){offset, width, bits};
}

static uint64_t float_bits(float value)
{
    uint32_t bits;
    memcpy(&bits, &value, sizeof bits);
    return bits;
}

static void crafted_states(const block *b, misuse_list *list)
{
    if (!b->layout_known) return;
    const md_variable *cycle = NULL;
    for (size_t i = 0; i < b->md.count; i++)
        if (b->md.variables[i].is_cycle) cycle = &b->md.variables[i];
    misuse *m = crafted(b, list, "unchanged bytes, checksum recomputed", fmi2OK);
    add_patch(m, CLOCK_MODE, 4, MODE_STEP);
    m = crafted(b, list, "mode terminated", fmi2OK);
    add_patch(m, CLOCK_MODE, 4, MODE_TERMINATED);
    /* event and continuous-time mode are Model Exchange modes: no co-simulation state */
    uint32_t modes[] = {MODE_EVENT, MODE_CONTINUOUS, MODE_TERMINATED + 1, 0xFFFFFFFFu, 0x100};
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        char what[64];
        snprintf(what, sizeof what, "mode %d%s", (int32_t)modes[i],
                 modes[i] == MODE_EVENT        ? " (event mode)"
                 : modes[i] == MODE_CONTINUOUS ? " (continuous-time mode)"
                                               : "");
        add_patch(crafted(b, list, what, fmi2Error), CLOCK_MODE, 4, modes[i]);
    }
    add_patch(crafted(b, list, "cycle 0 µs", fmi2Error), CLOCK_CYCLE_US, 4, 0);
    add_patch(crafted(b, list, "cycle -1 µs", fmi2Error), CLOCK_CYCLE_US, 4, 0xFFFFFFFFu);
    if (cycle && cycle->has_min && cycle->has_max) {
        long low = lround(cycle->min * 1e6) - 1, high = lround(cycle->max * 1e6) + 1;
        char what[64];
        if (low > 0) {
            snprintf(what, sizeof what, "cycle %ld µs (below min)", low);
            add_patch(crafted(b, list, what, fmi2Error), CLOCK_CYCLE_US, 4, (uint64_t)low);
        }
        snprintf(what, sizeof what, "cycle %ld µs (above max)", high);
        add_patch(crafted(b, list, what, fmi2Error), CLOCK_CYCLE_US, 4, (uint64_t)high);
    }
    add_patch(crafted(b, list, "startTime NaN", fmi2Error), CLOCK_START, 8, bits_of(NAN));
    add_patch(crafted(b, list, "startTime +Inf", fmi2Error), CLOCK_START, 8, bits_of(INFINITY));
    add_patch(crafted(b, list, "time NaN", fmi2Error), CLOCK_TIME, 8, bits_of(NAN));
    add_patch(crafted(b, list, "time -Inf", fmi2Error), CLOCK_TIME, 8, bits_of(-INFINITY));
    add_patch(crafted(b, list, "calls -1", fmi2Error), CLOCK_CALLS, 8, UINT64_MAX);
    add_patch(crafted(b, list, "calls INT64_MIN", fmi2Error), CLOCK_CALLS, 8, 0x8000000000000000u);
    /* The clock must be one an instance can reach: a call counter whose time in µs fits the
     * 64 bits of the PLC clock, and a counter that matches the communication point (else the
     * next doStep would run up to ~1e15 calls to catch up). */
    if (cycle && cycle->has_max) {
        double c = cycle->max;
        uint64_t cycle_us = (uint64_t)llround(c * 1e6);
        m = crafted(b, list, "max cycle, 2e11 calls: their µs overflow 64 bits", fmi2Error);
        add_patch(m, CLOCK_CYCLE_US, 4, cycle_us);
        add_patch(m, CLOCK_CALLS, 8, 200000000000u);
        add_patch(m, CLOCK_TIME, 8, bits_of((200000000000.0 - 1) * c));
        m = crafted(b, list, "max cycle, 1000 calls at a matching time", fmi2OK);
        add_patch(m, CLOCK_CYCLE_US, 4, cycle_us);
        add_patch(m, CLOCK_CALLS, 8, 1000);
        add_patch(m, CLOCK_TIME, 8, bits_of(999 * c));
    }
    add_patch(crafted(b, list, "time 1e14 s, calls as they were", fmi2Error), CLOCK_TIME, 8,
              bits_of(1e14));
    add_patch(crafted(b, list, "calls 1e6, time as it was", fmi2Error), CLOCK_CALLS, 8, 1000000);
    add_patch(crafted(b, list, "mode instantiated after calls", fmi2Error), CLOCK_MODE, 4,
              PHASE_INSTANTIATED);

    for (int i = 0; i < b->n_located; i++) {
        const located_variable *where = &b->located[i];
        const md_variable *v = &b->md.variables[where->index];
        char what[160];
        if (v->kind == KIND_BOOLEAN) {
            snprintf(what, sizeof what, "%s holds byte 2", v->name);
            m = crafted(b, list, what, fmi2Error);
            add_patch(m, where->offset, 1, 2);
            snprintf(m->contains, sizeof m->contains, "%s", v->name);
            snprintf(what, sizeof what, "%s holds byte 0xFF", v->name);
            m = crafted(b, list, what, fmi2Error);
            add_patch(m, where->offset, 1, 0xFF);
            snprintf(m->contains, sizeof m->contains, "%s", v->name);
        } else if (v->kind == KIND_REAL && where->width == 8) {
            snprintf(what, sizeof what, "%s holds NaN", v->name);
            m = crafted(b, list, what, fmi2Error);
            add_patch(m, where->offset, 8, bits_of(NAN));
            snprintf(m->contains, sizeof m->contains, "%s", v->name);
        } else if (v->kind == KIND_REAL && !v->is_time && where->width == 4) { /* a REAL */
            snprintf(what, sizeof what, "%s holds NaN (float)", v->name);
            m = crafted(b, list, what, fmi2Error);
            add_patch(m, where->offset, 4, float_bits(NAN));
            snprintf(m->contains, sizeof m->contains, "%s", v->name);
            if (v->has_max && (float)v->max < FLT_MAX) {
                float above = nextafterf((float)v->max, INFINITY);
                snprintf(what, sizeof what, "%s holds %.9g (above max)", v->name, (double)above);
                m = crafted(b, list, what, fmi2Error);
                add_patch(m, where->offset, 4, float_bits(above));
                snprintf(m->contains, sizeof m->contains, "%s", v->name);
            }
        } else if (v->kind == KIND_REAL && v->is_time && where->width == 4) {
            int64_t low = v->has_min ? (int64_t)llround(v->min * 1000) - 1 : INT64_MIN;
            if (low >= INT32_MIN) {
                snprintf(what, sizeof what, "%s holds %lld ms (below min)", v->name,
                         (long long)low);
                m = crafted(b, list, what, fmi2Error);
                add_patch(m, where->offset, 4, (uint64_t)(uint32_t)(int32_t)low);
                snprintf(m->contains, sizeof m->contains, "%s", v->name);
            }
            int64_t high = v->has_max ? (int64_t)llround(v->max * 1000) + 1 : INT64_MAX;
            if (high <= INT32_MAX) {
                snprintf(what, sizeof what, "%s holds %lld ms (above max)", v->name,
                         (long long)high);
                m = crafted(b, list, what, fmi2Error);
                add_patch(m, where->offset, 4, (uint64_t)(uint32_t)(int32_t)high);
                snprintf(m->contains, sizeof m->contains, "%s", v->name);
            }
        } else if (v->kind == KIND_INTEGER && where->width == 2) {
            double limits[2] = {v->has_min ? v->min - 1 : -1e9, v->has_max ? v->max + 1 : 1e9};
            for (int k = 0; k < 2; k++) {
                if (limits[k] < -32768 || limits[k] > 32767) continue;
                snprintf(what, sizeof what, "%s holds %g", v->name, limits[k]);
                m = crafted(b, list, what, fmi2Error);
                add_patch(m, where->offset, 2, (uint64_t)(uint16_t)(int16_t)limits[k]);
                snprintf(m->contains, sizeof m->contains, "%s", v->name);
            }
        } else if (v->kind == KIND_INTEGER && where->width == 4) { /* a UDINT */
            /* FMI 2.0 declares what an fmi2Integer carries (max 2^31 - 1): a state beyond it
             * is one no FMI 2.0 run produces */
            double limits[2] = {v->has_min ? v->min - 1 : -1,
                                v->has_max ? v->max + 1 : 4294967296.0};
            for (int k = 0; k < 2; k++) {
                if (limits[k] < 0 || limits[k] > 4294967295.0) continue;
                snprintf(what, sizeof what, "%s holds %.0f", v->name, limits[k]);
                m = crafted(b, list, what, fmi2Error);
                add_patch(m, where->offset, 4, (uint64_t)(uint32_t)limits[k]);
                snprintf(m->contains, sizeof m->contains, "%s", v->name);
            }
        }
    }
}

void build_misuses(const block *b, const block *other, misuse_list *list)
{
    out_of_range(b, list);
    wrong_variables(b, list);
    unknown_references(b, list);
    multiple_values(b, list);
    step_arguments(b, list);
    null_arrays_and_logging(b, list);
    warnings(b, list);
    state_pointers(b, other, list);
    serialized(b, other, list);
    crafted_states(b, list);
}

/* Groups the cases for the report: a stable sort by the order in which group names first
 * appear. */
void sort_misuses(misuse_list *list)
{
    size_t n = list->count;
    misuse *sorted = malloc(n * sizeof *sorted);
    if (!sorted) return;
    size_t k = 0;
    for (size_t i = 0; i < n; i++) {
        bool seen = false;
        for (size_t j = 0; j < i && !seen; j++)
            seen = !strcmp(list->items[j].group, list->items[i].group);
        if (seen) continue;
        for (size_t j = i; j < n; j++)
            if (!strcmp(list->items[j].group, list->items[i].group)) sorted[k++] = list->items[j];
    }
    memcpy(list->items, sorted, n * sizeof *sorted);
    free(sorted);
}

/* ---- Model Exchange ---- */

#define SENTINEL (-7.25) /* what the arrays of the nx = 0 functions hold before a call */

/* One Model Exchange function (i), with arguments by i2:
 *   the event iteration          0 valid out-arguments (checked when OK), 1 NULL
 *   the integrator step done     0 both pointers valid (checked when OK), 1 enterEventMode
 *                                NULL, 2 terminateSimulation NULL, 3 both NULL
 *   the time                     0 the sim's time + r, 1 r
 *   the array functions          nx (or ni) 0, 1 or SIZE_MAX (i2 = 0, 1, 2); vr2 = 1: the
 *                                array is NULL, else it must come back untouched (nothing
 *                                to write for nx = 0, and a refused call writes nothing) */
int op_me(sim *s, const misuse *m)
{
    const block *b = s->b;
    double x[8];
    for (int j = 0; j < 8; j++) x[j] = SENTINEL;
    double *array = m->vr2 ? NULL : x;
    size_t n = m->i2 == 0 ? 0 : m->i2 == 1 ? 1 : SIZE_MAX;
    int result = -1;
    switch (m->i) {
    case ME_ENTER_EVENT: return FMU(b, enter_event, s->c);
    case ME_NEW_DISCRETE: {
        if (m->i2) return FMU(b, update_discrete, s->c, NULL);
        event_info info;
        double next = call_time(b, s->k + 1);
        result = FMU(b, update_discrete, s->c, &info);
        if (result == fmi2OK &&
            (info.needed || info.terminate || info.nominals_changed || info.values_changed ||
             info.next_defined != 1 || info.next != next))
            result = OTHER_RESULT;
        return result;
    }
    case ME_ENTER_CONTINUOUS: return FMU(b, enter_continuous, s->c);
    case ME_COMPLETED: {
        int enter = 1, terminate = 1;
        result = FMU(b, completed, s->c, false, m->i2 == 1 || m->i2 == 3 ? NULL : &enter,
                     m->i2 == 2 || m->i2 == 3 ? NULL : &terminate);
        if (result == fmi2OK && (enter != 0 || terminate != 0)) result = OTHER_RESULT;
        if (result != fmi2OK && (enter != 1 || terminate != 1)) result = OTHER_RESULT;
        return result;
    }
    case ME_SET_TIME: return FMU(b, set_time, s->c, m->i2 ? m->r : s->t + m->r);
    default: result = FMU(b, no_states, s->c, (int)m->i - ME_SET_STATES, array, n); break;
    }
    for (int j = 0; j < 8; j++)
        if (x[j] != SENTINEL) result = OTHER_RESULT;
    return result;
}

/* getting and freeing a state: allowed in every mode of both interfaces */
int op_get_free_state(sim *s, const misuse *m)
{
    (void)m;
    void *state = NULL;
    int got = FMU(s->b, get_state, s->c, &state);
    if (got != fmi2OK) return got;
    int freed = FMU(s->b, free_state, s->c, &state);
    return state ? OTHER_RESULT : freed;
}

/* The Model Exchange functions with a NULL instance (i: the function). */
int op_me_null_component(sim *s, const misuse *m)
{
    const block *b = s->b;
    event_info info;
    int enter = 1, terminate = 1;
    switch (m->i) {
    case ME_ENTER_EVENT: return FMU(b, enter_event, NULL);
    case ME_NEW_DISCRETE: return FMU(b, update_discrete, NULL, &info);
    case ME_ENTER_CONTINUOUS: return FMU(b, enter_continuous, NULL);
    case ME_COMPLETED: return FMU(b, completed, NULL, false, &enter, &terminate);
    case ME_SET_TIME: return FMU(b, set_time, NULL, 0.0);
    default: return FMU(b, no_states, NULL, (int)m->i - ME_SET_STATES, NULL, 0);
    }
}

/* The Model Exchange functions on a co-simulation instance, in every mode: refused, naming
 * the interface. */
static void me_on_co_simulation(const block *b, misuse_list *list)
{
    for (int f = 0; f < ME_FUNCTIONS; f++) {
        for (int phase = PHASE_INSTANTIATED; phase <= PHASE_TERMINATED; phase++) {
            misuse *m = misuse_add(list, "ME functions on co-simulation", phase, op_me);
            label(m, "%s", FN(b, FN_ENTER_EVENT + f));
            m->i = f;
            m->function = FN(b, FN_ENTER_EVENT + f);
            snprintf(m->contains, sizeof m->contains, "Model Exchange function");
        }
    }
}

static void me_arguments(const block *b, misuse_list *list)
{
    double c = b->cycle, stop = me_stop_time(b), t = call_time(b, STEP_PHASE_AT);
    const char *set_time = FN(b, FN_SET_TIME);
    struct {
        const char *what;
        int absolute;
        double r;
        int expect;
        const char *contains;
    } times[] = {
        {"a cycle back", 0, -c, fmi2Error, "not before"},
        {"1.1e-4 cycles back (the tolerance is 1e-4)", 0, -1.1e-4 * c, fmi2Error, "not before"},
        {"2e-4 cycles back", 0, -2e-4 * c, fmi2Error, "not before"},
        {"the start time, 0", 1, 0.0, fmi2Error, "not before"},
        {"-DBL_MAX", 1, -DBL_MAX, fmi2Error, "not before"},
        {"NaN", 1, NAN, fmi2Error, "finite"},
        {"-NaN", 1, -NAN, fmi2Error, "finite"},
        {"+Inf", 1, INFINITY, fmi2Error, "finite"},
        {"-Inf", 1, -INFINITY, fmi2Error, "finite"},
        {"1e300", 1, 1e300, fmi2Error, "beyond the last call"},
        {"DBL_MAX", 1, DBL_MAX, fmi2Error, "beyond the last call"},
        /* accepted, and applied */
        {"0.5e-4 cycles back (within the tolerance)", 0, -0.5e-4 * c, fmi2OK, NULL},
        {"the stopTime", 1, stop, fmi2OK, NULL},
        {"0.5e-4 cycles past the stopTime (within the tolerance)", 1, stop + 0.5e-4 * c, fmi2OK,
         NULL},
        /* the stop time binds co-simulation steps; an integrator may look beyond it */
        {"2e-4 cycles past the stopTime", 1, stop + 2e-4 * c, fmi2OK, NULL},
        {"a cycle past the stopTime", 1, stop + c, fmi2OK, NULL},
        {"half a cycle on", 0, 0.5 * c, fmi2OK, NULL},
    };
    const char *time_group =
        b->ops->version == 3 ? "ME: fmi3SetTime arguments" : "ME: fmi2SetTime arguments";
    for (int phase = PHASE_STEP; phase <= PHASE_CONTINUOUS;
         phase += PHASE_CONTINUOUS - PHASE_STEP) {
        for (size_t i = 0; i < sizeof times / sizeof times[0]; i++) {
            misuse *m = misuse_add(list, time_group, phase, op_me);
            m->type = fmi2ModelExchange;
            label(m, "%s to %s (t = %.17g)", set_time, times[i].what,
                  times[i].absolute ? times[i].r : t + times[i].r);
            m->i = ME_SET_TIME, m->i2 = times[i].absolute, m->r = times[i].r;
            m->function = set_time;
            if (times[i].expect == fmi2OK)
                m->expect = fmi2OK, m->logs = 0, m->changes_state = true;
            else
                snprintf(m->contains, sizeof m->contains, "%s", times[i].contains);
        }
    }
    const char *group = "ME: arguments";
    misuse *m = misuse_add(list, group, PHASE_STEP, op_me);
    m->type = fmi2ModelExchange;
    label(m, "%s with %s", FN(b, FN_UPDATE_DISCRETE),
          b->ops->version == 3 ? "every out-pointer NULL" : "eventInfo NULL");
    m->i = ME_NEW_DISCRETE, m->i2 = 1, m->function = FN(b, FN_UPDATE_DISCRETE);
    snprintf(m->contains, sizeof m->contains, "%s", b->ops->version == 3 ? "NULL" : "eventInfo");
    static const char *const completed[] = {"", "enterEventMode NULL", "terminateSimulation NULL",
                                            "both NULL"};
    for (int i = 1; i <= 3; i++) {
        m = misuse_add(list, group, PHASE_CONTINUOUS, op_me);
        m->type = fmi2ModelExchange;
        label(m, "%s with %s", FN(b, FN_COMPLETED), completed[i]);
        m->i = ME_COMPLETED, m->i2 = i, m->function = FN(b, FN_COMPLETED);
        snprintf(m->contains, sizeof m->contains, "NULL");
    }
    /* the FMU has no continuous states and no event indicators: nx and ni must be 0 */
    for (int f = ME_SET_STATES; f <= ME_GET_NOMINALS; f++) {
        int phases[] = {PHASE_STEP, PHASE_CONTINUOUS};
        for (int p = 0; p < 2; p++) {
            if (f == ME_SET_STATES && phases[p] != PHASE_CONTINUOUS) continue;
            for (int n = 0; n <= 2; n++) {
                for (int null = 0; null <= 1; null++) {
                    m = misuse_add(list, group, phases[p], op_me);
                    m->type = fmi2ModelExchange;
                    /* FMI 3.0 names the counts nContinuousStates and nEventIndicators */
                    const char *count =
                        b->ops->version == 3
                            ? (f == ME_GET_INDICATORS ? "nEventIndicators" : "nContinuousStates")
                            : (f == ME_GET_INDICATORS ? "ni" : "nx");
                    label(m, "%s with %s = %s and %s", FN(b, FN_ENTER_EVENT + f), count,
                          n == 0   ? "0"
                          : n == 1 ? "1"
                                   : "SIZE_MAX",
                          null ? "a NULL array" : "an array");
                    m->i = f, m->i2 = n, m->vr2 = (uint32_t)null;
                    m->function = FN(b, FN_ENTER_EVENT + f);
                    if (n == 0)
                        m->expect = fmi2OK, m->logs = 0;
                    else
                        snprintf(m->contains, sizeof m->contains, "%s is", count);
                }
            }
        }
    }
    for (int f = 0; f < ME_FUNCTIONS; f++) {
        m = misuse_add(list, "ME: NULL component", PHASE_STEP, op_me_null_component);
        m->type = fmi2ModelExchange;
        label(m, "%s(NULL, ...)", FN(b, FN_ENTER_EVENT + f));
        m->i = f, m->logs = 0;
    }
}

/* Model Exchange states with a valid header and checksum whose clock is changed. */
static void me_crafted_states(const block *b, misuse_list *list)
{
    if (!b->layout_known) return;
    struct {
        const char *what;
        int phase;
        uint32_t mode;
        int expect;
    } modes[] = {
        {"unchanged bytes, checksum recomputed", PHASE_STEP, MODE_EVENT, fmi2OK},
        {"mode continuous-time instead of event", PHASE_STEP, MODE_CONTINUOUS, fmi2OK},
        {"mode event instead of continuous-time", PHASE_CONTINUOUS, MODE_EVENT, fmi2OK},
        {"mode terminated", PHASE_STEP, MODE_TERMINATED, fmi2OK},
        {"mode step (co-simulation)", PHASE_STEP, MODE_STEP, fmi2Error},
        {"mode step (co-simulation)", PHASE_CONTINUOUS, MODE_STEP, fmi2Error},
        {"mode instantiated after calls", PHASE_STEP, MODE_INSTANTIATED, fmi2Error},
        {"mode 6", PHASE_STEP, MODE_TERMINATED + 1, fmi2Error},
    };
    for (size_t i = 0; i < sizeof modes / sizeof modes[0]; i++) {
        misuse *m = crafted(b, list, modes[i].what, modes[i].expect);
        m->group = "ME: crafted states";
        m->type = fmi2ModelExchange;
        m->phase = modes[i].phase;
        add_patch(m, CLOCK_MODE, 4, modes[i].mode);
    }
    /* In event mode at t_k, call k may still be due (the time set, the event not handled). */
    int64_t k = STEP_PHASE_AT;
    misuse *m = crafted(b, list, "calls one behind the time (call k due at t_k)", fmi2OK);
    m->group = "ME: crafted states", m->type = fmi2ModelExchange;
    add_patch(m, CLOCK_CALLS, 8, (uint64_t)k);
    m = crafted(b, list, "calls two ahead of the time", fmi2Error);
    m->group = "ME: crafted states", m->type = fmi2ModelExchange;
    add_patch(m, CLOCK_CALLS, 8, (uint64_t)k + 3);
    m = crafted(b, list, "time past the stopTime (an integrator may look beyond it)", fmi2OK);
    m->group = "ME: crafted states", m->type = fmi2ModelExchange;
    add_patch(m, CLOCK_TIME, 8, bits_of(me_stop_time(b) + b->cycle));
}

void build_me_misuses(const block *b, misuse_list *list)
{
    me_on_co_simulation(b, list);
    me_arguments(b, list);
    me_crafted_states(b, list);
}

/* ---- the cases only FMI 2.0 has ---- */

enum {
    I = 1 << PHASE_INSTANTIATED,
    N = 1 << PHASE_INITIALIZATION,
    S = 1 << PHASE_STEP,
    T = 1 << PHASE_TERMINATED,
    C = 1 << PHASE_CONTINUOUS,
    ALL = I | N | S | T | C
};

/* Every function that depends on the state, in every state: refused where FMI 2.0 (4.2.4,
 * the co-simulation state table) forbids it; where it allows a call that changes nothing (a
 * get, a status query, a String call with nvr = 0), the call succeeds without a message. */
static void wrong_states(const block *b, misuse_list *list)
{
    const md_variable *real = first_of(b, KIND_REAL, is_any),
                      *integer = first_of(b, KIND_INTEGER, is_any),
                      *boolean = first_of(b, KIND_BOOLEAN, is_any);
    const md_variable *real_in = first_of(b, KIND_REAL, is_input),
                      *integer_in = first_of(b, KIND_INTEGER, is_input),
                      *boolean_in = first_of(b, KIND_BOOLEAN, is_input);
    const mode_row rows[] = {
        {"fmi2SetupExperiment", "", op_setup, 0, 0, NULL, I, 0, NULL, false},
        {"fmi2EnterInitializationMode", "", op_enter, 0, 0, NULL, I, 0, NULL, false},
        {"fmi2ExitInitializationMode", "", op_exit, 0, 0, NULL, N, 0, NULL, false},
        {"fmi2DoStep", "", op_dostep, 0, 0, NULL, S, 0, NULL, false},
        {"fmi2Terminate", "", op_terminate, 0, 0, NULL, S, 0, NULL, false},
        {"fmi2GetReal", "", op_get, KIND_REAL, 0, real, N | S | T, N | S | T, NULL, false},
        {"fmi2GetInteger", "", op_get, KIND_INTEGER, 0, integer, N | S | T, N | S | T, NULL, false},
        {"fmi2GetBoolean", "", op_get, KIND_BOOLEAN, 0, boolean, N | S | T, N | S | T, NULL, false},
        {"fmi2GetString", " with nvr = 0", op_null_array, KIND_STRING, 5, NULL, N | S | T,
         N | S | T, NULL, false},
        {"fmi2SetReal", " of an input", op_set, KIND_REAL, 0, real_in, I | N | S, 0, NULL, false},
        {"fmi2SetInteger", " of an input", op_set, KIND_INTEGER, 0, integer_in, I | N | S, 0, NULL,
         false},
        {"fmi2SetBoolean", " of an input", op_set, KIND_BOOLEAN, 0, boolean_in, I | N | S, 0, NULL,
         false},
        {"fmi2SetString", " with nvr = 0", op_null_array, KIND_STRING, 4, NULL, I | N | S,
         I | N | S, NULL, false},
        {"fmi2GetRealStatus", "(fmi2LastSuccessfulTime)", op_unsupported, 11, 0, NULL, S | T, S | T,
         NULL, false},
        {"fmi2GetBooleanStatus", "(fmi2Terminated)", op_unsupported, 12, 0, NULL, S | T, S | T,
         NULL, false},
        /* never available (no asynchronous steps, so no pending status): where the status
         * functions may be called, fmi2Discard (FMI 2.0, 4.2.3) */
        {"fmi2GetStatus", "(fmi2DoStepStatus)", op_unsupported, 1, 0, NULL, S | T, S | T, NULL,
         true},
        {"fmi2GetIntegerStatus", "", op_unsupported, 4, 0, NULL, S | T, S | T, NULL, true},
        {"fmi2GetStringStatus", "(fmi2PendingStatus)", op_unsupported, 7, 0, NULL, S | T, S | T,
         NULL, true},
        {"fmi2CancelStep", "", op_unsupported, 0, 0, NULL, 0, 0, NULL, false},
    };
    static const int phases[] = {PHASE_INSTANTIATED, PHASE_INITIALIZATION, PHASE_STEP,
                                 PHASE_TERMINATED};
    add_mode_cases(b, list, "calls in the wrong state", fmi2CoSimulation, rows,
                   sizeof rows / sizeof rows[0], phases, sizeof phases / sizeof phases[0]);
}

static void null_and_unsupported(const block *b, misuse_list *list)
{
    const md_variable *real_in = first_of(b, KIND_REAL, is_input);
    const md_variable *real_out = first_of(b, KIND_REAL, is_output);
    const md_variable *any_real = first_of(b, KIND_REAL, is_any);
    for (int i = 0; i < NULL_COMPONENT_CALLS; i++) {
        misuse *m = misuse_add(list, "NULL component", PHASE_STEP, op_null_component);
        label(m, "%s(NULL, ...)", NULL_COMPONENT_NAMES[i]);
        m->i = i, m->vr = any_real ? any_real->vr : 0, m->logs = 0;
        if (i == 30) m->expect = fmi2OK; /* fmi2FreeInstance(NULL): a no-op */
    }
    static const char *const unsupported[] = {"fmi2CancelStep",
                                              "fmi2GetStatus",
                                              "fmi2GetRealStatus",
                                              "fmi2GetRealStatus",
                                              "fmi2GetIntegerStatus",
                                              "fmi2GetBooleanStatus",
                                              "fmi2GetBooleanStatus",
                                              "fmi2GetStringStatus",
                                              "fmi2SetRealInputDerivatives",
                                              "fmi2GetRealOutputDerivatives",
                                              "fmi2GetDirectionalDerivative",
                                              "fmi2GetRealStatus",
                                              "fmi2GetBooleanStatus",
                                              "fmi2SetRealInputDerivatives",
                                              "fmi2GetDirectionalDerivative"};
    static const char *const detail[] = {"",
                                         "(fmi2DoStepStatus)",
                                         "(fmi2DoStepStatus)",
                                         "(fmi2LastSuccessfulTime, NULL)",
                                         "(fmi2DoStepStatus)",
                                         "(fmi2DoStepStatus)",
                                         "(fmi2Terminated, NULL)",
                                         "(fmi2PendingStatus)",
                                         "",
                                         "",
                                         "",
                                         "(fmi2LastSuccessfulTime) is supported",
                                         "(fmi2Terminated) is supported",
                                         "with NULL arrays",
                                         "with NULL arrays"};
    for (int i = 0; i < 15; i++) {
        misuse *m = misuse_add(list, "unsupported functions", PHASE_STEP, op_unsupported);
        label(m, "%s %s", unsupported[i], detail[i]);
        m->i = i;
        m->vr = real_in ? real_in->vr : 0;
        m->vr2 = real_out ? real_out->vr : m->vr;
        m->function = unsupported[i];
        if (i == 11 || i == 12) m->expect = fmi2OK, m->logs = 0;
        /* a status kind the FMU cannot provide (FMI 2.0, 4.2.3) */
        if (i == 1 || i == 2 || i == 4 || i == 5 || i == 7) m->expect = m->log_status = fmi2Discard;
    }
    misuse *m = misuse_add(list, "FMU state out of memory", PHASE_STEP, op_out_of_memory);
    label(m, "fmi2GetFMUstate when allocateMemory fails");
    m->i = 0, m->function = "fmi2GetFMUstate";
    snprintf(m->contains, sizeof m->contains, "memory");
    m = misuse_add(list, "FMU state out of memory", PHASE_STEP, op_out_of_memory);
    label(m, "fmi2DeSerializeFMUstate when allocateMemory fails");
    m->i = 1, m->function = "fmi2DeSerializeFMUstate";
    snprintf(m->contains, sizeof m->contains, "memory");
}

/* Every function whose use depends on the mode, in every mode of a Model Exchange instance
 * (FMI 2.0, 3.2.3), and the co-simulation functions there. Where a call is allowed and
 * changes nothing (a get, a second event iteration, fmi2SetTime to the FMU's own time,
 * fmi2CompletedIntegratorStep, the nx = 0 functions) it is made: fmi2OK, no message. */
static void me_wrong_modes(const block *b, misuse_list *list)
{
    const md_variable *real = first_of(b, KIND_REAL, is_any),
                      *integer = first_of(b, KIND_INTEGER, is_any),
                      *boolean = first_of(b, KIND_BOOLEAN, is_any);
    const md_variable *real_in = first_of(b, KIND_REAL, is_input),
                      *integer_in = first_of(b, KIND_INTEGER, is_input),
                      *boolean_in = first_of(b, KIND_BOOLEAN, is_input);
    const char *mode = "must not be called in", *cs = "co-simulation function",
               *no = "not supported";
    const mode_row rows[] = {
        {"fmi2SetupExperiment", "", op_setup, 0, 0, NULL, I, 0, mode, false},
        {"fmi2EnterInitializationMode", "", op_enter, 0, 0, NULL, I, 0, mode, false},
        {"fmi2ExitInitializationMode", "", op_exit, 0, 0, NULL, N, 0, mode, false},
        {"fmi2Terminate", "", op_terminate, 0, 0, NULL, S | C, 0, mode, false},
        {"fmi2GetReal", "", op_get, KIND_REAL, 0, real, N | S | C | T, N | S | C | T, "must not",
         false},
        {"fmi2GetInteger", "", op_get, KIND_INTEGER, 0, integer, N | S | C | T, N | S | C | T,
         "must not", false},
        {"fmi2GetBoolean", "", op_get, KIND_BOOLEAN, 0, boolean, N | S | C | T, N | S | C | T,
         "must not", false},
        {"fmi2GetString", " with nvr = 0", op_null_array, KIND_STRING, 5, NULL, N | S | C | T,
         N | S | C | T, "must not", false},
        {"fmi2SetReal", " of an input", op_set, KIND_REAL, 0, real_in, I | N | S | C, 0, "must not",
         false},
        /* discrete inputs are taken in continuous-time mode too, for importers that set them
         * there (OMSimulator); the next PLC call reads them (docs/behaviour.md §1.11) */
        {"fmi2SetInteger", " of an input", op_set, KIND_INTEGER, 0, integer_in, I | N | S | C, 0,
         "must not", false},
        {"fmi2SetBoolean", " of an input", op_set, KIND_BOOLEAN, 0, boolean_in, I | N | S | C, 0,
         "must not", false},
        {"fmi2SetString", " with nvr = 0", op_null_array, KIND_STRING, 4, NULL, I | N | S | C,
         I | N | S | C, "must not", false},
        {"fmi2EnterEventMode", "", op_me, ME_ENTER_EVENT, 0, NULL, S | C, S, "must not", false},
        {"fmi2NewDiscreteStates", "", op_me, ME_NEW_DISCRETE, 0, NULL, S, S, "must not", false},
        {"fmi2EnterContinuousTimeMode", "", op_me, ME_ENTER_CONTINUOUS, 0, NULL, S, 0, "must not",
         false},
        {"fmi2CompletedIntegratorStep", "", op_me, ME_COMPLETED, 0, NULL, C, C, "must not", false},
        {"fmi2SetTime", " (the FMU's time)", op_me, ME_SET_TIME, 0, NULL, S | C, S | C, "must not",
         false},
        {"fmi2SetContinuousStates", " with nx = 0", op_me, ME_SET_STATES, 0, NULL, C, C, "must not",
         false},
        {"fmi2GetDerivatives", " with nx = 0", op_me, ME_GET_DERIVATIVES, 0, NULL, N | S | C | T,
         N | S | C | T, "must not", false},
        {"fmi2GetEventIndicators", " with ni = 0", op_me, ME_GET_INDICATORS, 0, NULL, N | S | C | T,
         N | S | C | T, "must not", false},
        {"fmi2GetContinuousStates", " with nx = 0", op_me, ME_GET_STATES, 0, NULL, N | S | C | T,
         N | S | C | T, "must not", false},
        {"fmi2GetNominalsOfContinuousStates", " with nx = 0", op_me, ME_GET_NOMINALS, 0, NULL, ALL,
         ALL, "must not", false},
        {"fmi2GetFMUstate", " and fmi2FreeFMUstate", op_get_free_state, 0, 0, NULL, ALL, ALL,
         "must not", false},
        /* co-simulation only: refused in every mode, naming the interface */
        {"fmi2DoStep", "", op_dostep, 0, 0, NULL, 0, 0, cs, false},
        {"fmi2GetStatus", "(fmi2DoStepStatus)", op_unsupported, 1, 0, NULL, 0, 0, cs, false},
        {"fmi2GetRealStatus", "(fmi2LastSuccessfulTime)", op_unsupported, 11, 0, NULL, 0, 0, cs,
         false},
        {"fmi2GetIntegerStatus", "", op_unsupported, 4, 0, NULL, 0, 0, cs, false},
        {"fmi2GetBooleanStatus", "(fmi2Terminated)", op_unsupported, 12, 0, NULL, 0, 0, cs, false},
        {"fmi2GetStringStatus", "(fmi2PendingStatus)", op_unsupported, 7, 0, NULL, 0, 0, cs, false},
        /* not supported in either interface */
        {"fmi2CancelStep", "", op_unsupported, 0, 0, NULL, 0, 0, no, false},
        {"fmi2SetRealInputDerivatives", "", op_unsupported, 8, 0, NULL, 0, 0, no, false},
        {"fmi2GetRealOutputDerivatives", "", op_unsupported, 9, 0, NULL, 0, 0, no, false},
        {"fmi2GetDirectionalDerivative", "", op_unsupported, 10, 0, NULL, 0, 0, no, false},
    };
    static const int phases[] = {PHASE_INSTANTIATED, PHASE_INITIALIZATION, PHASE_STEP,
                                 PHASE_CONTINUOUS, PHASE_TERMINATED};
    add_mode_cases(b, list, "ME: calls in the wrong mode", fmi2ModelExchange, rows,
                   sizeof rows / sizeof rows[0], phases, sizeof phases / sizeof phases[0]);
}

void build_fmi2_misuses(const block *b, misuse_list *list)
{
    wrong_states(b, list);
    null_and_unsupported(b, list);
    me_wrong_modes(b, list);
}
