/* The native simulation loop of the lgf_fmus package (python/lgf_fmus/_runner.py loads it with
 * ctypes). It opens an FMU's co-simulation binary with dlopen, keeps one instance and runs
 * batches of runs on it, each ended with fmi2Terminate and fmi2Reset, so that the next run
 * starts from a fresh instance without a new fmi2Instantiate.
 *
 * One run follows the master of FMPy 0.3.32 (fmpy.simulation.simulateCS with its Input and
 * Recorder) decision for decision, so that its results equal fmpy.simulate_fmu bit for bit:
 *   - fmi2SetupExperiment(tolerance, startTime, stopTime defined), then the start values
 *     settable after instantiation, fmi2EnterInitializationMode, the other start values, the
 *     inputs at the start time (the row before an event), fmi2ExitInitializationMode;
 *   - the outputs recorded at the start time and after every step;
 *   - communication points start + n * interval, cut short at the next input event (a row at
 *     which some input changes) and at the stop time, with math.isclose (rel_tol 1e-9) wherever
 *     FMPy uses it; before every step every input is set to the value of the last row at or
 *     before the communication point (after the event);
 *   - a one-row table holds its row (FMPy means to, and crashes instead).
 * The inputs are the FMU's discrete inputs (all inputs of the LGF FMUs are discrete); values
 * arrive as doubles and are converted to the variable's type, as FMPy's ctypes arrays do.
 *
 * Everything is plain C with the FMI 2.0 headers: no Python API, so one binary serves every
 * Python version. */
#include <dlfcn.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fmi2Functions.h"

#if defined(_WIN32)
#define LGF_EXPORT __declspec(dllexport)
#else
#define LGF_EXPORT __attribute__((visibility("default")))
#endif

enum { TYPE_REAL = 0, TYPE_INTEGER = 1, TYPE_BOOLEAN = 2, N_TYPES = 3 };
enum { RUN_OK = 0, RUN_WARNING = 1, RUN_FAILED = 2 };

#define LOG_CAPACITY 4096

/* The functions a run calls, looked up with dlsym as fmi2<Name>. */
/* One X() per function, in the order of the standard; laid out by hand. */
/* clang-format off */
#define RUNNER_FUNCTIONS(X)    \
    X(Instantiate)             \
    X(FreeInstance)            \
    X(SetupExperiment)         \
    X(EnterInitializationMode) \
    X(ExitInitializationMode)  \
    X(Terminate)               \
    X(Reset)                   \
    X(SetReal)                 \
    X(SetInteger)              \
    X(SetBoolean)              \
    X(GetReal)                 \
    X(GetInteger)              \
    X(GetBoolean)              \
    X(DoStep)                  \
    X(GetBooleanStatus)        \
    X(GetRealStatus)
/* clang-format on */

typedef struct {
    void *library;
#define DECLARE_POINTER(name) fmi2##name##TYPE *name;
    RUNNER_FUNCTIONS(DECLARE_POINTER)
#undef DECLARE_POINTER
    fmi2Component component;
    fmi2CallbackFunctions callbacks;
    char *instance_name, *guid, *resource_location;
    char log[LOG_CAPACITY];
    size_t log_length;
} lgf_runner;

/* What every run of a batch shares: times, the variables set and recorded (value references
 * and types), and the size of the caller's buffers. */
typedef struct {
    double start_time, stop_time, output_interval;
    int tolerance_defined;
    double tolerance;
    int can_handle_variable_step_size;
    int n_start; /* start values, in the order FMPy sets them */
    const unsigned *start_vr;
    const int *start_type;
    const int *start_phase; /* 0: before fmi2EnterInitializationMode, 1: in it */
    int n_inputs;           /* the input table's columns */
    const unsigned *input_vr;
    const int *input_type;
    int n_outputs; /* recorded variables, in the order of the caller's buffer */
    const unsigned *output_vr;
    const int *output_type;
    int max_samples;  /* samples the buffers hold per run */
    int message_size; /* bytes per run's message, with the terminating 0 */
} lgf_plan;

/* FMPy's comparisons are math.isclose(a, b) with rel_tol 1e-9 and abs_tol 0, as CPython
 * computes it. */
static int is_close(double a, double b)
{
    if (a == b) return 1;
    if (isinf(a) || isinf(b)) return 0;
    double diff = fabs(b - a);
    return diff <= fabs(1e-9 * b) || diff <= fabs(1e-9 * a);
}

/* The FMUs write a literal '#' as "##" (FMI 2.0, 2.1.5); the message is kept as read. */
static void logger(fmi2ComponentEnvironment environment, fmi2String instance, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    (void)instance;
    (void)category;
    lgf_runner *r = (lgf_runner *)environment;
    if (r == NULL || message == NULL || status == fmi2OK) return;
    char text[1024];
    va_list args;
    va_start(args, message);
    vsnprintf(text, sizeof text, message, args);
    va_end(args);
    size_t room = LOG_CAPACITY - 1 - r->log_length;
    if (room < 2) return;
    if (r->log_length > 0) {
        r->log[r->log_length++] = '\n';
        room--;
    }
    for (const char *p = text; *p && room > 0; p++) {
        if (p[0] == '#' && p[1] == '#') p++;
        r->log[r->log_length++] = *p;
        room--;
    }
    r->log[r->log_length] = '\0';
}

static char *copy(const char *text)
{
    size_t n = strlen(text) + 1;
    char *result = malloc(n);
    if (result) memcpy(result, text, n);
    return result;
}

LGF_EXPORT void lgf_runner_close(lgf_runner *r)
{
    if (r == NULL) return;
    if (r->component) r->FreeInstance(r->component);
    if (r->library) dlclose(r->library);
    free(r->instance_name);
    free(r->guid);
    free(r->resource_location);
    free(r);
}

/* Opens the binary of an FMU and resolves the functions a run needs; NULL with the reason in
 * `message` if that fails. The instance is created by the first run. */
LGF_EXPORT lgf_runner *lgf_runner_open(const char *library, const char *instance_name,
                                       const char *guid, const char *resource_location,
                                       char *message, size_t message_size)
{
    lgf_runner *r = calloc(1, sizeof *r);
    if (r == NULL) {
        snprintf(message, message_size, "out of memory");
        return NULL;
    }
    r->library = dlopen(library, RTLD_NOW | RTLD_LOCAL);
    if (r->library == NULL) {
        snprintf(message, message_size, "cannot load %s: %s", library, dlerror());
        lgf_runner_close(r);
        return NULL;
    }
#define RESOLVE(name)                                                                              \
    do {                                                                                           \
        *(void **)(&r->name) = dlsym(r->library, "fmi2" #name);                                    \
        if (r->name == NULL) {                                                                     \
            snprintf(message, message_size, "%s does not export fmi2" #name, library);             \
            lgf_runner_close(r);                                                                   \
            return NULL;                                                                           \
        }                                                                                          \
    } while (0);
    RUNNER_FUNCTIONS(RESOLVE)
#undef RESOLVE
    r->instance_name = copy(instance_name);
    r->guid = copy(guid);
    r->resource_location = copy(resource_location);
    if (!r->instance_name || !r->guid || !r->resource_location) {
        snprintf(message, message_size, "out of memory");
        lgf_runner_close(r);
        return NULL;
    }
    r->callbacks.logger = logger;
    r->callbacks.allocateMemory = calloc;
    r->callbacks.freeMemory = free;
    r->callbacks.stepFinished = NULL;
    r->callbacks.componentEnvironment = r;
    return r;
}

/* ---- one run ---------------------------------------------------------------------------- */

typedef struct {
    lgf_runner *r;
    const lgf_plan *plan;
    const double *times;  /* the run's input rows */
    const double *values; /* row-major, n_inputs per row */
    long long n_rows;
    double *events; /* FMPy's Input.t_events: sorted, distinct, ending with +inf */
    long long n_events;
    long long next_event; /* where next_event's search starts: the run's time never decreases */
    /* per type: the positions in the plan's input and output lists */
    int in_index[N_TYPES][64], in_count[N_TYPES];
    int *out_index[N_TYPES];
    int out_count[N_TYPES];
    unsigned in_vr[N_TYPES][64];
    unsigned *out_vr[N_TYPES];
    double *real_buffer;
    fmi2Integer *integer_buffer;
    fmi2Boolean *boolean_buffer;
    char *message;
    int failed;
} run_state;

static int fail(run_state *s, const char *function, double time, fmi2Status status)
{
    static const char *names[] = {"fmi2OK",    "fmi2Warning", "fmi2Discard",
                                  "fmi2Error", "fmi2Fatal",   "fmi2Pending"};
    const char *name = (status >= 0 && status <= 5) ? names[status] : "an unknown status";
    if (s->r->log_length)
        snprintf(s->message, (size_t)s->plan->message_size, "%s (%s returned %s at t = %.17g)",
                 s->r->log, function, name, time);
    else
        snprintf(s->message, (size_t)s->plan->message_size, "%s returned %s at t = %.17g", function,
                 name, time);
    s->failed = 1;
    return 0;
}

static int compare_doubles(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Input.findEvents: the time of every row at which some input's value differs from the row
 * before (numpy.diff != 0, so NaN - NaN and inf - inf count as a change), and of every row
 * followed by one at the same time; +inf; sorted and without repeats. */
static int find_events(run_state *s)
{
    long long n = s->n_rows, count = 0;
    int m = s->plan->n_inputs;
    s->events = malloc((size_t)(n + 1) * sizeof(double));
    if (s->events == NULL) return 0;
    if (n >= 2) {
        for (long long i = 0; i + 1 < n; i++) {
            if (s->times[i + 1] - s->times[i] == 0.0) s->events[count++] = s->times[i];
            for (int j = 0; j < m; j++) {
                if (!(s->values[(i + 1) * m + j] - s->values[i * m + j] == 0.0)) {
                    s->events[count++] = s->times[i + 1];
                    break;
                }
            }
        }
    }
    s->events[count++] = INFINITY;
    qsort(s->events, (size_t)count, sizeof(double), compare_doubles);
    long long distinct = 0;
    for (long long i = 0; i < count; i++)
        if (distinct == 0 || s->events[i] != s->events[distinct - 1])
            s->events[distinct++] = s->events[i];
    s->n_events = distinct;
    return 1;
}

/* Input.nextEvent: the first event after `time` that is not close to it. FMPy searches from the
 * first event at every step, which makes a run quadratic in its input rows; as the run's time
 * never decreases, an event that is passed (not after time, or close to it) stays passed, so
 * the search goes on from where the last one stopped: the same event, in linear time overall. */
static double next_event(run_state *s, double time)
{
    while (s->next_event < s->n_events &&
           !(s->events[s->next_event] > time && !is_close(s->events[s->next_event], time)))
        s->next_event++;
    return s->next_event < s->n_events ? s->events[s->next_event] : INFINITY;
}

/* Input.interpolate(discrete=True): the row whose values hold at `time`. */
static long long row_at(const run_state *s, double time, int after_event)
{
    long long n = s->n_rows;
    if (n < 2) return 0;
    long long lo = 0, hi = n; /* numpy.searchsorted(t, time), side 'left' */
    while (lo < hi) {
        long long mid = lo + (hi - lo) / 2;
        if (s->times[mid] < time)
            lo = mid + 1;
        else
            hi = mid;
    }
    if (lo == 0) return 0;
    if (lo == n) return n - 1;
    long long i = lo - 1;
    if (after_event)
        while (i + 1 < n && (s->times[i + 1] < time || is_close(time, s->times[i + 1]))) i++;
    return i;
}

static fmi2Status set_values(run_state *s, int type, const unsigned *vr, int n,
                             const double *source, const int *positions)
{
    lgf_runner *r = s->r;
    if (n == 0) return fmi2OK;
    for (int k = 0; k < n; k++) {
        double v = source[positions[k]];
        if (type == TYPE_REAL)
            s->real_buffer[k] = v;
        else if (type == TYPE_INTEGER)
            s->integer_buffer[k] = (fmi2Integer)v;
        else
            s->boolean_buffer[k] = (fmi2Boolean)(int)v;
    }
    if (type == TYPE_REAL) return r->SetReal(r->component, vr, (size_t)n, s->real_buffer);
    if (type == TYPE_INTEGER) return r->SetInteger(r->component, vr, (size_t)n, s->integer_buffer);
    return r->SetBoolean(r->component, vr, (size_t)n, s->boolean_buffer);
}

/* Input.apply: every input column, one fmi2Set call per type. */
static int apply_inputs(run_state *s, double time, int after_event)
{
    if (s->plan->n_inputs == 0) return 1;
    const double *row = s->values + row_at(s, time, after_event) * s->plan->n_inputs;
    static const char *setters[] = {"fmi2SetReal", "fmi2SetInteger", "fmi2SetBoolean"};
    for (int type = 0; type < N_TYPES; type++) {
        fmi2Status status =
            set_values(s, type, s->in_vr[type], s->in_count[type], row, s->in_index[type]);
        if (status > fmi2Warning) {
            fail(s, setters[type], time, status);
            return 0;
        }
    }
    return 1;
}

/* Recorder.sample: the outputs into the caller's buffers. */
static int sample(run_state *s, double time, double *sample_times, double *samples, int *count)
{
    const lgf_plan *p = s->plan;
    lgf_runner *r = s->r;
    if (*count >= p->max_samples) {
        snprintf(s->message, (size_t)p->message_size,
                 "more than the %d samples expected (t = %.17g)", p->max_samples, time);
        s->failed = 1;
        return 0;
    }
    double *out = samples + (size_t)(*count) * (size_t)p->n_outputs;
    sample_times[*count] = time;
    for (int type = 0; type < N_TYPES; type++) {
        int n = s->out_count[type];
        if (n == 0) continue;
        fmi2Status status;
        if (type == TYPE_REAL) {
            status = r->GetReal(r->component, s->out_vr[type], (size_t)n, s->real_buffer);
            for (int k = 0; k < n; k++) out[s->out_index[type][k]] = s->real_buffer[k];
        } else if (type == TYPE_INTEGER) {
            status = r->GetInteger(r->component, s->out_vr[type], (size_t)n, s->integer_buffer);
            for (int k = 0; k < n; k++) out[s->out_index[type][k]] = s->integer_buffer[k];
        } else {
            status = r->GetBoolean(r->component, s->out_vr[type], (size_t)n, s->boolean_buffer);
            for (int k = 0; k < n; k++) out[s->out_index[type][k]] = s->boolean_buffer[k] != 0;
        }
        if (status > fmi2Warning) {
            static const char *getters[] = {"fmi2GetReal", "fmi2GetInteger", "fmi2GetBoolean"};
            fail(s, getters[type], time, status);
            return 0;
        }
    }
    (*count)++;
    return 1;
}

static int start_values(run_state *s, int phase, const double *values)
{
    const lgf_plan *p = s->plan;
    static const char *setters[] = {"fmi2SetReal", "fmi2SetInteger", "fmi2SetBoolean"};
    for (int k = 0; k < p->n_start; k++) {
        if (p->start_phase[k] != phase) continue;
        int type = p->start_type[k], position = k;
        fmi2Status status = set_values(s, type, &p->start_vr[k], 1, values, &position);
        if (status > fmi2Warning) {
            fail(s, setters[type], p->start_time, status);
            return 0;
        }
    }
    return 1;
}

static int simulate(run_state *s, const double *start, double *sample_times, double *samples,
                    int *count)
{
    const lgf_plan *p = s->plan;
    lgf_runner *r = s->r;
    double time = p->start_time;
    fmi2Status status;
    *count = 0;
    if (!find_events(s)) {
        snprintf(s->message, (size_t)p->message_size, "out of memory");
        s->failed = 1;
        return 0;
    }
    status = r->SetupExperiment(r->component, p->tolerance_defined, p->tolerance, time, fmi2True,
                                p->stop_time);
    if (status > fmi2Warning) return fail(s, "fmi2SetupExperiment", time, status);
    if (!start_values(s, 0, start)) return 0;
    status = r->EnterInitializationMode(r->component);
    if (status > fmi2Warning) return fail(s, "fmi2EnterInitializationMode", time, status);
    if (!start_values(s, 1, start)) return 0;
    if (!apply_inputs(s, time, 0)) return 0;
    status = r->ExitInitializationMode(r->component);
    if (status > fmi2Warning) return fail(s, "fmi2ExitInitializationMode", time, status);
    if (!sample(s, time, sample_times, samples, count)) return 0;

    long long n_steps = 0;
    for (;;) {
        if (time > p->stop_time || is_close(time, p->stop_time)) break;
        double next_regular = p->start_time + (double)(n_steps + 1) * p->output_interval;
        double next = next_regular;
        double input_event = next_event(s, time);
        if (p->can_handle_variable_step_size && next > input_event && !is_close(next, input_event))
            next = input_event;
        if (next > p->stop_time && !is_close(next, p->stop_time)) {
            if (p->can_handle_variable_step_size)
                next = p->stop_time;
            else
                break;
        }
        double step = next - time;
        if (!apply_inputs(s, time, 1)) return 0;
        status = r->DoStep(r->component, time, step, fmi2True);
        if (status == fmi2Discard) {
            fmi2Boolean terminated = fmi2False;
            r->GetBooleanStatus(r->component, fmi2Terminated, &terminated);
            if (!terminated) return fail(s, "fmi2DoStep", time, status);
            r->GetRealStatus(r->component, fmi2LastSuccessfulTime, &time);
            return sample(s, time, sample_times, samples, count);
        }
        if (status > fmi2Warning) return fail(s, "fmi2DoStep", time, status);
        time = next;
        if (!sample(s, time, sample_times, samples, count)) return 0;
        if (is_close(time, next_regular)) n_steps++;
    }
    return 1;
}

static int prepare(run_state *s)
{
    const lgf_plan *p = s->plan;
    for (int type = 0; type < N_TYPES; type++) {
        s->in_count[type] = 0;
        s->out_count[type] = 0;
        s->out_index[type] = malloc(sizeof(int) * (size_t)(p->n_outputs + 1));
        s->out_vr[type] = malloc(sizeof(unsigned) * (size_t)(p->n_outputs + 1));
        if (!s->out_index[type] || !s->out_vr[type]) return 0;
    }
    if (p->n_inputs > 64) return 0;
    for (int j = 0; j < p->n_inputs; j++) {
        int type = p->input_type[j];
        s->in_index[type][s->in_count[type]] = j;
        s->in_vr[type][s->in_count[type]++] = p->input_vr[j];
    }
    for (int k = 0; k < p->n_outputs; k++) {
        int type = p->output_type[k];
        s->out_index[type][s->out_count[type]] = k;
        s->out_vr[type][s->out_count[type]++] = p->output_vr[k];
    }
    size_t n = (size_t)(p->n_outputs > 64 ? p->n_outputs : 64) + 1;
    s->real_buffer = malloc(n * sizeof(double));
    s->integer_buffer = malloc(n * sizeof(fmi2Integer));
    s->boolean_buffer = malloc(n * sizeof(fmi2Boolean));
    return s->real_buffer && s->integer_buffer && s->boolean_buffer;
}

static void release(run_state *s)
{
    for (int type = 0; type < N_TYPES; type++) {
        free(s->out_index[type]);
        free(s->out_vr[type]);
    }
    free(s->real_buffer);
    free(s->integer_buffer);
    free(s->boolean_buffer);
}

/* Runs n_runs runs. Run i takes start_values[i * n_start ...], the input rows
 * rows_begin[i] .. rows_begin[i + 1] - 1 of input_times and input_values (n_inputs a row), and
 * writes up to max_samples samples into sample_times[i * max_samples ...] and
 * samples[(i * max_samples + s) * n_outputs + k], their number into n_samples[i], RUN_OK,
 * RUN_WARNING (the FMU logged warnings; they are in the message) or RUN_FAILED into status[i],
 * and a message into messages[i * message_size ...]. Returns the number of failed runs, or -1
 * if the plan itself cannot be run (more than 64 inputs, out of memory). */
LGF_EXPORT int lgf_runner_run(lgf_runner *r, const lgf_plan *plan, int n_runs, const double *start,
                              const long long *rows_begin, const double *input_times,
                              const double *input_values, double *sample_times, double *samples,
                              int *n_samples, int *status, char *messages)
{
    run_state s;
    memset(&s, 0, sizeof s);
    s.r = r;
    s.plan = plan;
    int failures = 0;
    if (!prepare(&s)) {
        release(&s);
        return -1;
    }
    for (int i = 0; i < n_runs; i++) {
        size_t samples_at = (size_t)i * (size_t)plan->max_samples;
        s.message = messages + (size_t)i * (size_t)plan->message_size;
        s.message[0] = '\0';
        s.failed = 0;
        s.times = input_times + rows_begin[i];
        s.values = input_values + rows_begin[i] * plan->n_inputs;
        s.n_rows = rows_begin[i + 1] - rows_begin[i];
        s.events = NULL;
        s.next_event = 0;
        r->log_length = 0;
        r->log[0] = '\0';
        n_samples[i] = 0;
        if (r->component == NULL) {
            r->component =
                r->Instantiate(r->instance_name, fmi2CoSimulation, r->guid, r->resource_location,
                               &r->callbacks, fmi2False, fmi2False);
            if (r->component == NULL) {
                snprintf(s.message, (size_t)plan->message_size, "fmi2Instantiate failed%s%s",
                         r->log_length ? ": " : "", r->log);
                status[i] = RUN_FAILED;
                failures++;
                continue;
            }
        }
        simulate(&s, start + (size_t)i * (size_t)plan->n_start, sample_times + samples_at,
                 samples + samples_at * (size_t)plan->n_outputs, &n_samples[i]);
        free(s.events);
        if (s.failed) {
            status[i] = RUN_FAILED;
            failures++;
        } else if (r->log_length) {
            snprintf(s.message, (size_t)plan->message_size, "%s", r->log);
            status[i] = RUN_WARNING;
        } else {
            status[i] = RUN_OK;
        }
        /* Ready for the next run: fmi2Terminate where it is allowed, then fmi2Reset; an
         * instance that refuses the reset is freed and the next run instantiates anew. */
        r->Terminate(r->component);
        if (r->Reset(r->component) > fmi2Warning) {
            r->FreeInstance(r->component);
            r->component = NULL;
        }
    }
    release(&s);
    return failures;
}
