/* The C harness of the LGF FMUs: drives one block's FMU binary through dlopen, as an importer
 * does, and checks every misuse of docs/behaviour.md §1.7, FMU states, leaks and threads.
 *
 *   harness [options] <Block>.so <Block>.xml <guid> [<Other>.so <Other>.xml <other guid>]
 *
 * The version (FMI 2.0 or 3.0) is the XML's fmiVersion; everything but what only one version
 * has (fmi2.c's and fmi3.c's cases and groups) runs through the block's fmu_ops. The optional
 * second block (of the same version) supplies a state and a serialized state of another FMU.
 * Options: --cycles N (instantiate/free and state cycles, default 10000), --threads N
 * (default 8), --rounds N (parallel rounds, default 10), --timeout S (default 600),
 * --fmi2 <Block>.so <Block>.xml (FMI 3.0: the same block's FMI 2.0 library, whose outputs and
 * states the FMI 3.0 ones must equal).
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
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

int STEPS = 30;
int STEP_PHASE_AT = 10;
foreign_states FOREIGN;

long CYCLES = 10000;
int THREADS = 8;
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

void sim_fail(sim *s, const char *fmt, ...)
{
    if (s->failure[0]) return;
    va_list args;
    va_start(args, fmt);
    vsnprintf(s->failure, sizeof s->failure, fmt, args);
    va_end(args);
}

const char *interface_name(fmi2Type type)
{
    return type == fmi2ModelExchange ? "Model Exchange" : "co-simulation";
}

const char *phase_name(fmi2Type type, int phase)
{
    static const char *const names[PHASES] = {"instantiated", "initialization mode", "step mode",
                                              "terminated", "continuous-time mode"};
    if (phase == PHASE_STEP && type == fmi2ModelExchange) return "event mode";
    return phase >= 0 && phase < PHASES ? names[phase] : "?";
}

static int64_t cycle_us(const block *b) { return (int64_t)llround(b->cycle * 1e6); }

/* The FMU's nextEventTime: t0 + (k·cycle_us)/1e6, from integers (src/core/clock.c). */
double call_time(const block *b, int64_t k) { return 0.0 + (double)(k * cycle_us(b)) / 1e6; }

double me_stop_time(const block *b) { return call_time(b, STEPS + 2); }

bool sim_open_as(sim *s, const block *b, int variant, fmi2Type type)
{
    memset(s, 0, sizeof *s);
    s->b = b;
    s->type = type;
    s->variant = variant;
    snprintf(s->name, sizeof s->name, "%s%d", type == fmi2ModelExchange ? "me" : "harness",
             variant);
    s->trace =
        calloc((size_t)(STEPS + 1) * (size_t)(b->n_outputs ? b->n_outputs : 1), sizeof *s->trace);
    s->c = FMU(b, instantiate, s->name, type, &s->log);
    if (!s->c || !s->trace) {
        sim_fail(s, "instantiating (%s) failed", interface_name(type));
        return false;
    }
    return true;
}

bool sim_open(sim *s, const block *b, int variant)
{
    return sim_open_as(s, b, variant, fmi2CoSimulation);
}

void sim_close(sim *s)
{
    if (s->c) FMU(s->b, free_instance, s->c);
    s->c = NULL;
    free(s->trace);
    s->trace = NULL;
}

double step_size(const sim *s, int k)
{
    static const double factors[] = {1.0, 2.0, 0.5, 1.5};
    return s->uniform ? s->b->cycle : s->b->cycle * factors[k % 4];
}

enum { INPUTS_ALL, INPUTS_REAL, INPUTS_DISCRETE }; /* which inputs sim_set_inputs_part sets */

/* Inputs of call k: patterns within each input's range that change at different rates. */
static void sim_set_inputs_part(sim *s, int k, int part)
{
    const block *b = s->b;
    for (int p = 0; p < b->n_inputs; p++) {
        const md_variable *v = &b->md.variables[b->inputs[p]];
        if ((part == INPUTS_REAL && v->kind != KIND_REAL) ||
            (part == INPUTS_DISCRETE && v->kind == KIND_REAL))
            continue;
        int n = k + s->variant + p;
        double value;
        if (v->kind == KIND_BOOLEAN) {
            int period = 3 + 2 * (p % 4);
            value = ((n / period) + p) % 2 ? 1 : 0;
        } else if (v->kind == KIND_INTEGER) {
            /* held for four calls: LGF_FloatingAverage restarts at each new windowSize and reads
             * nothing in that call, so a size that changed in every call would hide the block */
            value = v->start + (n / 4) % 3;
            if (v->has_max && value > v->max) value = v->max;
        } else if (v->kind == KIND_REAL) {
            value = v->is_time ? v->start + 0.1 * (n % 3) : v->start + 2.5 * (n % 5) - 3.0;
            if (v->has_max && value > v->max) value = v->max;
            if (v->has_min && value < v->min) value = v->min;
        } else {
            continue;
        }
        int status = FMU(b, set, s->c, v->type, &v->vr, 1, &value, 1);
        if (status != fmi2OK)
            sim_fail(s, "setting input %s for call %d gave %d", v->name, k, status);
    }
}

void sim_set_inputs_for(sim *s, int k) { sim_set_inputs_part(s, k, INPUTS_ALL); }

/* A row holds each output as 64 bits: a Real (FMI 3.0: Float64, or a Float32 widened) as the
 * bits of its double, an integer of any width as its int64_t, a Boolean as 0 or 1; so rows of
 * both versions compare bit for bit. */
bool sim_read_outputs(sim *s, uint64_t *row)
{
    const block *b = s->b;
    for (int p = 0; p < b->n_outputs; p++) {
        const md_variable *v = &b->md.variables[b->outputs[p]];
        double value = 0;
        int status = FMU(b, get, s->c, v->type, &v->vr, 1, &value, 1);
        if (v->kind == KIND_REAL)
            memcpy(&row[p], &value, sizeof value);
        else
            row[p] = (uint64_t)(int64_t)value;
        if (status != fmi2OK) {
            sim_fail(s, "reading output %s gave %d", v->name, status);
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
        if (!v->has_start || v->kind == KIND_STRING || v->kind == KIND_OTHER) continue;
        double value = v->kind == KIND_BOOLEAN ? v->start != 0 : v->start;
        int status = FMU(b, set, s->c, v->type, &v->vr, 1, &value, 1);
        if (status != fmi2OK) {
            sim_fail(s, "setting parameter %s to its start value gave %d", v->name, status);
            return false;
        }
    }
    return true;
}

static bool sim_step_me(sim *s);

bool sim_step(sim *s)
{
    if (s->type == fmi2ModelExchange) return sim_step_me(s);
    int k = s->k + 1;
    sim_set_inputs_for(s, k);
    double h = step_size(s, k);
    int status = FMU(s->b, do_step, s->c, s->t, h);
    if (status != fmi2OK) {
        sim_fail(s, "%s(%.17g, %g) of step %d gave %d", FN(s->b, FN_DO_STEP), s->t, h, k, status);
        return false;
    }
    s->t += h;
    s->k = k;
    s->rows = k + 1;
    return sim_read_outputs(s, s->trace + (size_t)k * (size_t)s->b->n_outputs) && !s->failure[0];
}

/* ---- the Model Exchange scenario ---- */

/* Whether eventInfo is what the FMU promises after the event iteration that executed call k
 * (or found no call due, the last call being k): no further iteration, no end, no continuous
 * states, the next time event at call k + 1. */
static bool event_info_ok(sim *s, const event_info *info, int k, const char *when)
{
    double next = call_time(s->b, k + 1);
    if (info->needed != 0 || info->terminate != 0 || info->nominals_changed != 0 ||
        info->values_changed != 0 || info->next_defined != 1 ||
        memcmp(&info->next, &next, sizeof next)) {
        sim_fail(s,
                 "%s: eventInfo {needed %d, terminate %d, nominals %d, values %d, defined %d, "
                 "next %.17g}, expected {0, 0, 0, 0, 1, %.17g}",
                 when, info->needed, info->terminate, info->nominals_changed, info->values_changed,
                 info->next_defined, info->next, next);
        return false;
    }
    s->next_event = info->next;
    return true;
}

static bool me_call(sim *s, int status, const char *what, int k)
{
    if (status == fmi2OK) return true;
    sim_fail(s, "%s before call %d gave %d", what, k, (int)status);
    return false;
}

/* An event iteration that must execute no call: the outputs stay those of call k, the
 * state's call counter does not move, eventInfo still points at call k + 1. */
static bool no_call_event(sim *s, int k, const char *when)
{
    uint64_t before[64], after[64];
    unsigned char *bytes0 = NULL, *bytes1 = NULL;
    size_t size0 = 0, size1 = 0;
    event_info info;
    bool ok = s->b->n_outputs <= 64 && sim_read_outputs(s, before) &&
              sim_state_bytes(s, &bytes0, &size0) &&
              me_call(s, FMU(s->b, update_discrete, s->c, &info), when, k + 1) &&
              event_info_ok(s, &info, k, when) && sim_read_outputs(s, after) &&
              sim_state_bytes(s, &bytes1, &size1);
    if (ok && (memcmp(before, after, (size_t)s->b->n_outputs * sizeof before[0]) ||
               size0 != size1 || memcmp(bytes0, bytes1, size0))) {
        sim_fail(s, "%s executed a call (the outputs or the state changed)", when);
        ok = false;
    }
    free(bytes0);
    free(bytes1);
    return ok;
}

/* Call k = s->k + 1: what the importer does from event mode right after the event iteration
 * of call k - 1 (or from continuous-time mode, in PHASE_CONTINUOUS) up to the event iteration
 * of call k, which leaves it in event mode. The pattern varies with k and the variant. */
static bool sim_step_me(sim *s)
{
    const block *b = s->b;
    int k = s->k + 1;
    double tk = call_time(s->b, k), t_prev = s->t;
    if (memcmp(&tk, &s->next_event, sizeof tk)) {
        sim_fail(s, "nextEventTime %.17g is not the time %.17g of call %d", s->next_event, tk, k);
        return false;
    }
    int pattern = (k + s->variant) % 6;
    if (pattern == 3 && s->in_event) {
        /* stays in event mode: the time of the next event is set there */
        if (!me_call(s, FMU(b, set_time, s->c, tk), "setting the time in event mode", k))
            return false;
    } else {
        if (s->in_event &&
            !me_call(s, FMU(b, enter_continuous, s->c), FN(b, FN_ENTER_CONTINUOUS), k))
            return false;
        s->in_event = false;
        if (pattern == 4) sim_set_inputs_part(s, k, INPUTS_REAL); /* Real inputs in CT mode */
        if (pattern == 1 || pattern == 2 || pattern == 4) {
            double mid = t_prev + 0.4 * (tk - t_prev);
            int enter = 1, terminate = 1;
            if (!me_call(s, FMU(b, set_time, s->c, mid), "setting an intermediate time", k) ||
                !me_call(s, FMU(b, completed, s->c, true, &enter, &terminate), FN(b, FN_COMPLETED),
                         k))
                return false;
            if (enter != 0 || terminate != 0) {
                sim_fail(s, "%s before call %d: enterEventMode %d, terminateSimulation %d",
                         FN(b, FN_COMPLETED), k, enter, terminate);
                return false;
            }
            s->t = mid;
            if (pattern == 2) { /* a state event of another FMU, at no call time */
                if (!me_call(s, FMU(b, enter_event, s->c), "entering event mode (state event)",
                             k) ||
                    !no_call_event(s, k - 1, "the event iteration of a state event") ||
                    !me_call(s, FMU(b, enter_continuous, s->c), FN(b, FN_ENTER_CONTINUOUS), k))
                    return false;
            }
        }
        if (!me_call(s, FMU(b, set_time, s->c, tk), FN(b, FN_SET_TIME), k) ||
            !me_call(s, FMU(b, enter_event, s->c), FN(b, FN_ENTER_EVENT), k))
            return false;
        s->in_event = true;
    }
    s->t = tk;
    sim_set_inputs_part(s, k, pattern == 4 ? INPUTS_DISCRETE : INPUTS_ALL);
    if (s->failure[0]) return false;
    event_info info;
    if (!me_call(s, FMU(b, update_discrete, s->c, &info), FN(b, FN_UPDATE_DISCRETE), k) ||
        !event_info_ok(s, &info, k, "the event iteration of a call"))
        return false;
    s->k = k;
    s->rows = k + 1;
    if (!sim_read_outputs(s, s->trace + (size_t)k * (size_t)s->b->n_outputs)) return false;
    /* a second event iteration at the same instant executes nothing */
    if (pattern == 5 && !no_call_event(s, k, "a second event iteration at a call's instant"))
        return false;
    return !s->failure[0];
}

/* Where a phase lies in the run: PHASE_CONTINUOUS comes right after PHASE_STEP. */
static int phase_rank(int phase)
{
    static const int rank[PHASES] = {0, 1, 2, 4, 3};
    return rank[phase];
}

bool sim_advance(sim *s, int phase)
{
    const block *b = s->b;
    bool me = s->type == fmi2ModelExchange;
    while (phase_rank(s->phase) < phase_rank(phase) && !s->failure[0]) {
        switch (s->phase) {
        case PHASE_INSTANTIATED:
            if (FMU(b, begin, s->c, 0.0, me, me ? me_stop_time(b) : 0.0) != fmi2OK) {
                sim_fail(s, "%s failed", FN(b, FN_ENTER_INIT));
                return false;
            }
            if (!set_parameters(s)) return false;
            sim_set_inputs_for(s, 0);
            s->phase = PHASE_INITIALIZATION;
            break;
        case PHASE_INITIALIZATION:
            if (FMU(b, exit_init, s->c) != fmi2OK) {
                sim_fail(s, "%s failed", FN(b, FN_EXIT_INIT));
                return false;
            }
            s->t = 0.0;
            s->k = 0;
            s->rows = 1;
            if (!sim_read_outputs(s, s->trace)) return false;
            /* Model Exchange: event mode; the event iteration at t0 finds call 0 done */
            s->in_event = me;
            if (me && !no_call_event(s, 0, "the event iteration at t0")) return false;
            while (s->k < STEP_PHASE_AT)
                if (!sim_step(s)) return false;
            s->phase = PHASE_STEP;
            break;
        case PHASE_STEP:
            if (phase == PHASE_CONTINUOUS) {
                if (!me_call(s, FMU(b, enter_continuous, s->c), FN(b, FN_ENTER_CONTINUOUS),
                             s->k + 1))
                    return false;
                s->in_event = false;
                s->phase = PHASE_CONTINUOUS;
                break;
            }
            /* fall through */
        case PHASE_CONTINUOUS:
            while (s->k < STEPS)
                if (!sim_step(s)) return false;
            /* Model Exchange ends in continuous-time mode half a cycle on in odd variants */
            if (me && s->variant % 2) {
                double end = s->t + 0.5 * b->cycle;
                if (!me_call(s, FMU(b, enter_continuous, s->c), FN(b, FN_ENTER_CONTINUOUS), 0) ||
                    !me_call(s, FMU(b, set_time, s->c, end), FN(b, FN_SET_TIME), 0))
                    return false;
                s->in_event = false;
                s->t = end;
            }
            if (FMU(b, terminate, s->c) != fmi2OK) {
                sim_fail(s, "%s failed", FN(b, FN_TERMINATE));
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

/* That nothing allocated since `live` (a count of live_allocations()) is left after `what`. */
static void check_none_left(long live, const char *what)
{
    check(live_allocations() == live, "%ld blocks left after %s", live_allocations() - live, what);
}

/* The end of a group that must leave nothing allocated: check_none_left, then group_end. */
static void group_end_leaving_none(long live, const char *what)
{
    check_none_left(live, what);
    group_end();
}

bool sim_state_bytes(sim *s, unsigned char **bytes, size_t *size)
{
    const block *b = s->b;
    void *state = NULL;
    *bytes = NULL;
    *size = 0;
    if (FMU(b, get_state, s->c, &state) != fmi2OK || !state) {
        sim_fail(s, "%s failed", FN(b, FN_GET_STATE));
        return false;
    }
    bool ok = FMU(b, state_size, s->c, state, size) == fmi2OK && *size >= HEADER_SIZE;
    if (ok) *bytes = malloc(*size);
    ok = ok && *bytes && FMU(b, serialize, s->c, state, *bytes, *size) == fmi2OK;
    if (FMU(b, free_state, s->c, &state) != fmi2OK || state) ok = false;
    if (!ok) {
        free(*bytes);
        *bytes = NULL;
        sim_fail(s, "serializing the state failed");
    }
    return ok;
}

/* The state of `from`, serialized, restored into `to` (deserialize, set, free): one instance's
 * state carried into another, as an importer does (a state in memory is a handle of the
 * instance that made it, docs/behaviour.md §1.9). */
static bool sim_carry_state(sim *from, sim *to)
{
    const block *b = to->b;
    unsigned char *bytes = NULL;
    size_t n = 0;
    void *state = NULL;
    bool ok = sim_state_bytes(from, &bytes, &n) &&
              FMU(b, deserialize, to->c, bytes, n, &state) == fmi2OK &&
              FMU(b, set_state, to->c, state) == fmi2OK &&
              FMU(b, free_state, to->c, &state) == fmi2OK;
    free(bytes);
    return ok;
}

bool reference_run(const block *b, int variant, reference *ref)
{
    return reference_run_as(b, variant, fmi2CoSimulation, false, ref);
}

bool reference_run_as(const block *b, int variant, fmi2Type type, bool uniform, reference *ref)
{
    memset(ref, 0, sizeof *ref);
    sim s;
    bool ok = sim_open_as(&s, b, variant, type);
    s.uniform = uniform;
    for (int phase = PHASE_INSTANTIATED; ok && phase <= PHASE_TERMINATED; phase++)
        ok = sim_advance(&s, phase) &&
             sim_state_bytes(&s, &ref->state_at[phase], &ref->size_at[phase]);
    if (ok) {
        size_t n = (size_t)s.rows * (size_t)b->n_outputs;
        ref->trace = malloc((n ? n : 1) * sizeof *ref->trace);
        ok = ref->trace != NULL;
        if (ok) memcpy(ref->trace, s.trace, n * sizeof *ref->trace);
        ref->rows = s.rows;
        ref->final_state = malloc(ref->size_at[PHASE_TERMINATED]);
        ok = ok && ref->final_state;
        if (ok) {
            memcpy(ref->final_state, ref->state_at[PHASE_TERMINATED],
                   ref->size_at[PHASE_TERMINATED]);
            ref->final_size = ref->size_at[PHASE_TERMINATED];
        }
    }
    if (!ok)
        fprintf(stdout, "  %s reference run of variant %d failed: %s\n", interface_name(type),
                variant, s.failure);
    sim_close(&s);
    return ok;
}

void reference_free(reference *ref)
{
    free(ref->trace);
    free(ref->final_state);
    for (int i = 0; i < PHASES; i++) free(ref->state_at[i]);
    memset(ref, 0, sizeof *ref);
}

/* Whether s's trace from row `from` on equals the reference; the difference into why. */
bool same_trace(const sim *s, const reference *ref, int from, char *why, size_t size)
{
    int n = s->b->n_outputs;
    if (s->rows != ref->rows) {
        snprintf(why, size, "%d rows instead of %d", s->rows, ref->rows);
        return false;
    }
    for (int r = from; r < s->rows; r++) {
        for (int p = 0; p < n; p++) {
            if (s->trace[(size_t)r * (size_t)n + (size_t)p] !=
                ref->trace[(size_t)r * (size_t)n + (size_t)p]) {
                snprintf(why, size, "output %s differs at row %d",
                         s->b->md.variables[s->b->outputs[p]].name, r);
                return false;
            }
        }
    }
    return true;
}

bool same_bytes(const unsigned char *a, size_t na, const unsigned char *b, size_t nb, char *why,
                size_t size, const char *what)
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

bool same_reference(const block *b, const reference *x, const reference *y, char *why, size_t size)
{
    int n = b->n_outputs;
    if (x->rows != y->rows) {
        snprintf(why, size, "%d rows and %d rows", x->rows, y->rows);
        return false;
    }
    for (int r = 0; r < x->rows; r++)
        for (int p = 0; p < n; p++)
            if (x->trace[(size_t)r * (size_t)n + (size_t)p] !=
                y->trace[(size_t)r * (size_t)n + (size_t)p]) {
                snprintf(why, size, "output %s differs in row %d",
                         b->md.variables[b->outputs[p]].name, r);
                return false;
            }
    static const char *const phases[PHASES] = {"instantiated", "initialization mode",
                                               "after call/step 10", "terminated",
                                               "continuous-time mode"};
    for (int phase = 0; phase < PHASES; phase++) {
        if (!x->state_at[phase] && !y->state_at[phase]) continue;
        char what[96];
        snprintf(what, sizeof what, "the serialized state (%s)", phases[phase]);
        if (!same_bytes(x->state_at[phase], x->size_at[phase], y->state_at[phase],
                        y->size_at[phase], why, size, what))
            return false;
    }
    return true;
}

bool isolated(bool (*fn)(void *arg, char *why, size_t size), void *arg, char *why, size_t size)
{
    enum { CHECKS_FAILED = 42 };
    int channel[2];
    why[0] = '\0';
    fflush(stdout);
    fflush(stderr);
    if (pipe(channel) != 0) {
        snprintf(why, size, "pipe failed");
        return false;
    }
    pid_t child = fork();
    if (child < 0) {
        close(channel[0]);
        close(channel[1]);
        snprintf(why, size, "fork failed");
        return false;
    }
    if (child == 0) {
        close(channel[0]);
        bool ok = fn(arg, why, size);
        ssize_t ignored = write(channel[1], why, strlen(why));
        (void)ignored;
        _exit(ok ? 0 : CHECKS_FAILED);
    }
    close(channel[1]);
    size_t got = 0;
    for (ssize_t n; got + 1 < size && (n = read(channel[0], why + got, size - 1 - got)) > 0;)
        got += (size_t)n;
    why[got] = '\0';
    close(channel[0]);
    int status = 0;
    if (waitpid(child, &status, 0) != child) {
        snprintf(why, size, "waitpid failed");
        return false;
    }
    if (WIFEXITED(status) && (WEXITSTATUS(status) == 0 || WEXITSTATUS(status) == CHECKS_FAILED))
        return WEXITSTATUS(status) == 0;
    if (WIFSIGNALED(status))
        snprintf(why + got, size - got, "%sthe call crashed (signal %d%s)", got ? "; " : "",
                 WTERMSIG(status), WTERMSIG(status) == SIGSEGV ? ", a segmentation fault" : "");
    else
        snprintf(why + got, size - got,
                 "%sthe child ended with exit status %d (a sanitizer's report?)", got ? "; " : "",
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1);
    return false;
}

/* ---- one misuse: the call, its log, the unchanged state, an unchanged future ---- */

void run_misuse(const block *b, const reference *ref, const misuse *m)
{
    char why[1024] = "";
    long live_before = live_allocations();
    sim s;
    unsigned char *before = NULL, *after = NULL;
    size_t before_size = 0, after_size = 0;
    bool ok = sim_open_as(&s, b, 0, m->type) && sim_advance(&s, m->phase) &&
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
        snprintf(why, sizeof why, "%d messages instead of %d (%ld in all); last: \"%.300s\"",
                 logged, m->logs, total_log_messages() - messages, e && logged ? e->text : "");
        ok = false;
        goto done;
    }
    for (int j = mark; j < s.log.total; j++) {
        const log_entry *e = log_get(&s.log, j);
        const char *category = m->log_status == fmi2Warning   ? "logStatusWarning"
                               : m->log_status == fmi2Discard ? "logStatusDiscard"
                                                              : "logStatusError";
        /* FMI 3.0's logMessage gets no instance name */
        if (!e || (int)e->status != m->log_status || strcmp(e->category, category) ||
            (b->ops->version == 2 && strcmp(e->instance, s.name)) ||
            strncmp(e->text, m->function, strlen(m->function)) ||
            (m->contains[0] && !strstr(e->text, m->contains))) {
            snprintf(why, sizeof why,
                     "message (status %d, category %.40s, instance %.40s) \"%.300s\" should have "
                     "status %d "
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
            if (FMU(b, reset, s.c) != fmi2OK) {
                snprintf(why, sizeof why, "%s after the call failed", FN(b, FN_RESET));
                ok = false;
                goto done;
            }
            s.phase = PHASE_INSTANTIATED;
            s.k = s.rows = 0;
            s.t = 0;
            s.in_event = false;
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
    check(ok, "%s (%s, in %s): %s", m->label, interface_name(m->type),
          phase_name(m->type, m->phase), why);
}

/* ---- the block ---- */

bool load_block(block *b, const char *library, const char *xml, const char *guid)
{
    char error[512];
    memset(b, 0, sizeof *b);
    b->library = library;
    snprintf(b->guid, sizeof b->guid, "%s", guid);
    if (!md_read(&b->md, xml, error, sizeof error)) {
        printf("  cannot load %s: %s\n", library, error);
        return false;
    }
    b->ops = b->md.version == 3 ? &fmi3_ops : &fmi2_ops;
    if (!b->ops->load(b, error, sizeof error)) {
        printf("  cannot load %s: %s\n", library, error);
        md_free(&b->md);
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

void unload_block(block *b)
{
    if (b->ops) b->ops->unload(b);
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
    const char *version = b->ops->get_version(b);
    check(!strcmp(version, b->ops->version_string), "fmi%dGetVersion is \"%s\"", b->ops->version,
          version);
    if (b->ops->version == 2)
        check(!strcmp(b->api.GetTypesPlatform(), "default"), "fmi2GetTypesPlatform is \"%s\"",
              b->api.GetTypesPlatform());
    check(!strcmp(b->md.fmi_version, b->ops->version_string), "fmiVersion is %s",
          b->md.fmi_version);
    check(!strcmp(b->md.guid, guid), "the XML's %s %s is not the one given (%s)",
          b->ops->version == 3 ? "instantiationToken" : "guid", b->md.guid, guid);
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
        int set = fmi2Error, back = fmi2Error;
        /* A REAL (float32) is 4 bytes: FMI 3.0 says so (Float32); FMI 2.0 calls it a Real like an
         * LREAL, so a value whose double differs in every byte from the one before tells: a
         * double changes 8 bytes, a float at most 4. */
        int width = v->kind == KIND_REAL ? (v->is_cycle || v->is_time || v->single ? 4 : 8)
                    : v->kind == KIND_INTEGER
                        ? (v->type == T3_UINT32 && b->ops->version == 3 ? 4 : 2)
                        : 1;
        double current = 0, value = 0;
        FMU(b, get, s.c, v->type, &v->vr, 1, &current, 1);
        if (v->kind == KIND_REAL)
            value = v->is_cycle  ? v->start * 2
                    : v->is_time ? v->start + 1.234
                                 : current + 1234.56789012345678 + (current == 0 ? 0.25 : current);
        else if (v->kind == KIND_INTEGER)
            value = v->has_max && current + 1 > v->max ? current - 1 : current + 1;
        else
            value = current == 0;
        if (v->kind == KIND_REAL && v->has_max && value > v->max) value = v->max;
        if (v->kind == KIND_REAL && v->has_min && value < v->min) value = v->min;
        if (!sim_state_bytes(&s, &before, &nb)) break;
        set = FMU(b, set, s.c, v->type, &v->vr, 1, &value, 1);
        if (sim_state_bytes(&s, &after, &na))
            back = FMU(b, set, s.c, v->type, &v->vr, 1, &current, 1);
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
        /* FMI 2.0 Real: a UDINT counts in a 4-byte word, and a Real that changed no more than
         * one aligned 4-byte word is a float */
        if (b->ops->version == 2 && v->kind == KIND_REAL && width == 8 &&
            (lo - HEADER_SIZE) / 4 == (hi - HEADER_SIZE) / 4)
            width = 4;
        if (b->ops->version == 2 && v->kind == KIND_INTEGER && (v->has_max && v->max > 65535))
            width = 4;
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
    /* The clock at the start of the payload, as src/core/state.c lays it out. */
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
        b->layout_known = check(
            mode == MODE_STEP && cycle_us == (int32_t)llround(b->cycle * 1e6) && start == 0.0 &&
                now == s.t && calls == expected_calls,
            "the payload does not start with the clock of src/core/state.c (mode %d, "
            "cycle %d µs, t0 %g, t %g, calls %lld; expected t %g, calls %lld)",
            (int)mode, (int)cycle_us, start, now, (long long)calls, s.t, (long long)expected_calls);
    }
    free(bytes);
    sim_close(&s);
    group_end();
}

void make_wrong_guids(const block *b, wrong_guids *w)
{
    snprintf(w->other, sizeof w->other, "%s",
             FOREIGN.other ? FOREIGN.other->guid : "{00000000-0000-0000-0000-000000000001}");
    snprintf(w->prefix, sizeof w->prefix, "%.*s", (int)strlen(b->guid) - 1, b->guid);
    snprintf(w->changed, sizeof w->changed, "%s", b->guid);
    w->changed[1] = w->changed[1] == 'a' ? 'b' : 'a';
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
    wrong_guids wrong;
    make_wrong_guids(b, &wrong);
    const instantiation cases[] = {
        {"valid", "i", fmi2CoSimulation, b->guid, 0, "file:///tmp", true, 0, NULL},
        {"NULL fmuResourceLocation", "i", fmi2CoSimulation, b->guid, 0, NULL, true, 0, NULL},
        {"wrong GUID", "i", fmi2CoSimulation, "{00000000-0000-0000-0000-000000000000}", 0, "",
         false, 1, "fmuGUID"},
        {"GUID of another block", "i", fmi2CoSimulation, wrong.other, 0, "", false, 1, "fmuGUID"},
        {"GUID without its last character", "i", fmi2CoSimulation, wrong.prefix, 0, "", false, 1,
         "fmuGUID"},
        {"GUID with one character changed", "i", fmi2CoSimulation, wrong.changed, 0, "", false, 1,
         "fmuGUID"},
        {"empty GUID", "i", fmi2CoSimulation, "", 0, "", false, 1, "fmuGUID"},
        {"NULL GUID", "i", fmi2CoSimulation, NULL, 0, "", false, 1, "fmuGUID"},
        {"Model Exchange", "i", fmi2ModelExchange, b->guid, 0, "file:///tmp", true, 0, NULL},
        {"Model Exchange, NULL fmuResourceLocation", "i", fmi2ModelExchange, b->guid, 0, NULL, true,
         0, NULL},
        {"fmuType 2 (no such type)", "i", 2, b->guid, 0, "", false, 1, "fmuType"},
        {"fmuType -1 (no such type)", "i", -1, b->guid, 0, "", false, 1, "fmuType"},
        {"Model Exchange, NULL instanceName", NULL, fmi2ModelExchange, b->guid, 0, "", false, 1,
         "instanceName"},
        {"Model Exchange, NULL allocateMemory", "i", fmi2ModelExchange, b->guid, 3, "", false, 1,
         "allocateMemory"},
        {"Model Exchange, NULL logger", "i", fmi2ModelExchange, b->guid, 2, "", false, 0, NULL},
        {"NULL instanceName", NULL, fmi2CoSimulation, b->guid, 0, "", false, 1, "instanceName"},
        {"empty instanceName", "", fmi2CoSimulation, b->guid, 0, "", false, 1, "instanceName"},
        {"NULL functions", "i", fmi2CoSimulation, b->guid, 1, "", false, 0, NULL},
        {"NULL logger", "i", fmi2CoSimulation, b->guid, 2, "", false, 0, NULL},
        {"NULL allocateMemory", "i", fmi2CoSimulation, b->guid, 3, "", false, 1, "allocateMemory"},
        {"NULL freeMemory", "i", fmi2CoSimulation, b->guid, 4, "", false, 1, "freeMemory"},
        {"Model Exchange and wrong GUID", "i", fmi2ModelExchange, "{x}", 0, "", false, 1,
         "fmi2Instantiate"},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        const instantiation *t = &cases[i];
        log_record log = {0};
        fmi2CallbackFunctions callbacks = harness_callbacks(&log);
        if (t->callbacks == 2) callbacks.logger = NULL;
        if (t->callbacks == 3) callbacks.allocateMemory = NULL;
        if (t->callbacks == 4) callbacks.freeMemory = NULL;
        long live = live_allocations(), messages = total_log_messages();
        fmi2Component c =
            b->api.Instantiate(t->name, (fmi2Type)t->type, t->guid, t->resources,
                               t->callbacks == 1 ? NULL : &callbacks, fmi2False, fmi2False);
        const log_entry *e = log_get(&log, 0);
        bool ok = (c != NULL) == t->succeeds && log.total == t->logs &&
                  total_log_messages() - messages == t->logs;
        if (ok && t->logs)
            ok = e && e->status == fmi2Error && !strcmp(e->category, "logStatusError") &&
                 !strncmp(e->text, "fmi2Instantiate", 15) && strstr(e->text, t->contains) &&
                 !strcmp(e->instance, t->name && *t->name ? t->name : e->instance);
        if (c) {
            /* it works: a step (or the time event of call 1) and a clean free */
            fmi2EventInfo info;
            ok = ok && b->api.SetupExperiment(c, fmi2False, 0, 0, fmi2False, 0) == fmi2OK &&
                 b->api.EnterInitializationMode(c) == fmi2OK &&
                 b->api.ExitInitializationMode(c) == fmi2OK;
            if (t->type == fmi2ModelExchange)
                ok = ok && b->api.NewDiscreteStates(c, &info) == fmi2OK &&
                     b->api.EnterContinuousTimeMode(c) == fmi2OK &&
                     b->api.SetTime(c, info.nextEventTime) == fmi2OK &&
                     b->api.EnterEventMode(c) == fmi2OK &&
                     b->api.NewDiscreteStates(c, &info) == fmi2OK &&
                     info.nextEventTime == call_time(b, 2) &&
                     b->api.DoStep(c, 0.0, b->cycle, fmi2True) == fmi2Error;
            else
                ok = ok && b->api.DoStep(c, 0.0, b->cycle, fmi2True) == fmi2OK;
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
    fmi2Component a =
        b->api.Instantiate("same", fmi2CoSimulation, b->guid, "", &c1, fmi2False, fmi2False);
    fmi2Component z =
        b->api.Instantiate("same", fmi2CoSimulation, b->guid, "", &c2, fmi2True, fmi2True);
    check(a && z && a != z, "two instances of the same name");
    if (a) b->api.FreeInstance(a);
    if (z) b->api.FreeInstance(z);
    /* The FMU copies the callbacks: a struct that goes away after fmi2Instantiate is fine. */
    log_record l3 = {0};
    fmi2CallbackFunctions *temporary = malloc(sizeof *temporary);
    fmi2Component c = NULL;
    if (temporary) {
        *temporary = harness_callbacks(&l3);
        c = b->api.Instantiate("copy", fmi2CoSimulation, b->guid, "", temporary, fmi2False,
                               fmi2False);
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
        c = b->api.Instantiate(name, fmi2CoSimulation, b->guid, "", &callbacks, fmi2False,
                               fmi2False);
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
    for (int type = fmi2ModelExchange; type <= fmi2CoSimulation; type++) {
        log_record log = {0};
        fmi2CallbackFunctions callbacks = harness_callbacks(&log);
        long live = live_allocations();
        fmi2Component c =
            b->api.Instantiate("m", (fmi2Type)type, b->guid, "", &callbacks, fmi2False, fmi2False);
        long needed = live_allocations() - live;
        if (c) b->api.FreeInstance(c);
        check(c && needed > 0, "a plain fmi2Instantiate (%s) allocates",
              interface_name((fmi2Type)type));
        for (long n = 1; n <= needed; n++) {
            log = (log_record){0};
            fail_allocation_after(n);
            c = b->api.Instantiate("m", (fmi2Type)type, b->guid, "", &callbacks, fmi2False,
                                   fmi2False);
            fail_allocation_after(0);
            const log_entry *e = log_get(&log, 0);
            bool ok = !c && log.total == 1 && e && e->status == fmi2Error &&
                      !strncmp(e->text, "fmi2Instantiate", 15) && strstr(e->text, "memory");
            if (c) b->api.FreeInstance(c);
            check(ok && live_allocations() == live,
                  "%s: allocation %ld of %ld fails: %s, %d messages \"%s\", %ld blocks left",
                  interface_name((fmi2Type)type), n, needed, c ? "an instance" : "NULL", log.total,
                  e ? e->text : "", live_allocations() - live);
        }
    }
    group_end();
}

/* fmi2Reset from every phase leads to a run identical to the reference. */
static void group_reset(const block *b, const reference *ref, const reference *me_ref)
{
    group_begin(b->ops->version == 3 ? "fmi3Reset" : "fmi2Reset");
    for (int type = fmi2ModelExchange; type <= fmi2CoSimulation; type++) {
        for (int phase = PHASE_INSTANTIATED; phase < PHASES; phase++) {
            if (phase == PHASE_CONTINUOUS && type != fmi2ModelExchange) continue;
            sim s;
            char why[256] = "";
            bool ok = sim_open_as(&s, b, 0, (fmi2Type)type) && sim_advance(&s, phase);
            int logged = s.log.total;
            ok = ok && FMU(b, reset, s.c) == fmi2OK && s.log.total == logged;
            if (ok) {
                s.phase = PHASE_INSTANTIATED;
                s.k = s.rows = 0;
                s.t = 0;
                s.in_event = false;
                ok = sim_run_to_end(&s) &&
                     same_trace(&s, type == fmi2ModelExchange ? me_ref : ref, 0, why, sizeof why);
            }
            check(ok, "%s: fmi2Reset in %s, then a whole run: %s %s",
                  interface_name((fmi2Type)type), phase_name((fmi2Type)type, phase), s.failure,
                  why);
            sim_close(&s);
        }
    }
    group_end();
}

/* get, continue, set, replay; serialize, deserialize into a fresh instance, continue. */
static void group_state_round_trip(const block *b, const reference *ref)
{
    group_begin("state round trip");
    char why[256] = "";
    long live = live_allocations();

    /* 1. get at step STEP_PHASE_AT, run on, set it back, replay: the same bits. */
    {
        sim s;
        void *state = NULL;
        bool ok = sim_open(&s, b, 0) && sim_advance(&s, PHASE_STEP) &&
                  FMU(b, get_state, s.c, &state) == fmi2OK && state;
        int k0 = s.k;
        double t0 = s.t;
        ok = ok && sim_run_to_end(&s);
        size_t n = (size_t)b->n_outputs * (size_t)(STEPS + 1);
        uint64_t *first = malloc(n * sizeof *first);
        if (ok && first) memcpy(first, s.trace, n * sizeof *first);
        ok = ok && first && FMU(b, set_state, s.c, state) == fmi2OK;
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
        void *same = state;
        ok = ok && FMU(b, get_state, s.c, &state) == fmi2OK && state == same &&
             sim_state_bytes(&s, &now, &now_size) &&
             FMU(b, state_size, s.c, state, &got_size) == fmi2OK && (got = malloc(got_size)) &&
             FMU(b, serialize, s.c, state, got, got_size) == fmi2OK &&
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
        FMU(b, free_state, s.c, &state);
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
        void *state = NULL;
        bool ok = sim_open(&s, b, 0) && sim_advance(&s, PHASE_STEP) &&
                  sim_state_bytes(&s, &bytes, &size) && sim_open(&fresh, b, 1);
        if (ok && into_existing) ok = FMU(b, get_state, fresh.c, &state) == fmi2OK;
        void *existing = state;
        ok = ok && FMU(b, deserialize, fresh.c, bytes, size, &state) == fmi2OK && state &&
             (!into_existing || state == existing) && FMU(b, set_state, fresh.c, state) == fmi2OK &&
             FMU(b, free_state, fresh.c, &state) == fmi2OK;
        double time = -1;
        ok = ok && FMU(b, now, fresh.c, &time) == fmi2OK && time == s.t;
        if (ok) {
            fresh.variant = 0; /* the same inputs as the reference from here on */
            fresh.phase = PHASE_STEP;
            fresh.k = s.k;
            fresh.t = s.t;
            memcpy(fresh.trace, ref->trace,
                   (size_t)(s.k + 1) * (size_t)b->n_outputs * sizeof *fresh.trace);
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
        void *state = NULL;
        bool ok = sim_open(&s, b, 0) && sim_advance(&s, PHASE_INITIALIZATION) &&
                  FMU(b, get_state, s.c, &state) == fmi2OK && sim_advance(&s, PHASE_STEP) &&
                  FMU(b, set_state, s.c, state) == fmi2OK;
        if (ok) {
            s.phase = PHASE_INITIALIZATION;
            s.k = s.rows = 0;
            s.t = 0;
            ok = sim_run_to_end(&s) && same_trace(&s, ref, 0, why, sizeof why);
        }
        if (state) FMU(b, free_state, s.c, &state);
        check(ok, "a state of initialization mode set in step mode: %s %s", s.failure, why);
        sim_close(&s);
    }

    /* 6. a state of one instance carried into another instance of the same FMU: serialized (a
     * state in memory is a handle of the instance that made it, docs/behaviour.md §1.9) */
    {
        sim a, z;
        bool ok = sim_open(&a, b, 0) && sim_open(&z, b, 3) && sim_advance(&a, PHASE_STEP) &&
                  sim_advance(&z, PHASE_STEP) && sim_carry_state(&a, &z);
        if (ok) {
            z.variant = 0;
            memcpy(z.trace, a.trace, (size_t)(a.k + 1) * (size_t)b->n_outputs * sizeof *z.trace);
            ok = sim_run_to_end(&z) && same_trace(&z, ref, 0, why, sizeof why);
        }
        check(ok, "a state of one instance carried into another, serialized: %s %s %s", a.failure,
              z.failure, why);
        sim_close(&a);
        sim_close(&z);
    }
    group_end_leaving_none(live, "the round trips");
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
        {cycle->max, 1e14},              /* 1.7e12 calls: their µs would overflow 64 bits */
        {cycle->max, 2e11 * 60},         /* just as far */
        {cycle->min, cycle->min * 1e16}, /* more calls than the counter allows */
        {0.1, 1e300},
        {0.1, 5e14},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        log_record log = {0};
        void *c = FMU(b, instantiate, "clock", fmi2CoSimulation, &log);
        uint32_t vr = cycle->vr;
        bool ok = c && FMU(b, begin, c, 0, false, 0) == fmi2OK &&
                  FMU(b, set, c, cycle->type, &vr, 1, &cases[i].cycle, 1) == fmi2OK &&
                  FMU(b, exit_init, c) == fmi2OK;
        int before = log.total;
        int status = ok ? FMU(b, do_step, c, 0.0, cases[i].h) : fmi2Fatal;
        const log_entry *e = log_get(&log, log.total - 1);
        const char *do_step = FN(b, FN_DO_STEP), *set_time = FN(b, FN_SET_TIME);
        ok = ok && status == fmi2Error && log.total == before + 1 && e &&
             !strncmp(e->text, do_step, strlen(do_step)) &&
             FMU(b, do_step, c, 0.0, cases[i].cycle) == fmi2OK;
        check(ok,
              "cycleTime %g s, %s(0, %g) returns %d (expected a refusal, then a normal "
              "step): \"%s\"",
              cases[i].cycle, do_step, cases[i].h, status, e ? e->text : "");
        if (c) FMU(b, free_instance, c);

        /* Model Exchange: the time set to the end of such a step */
        log = (log_record){0};
        c = FMU(b, instantiate, "clock", fmi2ModelExchange, &log);
        event_info info = {0};
        ok = c && FMU(b, begin, c, 0, false, 0) == fmi2OK &&
             FMU(b, set, c, cycle->type, &vr, 1, &cases[i].cycle, 1) == fmi2OK &&
             FMU(b, exit_init, c) == fmi2OK && FMU(b, update_discrete, c, &info) == fmi2OK &&
             FMU(b, enter_continuous, c) == fmi2OK;
        before = log.total;
        status = ok ? FMU(b, set_time, c, cases[i].h) : fmi2Fatal;
        e = log_get(&log, log.total - 1);
        double next = info.next;
        ok = ok && status == fmi2Error && log.total == before + 1 && e &&
             !strncmp(e->text, set_time, strlen(set_time)) && FMU(b, set_time, c, next) == fmi2OK &&
             FMU(b, enter_event, c) == fmi2OK && FMU(b, update_discrete, c, &info) == fmi2OK &&
             info.next == (double)(2 * llround(cases[i].cycle * 1e6)) / 1e6;
        check(ok,
              "cycleTime %g s, Model Exchange %s(%g) returns %d (expected a refusal, "
              "then the next time event): \"%s\"",
              cases[i].cycle, set_time, cases[i].h, status, e ? e->text : "");
        if (c) FMU(b, free_instance, c);
    }

    /* Co-simulation: a currentCommunicationPoint within the tolerance before the FMU's time
     * is accepted, and the step ends at t + h. Steps that each start 0.9 tolerances early and
     * are shorter than that must not carry the time back beyond the tolerance, nor into a
     * state the FMU refuses. */
    {
        sim s;
        char why[256] = "";
        bool ok = sim_open(&s, b, 0) && sim_advance(&s, PHASE_STEP);
        double latest = s.t, tolerance = 1e-4 * b->cycle, h = 1e-6 * tolerance, t = s.t;
        long steps = (long)(2.5 / 0.9e-4), accepted = 0;
        for (long i = 0; ok && i < steps; i++) {
            double from = t - 0.9 * tolerance;
            if (FMU(b, do_step, s.c, from, h) != fmi2OK) break;
            t = from + h;
            accepted++;
        }
        double now = NAN;
        ok = ok && FMU(b, now, s.c, &now) == fmi2OK;
        check(ok && now >= latest - tolerance,
              "co-simulation: %ld doSteps of %g s, each from 0.9e-4 cycles before the FMU's time: "
              "%ld accepted, the time went from %.17g back to %.17g (%.3g cycles; the tolerance is "
              "1e-4)",
              steps, h, accepted, latest, now, (latest - now) / b->cycle);
        check(ok && takes_own_state(&s, why, sizeof why),
              "co-simulation, after those steps: the FMU takes back its own serialized state: %s",
              why);
        sim_close(&s);
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
    void *c = FMU(b, instantiate, "extreme", fmi2CoSimulation, &log);
    bool ok = c && FMU(b, begin, c, 0, false, 0) == fmi2OK;
    for (int p = 0; ok && booleans_true && p < b->n_parameters; p++) {
        const md_variable *v = &b->md.variables[b->parameters[p]];
        double on = 1;
        if (v->kind == KIND_BOOLEAN) ok = FMU(b, set, c, v->type, &v->vr, 1, &on, 1) == fmi2OK;
    }
    ok = ok && FMU(b, exit_init, c) == fmi2OK;
    double h = b->cycle, t = 0;
    for (int k = 0; ok && k < steps; k++, t += h) ok = FMU(b, do_step, c, t, h) == fmi2OK;
    void *original = NULL;
    size_t size = 0;
    ok = ok && FMU(b, get_state, c, &original) == fmi2OK &&
         FMU(b, state_size, c, original, &size) == fmi2OK && size > HEADER_SIZE + 32;
    unsigned char *bytes = ok ? malloc(size) : NULL, *copy = ok ? malloc(size) : NULL;
    ok = ok && bytes && copy && FMU(b, serialize, c, original, bytes, size) == fmi2OK;
    if (check(ok, "a state after %d steps%s", steps,
              booleans_true ? " with Boolean parameters TRUE" : "")) {
        static const struct {
            unsigned width;
            uint64_t bits;
        } extremes[] = {{8, UINT64_C(0x8000000000000000)},
                        {8, UINT64_C(0x7FFFFFFFFFFFFFFF)},
                        {4, 0x80000000u},
                        {4, 0x7FFFFFFFu},
                        {2, 0x8000u},
                        {2, 0x7FFFu}};
        for (size_t e = 0; e < sizeof extremes / sizeof extremes[0]; e++) {
            unsigned width = extremes[e].width;
            for (size_t at = HEADER_SIZE + 32; at + width <= size; at += width) {
                memcpy(copy, bytes, size);
                for (unsigned i = 0; i < width; i++)
                    copy[at + i] = (unsigned char)(extremes[e].bits >> (8 * i));
                uint64_t sum = fnv1a64(copy + HEADER_SIZE, size - HEADER_SIZE);
                for (unsigned i = 0; i < 8; i++) copy[88 + i] = (unsigned char)(sum >> (8 * i));
                void *state = NULL;
                int status = FMU(b, deserialize, c, copy, size, &state);
                bool fine = status == fmi2OK || status == fmi2Error;
                if (status == fmi2OK) {
                    fine = FMU(b, set_state, c, state) == fmi2OK;
                    for (int k = 0; fine && k < 8; k++)
                        fine = FMU(b, do_step, c, t + k * h, h) == fmi2OK;
                    fine = FMU(b, free_state, c, &state) == fmi2OK && fine;
                }
                check(fine, "payload byte %zu holds a %u-byte extreme: deserialize %d, then a run",
                      at - HEADER_SIZE, width, (int)status);
            }
        }
    }
    free(bytes);
    free(copy);
    if (original) FMU(b, free_state, c, &original);
    if (c) FMU(b, free_instance, c);
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
    long live = live_allocations();
    long broken = 0, leaked = 0;
    for (long i = 0; i < CYCLES; i++) {
        log_record log = {0};
        void *c = FMU(b, instantiate, "cycle", fmi2CoSimulation, &log);
        if (!c) {
            broken++;
            continue;
        }
        if (i % 2 == 0 &&
            (FMU(b, begin, c, 0, false, 0) != fmi2OK || FMU(b, exit_init, c) != fmi2OK ||
             FMU(b, do_step, c, 0.0, b->cycle) != fmi2OK))
            broken++;
        if (i % 3 == 0) FMU(b, terminate, c); /* refused in some modes, harmless */
        FMU(b, free_instance, c);
        if (live_allocations() != live) {
            leaked++;
            live = live_allocations();
        }
    }
    check(broken == 0 && leaked == 0, "%ld instantiate/free cycles: %ld broken, %ld leaked", CYCLES,
          broken, leaked);

    /* Model Exchange instances: every other one through initialization and two time events */
    broken = leaked = 0;
    live = live_allocations();
    for (long i = 0; i < CYCLES; i++) {
        log_record log = {0};
        void *c = FMU(b, instantiate, "cycle", fmi2ModelExchange, &log);
        if (!c) {
            broken++;
            continue;
        }
        event_info info = {0};
        if (i % 2 == 0 &&
            (FMU(b, begin, c, 0, false, 0) != fmi2OK || FMU(b, exit_init, c) != fmi2OK ||
             FMU(b, update_discrete, c, &info) != fmi2OK || FMU(b, enter_continuous, c) != fmi2OK ||
             FMU(b, set_time, c, info.next) != fmi2OK || FMU(b, enter_event, c) != fmi2OK ||
             FMU(b, update_discrete, c, &info) != fmi2OK || info.next != call_time(b, 2)))
            broken++;
        if (i % 3 == 0) FMU(b, terminate, c); /* refused in some modes, harmless */
        FMU(b, free_instance, c);
        if (live_allocations() != live) {
            leaked++;
            live = live_allocations();
        }
    }
    check(broken == 0 && leaked == 0,
          "%ld Model Exchange instantiate/free cycles: %ld broken, %ld leaked", CYCLES, broken,
          leaked);

    for (int type = fmi2ModelExchange; type <= fmi2CoSimulation; type++) {
        sim s;
        broken = leaked = 0;
        bool ok = sim_open_as(&s, b, 0, (fmi2Type)type) &&
                  sim_advance(&s, type == fmi2ModelExchange ? PHASE_CONTINUOUS : PHASE_STEP);
        live = live_allocations();
        unsigned char *bytes = NULL;
        size_t size = 0;
        ok = ok && sim_state_bytes(&s, &bytes, &size);
        for (long i = 0; ok && i < CYCLES; i++) {
            void *state = NULL, *copy = NULL;
            if (FMU(b, get_state, s.c, &state) != fmi2OK) broken++;
            if (i % 2 == 0 && FMU(b, set_state, s.c, state) != fmi2OK) broken++;
            if (i % 4 == 0 && (FMU(b, deserialize, s.c, bytes, size, &copy) != fmi2OK ||
                               FMU(b, free_state, s.c, &copy) != fmi2OK))
                broken++;
            if (FMU(b, free_state, s.c, &state) != fmi2OK || state) broken++;
            if (live_allocations() != live) {
                leaked++;
                live = live_allocations();
            }
        }
        (void)size;
        free(bytes);
        check(ok && broken == 0, "%s: %ld get/set/deserialize/free state cycles: %ld broken (%s)",
              interface_name((fmi2Type)type), CYCLES, broken, s.failure);
        check(leaked == 0, "%s: state cycles leaked %ld times", interface_name((fmi2Type)type),
              leaked);
        sim_close(&s);
    }
    group_end();
}

/* ---- threads: N instances on N threads give exactly the serial outputs ---- */

typedef struct {
    const block *b;
    const reference *ref;
    int variant;
    fmi2Type type;
    bool ok;
    char why[520];
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
    const block *b = job->b;
    sim s;
    void *state = NULL, *copy = NULL;
    unsigned char *bytes = NULL;
    size_t size = 0;
    char why[256] = "";
    bool ok = sim_open_as(&s, job->b, job->variant, job->type) && sim_advance(&s, PHASE_STEP) &&
              FMU(b, get_state, s.c, &state) == fmi2OK && sim_state_bytes(&s, &bytes, &size) &&
              FMU(b, deserialize, s.c, bytes, size, &copy) == fmi2OK;
    int k0 = s.k;
    double t0 = s.t, next0 = s.next_event;
    bool in_event0 = s.in_event;
    ok = ok && sim_run_to_end(&s) && same_trace(&s, job->ref, 0, why, sizeof why);
    /* back to the middle from the deserialized copy, and the same end again */
    if (ok && FMU(b, set_state, s.c, copy) == fmi2OK) {
        s.k = k0;
        s.t = t0;
        s.next_event = next0;
        s.in_event = in_event0;
        s.phase = PHASE_STEP;
        ok = sim_run_to_end(&s) && same_trace(&s, job->ref, 0, why, sizeof why);
    } else {
        ok = false;
    }
    if (state) FMU(b, free_state, s.c, &state);
    if (copy) FMU(b, free_state, s.c, &copy);
    free(bytes);
    snprintf(job->why, sizeof job->why, "%s %s", s.failure, why);
    sim_close(&s);
    return ok;
}

/* THREADS instances of the block, each on its own thread with its own input pattern (every
 * other one a Model Exchange instance), plus, when another block is given, two instances of
 * that library alongside. */
static void group_threads(const block *b, const reference *refs, const reference *me_refs)
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
            if (i < THREADS && i % 2)
                jobs[i] = (thread_job){
                    .b = b, .ref = &me_refs[i], .variant = i, .type = fmi2ModelExchange};
            else if (i < THREADS)
                jobs[i] =
                    (thread_job){.b = b, .ref = &refs[i], .variant = i, .type = fmi2CoSimulation};
            else
                jobs[i] = (thread_job){.b = FOREIGN.other,
                                       .ref = &other_refs[i - THREADS],
                                       .variant = i - THREADS,
                                       .type = fmi2CoSimulation};
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
                check(false, "round %d, thread %d (%s, %s): %s", round, i, jobs[i].b->md.identifier,
                      interface_name(jobs[i].type), jobs[i].why);
        check(good == n,
              "round %d: %d of %d threads (%d of %s, half of them Model Exchange, %d of "
              "the other block) gave the serial outputs",
              round, good, n, THREADS, b->md.identifier, others);
    }
    check_none_left(live, "the threads");
    for (int i = 0; i < others; i++) reference_free(&other_refs[i]);
    free(jobs);
    free(threads);
    free(started);
    group_end();
}

/* ---- Model Exchange ---- */

/* The clock of a serialized state (HEADER_SIZE + payload). */
typedef struct {
    int32_t mode;
    double time;
    int64_t calls;
} clock_view;

static bool clock_of(const unsigned char *bytes, size_t size, clock_view *clock)
{
    if (!bytes || size < HEADER_SIZE + CLOCK_SIZE) return false;
    memcpy(&clock->mode, bytes + HEADER_SIZE + CLOCK_MODE, 4);
    memcpy(&clock->time, bytes + HEADER_SIZE + CLOCK_TIME, 8);
    memcpy(&clock->calls, bytes + HEADER_SIZE + CLOCK_CALLS, 8);
    return true;
}

/* Whether two serialized states hold the same block: the same call counter and the same
 * bytes after the clock (every input, parameter, output and static). */
static bool same_block(const unsigned char *a, size_t na, const unsigned char *b, size_t nb,
                       char *why, size_t size)
{
    clock_view ca, cb;
    if (!clock_of(a, na, &ca) || !clock_of(b, nb, &cb) || na != nb) {
        snprintf(why, size, "states of %zu and %zu bytes", na, nb);
        return false;
    }
    if (ca.calls != cb.calls) {
        snprintf(why, size, "%lld calls and %lld calls", (long long)ca.calls, (long long)cb.calls);
        return false;
    }
    for (size_t i = HEADER_SIZE + CLOCK_SIZE; i < na; i++) {
        if (a[i] != b[i]) {
            snprintf(why, size, "the block's data differ at payload byte %zu", i - HEADER_SIZE);
            return false;
        }
    }
    return true;
}

/* The Model Exchange scenario gives, call for call, the outputs of co-simulation in steps of
 * one cycle fed the same inputs per call, and ends with the same block data. */
static void group_me_versus_cs(const block *b, const reference *me_refs)
{
    group_begin("ME against co-simulation");
    check(b->md.me_identifier[0] && !strcmp(b->md.me_identifier, b->md.identifier),
          "the XML has a ModelExchange element with modelIdentifier %s (got \"%s\")",
          b->md.identifier, b->md.me_identifier);
    check(b->md.event_indicators == 0, "numberOfEventIndicators is 0 (got %g)",
          b->md.event_indicators);
    for (int variant = 0; variant < THREADS; variant++) {
        reference cs;
        if (!check(reference_run_as(b, variant, fmi2CoSimulation, true, &cs),
                   "variant %d: the co-simulation run in steps of one cycle", variant))
            continue;
        const reference *me = &me_refs[variant];
        int n = b->n_outputs, row = -1, output = -1;
        bool moves = false;
        for (int r = 0; r < me->rows && r < cs.rows; r++) {
            for (int p = 0; p < n; p++) {
                uint64_t x = me->trace[(size_t)r * (size_t)n + (size_t)p];
                uint64_t y = cs.trace[(size_t)r * (size_t)n + (size_t)p];
                if (x != y && row < 0) row = r, output = p;
                if (r > 0 && x != me->trace[(size_t)p]) moves = true;
            }
        }
        check(me->rows == STEPS + 1 && cs.rows == STEPS + 1 && row < 0,
              "variant %d: %d and %d rows; output %s of call %d differs between Model Exchange "
              "and co-simulation",
              variant, me->rows, cs.rows,
              output >= 0 ? b->md.variables[b->outputs[output]].name : "-", row);
        check(moves, "variant %d: the outputs of the Model Exchange run never change", variant);
        char why[256] = "";
        check(same_block(me->state_at[PHASE_STEP], me->size_at[PHASE_STEP], cs.state_at[PHASE_STEP],
                         cs.size_at[PHASE_STEP], why, sizeof why),
              "variant %d: after call %d the Model Exchange and co-simulation states differ: %s",
              variant, STEP_PHASE_AT, why);
        check(same_block(me->final_state, me->final_size, cs.final_state, cs.final_size, why,
                         sizeof why),
              "variant %d: the final Model Exchange and co-simulation states differ: %s", variant,
              why);
        reference_free(&cs);
    }
    group_end();
}

/* A Model Exchange run restored from a state: the reference from there on. */
static bool resume_me(sim *s, const reference *ref, int k, bool in_event, char *why, size_t size)
{
    s->variant = 0;
    s->phase = in_event ? PHASE_STEP : PHASE_CONTINUOUS;
    s->k = k;
    s->t = call_time(s->b, k);
    s->next_event = call_time(s->b, k + 1);
    s->in_event = in_event;
    memcpy(s->trace, ref->trace, (size_t)(k + 1) * (size_t)s->b->n_outputs * sizeof *s->trace);
    s->rows = k + 1;
    unsigned char *final = NULL;
    size_t final_size = 0;
    bool ok = sim_run_to_end(s) && same_trace(s, ref, 0, why, size) &&
              sim_state_bytes(s, &final, &final_size) &&
              same_bytes(final, final_size, ref->final_state, ref->final_size, why, size,
                         "the final state");
    free(final);
    return ok;
}

/* FMU states of Model Exchange instances: the clock they hold, get/set and replay, serialize
 * into a fresh instance, a state of initialization mode, a state of another instance. */
static void group_me_round_trip(const block *b, const reference *ref)
{
    group_begin("ME state round trip");
    long live = live_allocations();
    char why[256] = "";
    static const struct {
        int phase;
        int32_t mode;
    } clocks[] = {{PHASE_INSTANTIATED, MODE_INSTANTIATED},
                  {PHASE_INITIALIZATION, MODE_INITIALIZATION},
                  {PHASE_STEP, MODE_EVENT},
                  {PHASE_TERMINATED, MODE_TERMINATED}};
    for (size_t i = 0; i < sizeof clocks / sizeof clocks[0]; i++) {
        clock_view clock = {0};
        int phase = clocks[i].phase;
        bool running = phase == PHASE_STEP || phase == PHASE_TERMINATED;
        int64_t calls = phase == PHASE_STEP         ? STEP_PHASE_AT + 1
                        : phase == PHASE_TERMINATED ? STEPS + 1
                                                    : 0;
        double time = phase == PHASE_STEP ? call_time(b, STEP_PHASE_AT) : 0.0;
        bool ok = clock_of(ref->state_at[phase], ref->size_at[phase], &clock) &&
                  clock.mode == clocks[i].mode && clock.calls == calls &&
                  (!running || phase == PHASE_TERMINATED || clock.time == time);
        check(ok,
              "the clock of a Model Exchange state in %s: mode %d, %lld calls, t %.17g "
              "(expected mode %d, %lld calls, t %.17g)",
              phase_name(fmi2ModelExchange, phase), (int)clock.mode, (long long)clock.calls,
              clock.time, (int)clocks[i].mode, (long long)calls, time);
    }

    /* get in event or continuous-time mode, run to the end, set back, replay */
    for (int phase = PHASE_STEP; phase <= PHASE_CONTINUOUS;
         phase += PHASE_CONTINUOUS - PHASE_STEP) {
        sim s;
        void *state = NULL;
        bool ok = sim_open_as(&s, b, 0, fmi2ModelExchange) && sim_advance(&s, phase) &&
                  FMU(b, get_state, s.c, &state) == fmi2OK && state && sim_run_to_end(&s) &&
                  same_trace(&s, ref, 0, why, sizeof why) &&
                  FMU(b, set_state, s.c, state) == fmi2OK;
        ok = ok && resume_me(&s, ref, STEP_PHASE_AT, phase == PHASE_STEP, why, sizeof why);
        if (state) FMU(b, free_state, s.c, &state);
        check(ok, "a state of %s set after terminate, and the replay: %s %s",
              phase_name(fmi2ModelExchange, phase), s.failure, why);
        sim_close(&s);
    }

    /* serialize in event or continuous-time mode, deserialize into a fresh instance (only
     * instantiated), go on there */
    for (int phase = PHASE_STEP; phase <= PHASE_CONTINUOUS;
         phase += PHASE_CONTINUOUS - PHASE_STEP) {
        sim s, fresh;
        unsigned char *bytes = NULL;
        size_t size = 0;
        void *state = NULL;
        bool ok = sim_open_as(&s, b, 0, fmi2ModelExchange) && sim_advance(&s, phase) &&
                  sim_state_bytes(&s, &bytes, &size) &&
                  sim_open_as(&fresh, b, 1, fmi2ModelExchange) &&
                  FMU(b, deserialize, fresh.c, bytes, size, &state) == fmi2OK &&
                  FMU(b, set_state, fresh.c, state) == fmi2OK &&
                  FMU(b, free_state, fresh.c, &state) == fmi2OK;
        ok = ok && resume_me(&fresh, ref, STEP_PHASE_AT, phase == PHASE_STEP, why, sizeof why);
        check(ok, "serialized in %s, deserialized into a fresh instance, continued: %s %s %s",
              phase_name(fmi2ModelExchange, phase), s.failure, fresh.failure, why);
        free(bytes);
        sim_close(&s);
        sim_close(&fresh);
    }

    /* a state of initialization mode brings a running instance back there */
    {
        sim s;
        void *state = NULL;
        bool ok = sim_open_as(&s, b, 0, fmi2ModelExchange) &&
                  sim_advance(&s, PHASE_INITIALIZATION) &&
                  FMU(b, get_state, s.c, &state) == fmi2OK && sim_advance(&s, PHASE_CONTINUOUS) &&
                  FMU(b, set_state, s.c, state) == fmi2OK;
        if (ok) {
            s.phase = PHASE_INITIALIZATION;
            s.k = s.rows = 0;
            s.t = 0;
            s.in_event = false;
            ok = sim_run_to_end(&s) && same_trace(&s, ref, 0, why, sizeof why);
        }
        if (state) FMU(b, free_state, s.c, &state);
        check(ok, "a state of initialization mode set in continuous-time mode: %s %s", s.failure,
              why);
        sim_close(&s);
    }

    /* a state of one instance carried into another, serialized */
    {
        sim a, z;
        bool ok = sim_open_as(&a, b, 0, fmi2ModelExchange) &&
                  sim_open_as(&z, b, 3, fmi2ModelExchange) && sim_advance(&a, PHASE_STEP) &&
                  sim_advance(&z, PHASE_CONTINUOUS) && sim_carry_state(&a, &z);
        ok = ok && resume_me(&z, ref, STEP_PHASE_AT, true, why, sizeof why);
        check(ok, "a state of one instance carried into another, serialized: %s %s %s", a.failure,
              z.failure, why);
        sim_close(&a);
        sim_close(&z);
    }
    group_end_leaving_none(live, "the round trips");
}

/* A state taken while an instance of one interface runs (co-simulation step mode, Model Exchange
 * event or continuous-time mode) is refused by an instance of the other when serialized: one
 * message, nothing changed, nothing allocated. A state of the same interface is accepted, and so
 * is one taken before initialization ended or after termination, which holds nothing of its
 * interface (docs/behaviour.md §1.11). In memory, a state is a handle of the instance that made
 * it: any other instance refuses it in the same way (docs/behaviour.md §1.9). */
static void group_state_interfaces(const block *b)
{
    group_begin("states across interfaces");
    static const int cs_phases[] = {PHASE_INSTANTIATED, PHASE_INITIALIZATION, PHASE_STEP,
                                    PHASE_TERMINATED};
    static const int me_phases[] = {PHASE_INSTANTIATED, PHASE_INITIALIZATION, PHASE_STEP,
                                    PHASE_CONTINUOUS, PHASE_TERMINATED};
    for (int from = fmi2ModelExchange; from <= fmi2CoSimulation; from++) {
        const int *phases = from == fmi2ModelExchange ? me_phases : cs_phases;
        int n_phases = from == fmi2ModelExchange ? 5 : 4;
        fmi2Type to = from == fmi2ModelExchange ? fmi2CoSimulation : fmi2ModelExchange;
        for (int p = 0; p < n_phases; p++) {
            sim source;
            void *state = NULL;
            unsigned char *bytes = NULL;
            size_t size = 0;
            bool ok = sim_open_as(&source, b, 0, (fmi2Type)from) &&
                      sim_advance(&source, phases[p]) &&
                      FMU(b, get_state, source.c, &state) == fmi2OK &&
                      sim_state_bytes(&source, &bytes, &size);
            if (!check(ok, "a %s state in %s: %s", interface_name((fmi2Type)from),
                       phase_name((fmi2Type)from, phases[p]), source.failure)) {
                if (state) FMU(b, free_state, source.c, &state);
                free(bytes);
                sim_close(&source);
                continue;
            }
            bool specific = phases[p] == PHASE_STEP || phases[p] == PHASE_CONTINUOUS;
            for (int same = 0; same <= 1; same++) {
                fmi2Type target_type = same ? (fmi2Type)from : to;
                for (int deserialize = 0; deserialize <= 1; deserialize++) {
                    bool accepted = deserialize && (same || !specific);
                    sim target;
                    unsigned char *before = NULL, *after = NULL;
                    size_t before_size = 0, after_size = 0;
                    char why[256] = "";
                    bool fine = sim_open_as(&target, b, 1, target_type) &&
                                sim_advance(&target, PHASE_STEP) &&
                                sim_state_bytes(&target, &before, &before_size);
                    long live = live_allocations();
                    int mark = target.log.total;
                    void *copy = NULL;
                    int status = fmi2Fatal;
                    if (fine)
                        status = deserialize ? FMU(b, deserialize, target.c, bytes, size, &copy)
                                             : FMU(b, set_state, target.c, state);
                    const char *function = FN(b, deserialize ? FN_DESERIALIZE : FN_SET_STATE);
                    const log_entry *e = log_get(&target.log, target.log.total - 1);
                    if (fine && accepted) {
                        fine = status == fmi2OK && target.log.total == mark;
                        if (copy) FMU(b, free_state, target.c, &copy);
                    } else if (fine) {
                        fine = status == fmi2Error && target.log.total == mark + 1 && e &&
                               e->status == fmi2Error &&
                               !strncmp(e->text, function, strlen(function)) && !copy &&
                               live_allocations() == live &&
                               sim_state_bytes(&target, &after, &after_size) &&
                               same_bytes(before, before_size, after, after_size, why, sizeof why,
                                          "the state changed");
                        if (copy) FMU(b, free_state, target.c, &copy);
                    }
                    check(fine,
                          "%s of a %s state taken in %s into a %s instance in %s: %s (%d, "
                          "%d messages: \"%s\") %s %s",
                          function, interface_name((fmi2Type)from),
                          phase_name((fmi2Type)from, phases[p]), interface_name(target_type),
                          phase_name(target_type, PHASE_STEP),
                          accepted ? "must be accepted" : "must be refused", (int)status,
                          target.log.total - mark, e && target.log.total > mark ? e->text : "",
                          target.failure, why);
                    free(before);
                    free(after);
                    sim_close(&target);
                }
            }
            FMU(b, free_state, source.c, &state);
            free(bytes);
            sim_close(&source);
        }
    }
    group_end();
}

/* The FMU's time in a serialized state of s, or NaN. */
static double time_of(sim *s)
{
    unsigned char *bytes = NULL;
    size_t size = 0;
    clock_view clock = {.time = NAN};
    if (sim_state_bytes(s, &bytes, &size)) clock_of(bytes, size, &clock);
    free(bytes);
    return clock.time;
}

/* Whether the FMU takes back its own state, serialized. */
bool takes_own_state(sim *s, char *why, size_t size)
{
    unsigned char *bytes = NULL;
    size_t n = 0;
    void *state = NULL;
    int mark = s->log.total;
    bool ok =
        sim_state_bytes(s, &bytes, &n) && FMU(s->b, deserialize, s->c, bytes, n, &state) == fmi2OK;
    const log_entry *e = log_get(&s->log, s->log.total - 1);
    if (!ok)
        snprintf(why, size, "refused: \"%.200s\"", e && s->log.total > mark ? e->text : s->failure);
    if (state) FMU(s->b, free_state, s->c, &state);
    free(bytes);
    return ok;
}

/* Time events the importer does not stop at, times within the grid tolerance, and a time
 * that creeps back by steps within the tolerance. */
static void group_me_time_events(const block *b)
{
    group_begin("ME time events");
    double c = b->cycle;
    int k = STEP_PHASE_AT;
    char why[256] = "";

    /* An importer that passes call times without stopping: the next event iteration executes
     * the calls it skipped, with the inputs as they are then (as one co-simulation step over
     * them would); until then, its state is one the FMU takes back serialized. */
    for (int in_event = 0; in_event <= 1; in_event++) {
        sim me, cs;
        event_info info;
        int skipped = 3;
        double t = call_time(b, k + skipped) + (in_event ? 0.0 : 0.5 * c);
        bool ok = sim_open_as(&me, b, 0, fmi2ModelExchange) &&
                  sim_advance(&me, in_event ? PHASE_STEP : PHASE_CONTINUOUS) &&
                  FMU(b, set_time, me.c, t) == fmi2OK;
        bool own = ok && takes_own_state(&me, why, sizeof why);
        check(own,
              "the FMU takes back its own serialized state after fmi2SetTime(%.17g) in %s "
              "passed %d call times (the last call was at %.17g): %s %s",
              t, in_event ? "event mode" : "continuous-time mode", skipped, call_time(b, k),
              me.failure, why);
        ok = ok && (in_event || FMU(b, enter_event, me.c) == fmi2OK);
        sim_set_inputs_for(&me, k + skipped);
        ok = ok && !me.failure[0] && FMU(b, update_discrete, me.c, &info) == fmi2OK &&
             info.next == call_time(b, k + skipped + 1);
        uint64_t me_row[64], cs_row[64];
        ok = ok && b->n_outputs <= 64 && sim_read_outputs(&me, me_row);
        /* co-simulation: one step over the same calls with the same inputs */
        ok = ok && sim_open_as(&cs, b, 0, fmi2CoSimulation);
        cs.uniform = true;
        ok = ok && sim_advance(&cs, PHASE_STEP);
        sim_set_inputs_for(&cs, k + skipped);
        ok = ok && !cs.failure[0] && FMU(b, do_step, cs.c, cs.t, skipped * c) == fmi2OK &&
             sim_read_outputs(&cs, cs_row) &&
             !memcmp(me_row, cs_row, (size_t)b->n_outputs * sizeof me_row[0]);
        unsigned char *x = NULL, *y = NULL;
        size_t nx = 0, ny = 0;
        ok = ok && sim_state_bytes(&me, &x, &nx) && sim_state_bytes(&cs, &y, &ny) &&
             same_block(x, nx, y, ny, why, sizeof why);
        check(ok,
              "after fmi2SetTime past %d call times (%s), the event iteration executes the "
              "skipped calls as one co-simulation step over them: %s %s %s",
              skipped, in_event ? "event mode" : "continuous-time mode", me.failure, cs.failure,
              why);
        free(x);
        free(y);
        sim_close(&me);
        if (cs.c || cs.trace) sim_close(&cs);
    }

    /* An importer that ends at a stop time which is a call time, without the event there
     * (integrate to tStop, fmi2Terminate), or after passing call times: the terminated
     * instance's state is one the FMU takes back. */
    for (int skipped = 0; skipped <= 2; skipped += 2) {
        sim s;
        double t = call_time(b, k + 1 + skipped);
        int enter = 1, terminate = 1;
        bool ok = sim_open_as(&s, b, 0, fmi2ModelExchange) && sim_advance(&s, PHASE_CONTINUOUS) &&
                  FMU(b, set_time, s.c, t) == fmi2OK &&
                  FMU(b, completed, s.c, true, &enter, &terminate) == fmi2OK &&
                  FMU(b, terminate, s.c) == fmi2OK;
        check(ok && takes_own_state(&s, why, sizeof why),
              "fmi2SetTime(%.17g) (the time of call %d%s, its event not handled), fmi2Terminate: "
              "the FMU takes back its own serialized state: %s %s",
              t, k + 1 + skipped, skipped ? ", two call times passed" : "", s.failure, why);
        sim_close(&s);
    }

    /* A time within the tolerance of a call time is that call's time; one beyond it is not. */
    static const struct {
        double offset; /* in cycles, from t_(k+1) */
        bool executes;
    } near[] = {{-0.5e-4, true}, {0.5e-4, true}, {-2e-4, false}, {-0.5, false}};
    for (size_t i = 0; i < sizeof near / sizeof near[0]; i++) {
        sim s;
        event_info info;
        double t = call_time(b, k + 1) + near[i].offset * c;
        bool ok = sim_open_as(&s, b, 0, fmi2ModelExchange) && sim_advance(&s, PHASE_CONTINUOUS) &&
                  FMU(b, set_time, s.c, t) == fmi2OK && FMU(b, enter_event, s.c) == fmi2OK &&
                  FMU(b, update_discrete, s.c, &info) == fmi2OK;
        int64_t due = near[i].executes ? k + 2 : k + 1;
        unsigned char *bytes = NULL;
        size_t size = 0;
        clock_view clock = {0};
        ok = ok && sim_state_bytes(&s, &bytes, &size) && clock_of(bytes, size, &clock) &&
             clock.calls == due && info.next == call_time(b, due);
        check(ok, "an event at t_%d %+g cycles %s call %d (calls %lld, nextEventTime %.17g)", k + 1,
              near[i].offset, near[i].executes ? "executes" : "does not execute", k + 1,
              (long long)clock.calls, info.next);
        free(bytes);
        sim_close(&s);
    }

    /* fmi2SetTime may go back within the tolerance, but not by many such steps beyond it: the
     * time stays within the tolerance of the latest time, and the state is one the FMU takes
     * back. */
    {
        sim s;
        double tolerance = 1e-4 * c, latest = call_time(b, k);
        bool ok = sim_open_as(&s, b, 0, fmi2ModelExchange) && sim_advance(&s, PHASE_CONTINUOUS);
        double t = latest;
        long accepted = 0, steps = (long)(2.5 / 0.9e-4); /* 2.5 cycles back in all */
        for (long i = 0; ok && i < steps; i++) {
            double next = t - 0.9 * tolerance;
            if (FMU(b, set_time, s.c, next) != fmi2OK) break;
            t = next;
            accepted++;
        }
        double now = ok ? time_of(&s) : NAN;
        check(ok && now >= latest - tolerance,
              "fmi2SetTime %ld times 0.9e-4 cycles back from %.17g: %ld accepted, the FMU's time "
              "is now %.17g, %.3g cycles before the latest time it had (the tolerance is 1e-4)",
              steps, latest, accepted, now, (latest - now) / c);
        check(ok && takes_own_state(&s, why, sizeof why),
              "after the time crept back: the FMU takes back its own serialized state: %s", why);
        sim_close(&s);
    }
    group_end();
}

/* ---- main ---- */

static void usage(void)
{
    fprintf(stderr,
            "usage: harness [--cycles N] [--threads N] [--rounds N] [--timeout S] "
            "[--fmi2 <FMI 2.0 lib.so> <its modelDescription.xml>] "
            "<lib.so> <modelDescription.xml> <guid> [<other lib.so> <other xml> <other guid>]\n");
}

/* The other block's state and serialized state, taken in step mode. */
static void foreign_states_of(block *other, const char *library)
{
    FOREIGN.other = other;
    FOREIGN.other_instance = FMU(other, instantiate, "other", fmi2CoSimulation, &FOREIGN.other_log);
    sim os;
    memset(&os, 0, sizeof os);
    os.b = other;
    os.type = fmi2CoSimulation;
    os.c = FOREIGN.other_instance;
    os.trace = calloc((size_t)(STEPS + 1) * (size_t)other->n_outputs, sizeof *os.trace);
    snprintf(os.name, sizeof os.name, "other");
    if (!os.c || !os.trace || !sim_advance(&os, PHASE_STEP) ||
        !sim_state_bytes(&os, &FOREIGN.other_bytes, &FOREIGN.other_size) ||
        FMU(other, get_state, os.c, &FOREIGN.other_state) != fmi2OK) {
        printf("  the other block %s does not run: %s\n", library, os.failure);
        FOREIGN.other = NULL;
    }
    free(os.trace);
}

int main(int argc, char **argv)
{
    int timeout = 600;
    const char *fmi2_library = NULL, *fmi2_xml = NULL;
    int a = 1;
    for (; a + 1 < argc && !strncmp(argv[a], "--", 2); a += 2) {
        if (!strcmp(argv[a], "--cycles"))
            CYCLES = atol(argv[a + 1]);
        else if (!strcmp(argv[a], "--threads"))
            THREADS = atoi(argv[a + 1]);
        else if (!strcmp(argv[a], "--rounds"))
            ROUNDS = atoi(argv[a + 1]);
        else if (!strcmp(argv[a], "--timeout"))
            timeout = atoi(argv[a + 1]);
        else if (!strcmp(argv[a], "--fmi2") && a + 2 < argc)
            fmi2_library = argv[a + 1], fmi2_xml = argv[++a + 1];
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

    static block main_block, other_block, fmi2_block;
    block *b = &main_block;
    if (!load_block(b, argv[a], argv[a + 1], argv[a + 2])) {
        printf("0 passed, 1 failed\n");
        return 1;
    }
    printf("%s (%s, FMI %s)\n", b->md.identifier, b->library, b->ops->version_string);
    if (fmi2_library && b->ops->version == 3) {
        if (load_block(&fmi2_block, fmi2_library, fmi2_xml, argv[a + 2]) &&
            fmi2_block.ops->version == 2)
            b->fmi2 = &fmi2_block;
        else
            printf("  %s is no FMI 2.0 library of the block\n", fmi2_library);
    }
    if (b->ops->version == 3 && !b->fmi2)
        printf("  SKIPPED: the comparison with FMI 2.0 (no --fmi2 library given)\n");
    if (argc - a == 6 && load_block(&other_block, argv[a + 3], argv[a + 4], argv[a + 5])) {
        if (other_block.ops == b->ops)
            foreign_states_of(&other_block, argv[a + 3]);
        else
            printf("  the other block %s is of another FMI version\n", argv[a + 3]);
    }
    if (!FOREIGN.other)
        printf("  SKIPPED: cases with another block's state (no usable second block given)\n");

    reference *refs = calloc((size_t)THREADS, sizeof *refs);
    reference *me_refs = calloc((size_t)THREADS, sizeof *me_refs);
    bool refs_ok = refs != NULL && me_refs != NULL;
    for (int v = 0; refs_ok && v < THREADS; v++)
        refs_ok = reference_run(b, v, &refs[v]) &&
                  reference_run_as(b, v, fmi2ModelExchange, false, &me_refs[v]);
    if (!refs_ok) {
        printf("  the reference scenario does not run; nothing else can be checked\n");
        printf("0 passed, 1 failed\n");
        return 1;
    }

    struct timespec start;
    clock_gettime(CLOCK_MONOTONIC, &start);
    group_library(b, argv[a + 2], refs);
    group_state_layout(b);
    if (b->ops->version == 2)
        group_instantiate(b);
    else
        fmi3_groups_before_cases(b, refs, me_refs);

    group_me_versus_cs(b, me_refs);

    misuse_list list = {0};
    build_misuses(b, FOREIGN.other, &list);
    build_me_misuses(b, &list);
    if (b->ops->version == 2)
        build_fmi2_misuses(b, &list);
    else
        build_fmi3_misuses(b, &list);
    sort_misuses(&list);
    const char *current = NULL;
    for (size_t i = 0; i < list.count; i++) {
        if (!current || strcmp(current, list.items[i].group)) {
            if (current) group_end();
            current = list.items[i].group;
            group_begin(current);
        }
        run_misuse(b, list.items[i].type == fmi2ModelExchange ? &me_refs[0] : &refs[0],
                   &list.items[i]);
    }
    if (current) group_end();
    free(list.items);

    if (b->ops->version == 2) group_out_of_memory(b); /* FMI 3.0 has no allocator callbacks */
    group_reset(b, &refs[0], &me_refs[0]);
    group_state_round_trip(b, &refs[0]);
    group_me_round_trip(b, &me_refs[0]);
    group_state_interfaces(b);
    group_me_time_events(b);
    group_clock_limits(b);
    group_extreme_words(b);
    if (b->ops->version == 3) fmi3_groups_after_cases(b);
    group_cycles(b);
    group_threads(b, refs, me_refs);

    double elapsed = seconds_since(&start);
    for (int v = 0; v < THREADS; v++) {
        reference_free(&refs[v]);
        reference_free(&me_refs[v]);
    }
    free(refs);
    free(me_refs);
    if (FOREIGN.other) {
        FMU(FOREIGN.other, free_state, FOREIGN.other_instance, &FOREIGN.other_state);
        free(FOREIGN.other_bytes);
    }
    if (FOREIGN.other_instance) FMU(&other_block, free_instance, FOREIGN.other_instance);
    if (other_block.ops) unload_block(&other_block);
    if (fmi2_block.ops) unload_block(&fmi2_block);
    unload_block(b);
    check(live_allocations() == 0, "%ld blocks allocated through the callbacks were never freed",
          live_allocations());
    if (b->ops->version == 2)
        check(malformed_log_messages() == 0,
              "%ld log messages hold a '#' that is not escaped as \"##\" (FMI 2.0, 2.1.5)",
              malformed_log_messages());
    else
        check(doubled_hash_log_messages() == 0,
              "%ld of the %ld log messages with a '#' hold \"##\": FMI 3.0 passes plain text, "
              "without FMI 2.0's escape",
              doubled_hash_log_messages(), hash_log_messages());
    printf("checks took %.2f s\n", elapsed);
    printf("%d passed, %d failed\n", passed, failed);
    return failed ? 1 : 0;
}
