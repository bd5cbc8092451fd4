/* The C harness of the LGF FMUs: drives one block's FMU binary through dlopen, as an importer
 * does, and checks every misuse of docs/behaviour.md §1.7, FMU states, leaks and threads.
 *
 *   harness [options] <Block>.so <Block>.xml <guid> [<Other>.so <Other>.xml <other guid>]
 *
 * The optional second block supplies a state and a serialized state of another FMU.
 * Options: --cycles N (instantiate/free and state cycles, default 10000), --threads N
 * (default 8), --rounds N (parallel rounds, default 10), --timeout S (default 600).
 * Prints one line per group of checks and ends with "N passed, M failed". */
#define _POSIX_C_SOURCE 200809L
#include "harness.h"

#include <float.h>
#include <math.h>
#include <pthread.h>
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

int STEPS = 30;
int STEP_PHASE_AT = 10;
foreign_states FOREIGN;

static long CYCLES = 10000;
static int THREADS = 8;
static int ROUNDS = 10;

/* ---- checks ---- */

static int passed, failed, group_passed, group_failed, printed_failures;
static const char *group_name = "";
static struct timespec group_start;

static double seconds_since(const struct timespec *start)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - start->tv_sec) + (double)(now.tv_nsec - start->tv_nsec) / 1e9;
}

void group_begin(const char *name)
{
    group_name = name;
    group_passed = group_failed = 0;
    clock_gettime(CLOCK_MONOTONIC, &group_start);
}

void group_end(void)
{
    printf("  %-28s %5d passed, %d failed (%.2f s)\n", group_name, group_passed, group_failed,
           seconds_since(&group_start));
    fflush(stdout);
}

bool check(bool condition, const char *fmt, ...)
{
    if (condition) {
        passed++;
        group_passed++;
        return true;
    }
    failed++;
    group_failed++;
    if (printed_failures++ < 200) {
        char text[1024];
        va_list args;
        va_start(args, fmt);
        vsnprintf(text, sizeof text, fmt, args);
        va_end(args);
        printf("  FAIL [%s] %s\n", group_name, text);
    } else if (printed_failures == 201) {
        printf("  (further failures not printed)\n");
    }
    fflush(stdout);
    return false;
}

static void on_timeout(int signal_number)
{
    (void)signal_number;
    static const char text[] = "  FAIL harness timed out (a call hangs?)\n";
    ssize_t ignored = write(STDOUT_FILENO, text, sizeof text - 1);
    (void)ignored;
    _exit(3);
}

uint64_t fnv1a64(const unsigned char *bytes, size_t size)
{
    uint64_t hash = 0xcbf29ce484222325u;
    for (size_t i = 0; i < size; i++) hash = (hash ^ bytes[i]) * 0x100000001b3u;
    return hash;
}

/* ---- the standard scenario ---- */

static void fail_sim(sim *s, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

static void fail_sim(sim *s, const char *fmt, ...)
{
    if (s->failure[0]) return;
    va_list args;
    va_start(args, fmt);
    vsnprintf(s->failure, sizeof s->failure, fmt, args);
    va_end(args);
}

bool sim_open(sim *s, const block *b, int variant)
{
    memset(s, 0, sizeof *s);
    s->b = b;
    s->variant = variant;
    snprintf(s->name, sizeof s->name, "harness%d", variant);
    s->trace = calloc((size_t)(STEPS + 1) * (size_t)(b->n_outputs ? b->n_outputs : 1),
                      sizeof *s->trace);
    fmi2CallbackFunctions callbacks = harness_callbacks(&s->log);
    /* The FMU keeps a copy of the callbacks (FMI 2.0 2.1.5 allows the struct to go away). */
    s->c = b->api.Instantiate(s->name, fmi2CoSimulation, b->guid, "file:///tmp", &callbacks,
                              fmi2False, fmi2False);
    if (!s->c || !s->trace) {
        fail_sim(s, "fmi2Instantiate failed");
        return false;
    }
    return true;
}

void sim_close(sim *s)
{
    if (s->c) s->b->api.FreeInstance(s->c);
    s->c = NULL;
    free(s->trace);
    s->trace = NULL;
}

double step_size(const sim *s, int k)
{
    static const double factors[] = {1.0, 2.0, 0.5, 1.5};
    return s->b->cycle * factors[k % 4];
}

/* Inputs of call k: patterns within each input's range that change at different rates. */
void sim_set_inputs_for(sim *s, int k)
{
    const block *b = s->b;
    for (int p = 0; p < b->n_inputs; p++) {
        const md_variable *v = &b->md.variables[b->inputs[p]];
        int n = k + s->variant + p;
        fmi2Status status = fmi2OK;
        if (v->kind == KIND_BOOLEAN) {
            int period = 3 + 2 * (p % 4);
            fmi2Boolean value = ((n / period) + p) % 2 ? fmi2True : fmi2False;
            status = b->api.SetBoolean(s->c, &v->vr, 1, &value);
        } else if (v->kind == KIND_INTEGER) {
            double value = v->start + n % 3;
            if (v->has_max && value > v->max) value = v->max;
            fmi2Integer integer = (fmi2Integer)value;
            status = b->api.SetInteger(s->c, &v->vr, 1, &integer);
        } else if (v->kind == KIND_REAL) {
            double value = v->is_time ? v->start + 0.1 * (n % 3) : v->start + 2.5 * (n % 5) - 3.0;
            if (v->has_max && value > v->max) value = v->max;
            if (v->has_min && value < v->min) value = v->min;
            status = b->api.SetReal(s->c, &v->vr, 1, &value);
        }
        if (status != fmi2OK) fail_sim(s, "setting input %s for call %d gave %d", v->name, k, status);
    }
}

bool sim_read_outputs(sim *s, uint64_t *row)
{
    const block *b = s->b;
    for (int p = 0; p < b->n_outputs; p++) {
        const md_variable *v = &b->md.variables[b->outputs[p]];
        fmi2Status status = fmi2Error;
        if (v->kind == KIND_REAL) {
            double value = 0;
            status = b->api.GetReal(s->c, &v->vr, 1, &value);
            memcpy(&row[p], &value, sizeof value);
        } else if (v->kind == KIND_INTEGER) {
            fmi2Integer value = 0;
            status = b->api.GetInteger(s->c, &v->vr, 1, &value);
            row[p] = (uint64_t)(int64_t)value;
        } else if (v->kind == KIND_BOOLEAN) {
            fmi2Boolean value = 0;
            status = b->api.GetBoolean(s->c, &v->vr, 1, &value);
            row[p] = (uint64_t)value;
        }
        if (status != fmi2OK) {
            fail_sim(s, "reading output %s gave %d", v->name, status);
            return false;
        }
    }
    return true;
}

static bool set_parameters(sim *s)
{
    const block *b = s->b;
    for (int p = 0; p < b->n_parameters; p++) {
        const md_variable *v = &b->md.variables[b->parameters[p]];
        if (!v->has_start) continue;
        fmi2Status status = fmi2Error;
        if (v->kind == KIND_REAL) {
            status = b->api.SetReal(s->c, &v->vr, 1, &v->start);
        } else if (v->kind == KIND_INTEGER) {
            fmi2Integer value = (fmi2Integer)v->start;
            status = b->api.SetInteger(s->c, &v->vr, 1, &value);
        } else if (v->kind == KIND_BOOLEAN) {
            fmi2Boolean value = v->start != 0 ? fmi2True : fmi2False;
            status = b->api.SetBoolean(s->c, &v->vr, 1, &value);
        }
        if (status != fmi2OK) {
            fail_sim(s, "setting parameter %s to its start value gave %d", v->name, status);
            return false;
        }
    }
    return true;
}

bool sim_step(sim *s)
{
    const fmi2_api *api = &s->b->api;
    int k = s->k + 1;
    sim_set_inputs_for(s, k);
    double h = step_size(s, k);
    fmi2Status status = api->DoStep(s->c, s->t, h, fmi2True);
    if (status != fmi2OK) {
        fail_sim(s, "fmi2DoStep(%.17g, %g) of step %d gave %d", s->t, h, k, status);
        return false;
    }
    s->t += h;
    s->k = k;
    s->rows = k + 1;
    return sim_read_outputs(s, s->trace + (size_t)k * (size_t)s->b->n_outputs) && !s->failure[0];
}

bool sim_advance(sim *s, int phase)
{
    const fmi2_api *api = &s->b->api;
    while (s->phase < phase && !s->failure[0]) {
        switch (s->phase) {
        case PHASE_INSTANTIATED:
            if (api->SetupExperiment(s->c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK ||
                api->EnterInitializationMode(s->c) != fmi2OK) {
                fail_sim(s, "setupExperiment/enterInitializationMode failed");
                return false;
            }
            if (!set_parameters(s)) return false;
            sim_set_inputs_for(s, 0);
            s->phase = PHASE_INITIALIZATION;
            break;
        case PHASE_INITIALIZATION:
            if (api->ExitInitializationMode(s->c) != fmi2OK) {
                fail_sim(s, "fmi2ExitInitializationMode failed");
                return false;
            }
            s->t = 0.0;
            s->k = 0;
            s->rows = 1;
            if (!sim_read_outputs(s, s->trace)) return false;
            while (s->k < STEP_PHASE_AT)
                if (!sim_step(s)) return false;
            s->phase = PHASE_STEP;
            break;
        case PHASE_STEP:
            while (s->k < STEPS)
                if (!sim_step(s)) return false;
            if (api->Terminate(s->c) != fmi2OK) {
                fail_sim(s, "fmi2Terminate failed");
                return false;
            }
            s->phase = PHASE_TERMINATED;
            break;
        default: return false;
        }
    }
    return !s->failure[0];
}

bool sim_run_to_end(sim *s) { return sim_advance(s, PHASE_TERMINATED); }

bool sim_state_bytes(sim *s, unsigned char **bytes, size_t *size)
{
    const fmi2_api *api = &s->b->api;
    fmi2FMUstate state = NULL;
    *bytes = NULL;
    *size = 0;
    if (api->GetFMUstate(s->c, &state) != fmi2OK || !state) {
        fail_sim(s, "fmi2GetFMUstate failed");
        return false;
    }
    bool ok = api->SerializedFMUstateSize(s->c, state, size) == fmi2OK && *size >= HEADER_SIZE;
    if (ok) *bytes = malloc(*size);
    ok = ok && *bytes && api->SerializeFMUstate(s->c, state, (fmi2Byte *)*bytes, *size) == fmi2OK;
    if (api->FreeFMUstate(s->c, &state) != fmi2OK || state) ok = false;
    if (!ok) {
        free(*bytes);
        *bytes = NULL;
        fail_sim(s, "serializing the state failed");
    }
    return ok;
}

bool reference_run(const block *b, int variant, reference *ref)
{
    memset(ref, 0, sizeof *ref);
    sim s;
    bool ok = sim_open(&s, b, variant);
    for (int phase = PHASE_INSTANTIATED; ok && phase <= PHASE_TERMINATED; phase++)
        ok = sim_advance(&s, phase) && sim_state_bytes(&s, &ref->state_at[phase], &ref->size_at[phase]);
    if (ok) {
        size_t n = (size_t)s.rows * (size_t)b->n_outputs;
        ref->trace = malloc((n ? n : 1) * sizeof *ref->trace);
        ok = ref->trace != NULL;
        if (ok) memcpy(ref->trace, s.trace, n * sizeof *ref->trace);
        ref->rows = s.rows;
        ref->final_state = malloc(ref->size_at[PHASE_TERMINATED]);
        ok = ok && ref->final_state;
        if (ok) {
            memcpy(ref->final_state, ref->state_at[PHASE_TERMINATED], ref->size_at[PHASE_TERMINATED]);
            ref->final_size = ref->size_at[PHASE_TERMINATED];
        }
    }
    if (!ok) fprintf(stdout, "  reference run of variant %d failed: %s\n", variant, s.failure);
    sim_close(&s);
    return ok;
}

void reference_free(reference *ref)
{
    free(ref->trace);
    free(ref->final_state);
    for (int i = 0; i < 4; i++) free(ref->state_at[i]);
    memset(ref, 0, sizeof *ref);
}

/* Whether s's trace from row `from` on equals the reference; the difference into why. */
static bool same_trace(const sim *s, const reference *ref, int from, char *why, size_t size)
{
    int n = s->b->n_outputs;
    if (s->rows != ref->rows) {
        snprintf(why, size, "%d rows instead of %d", s->rows, ref->rows);
        return false;
    }
    for (int r = from; r < s->rows; r++) {
        for (int p = 0; p < n; p++) {
            if (s->trace[(size_t)r * (size_t)n + (size_t)p] != ref->trace[(size_t)r * (size_t)n + (size_t)p]) {
                snprintf(why, size, "output %s differs at row %d",
                         s->b->md.variables[s->b->outputs[p]].name, r);
                return false;
            }
        }
    }
    return true;
}

static bool same_bytes(const unsigned char *a, size_t na, const unsigned char *b, size_t nb,
                       char *why, size_t size, const char *what)
{
    if (!a || !b || na != nb) {
        snprintf(why, size, "%s: sizes %zu and %zu", what, na, nb);
        return false;
    }
    for (size_t i = 0; i < na; i++) {
        if (a[i] != b[i]) {
            snprintf(why, size, "%s: byte %zu differs (%s %zu)", what, i,
                     i < HEADER_SIZE ? "header" : "payload", i < HEADER_SIZE ? i : i - HEADER_SIZE);
            return false;
        }
    }
    return true;
}

/* ---- one misuse: the call, its log, the unchanged state, an unchanged future ---- */

static const char *phase_names[] = {"instantiated", "initialization mode", "step mode", "terminated"};

void run_misuse(const block *b, const reference *ref, const misuse *m)
{
    char why[1024] = "";
    long live_before = live_allocations();
    sim s;
    unsigned char *before = NULL, *after = NULL;
    size_t before_size = 0, after_size = 0;
    bool ok = sim_open(&s, b, 0) && sim_advance(&s, m->phase) &&
              sim_state_bytes(&s, &before, &before_size);
    if (!ok) {
        snprintf(why, sizeof why, "setting up: %s", s.failure);
        goto done;
    }
    int mark = s.log.total;
    long messages = total_log_messages();
    int status = m->op(&s, m);
    if (status != m->expect) {
        snprintf(why, sizeof why, "returned %d instead of %d", status, m->expect);
        ok = false;
        goto done;
    }
    int logged = s.log.total - mark;
    if (logged != m->logs || total_log_messages() - messages != m->logs) {
        const log_entry *e = log_get(&s.log, s.log.total - 1);
        snprintf(why, sizeof why, "%d messages instead of %d (%ld in all); last: \"%.300s\"", logged,
                 m->logs, total_log_messages() - messages, e && logged ? e->text : "");
        ok = false;
        goto done;
    }
    for (int j = mark; j < s.log.total; j++) {
        const log_entry *e = log_get(&s.log, j);
        const char *category = m->log_status == fmi2Warning   ? "logStatusWarning"
                               : m->log_status == fmi2Discard ? "logStatusDiscard"
                                                              : "logStatusError";
        if (!e || (int)e->status != m->log_status || strcmp(e->category, category) ||
            strcmp(e->instance, s.name) || strncmp(e->text, m->function, strlen(m->function)) ||
            (m->contains[0] && !strstr(e->text, m->contains))) {
            snprintf(why, sizeof why,
                     "message (status %d, category %.40s, instance %.40s) \"%.300s\" should have status %d "
                     "and start with \"%s\"%s%s%s",
                     e ? (int)e->status : -1, e ? e->category : "", e ? e->instance : "",
                     e ? e->text : "", m->log_status, m->function,
                     m->contains[0] ? " and contain \"" : "", m->contains,
                     m->contains[0] ? "\"" : "");
            ok = false;
            goto done;
        }
    }
    if (!m->changes_state) {
        if (!sim_state_bytes(&s, &after, &after_size) ||
            !same_bytes(before, before_size, after, after_size, why, sizeof why,
                        "the state changed")) {
            if (!why[0]) snprintf(why, sizeof why, "after the call: %s", s.failure);
            ok = false;
            goto done;
        }
        /* The future: the rest of the run, or from terminated a reset and a whole new run. */
        if (m->phase == PHASE_TERMINATED) {
            uint64_t row[64];
            if (b->n_outputs > 64 || !sim_read_outputs(&s, row) ||
                memcmp(row, ref->trace + (size_t)(ref->rows - 1) * (size_t)b->n_outputs,
                       (size_t)b->n_outputs * sizeof row[0])) {
                snprintf(why, sizeof why, "the outputs after terminate differ");
                ok = false;
                goto done;
            }
            if (b->api.Reset(s.c) != fmi2OK) {
                snprintf(why, sizeof why, "fmi2Reset after the call failed");
                ok = false;
                goto done;
            }
            s.phase = PHASE_INSTANTIATED;
            s.k = s.rows = 0;
            s.t = 0;
        }
        unsigned char *final = NULL;
        size_t final_size = 0;
        ok = sim_run_to_end(&s) && sim_state_bytes(&s, &final, &final_size);
        if (!ok) snprintf(why, sizeof why, "the run after the call failed: %s", s.failure);
        ok = ok && same_trace(&s, ref, 0, why, sizeof why) &&
             same_bytes(final, final_size, ref->final_state, ref->final_size, why, sizeof why,
                        "the final state differs from the reference");
        free(final);
    }
done:
    free(before);
    free(after);
    sim_close(&s);
    if (ok && live_allocations() != live_before) {
        snprintf(why, sizeof why, "%ld blocks allocated by the FMU were not freed",
                 live_allocations() - live_before);
        ok = false;
    }
    check(ok, "%s (in %s): %s", m->label, phase_names[m->phase], why);
}

/* ---- the block ---- */

static bool load_block(block *b, const char *library, const char *xml, const char *guid)
{
    char error[512];
    memset(b, 0, sizeof *b);
    b->library = library;
    snprintf(b->guid, sizeof b->guid, "%s", guid);
    if (!api_load(&b->api, library, error, sizeof error) ||
        !md_read(&b->md, xml, error, sizeof error)) {
        printf("  cannot load %s: %s\n", library, error);
        return false;
    }
    size_t n = b->md.count;
    b->inputs = calloc(n, sizeof(int));
    b->outputs = calloc(n, sizeof(int));
    b->parameters = calloc(n, sizeof(int));
    b->located = calloc(n, sizeof *b->located);
    if (!b->inputs || !b->outputs || !b->parameters || !b->located) return false;
    b->cycle = 0.1;
    for (size_t i = 0; i < n; i++) {
        const md_variable *v = &b->md.variables[i];
        if (v->causality == CAUS_INPUT) b->inputs[b->n_inputs++] = (int)i;
        if (v->causality == CAUS_OUTPUT) b->outputs[b->n_outputs++] = (int)i;
        if (v->causality == CAUS_PARAMETER) b->parameters[b->n_parameters++] = (int)i;
        if (v->is_cycle && v->has_start) b->cycle = v->start;
    }
    return true;
}

static void unload_block(block *b)
{
    api_unload(&b->api);
    md_free(&b->md);
    free(b->inputs);
    free(b->outputs);
    free(b->parameters);
    free(b->located);
}

/* ---- groups ---- */

static void group_library(const block *b, const char *guid, const reference *refs)
{
    group_begin("library and scenario");
    check(!strcmp(b->api.GetVersion(), "2.0"), "fmi2GetVersion is \"%s\"", b->api.GetVersion());
    check(!strcmp(b->api.GetTypesPlatform(), "default"), "fmi2GetTypesPlatform is \"%s\"",
          b->api.GetTypesPlatform());
    check(!strcmp(b->md.fmi_version, "2.0"), "fmiVersion is %s", b->md.fmi_version);
    check(!strcmp(b->md.guid, guid), "the XML's guid %s is not the one given (%s)", b->md.guid, guid);
    const char *base = strrchr(b->library, '/');
    base = base ? base + 1 : b->library;
    check(!strncmp(base, b->md.identifier, strlen(b->md.identifier)),
          "library %s is not named after modelIdentifier %s", base, b->md.identifier);
    check(b->n_outputs > 0 && b->n_inputs > 0, "the XML has inputs and outputs");
    /* The comparisons below only mean something if the outputs move during a scenario. */
    for (int variant = 0; variant < THREADS; variant++) {
        const reference *ref = &refs[variant];
        bool moves = false;
        for (int r = 1; r < ref->rows && !moves; r++)
            moves = memcmp(ref->trace, ref->trace + (size_t)r * (size_t)b->n_outputs,
                           (size_t)b->n_outputs * sizeof *ref->trace) != 0;
        check(ref->rows == STEPS + 1 && moves, "variant %d: the outputs never change", variant);
    }
    /* Running the same scenario twice gives the same bits. */
    reference again;
    if (check(reference_run(b, 0, &again), "second reference run")) {
        char why[256] = "";
        check(again.rows == refs[0].rows &&
                  !memcmp(again.trace, refs[0].trace,
                          (size_t)again.rows * (size_t)b->n_outputs * sizeof *again.trace) &&
                  same_bytes(again.final_state, again.final_size, refs[0].final_state,
                             refs[0].final_size, why, sizeof why, "final state"),
              "two runs of the same scenario differ %s", why);
        reference_free(&again);
    }
    group_end();
}

/* Where each parameter and input is stored in the payload: set it to another value in
 * initialization mode and see which bytes of the serialized state change. */
static void group_state_layout(block *b)
{
    group_begin("state layout");
    sim s;
    b->layout_known = false;
    bool ok = sim_open(&s, b, 0) && sim_advance(&s, PHASE_INITIALIZATION);
    check(ok, "scenario to initialization mode: %s", s.failure);
    for (size_t i = 0; ok && i < b->md.count; i++) {
        const md_variable *v = &b->md.variables[i];
        if (v->causality != CAUS_PARAMETER && v->causality != CAUS_INPUT) continue;
        unsigned char *before = NULL, *after = NULL;
        size_t nb = 0, na = 0;
        fmi2Status set = fmi2Error, back = fmi2Error;
        int width = 0;
        if (!sim_state_bytes(&s, &before, &nb)) break;
        if (v->kind == KIND_REAL) {
            double value = v->is_cycle ? v->start * 2 : v->is_time ? v->start + 1.234 : v->start + 1234.5;
            width = v->is_cycle || v->is_time ? 4 : 8;
            double current;
            b->api.GetReal(s.c, &v->vr, 1, &current);
            set = b->api.SetReal(s.c, &v->vr, 1, &value);
            if (sim_state_bytes(&s, &after, &na)) back = b->api.SetReal(s.c, &v->vr, 1, &current);
        } else if (v->kind == KIND_INTEGER) {
            fmi2Integer current, value;
            b->api.GetInteger(s.c, &v->vr, 1, &current);
            value = v->has_max && current + 1 > v->max ? current - 1 : current + 1;
            width = 2;
            set = b->api.SetInteger(s.c, &v->vr, 1, &value);
            if (sim_state_bytes(&s, &after, &na)) back = b->api.SetInteger(s.c, &v->vr, 1, &current);
        } else if (v->kind == KIND_BOOLEAN) {
            fmi2Boolean current, value;
            b->api.GetBoolean(s.c, &v->vr, 1, &current);
            value = !current;
            width = 1;
            set = b->api.SetBoolean(s.c, &v->vr, 1, &value);
            if (sim_state_bytes(&s, &after, &na)) back = b->api.SetBoolean(s.c, &v->vr, 1, &current);
        }
        size_t lo = SIZE_MAX, hi = 0;
        for (size_t j = HEADER_SIZE; after && j < nb && j < na; j++) {
            if (before[j] != after[j]) {
                if (j < lo) lo = j;
                hi = j;
            }
        }
        free(before);
        free(after);
        if (!check(set == fmi2OK && back == fmi2OK && na == nb && lo != SIZE_MAX,
                   "setting %s to another value changes no byte of the state", v->name))
            continue;
        size_t offset = (lo - HEADER_SIZE) / (size_t)width * (size_t)width;
        if (!check(hi - HEADER_SIZE < offset + (size_t)width,
                   "%s changes bytes %zu to %zu, more than its %d bytes", v->name, lo - HEADER_SIZE,
                   hi - HEADER_SIZE, width))
            continue;
        if (v->is_cycle) {
            check(offset == CLOCK_CYCLE_US, "cycleTime is not at the clock's cycle_us");
            continue;
        }
        b->located[b->n_located++] = (located_variable){(int)i, offset, width};
    }
    /* The clock at the start of the payload, as src/fmi2/instance.h lays it out. */
    ok = ok && sim_advance(&s, PHASE_STEP);
    unsigned char *bytes = NULL;
    size_t size = 0;
    if (ok && sim_state_bytes(&s, &bytes, &size) && size >= HEADER_SIZE + 32) {
        const unsigned char *p = bytes + HEADER_SIZE;
        int32_t mode, cycle_us;
        double start, now;
        int64_t calls;
        memcpy(&mode, p + CLOCK_MODE, 4);
        memcpy(&cycle_us, p + CLOCK_CYCLE_US, 4);
        memcpy(&start, p + CLOCK_START, 8);
        memcpy(&now, p + CLOCK_TIME, 8);
        memcpy(&calls, p + CLOCK_CALLS, 8);
        int64_t expected_calls = (int64_t)floor(s.t / b->cycle + 1e-6) + 1;
        b->layout_known = check(mode == PHASE_STEP && cycle_us == (int32_t)llround(b->cycle * 1e6) &&
                                    start == 0.0 && now == s.t && calls == expected_calls,
                                "the payload does not start with the clock of instance.h (mode %d, "
                                "cycle %d µs, t0 %g, t %g, calls %lld; expected t %g, calls %lld)",
                                (int)mode, (int)cycle_us, start, now, (long long)calls, s.t,
                                (long long)expected_calls);
    }
    free(bytes);
    sim_close(&s);
    group_end();
}

/* fmi2Instantiate refuses what it must refuse, with one message, and allocates nothing then. */
typedef struct {
    const char *label;
    const char *name;
    int type;
    const char *guid;
    int callbacks; /* 0 ok, 1 NULL struct, 2 NULL logger, 3 NULL allocateMemory, 4 NULL freeMemory */
    const char *resources;
    bool succeeds;
    int logs;
    const char *contains;
} instantiation;

static void group_instantiate(const block *b)
{
    group_begin("fmi2Instantiate");
    char other_guid[64], prefix[64], changed[64];
    snprintf(other_guid, sizeof other_guid, "%s",
             FOREIGN.other ? FOREIGN.other->guid : "{00000000-0000-0000-0000-000000000001}");
    snprintf(prefix, sizeof prefix, "%.*s", (int)strlen(b->guid) - 1, b->guid);
    snprintf(changed, sizeof changed, "%s", b->guid);
    changed[1] = changed[1] == 'a' ? 'b' : 'a';
    const instantiation cases[] = {
        {"valid", "i", fmi2CoSimulation, b->guid, 0, "file:///tmp", true, 0, NULL},
        {"NULL fmuResourceLocation", "i", fmi2CoSimulation, b->guid, 0, NULL, true, 0, NULL},
        {"wrong GUID", "i", fmi2CoSimulation, "{00000000-0000-0000-0000-000000000000}", 0, "", false, 1, "fmuGUID"},
        {"GUID of another block", "i", fmi2CoSimulation, other_guid, 0, "", false, 1, "fmuGUID"},
        {"GUID without its last character", "i", fmi2CoSimulation, prefix, 0, "", false, 1, "fmuGUID"},
        {"GUID with one character changed", "i", fmi2CoSimulation, changed, 0, "", false, 1, "fmuGUID"},
        {"empty GUID", "i", fmi2CoSimulation, "", 0, "", false, 1, "fmuGUID"},
        {"NULL GUID", "i", fmi2CoSimulation, NULL, 0, "", false, 1, "fmuGUID"},
        {"Model Exchange", "i", fmi2ModelExchange, b->guid, 0, "", false, 1, "Model Exchange"},
        {"fmuType 2 (no such type)", "i", 2, b->guid, 0, "", false, 1, "Model Exchange"},
        {"fmuType -1 (no such type)", "i", -1, b->guid, 0, "", false, 1, "Model Exchange"},
        {"NULL instanceName", NULL, fmi2CoSimulation, b->guid, 0, "", false, 1, "instanceName"},
        {"empty instanceName", "", fmi2CoSimulation, b->guid, 0, "", false, 1, "instanceName"},
        {"NULL functions", "i", fmi2CoSimulation, b->guid, 1, "", false, 0, NULL},
        {"NULL logger", "i", fmi2CoSimulation, b->guid, 2, "", false, 0, NULL},
        {"NULL allocateMemory", "i", fmi2CoSimulation, b->guid, 3, "", false, 1, "allocateMemory"},
        {"NULL freeMemory", "i", fmi2CoSimulation, b->guid, 4, "", false, 1, "freeMemory"},
        {"Model Exchange and wrong GUID", "i", fmi2ModelExchange, "{x}", 0, "", false, 1, "fmi2Instantiate"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const instantiation *t = &cases[i];
        log_record log = {0};
        fmi2CallbackFunctions callbacks = harness_callbacks(&log);
        if (t->callbacks == 2) callbacks.logger = NULL;
        if (t->callbacks == 3) callbacks.allocateMemory = NULL;
        if (t->callbacks == 4) callbacks.freeMemory = NULL;
        long live = live_allocations(), messages = total_log_messages();
        fmi2Component c = b->api.Instantiate(t->name, (fmi2Type)t->type, t->guid, t->resources,
                                             t->callbacks == 1 ? NULL : &callbacks, fmi2False,
                                             fmi2False);
        const log_entry *e = log_get(&log, 0);
        bool ok = (c != NULL) == t->succeeds && log.total == t->logs &&
                  total_log_messages() - messages == t->logs;
        if (ok && t->logs)
            ok = e && e->status == fmi2Error && !strcmp(e->category, "logStatusError") &&
                 !strncmp(e->text, "fmi2Instantiate", 15) && strstr(e->text, t->contains) &&
                 !strcmp(e->instance, t->name && *t->name ? t->name : e->instance);
        if (c) {
            /* it works: a step and a clean free */
            ok = ok && b->api.SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0) == fmi2OK &&
                 b->api.EnterInitializationMode(c) == fmi2OK &&
                 b->api.ExitInitializationMode(c) == fmi2OK &&
                 b->api.DoStep(c, 0.0, b->cycle, fmi2True) == fmi2OK;
            b->api.FreeInstance(c);
        }
        ok = ok && live_allocations() == live;
        check(ok, "%s: returned %s, %d messages (expected %d) \"%s\", %ld blocks left", t->label,
              c ? "an instance" : "NULL", log.total, t->logs, e ? e->text : "",
              live_allocations() - live);
    }
    /* Two instances of the same name are allowed and independent. */
    log_record l1 = {0}, l2 = {0};
    fmi2CallbackFunctions c1 = harness_callbacks(&l1), c2 = harness_callbacks(&l2);
    fmi2Component a = b->api.Instantiate("same", fmi2CoSimulation, b->guid, "", &c1, fmi2False, fmi2False);
    fmi2Component z = b->api.Instantiate("same", fmi2CoSimulation, b->guid, "", &c2, fmi2True, fmi2True);
    check(a && z && a != z, "two instances of the same name");
    if (a) b->api.FreeInstance(a);
    if (z) b->api.FreeInstance(z);
    /* The FMU copies the callbacks: a struct that goes away after fmi2Instantiate is fine. */
    log_record l3 = {0};
    fmi2CallbackFunctions *temporary = malloc(sizeof *temporary);
    fmi2Component c = NULL;
    if (temporary) {
        *temporary = harness_callbacks(&l3);
        c = b->api.Instantiate("copy", fmi2CoSimulation, b->guid, "", temporary, fmi2False, fmi2False);
        memset(temporary, 0, sizeof *temporary);
        free(temporary);
    }
    fmi2Real nan_value = NAN;
    check(c && b->api.SetReal(c, &b->md.variables[b->inputs[0]].vr, 1, &nan_value) != fmi2OK,
          "callbacks struct freed after fmi2Instantiate");
    if (c) b->api.FreeInstance(c);

    /* The FMU copies instanceName: the importer's buffer may change afterwards. A long name
     * and a NULL componentEnvironment are fine too. */
    fmi2ValueReference unknown_vr = 0xFFFFFFFFu;
    fmi2Real value = 0;
    char name[1200];
    for (int variant = 0; variant < 3; variant++) {
        log_record log = {0};
        fmi2CallbackFunctions callbacks = harness_callbacks(variant == 2 ? NULL : &log);
        size_t length = variant == 1 ? sizeof name - 1 : 8;
        memset(name, 'n', length);
        name[length] = '\0';
        long messages = total_log_messages();
        c = b->api.Instantiate(name, fmi2CoSimulation, b->guid, "", &callbacks, fmi2False, fmi2False);
        memset(name, 'x', length); /* the importer reuses its buffer */
        bool ok = c && b->api.GetReal(c, &unknown_vr, 1, &value) == fmi2Error &&
                  total_log_messages() == messages + 1;
        const log_entry *e = log_get(&log, 0);
        if (variant < 2)
            ok = ok && log.total == 1 && e && e->instance[0] == 'n' &&
                 strspn(e->instance, "n") == strlen(e->instance);
        if (c) b->api.FreeInstance(c);
        static const char *const what[] = {"instanceName buffer reused after fmi2Instantiate",
                                           "instanceName of 1199 characters",
                                           "componentEnvironment NULL"};
        check(ok, "%s: the logger got %s", what[variant], e ? e->instance : "nothing");
    }
    group_end();
}

/* fmi2Instantiate with each of its allocations failing in turn: NULL, one message, no leak. */
static void group_out_of_memory(const block *b)
{
    group_begin("out of memory");
    log_record log = {0};
    fmi2CallbackFunctions callbacks = harness_callbacks(&log);
    long live = live_allocations();
    fmi2Component c = b->api.Instantiate("m", fmi2CoSimulation, b->guid, "", &callbacks, fmi2False, fmi2False);
    long needed = live_allocations() - live;
    if (c) b->api.FreeInstance(c);
    check(c && needed > 0, "a plain fmi2Instantiate allocates");
    for (long n = 1; n <= needed; n++) {
        log = (log_record){0};
        fail_allocation_after(n);
        c = b->api.Instantiate("m", fmi2CoSimulation, b->guid, "", &callbacks, fmi2False, fmi2False);
        fail_allocation_after(0);
        const log_entry *e = log_get(&log, 0);
        bool ok = !c && log.total == 1 && e && e->status == fmi2Error &&
                  !strncmp(e->text, "fmi2Instantiate", 15) && strstr(e->text, "memory");
        if (c) b->api.FreeInstance(c);
        check(ok && live_allocations() == live,
              "allocation %ld of %ld fails: %s, %d messages \"%s\", %ld blocks left", n, needed,
              c ? "an instance" : "NULL", log.total, e ? e->text : "", live_allocations() - live);
    }
    group_end();
}

/* fmi2Reset from every phase leads to a run identical to the reference. */
static void group_reset(const block *b, const reference *ref)
{
    group_begin("fmi2Reset");
    for (int phase = PHASE_INSTANTIATED; phase <= PHASE_TERMINATED; phase++) {
        sim s;
        char why[256] = "";
        bool ok = sim_open(&s, b, 0) && sim_advance(&s, phase);
        int logged = s.log.total;
        ok = ok && b->api.Reset(s.c) == fmi2OK && s.log.total == logged;
        if (ok) {
            s.phase = PHASE_INSTANTIATED;
            s.k = s.rows = 0;
            s.t = 0;
            ok = sim_run_to_end(&s) && same_trace(&s, ref, 0, why, sizeof why);
        }
        check(ok, "fmi2Reset in %s, then a whole run: %s %s", phase_names[phase], s.failure, why);
        sim_close(&s);
    }
    group_end();
}

/* get, continue, set, replay; serialize, deserialize into a fresh instance, continue. */
static void group_state_round_trip(const block *b, const reference *ref)
{
    group_begin("state round trip");
    const fmi2_api *api = &b->api;
    char why[256] = "";
    long live = live_allocations();

    /* 1. get at step STEP_PHASE_AT, run on, set it back, replay: the same bits. */
    {
        sim s;
        fmi2FMUstate state = NULL;
        bool ok = sim_open(&s, b, 0) && sim_advance(&s, PHASE_STEP) &&
                  api->GetFMUstate(s.c, &state) == fmi2OK && state;
        int k0 = s.k;
        double t0 = s.t;
        ok = ok && sim_run_to_end(&s);
        size_t n = (size_t)b->n_outputs * (size_t)(STEPS + 1);
        uint64_t *first = malloc(n * sizeof *first);
        if (ok && first) memcpy(first, s.trace, n * sizeof *first);
        ok = ok && first && api->SetFMUstate(s.c, state) == fmi2OK;
        if (ok) {
            memset(s.trace + (size_t)(k0 + 1) * (size_t)b->n_outputs, 0,
                   (size_t)(STEPS - k0) * (size_t)b->n_outputs * sizeof *s.trace);
            s.k = k0;
            s.t = t0;
            s.phase = PHASE_STEP;
            ok = sim_run_to_end(&s) && !memcmp(first, s.trace, n * sizeof *first) &&
                 same_trace(&s, ref, 0, why, sizeof why);
        }
        check(ok, "set state and replay: %s %s", s.failure, why);
        /* 2. getting into an existing state overwrites it */
        unsigned char *now = NULL, *got = NULL;
        size_t now_size = 0, got_size = 0;
        fmi2FMUstate same = state;
        ok = ok && api->GetFMUstate(s.c, &state) == fmi2OK && state == same &&
             sim_state_bytes(&s, &now, &now_size) &&
             api->SerializedFMUstateSize(s.c, state, &got_size) == fmi2OK &&
             (got = malloc(got_size)) && api->SerializeFMUstate(s.c, state, (fmi2Byte *)got, got_size) == fmi2OK &&
             same_bytes(now, now_size, got, got_size, why, sizeof why, "state");
        check(ok, "fmi2GetFMUstate into an existing state updates it in place: %s", why);
        /* 3. serializing twice gives the same bytes, of the announced size */
        unsigned char *again = NULL;
        size_t again_size = 0;
        ok = got && sim_state_bytes(&s, &again, &again_size) &&
             same_bytes(now, now_size, again, again_size, why, sizeof why, "serialized twice") &&
             again_size == got_size;
        check(ok, "serialization is deterministic: %s", why);
        free(now);
        free(got);
        free(again);
        api->FreeFMUstate(s.c, &state);
        check(state == NULL, "fmi2FreeFMUstate sets the state to NULL");
        free(first);
        sim_close(&s);
    }

    /* 4. serialize at step STEP_PHASE_AT, deserialize into a fresh instance (only
     * instantiated, default inputs), continue: the reference from there on. Twice: into a new
     * state object and into an existing one. */
    for (int into_existing = 0; into_existing <= 1; into_existing++) {
        sim s, fresh;
        unsigned char *bytes = NULL;
        size_t size = 0;
        fmi2FMUstate state = NULL;
        bool ok = sim_open(&s, b, 0) && sim_advance(&s, PHASE_STEP) &&
                  sim_state_bytes(&s, &bytes, &size) && sim_open(&fresh, b, 1);
        if (ok && into_existing) ok = api->GetFMUstate(fresh.c, &state) == fmi2OK;
        fmi2FMUstate existing = state;
        ok = ok && api->DeSerializeFMUstate(fresh.c, (const fmi2Byte *)bytes, size, &state) == fmi2OK &&
             state && (!into_existing || state == existing) &&
             api->SetFMUstate(fresh.c, state) == fmi2OK && api->FreeFMUstate(fresh.c, &state) == fmi2OK;
        fmi2Real time = -1;
        ok = ok && api->GetRealStatus(fresh.c, fmi2LastSuccessfulTime, &time) == fmi2OK && time == s.t;
        if (ok) {
            fresh.variant = 0; /* the same inputs as the reference from here on */
            fresh.phase = PHASE_STEP;
            fresh.k = s.k;
            fresh.t = s.t;
            memcpy(fresh.trace, ref->trace, (size_t)(s.k + 1) * (size_t)b->n_outputs * sizeof *fresh.trace);
            fresh.rows = s.k + 1;
            unsigned char *final = NULL;
            size_t final_size = 0;
            ok = sim_run_to_end(&fresh) && same_trace(&fresh, ref, 0, why, sizeof why) &&
                 sim_state_bytes(&fresh, &final, &final_size);
            /* the final state differs from the reference only in nothing: same clock, same data */
            ok = ok && same_bytes(final, final_size, ref->final_state, ref->final_size, why,
                                  sizeof why, "final state");
            free(final);
        }
        check(ok, "serialize, deserialize %s in a fresh instance, continue: %s %s %s",
              into_existing ? "into an existing state" : "into a new state", s.failure,
              fresh.failure, why);
        free(bytes);
        sim_close(&s);
        sim_close(&fresh);
    }

    /* 5. a state taken in initialization mode brings a running instance back there. */
    {
        sim s;
        fmi2FMUstate state = NULL;
        bool ok = sim_open(&s, b, 0) && sim_advance(&s, PHASE_INITIALIZATION) &&
                  api->GetFMUstate(s.c, &state) == fmi2OK && sim_advance(&s, PHASE_STEP) &&
                  api->SetFMUstate(s.c, state) == fmi2OK;
        if (ok) {
            s.phase = PHASE_INITIALIZATION;
            s.k = s.rows = 0;
            s.t = 0;
            ok = sim_run_to_end(&s) && same_trace(&s, ref, 0, why, sizeof why);
        }
        if (state) api->FreeFMUstate(s.c, &state);
        check(ok, "a state of initialization mode set in step mode: %s %s", s.failure, why);
        sim_close(&s);
    }

    /* 6. a state of one instance set into another instance of the same FMU */
    {
        sim a, z;
        fmi2FMUstate state = NULL;
        bool ok = sim_open(&a, b, 0) && sim_open(&z, b, 3) && sim_advance(&a, PHASE_STEP) &&
                  sim_advance(&z, PHASE_STEP) && api->GetFMUstate(a.c, &state) == fmi2OK &&
                  api->SetFMUstate(z.c, state) == fmi2OK && api->FreeFMUstate(a.c, &state) == fmi2OK;
        if (ok) {
            z.variant = 0;
            memcpy(z.trace, a.trace, (size_t)(a.k + 1) * (size_t)b->n_outputs * sizeof *z.trace);
            ok = sim_run_to_end(&z) && same_trace(&z, ref, 0, why, sizeof why);
        }
        check(ok, "a state of one instance set into another: %s %s %s", a.failure, z.failure, why);
        sim_close(&a);
        sim_close(&z);
    }
    check(live_allocations() == live, "%ld blocks left after the round trips", live_allocations() - live);
    group_end();
}

/* The clock refuses steps it cannot count instead of overflowing or running for ages. */
static void group_clock_limits(const block *b)
{
    group_begin("clock limits");
    const md_variable *cycle = NULL;
    for (size_t i = 0; i < b->md.count; i++)
        if (b->md.variables[i].is_cycle) cycle = &b->md.variables[i];
    if (!check(cycle && cycle->has_min && cycle->has_max, "cycleTime with min and max")) {
        group_end();
        return;
    }
    const struct {
        double cycle, h;
    } cases[] = {
        {cycle->max, 1e14},       /* 1.7e12 calls: their µs would overflow 64 bits */
        {cycle->max, 2e11 * 60},  /* just as far */
        {cycle->min, cycle->min * 1e16}, /* more calls than the counter allows */
        {0.1, 1e300},
        {0.1, 5e14},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        log_record log = {0};
        fmi2CallbackFunctions callbacks = harness_callbacks(&log);
        fmi2Component c = b->api.Instantiate("clock", fmi2CoSimulation, b->guid, "", &callbacks,
                                             fmi2False, fmi2False);
        fmi2ValueReference vr = cycle->vr;
        bool ok = c && b->api.SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0) == fmi2OK &&
                  b->api.EnterInitializationMode(c) == fmi2OK &&
                  b->api.SetReal(c, &vr, 1, &cases[i].cycle) == fmi2OK &&
                  b->api.ExitInitializationMode(c) == fmi2OK;
        int before = log.total;
        fmi2Status status = ok ? b->api.DoStep(c, 0.0, cases[i].h, fmi2True) : fmi2Fatal;
        const log_entry *e = log_get(&log, log.total - 1);
        ok = ok && status == fmi2Error && log.total == before + 1 && e &&
             !strncmp(e->text, "fmi2DoStep", 10) &&
             b->api.DoStep(c, 0.0, cases[i].cycle, fmi2True) == fmi2OK;
        check(ok, "cycleTime %g s, fmi2DoStep(0, %g) returns %d (expected a refusal, then a normal "
                  "step): \"%s\"", cases[i].cycle, cases[i].h, (int)status, e ? e->text : "");
        if (c) b->api.FreeInstance(c);
    }
    group_end();
}

/* Every aligned word of the block's data in a state set to an extreme, the checksum made to
 * match: the layer cannot know a block's statics, so the block's own check must refuse what it
 * cannot run. Refused or run, nothing may go wrong: the sanitizer build aborts on undefined
 * behaviour, e.g. a timer start of INT64_MIN that overflows the elapsed time. The state comes
 * from runs with the start values and with every Boolean parameter TRUE (so that LGF_SawTooth's
 * PLC timer runs), taken at two points of time. */
static void extreme_words_from(const block *b, bool booleans_true, int steps)
{
    log_record log = {0};
    fmi2CallbackFunctions callbacks = harness_callbacks(&log);
    fmi2Component c = b->api.Instantiate("extreme", fmi2CoSimulation, b->guid, "", &callbacks,
                                         fmi2False, fmi2False);
    bool ok = c && b->api.SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0) == fmi2OK &&
              b->api.EnterInitializationMode(c) == fmi2OK;
    for (int p = 0; ok && booleans_true && p < b->n_parameters; p++) {
        const md_variable *v = &b->md.variables[b->parameters[p]];
        fmi2Boolean on = fmi2True;
        if (v->kind == KIND_BOOLEAN) ok = b->api.SetBoolean(c, &v->vr, 1, &on) == fmi2OK;
    }
    ok = ok && b->api.ExitInitializationMode(c) == fmi2OK;
    double h = b->cycle, t = 0;
    for (int k = 0; ok && k < steps; k++, t += h) ok = b->api.DoStep(c, t, h, fmi2True) == fmi2OK;
    fmi2FMUstate original = NULL;
    size_t size = 0;
    ok = ok && b->api.GetFMUstate(c, &original) == fmi2OK &&
         b->api.SerializedFMUstateSize(c, original, &size) == fmi2OK && size > HEADER_SIZE + 32;
    unsigned char *bytes = ok ? malloc(size) : NULL, *copy = ok ? malloc(size) : NULL;
    ok = ok && bytes && copy &&
         b->api.SerializeFMUstate(c, original, (fmi2Byte *)bytes, size) == fmi2OK;
    if (check(ok, "a state after %d steps%s", steps,
              booleans_true ? " with Boolean parameters TRUE" : "")) {
        static const struct {
            unsigned width;
            uint64_t bits;
        } extremes[] = {{8, UINT64_C(0x8000000000000000)}, {8, UINT64_C(0x7FFFFFFFFFFFFFFF)},
                        {4, 0x80000000u}, {4, 0x7FFFFFFFu}, {2, 0x8000u}, {2, 0x7FFFu}};
        for (size_t e = 0; e < sizeof extremes / sizeof extremes[0]; e++) {
            unsigned width = extremes[e].width;
            for (size_t at = HEADER_SIZE + 32; at + width <= size; at += width) {
                memcpy(copy, bytes, size);
                for (unsigned i = 0; i < width; i++)
                    copy[at + i] = (unsigned char)(extremes[e].bits >> (8 * i));
                uint64_t sum = fnv1a64(copy + HEADER_SIZE, size - HEADER_SIZE);
                for (unsigned i = 0; i < 8; i++) copy[88 + i] = (unsigned char)(sum >> (8 * i));
                fmi2FMUstate state = NULL;
                fmi2Status status = b->api.DeSerializeFMUstate(c, (fmi2Byte *)copy, size, &state);
                bool fine = status == fmi2OK || status == fmi2Error;
                if (status == fmi2OK) {
                    fine = b->api.SetFMUstate(c, state) == fmi2OK;
                    for (int k = 0; fine && k < 8; k++)
                        fine = b->api.DoStep(c, t + k * h, h, fmi2True) == fmi2OK;
                    fine = b->api.FreeFMUstate(c, &state) == fmi2OK && fine;
                }
                check(fine, "payload byte %zu holds a %u-byte extreme: deserialize %d, then a run",
                      at - HEADER_SIZE, width, (int)status);
            }
        }
    }
    free(bytes);
    free(copy);
    if (original) b->api.FreeFMUstate(c, &original);
    if (c) b->api.FreeInstance(c);
}

static void group_extreme_words(const block *b)
{
    group_begin("extreme words in a state");
    for (int steps = 3; steps <= 5; steps += 2) { /* the state at two phases of the blocks */
        extreme_words_from(b, false, steps);
        extreme_words_from(b, true, steps);
    }
    group_end();
}

/* Many instantiate/free and state cycles: nothing accumulates. */
static void group_cycles(const block *b)
{
    group_begin("instantiate/free cycles");
    const fmi2_api *api = &b->api;
    long live = live_allocations();
    long broken = 0, leaked = 0;
    for (long i = 0; i < CYCLES; i++) {
        log_record log = {0};
        fmi2CallbackFunctions callbacks = harness_callbacks(&log);
        fmi2Component c = api->Instantiate("cycle", fmi2CoSimulation, b->guid, "", &callbacks,
                                           fmi2False, fmi2False);
        if (!c) {
            broken++;
            continue;
        }
        if (i % 2 == 0 &&
            (api->SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0) != fmi2OK ||
             api->EnterInitializationMode(c) != fmi2OK || api->ExitInitializationMode(c) != fmi2OK ||
             api->DoStep(c, 0.0, b->cycle, fmi2True) != fmi2OK))
            broken++;
        if (i % 3 == 0) api->Terminate(c); /* refused in some modes, harmless */
        api->FreeInstance(c);
        if (live_allocations() != live) {
            leaked++;
            live = live_allocations();
        }
    }
    check(broken == 0 && leaked == 0, "%ld instantiate/free cycles: %ld broken, %ld leaked", CYCLES,
          broken, leaked);

    sim s;
    broken = leaked = 0;
    bool ok = sim_open(&s, b, 0) && sim_advance(&s, PHASE_STEP);
    live = live_allocations();
    unsigned char *bytes = NULL;
    size_t size = 0;
    ok = ok && sim_state_bytes(&s, &bytes, &size);
    for (long i = 0; ok && i < CYCLES; i++) {
        fmi2FMUstate state = NULL, copy = NULL;
        if (api->GetFMUstate(s.c, &state) != fmi2OK) broken++;
        if (i % 2 == 0 && api->SetFMUstate(s.c, state) != fmi2OK) broken++;
        if (i % 4 == 0 &&
            (api->DeSerializeFMUstate(s.c, (const fmi2Byte *)bytes, size, &copy) != fmi2OK ||
             api->FreeFMUstate(s.c, &copy) != fmi2OK))
            broken++;
        if (api->FreeFMUstate(s.c, &state) != fmi2OK || state) broken++;
        if (live_allocations() != live) {
            leaked++;
            live = live_allocations();
        }
    }
    (void)size;
    free(bytes);
    check(ok && broken == 0, "%ld get/set/deserialize/free state cycles: %ld broken (%s)", CYCLES,
          broken, s.failure);
    check(leaked == 0, "state cycles leaked %ld times", leaked);
    sim_close(&s);
    group_end();
}

/* ---- threads: N instances on N threads give exactly the serial outputs ---- */

typedef struct {
    const block *b;
    const reference *ref;
    int variant;
    bool ok;
    char why[300];
} thread_job;

static bool thread_scenario(thread_job *job);

/* Each thread repeats its scenario, so that the threads of a round overlap for long. */
#define THREAD_REPEATS 20

static void *thread_run(void *argument)
{
    thread_job *job = argument;
    job->ok = true;
    for (int i = 0; i < THREAD_REPEATS && job->ok; i++) job->ok = thread_scenario(job);
    return NULL;
}

static bool thread_scenario(thread_job *job)
{
    const fmi2_api *api = &job->b->api;
    sim s;
    fmi2FMUstate state = NULL, copy = NULL;
    unsigned char *bytes = NULL;
    size_t size = 0;
    char why[256] = "";
    bool ok = sim_open(&s, job->b, job->variant) && sim_advance(&s, PHASE_STEP) &&
              api->GetFMUstate(s.c, &state) == fmi2OK && sim_state_bytes(&s, &bytes, &size) &&
              api->DeSerializeFMUstate(s.c, (const fmi2Byte *)bytes, size, &copy) == fmi2OK;
    int k0 = s.k;
    double t0 = s.t;
    ok = ok && sim_run_to_end(&s) && same_trace(&s, job->ref, 0, why, sizeof why);
    /* back to the middle from the deserialized copy, and the same end again */
    if (ok && api->SetFMUstate(s.c, copy) == fmi2OK) {
        s.k = k0;
        s.t = t0;
        s.phase = PHASE_STEP;
        ok = sim_run_to_end(&s) && same_trace(&s, job->ref, 0, why, sizeof why);
    } else {
        ok = false;
    }
    if (state) api->FreeFMUstate(s.c, &state);
    if (copy) api->FreeFMUstate(s.c, &copy);
    free(bytes);
    snprintf(job->why, sizeof job->why, "%s %s", s.failure, why);
    sim_close(&s);
    return ok;
}

/* THREADS instances of the block, each on its own thread with its own input pattern, plus,
 * when another block is given, two instances of that library alongside. */
static void group_threads(const block *b, const reference *refs)
{
    group_begin("threads");
    reference other_refs[2];
    int others = 0;
    if (FOREIGN.other) {
        bool ok = reference_run(FOREIGN.other, 0, &other_refs[0]) &&
                  reference_run(FOREIGN.other, 1, &other_refs[1]);
        if (check(ok, "reference runs of %s", FOREIGN.other->md.identifier)) others = 2;
    }
    int n = THREADS + others;
    thread_job *jobs = calloc((size_t)n, sizeof *jobs);
    pthread_t *threads = calloc((size_t)n, sizeof *threads);
    bool *started = calloc((size_t)n, sizeof *started);
    long live = live_allocations();
    for (int round = 0; jobs && threads && started && round < ROUNDS; round++) {
        for (int i = 0; i < n; i++) {
            if (i < THREADS) jobs[i] = (thread_job){.b = b, .ref = &refs[i], .variant = i};
            else jobs[i] = (thread_job){.b = FOREIGN.other, .ref = &other_refs[i - THREADS], .variant = i - THREADS};
            started[i] = pthread_create(&threads[i], NULL, thread_run, &jobs[i]) == 0;
            if (!started[i]) snprintf(jobs[i].why, sizeof jobs[i].why, "pthread_create failed");
        }
        int good = 0;
        for (int i = 0; i < n; i++) {
            if (started[i]) pthread_join(threads[i], NULL);
            if (jobs[i].ok) good++;
        }
        for (int i = 0; i < n; i++)
            if (!jobs[i].ok)
                check(false, "round %d, thread %d (%s): %s", round, i, jobs[i].b->md.identifier, jobs[i].why);
        check(good == n, "round %d: %d of %d threads (%d of %s, %d of the other block) gave the "
                         "serial outputs", round, good, n, THREADS, b->md.identifier, others);
    }
    check(live_allocations() == live, "%ld blocks left after the threads", live_allocations() - live);
    for (int i = 0; i < others; i++) reference_free(&other_refs[i]);
    free(jobs);
    free(threads);
    free(started);
    group_end();
}

/* ---- main ---- */

static void usage(void)
{
    fprintf(stderr, "usage: harness [--cycles N] [--threads N] [--rounds N] [--timeout S] "
                    "<lib.so> <modelDescription.xml> <guid> [<other lib.so> <other xml> <other guid>]\n");
}

int main(int argc, char **argv)
{
    int timeout = 600;
    int a = 1;
    for (; a + 1 < argc && !strncmp(argv[a], "--", 2); a += 2) {
        if (!strcmp(argv[a], "--cycles")) CYCLES = atol(argv[a + 1]);
        else if (!strcmp(argv[a], "--threads")) THREADS = atoi(argv[a + 1]);
        else if (!strcmp(argv[a], "--rounds")) ROUNDS = atoi(argv[a + 1]);
        else if (!strcmp(argv[a], "--timeout")) timeout = atoi(argv[a + 1]);
        else {
            usage();
            return 2;
        }
    }
    if ((argc - a != 3 && argc - a != 6) || THREADS < 1 || THREADS > 64 || CYCLES < 1) {
        usage();
        return 2;
    }
    signal(SIGALRM, on_timeout);
    alarm((unsigned)timeout);
    setvbuf(stdout, NULL, _IOLBF, 0);

    static block main_block, other_block;
    block *b = &main_block;
    if (!load_block(b, argv[a], argv[a + 1], argv[a + 2])) {
        printf("0 passed, 1 failed\n");
        return 1;
    }
    printf("%s (%s)\n", b->md.identifier, b->library);
    if (argc - a == 6) {
        if (load_block(&other_block, argv[a + 3], argv[a + 4], argv[a + 5])) {
            FOREIGN.other = &other_block;
            fmi2CallbackFunctions callbacks = harness_callbacks(&FOREIGN.other_log);
            FOREIGN.other_instance = other_block.api.Instantiate(
                "other", fmi2CoSimulation, other_block.guid, "", &callbacks, fmi2False, fmi2False);
            sim os;
            memset(&os, 0, sizeof os);
            os.b = &other_block;
            os.c = FOREIGN.other_instance;
            os.trace = calloc((size_t)(STEPS + 1) * (size_t)other_block.n_outputs, sizeof *os.trace);
            snprintf(os.name, sizeof os.name, "other");
            if (!os.c || !os.trace || !sim_advance(&os, PHASE_STEP) ||
                !sim_state_bytes(&os, &FOREIGN.other_bytes, &FOREIGN.other_size) ||
                other_block.api.GetFMUstate(os.c, &FOREIGN.other_state) != fmi2OK) {
                printf("  the other block %s does not run: %s\n", argv[a + 3], os.failure);
                FOREIGN.other = NULL;
            }
            free(os.trace);
        }
    }
    if (!FOREIGN.other) printf("  SKIPPED: cases with another block's state (no usable second block given)\n");

    reference *refs = calloc((size_t)THREADS, sizeof *refs);
    bool refs_ok = refs != NULL;
    for (int v = 0; refs_ok && v < THREADS; v++) refs_ok = reference_run(b, v, &refs[v]);
    if (!refs_ok) {
        printf("  the reference scenario does not run; nothing else can be checked\n");
        printf("0 passed, 1 failed\n");
        return 1;
    }

    struct timespec start;
    clock_gettime(CLOCK_MONOTONIC, &start);
    group_library(b, argv[a + 2], refs);
    group_state_layout(b);
    group_instantiate(b);

    misuse_list list = {0};
    build_misuses(b, FOREIGN.other, &list);
    const char *current = NULL;
    for (size_t i = 0; i < list.count; i++) {
        if (!current || strcmp(current, list.items[i].group)) {
            if (current) group_end();
            current = list.items[i].group;
            group_begin(current);
        }
        run_misuse(b, &refs[0], &list.items[i]);
    }
    if (current) group_end();
    free(list.items);

    group_out_of_memory(b);
    group_reset(b, &refs[0]);
    group_state_round_trip(b, &refs[0]);
    group_clock_limits(b);
    group_extreme_words(b);
    group_cycles(b);
    group_threads(b, refs);

    double elapsed = seconds_since(&start);
    for (int v = 0; v < THREADS; v++) reference_free(&refs[v]);
    free(refs);
    if (FOREIGN.other) {
        other_block.api.FreeFMUstate(FOREIGN.other_instance, &FOREIGN.other_state);
        free(FOREIGN.other_bytes);
    }
    if (FOREIGN.other_instance) other_block.api.FreeInstance(FOREIGN.other_instance);
    if (other_block.api.handle) unload_block(&other_block);
    unload_block(b);
    check(live_allocations() == 0, "%ld blocks allocated through the callbacks were never freed",
          live_allocations());
    check(malformed_log_messages() == 0,
          "%ld log messages hold a '#' that is not escaped as \"##\" (FMI 2.0, 2.1.5)",
          malformed_log_messages());
    printf("checks took %.2f s\n", elapsed);
    printf("%d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
