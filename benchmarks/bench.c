/* The cost of one FMU, measured in C: the FMU's binary is opened with dlopen from an unpacked
 * FMU (as an importer does) and driven through its fmi2 functions; every figure is timed with
 * CLOCK_MONOTONIC, repeated, and the best repeat kept (the machine may be shared).
 *
 *   bench [--repeats N] [--callgrind] <unpacked FMU directory>
 *
 * For an LGF block with a scenario below it measures
 *   call      ns per PLC call inside one long doStep (10^6 calls of cycleTime 1 ms),
 *   plain     ns per call of a plain C loop of the same rule, written from docs/behaviour.md (not from
 *             the FMU's code), each call's result stored into a volatile sink,
 *   dostep    ns per doStep of one call,
 * and for every FMU (also one without a scenario, e.g. a Reference FMU)
 *   get.T     ns per fmi2GetT of all outputs of type T (Real, Integer, Boolean),
 *   set.T     ns per fmi2SetT of all inputs of type T (with the values they hold),
 *   plainset.T ns per call of a plain C set of the same values by the same rule (the checks of
 *             docs/behaviour.md §1.7, then the stores), from the modelDescription,
 * and for an LGF block with a scenario
 *   state.get ns per fmi2GetFMUstate into an existing state (no allocation),
 *   state.set ns per fmi2SetFMUstate,
 *   state.serialize    ns per fmi2SerializeFMUstate into a buffer of fmi2SerializedFMUstateSize
 *             bytes,
 *   state.deserialize  ns per fmi2DeSerializeFMUstate into an existing state (no allocation).
 * Output: tab-separated records for benchmarks/bench.py, which prints the table:
 *   meta   <id> <key> <text>      (key "serialized": the serialized state's size in bytes)
 *   time   <id> <figure> <ns per operation> [<values per operation> <names>]
 *   check  <id> plain|state ok|MISMATCH <text>   the plain loop against the FMU's outputs;
 *                                  a deserialized state set into the instance against the run
 *                                  it was taken from
 *   region <id> <figure> <operations>  (--callgrind) a callgrind dump named <id>/<figure>
 * With --callgrind (run under valgrind --tool=callgrind) every figure is one shorter run
 * between CALLGRIND_ZERO_STATS and CALLGRIND_DUMP_STATS_AT, so that bench.py can divide the
 * instructions of each dump by its operations. A benchmark, not a test: nothing is asserted
 * about speed; the exit status is non-zero only if the FMU cannot be driven at all. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "importer.h"

#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#define HAVE_CALLGRIND 1
#endif
#endif
#ifndef HAVE_CALLGRIND
#define CALLGRIND_ZERO_STATS
#define CALLGRIND_DUMP_STATS_AT(label) ((void)(label))
#define HAVE_CALLGRIND 0
#endif

/* ---- what is measured, and how often ---- */

#define CYCLE_US 1000 /* every scenario runs at cycleTime 1 ms */
#define MAX_SETTINGS 8
#define MAX_OUTPUTS 8
#define MAX_VALUES 64

static long calls_per_step = 1000000; /* (a) one doStep of 10^6 calls */
static long steps = 1000000;          /* (b) doSteps of one call */
static long accesses = 200000;        /* (c), (d) gets and sets */
static long state_ops = 100000;       /* (e) operations on FMU states, of each kind */
static int repeats = 7;
static bool callgrind;

/* Results of the plain loops go here, so that no loop can be optimised away. */
static volatile double sink_real;
static volatile long sink_integer;

typedef struct {
    int count;
    const char *names[MAX_OUTPUTS];
    double values[MAX_OUTPUTS]; /* in the FMI variable's unit (TIME in s, Booleans 0/1) */
} plain_outputs;

typedef struct {
    const char *name;
    double value;
} setting;

typedef struct {
    const char *identifier;
    const char *description;
    setting settings[MAX_SETTINGS];
    /* Runs `calls` calls after the first one (which the FMU makes in
     * fmi2ExitInitializationMode) and says what the outputs are after the last. */
    void (*plain)(long calls, plain_outputs *out);
} scenario;

/* ---- the plain C loops, one per rule, from docs/behaviour.md ----
 * The scenario's inputs are read from volatile variables at the start of each run, so the
 * compiler cannot fold the loop into a constant; inside the loop it may keep them in registers,
 * as any plain C program would. */

/* LGF_LimRateOfChangeCI (docs/behaviour.md §3, step 3), ramping on every call: value is never reached. */
#define LIM_VALUE 1e6
#define LIM_RATE 10.0
static volatile double lim_value = LIM_VALUE, lim_rate = LIM_RATE;
static volatile long lim_cycle_us = CYCLE_US;

static void plain_lim_rate(long calls, plain_outputs *out)
{
    const double value = lim_value, rate = lim_rate, dt = (double)lim_cycle_us / 1e6;
    double p = 0.0;
    /* the first call (in the FMU: fmi2ExitInitializationMode) */
    p = value < p ? fmax(p - rate * dt, value) : value > p ? fmin(p + rate * dt, value) : p;
    for (long k = 0; k < calls; k++) {
        double o;
        if (value < p) {
            double r = p - rate * dt;
            o = r >= value ? r : value;
        } else if (value > p) {
            double r = p + rate * dt;
            o = r <= value ? r : value;
        } else {
            o = p;
        }
        p = o;
        sink_real = o;
    }
    *out = (plain_outputs){1, {"delayedValue"}, {p}};
}

/* LGF_SawTooth (docs/behaviour.md §2, documented timing): step m at the first call at or after
 * t_ref + m·timeRange; numberSteps steps, then back to startValue; INT wrap. */
#define SAW_START 5
#define SAW_TIME_MS 20
#define SAW_INCREMENT 3
#define SAW_STEPS 4
static volatile int saw_start = SAW_START, saw_time_ms = SAW_TIME_MS, saw_increment = SAW_INCREMENT,
                    saw_steps = SAW_STEPS;
static volatile long saw_cycle_us = CYCLE_US;

static void plain_saw_tooth(long calls, plain_outputs *out)
{
    const int16_t start = (int16_t)saw_start, increment = (int16_t)saw_increment;
    const int number_steps = saw_steps;
    const int64_t range_us = (int64_t)saw_time_ms * 1000, cycle_us = saw_cycle_us;
    /* the first call latches at t_ref = 0 */
    int16_t value = start;
    int count = 0;
    int64_t next_us = range_us;
    for (long k = 1; k <= calls; k++) {
        int64_t now_us = k * cycle_us; /* call times from the call counter */
        if (now_us >= next_us) {
            if (count < number_steps) {
                count++;
                value = (int16_t)(uint16_t)((uint16_t)value + (uint16_t)increment);
            } else {
                count = 0;
                value = start;
            }
            if (range_us > 0) next_us += range_us;
        }
        sink_integer = value;
    }
    *out = (plain_outputs){1, {"value"}, {value}};
}

/* LGF_RampCI (docs/behaviour.md §4.3), a table run cyclically: a) at the start and at every wrap,
 * c) the interpolation, d) the snap onto each reached point, e) the end of the table. The
 * FMU's default table: 0 -> 100 in 5 s, hold 10 s, -> 0 in 5 s, last point 0 s. */
#define RAMP_POINTS 4
static volatile double ramp_values[RAMP_POINTS] = {0.0, 100.0, 100.0, 0.0};
static volatile int32_t ramp_times_ms[RAMP_POINTS] = {5000, 10000, 5000, 0};
static volatile long ramp_cycle_us = CYCLE_US;

static void plain_ramp(long calls, plain_outputs *out)
{
    double value[RAMP_POINTS];
    int32_t time_ms[RAMP_POINTS];
    int32_t total = 0;
    for (int i = 0; i < RAMP_POINTS; i++) {
        value[i] = ramp_values[i];
        time_ms[i] = ramp_times_ms[i];
        total += time_ms[i];
    }
    const int32_t ts = (int32_t)(ramp_cycle_us / 1000);
    const int last = RAMP_POINTS - 1;
    /* the first call: start's rising edge initialises the run (a) */
    double output = value[0], target = value[1];
    int32_t remain = time_ms[0], remain_total = total;
    int step = 1;
    bool init = false, active = true;
    for (long k = 0; k < calls; k++) {
        if (init) { /* a) */
            init = false;
            output = value[0];
            target = value[1];
            remain = time_ms[0];
            remain_total = total;
            step = 1;
            active = true;
        } else if (remain > ts) { /* c) */
            output = output + (target - output) / (double)remain * (double)ts;
            remain -= ts;
            remain_total -= ts;
        } else if (step < last) { /* d) */
            output = value[step];
            target = value[step + 1];
            remain = time_ms[step];
            step++;
            active = true;
            remain_total -= ts;
        } else { /* e) with cyclicOP */
            remain_total = 0;
            remain = 0;
            output = value[last];
            init = true;
        }
        sink_real = output;
    }
    *out = (plain_outputs){
        5,
        {"outputValue", "stepNumber", "remainTime", "remainTotalTime", "actTimeTable"},
        {output, step, remain / 1000.0, remain_total / 1000.0, active}};
}

static const scenario scenarios[] = {
    {"LGF_LimRateOfChangeCI",
     "cycleTime 1 ms; value 1e6, setChangeRate 10: step 3 ramps in every call",
     {{"cycleTime", CYCLE_US / 1e6}, {"value", LIM_VALUE}, {"setChangeRate", LIM_RATE}},
     plain_lim_rate},
    {"LGF_SawTooth",
     "cycleTime 1 ms; documented timing; startValue 5, timeRange 20 ms, incrementRange 3, "
     "numberSteps 4: a step every 20 calls",
     {{"cycleTime", CYCLE_US / 1e6},
      {"plcTiming", 0},
      {"startValue", SAW_START},
      {"timeRange", SAW_TIME_MS / 1000.0},
      {"incrementRange", SAW_INCREMENT},
      {"numberSteps", SAW_STEPS}},
     plain_saw_tooth},
    {"LGF_RampCI",
     "cycleTime 1 ms; the default table (0 -> 100 in 5 s, hold 10 s, -> 0 in 5 s) run with "
     "start and cyclicOP: interpolation, a snap at every point, a wrap every 20 s",
     {{"cycleTime", CYCLE_US / 1e6}, {"start", 1}, {"cyclicOP", 1}},
     plain_ramp},
};

/* ---- the FMU ---- */

typedef struct {
    fmi2_api api;
    model_description md;
    char resources[4200];
} fmu;

static void fail(const char *format, ...)
{
    va_list args;
    va_start(args, format);
    fputs("bench: ", stderr);
    vfprintf(stderr, format, args);
    fputc('\n', stderr);
    va_end(args);
    exit(1);
}

/* The minimal callbacks an importer passes: messages (only errors and warnings, since logging
 * is off) go to stderr. */
static void logger(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                   fmi2String category, fmi2String message, ...)
{
    (void)env;
    va_list args;
    va_start(args, message);
    fprintf(stderr, "bench: [%s] status %d, %s: ", instance ? instance : "?", (int)status,
            category ? category : "?");
    if (message) vfprintf(stderr, message, args);
    fputc('\n', stderr);
    va_end(args);
}

static const fmi2CallbackFunctions callbacks = {logger, calloc, free, NULL, NULL};

static const md_variable *variable(const fmu *f, const char *name)
{
    for (size_t i = 0; i < f->md.count; i++)
        if (!strcmp(f->md.variables[i].name, name)) return &f->md.variables[i];
    return NULL;
}

static void check(fmi2Status status, const char *what)
{
    if (status > fmi2Warning) fail("%s returned status %d", what, (int)status);
}

static void set_value(fmu *f, fmi2Component c, const char *name, double value)
{
    const md_variable *v = variable(f, name);
    if (!v) fail("%s has no variable %s", f->md.identifier, name);
    fmi2ValueReference vr = v->vr;
    switch (v->kind) {
    case KIND_REAL: check(f->api.SetReal(c, &vr, 1, &value), name); break;
    case KIND_INTEGER: {
        fmi2Integer i = (fmi2Integer)value;
        check(f->api.SetInteger(c, &vr, 1, &i), name);
        break;
    }
    case KIND_BOOLEAN: {
        fmi2Boolean b = value != 0;
        check(f->api.SetBoolean(c, &vr, 1, &b), name);
        break;
    }
    default: fail("%s: %s has a type the benchmark cannot set", f->md.identifier, name);
    }
}

static double get_value(fmu *f, fmi2Component c, const char *name)
{
    const md_variable *v = variable(f, name);
    if (!v) fail("%s has no variable %s", f->md.identifier, name);
    fmi2ValueReference vr = v->vr;
    switch (v->kind) {
    case KIND_REAL: {
        fmi2Real r;
        check(f->api.GetReal(c, &vr, 1, &r), name);
        return r;
    }
    case KIND_INTEGER: {
        fmi2Integer i;
        check(f->api.GetInteger(c, &vr, 1, &i), name);
        return i;
    }
    case KIND_BOOLEAN: {
        fmi2Boolean b;
        check(f->api.GetBoolean(c, &vr, 1, &b), name);
        return b;
    }
    default: fail("%s: %s has a type the benchmark cannot get", f->md.identifier, name);
    }
    return 0;
}

/* An instance in step mode at t = 0, with the scenario's settings (none: start values). */
static fmi2Component start(fmu *f, const scenario *s)
{
    fmi2Component c = f->api.Instantiate("bench", fmi2CoSimulation, f->md.guid, f->resources,
                                         &callbacks, fmi2False, fmi2False);
    if (!c) fail("fmi2Instantiate of %s failed", f->md.identifier);
    check(f->api.SetupExperiment(c, fmi2False, 0.0, 0.0, fmi2False, 0.0), "fmi2SetupExperiment");
    check(f->api.EnterInitializationMode(c), "fmi2EnterInitializationMode");
    for (int i = 0; s && i < MAX_SETTINGS && s->settings[i].name; i++)
        set_value(f, c, s->settings[i].name, s->settings[i].value);
    check(f->api.ExitInitializationMode(c), "fmi2ExitInitializationMode");
    return c;
}

static void stop(fmu *f, fmi2Component c)
{
    f->api.Terminate(c);
    f->api.FreeInstance(c);
}

/* ---- timing ---- */

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

static char region_label[160];

static void region_begin(const char *id, const char *figure)
{
    snprintf(region_label, sizeof region_label, "%s/%s", id, figure);
    if (callgrind) CALLGRIND_ZERO_STATS;
}

static void region_end(const char *id, const char *figure, long operations)
{
    if (!callgrind) return;
    CALLGRIND_DUMP_STATS_AT(region_label);
    printf("region\t%s\t%s\t%ld\n", id, figure, operations);
}

/* (a) and the plain loop of the same rule */
static void measure_calls(fmu *f, const scenario *s)
{
    const char *id = s->identifier;
    double h = (double)calls_per_step * CYCLE_US / 1e6;
    double best = INFINITY, best_plain = INFINITY;
    plain_outputs plain = {0};
    for (int r = 0; r < repeats; r++) {
        fmi2Component c = start(f, s);
        region_begin(id, "call");
        double t0 = now_ns();
        check(f->api.DoStep(c, 0.0, h, fmi2True), "fmi2DoStep");
        double t1 = now_ns();
        region_end(id, "call", calls_per_step);
        best = fmin(best, (t1 - t0) / (double)calls_per_step);
        if (r == 0) {
            /* the plain loop must compute what the FMU computed */
            s->plain(calls_per_step, &plain);
            char text[1024] = "";
            size_t used = 0;
            bool same = true;
            for (int i = 0; i < plain.count; i++) {
                double got = get_value(f, c, plain.names[i]);
                bool equal = got == plain.values[i];
                same = same && equal;
                used += (size_t)snprintf(text + used, used < sizeof text ? sizeof text - used : 0,
                                         "%s%s %.17g%s%.17g", i ? ", " : "", plain.names[i], got,
                                         equal ? " = " : " != plain ", plain.values[i]);
            }
            printf("check\t%s\tplain\t%s\tafter %ld calls: %s\n", id, same ? "ok" : "MISMATCH",
                   calls_per_step + 1, text);
        }
        stop(f, c);

        region_begin(id, "plain");
        t0 = now_ns();
        s->plain(calls_per_step, &plain);
        t1 = now_ns();
        region_end(id, "plain", calls_per_step);
        best_plain = fmin(best_plain, (t1 - t0) / (double)calls_per_step);
    }
    printf("time\t%s\tcall\t%.3f\n", id, best);
    printf("time\t%s\tplain\t%.3f\n", id, best_plain);
}

/* (b) a master's loop of doSteps of one cycle, t = n·h */
static void measure_steps(fmu *f, const scenario *s)
{
    const char *id = s->identifier;
    const double h = CYCLE_US / 1e6;
    double best = INFINITY;
    for (int r = 0; r < repeats; r++) {
        fmi2Component c = start(f, s);
        fmi2DoStepTYPE *do_step = f->api.DoStep;
        fmi2Status status = fmi2OK;
        region_begin(id, "dostep");
        double t0 = now_ns();
        for (long n = 0; n < steps; n++) status |= do_step(c, (double)n * h, h, fmi2True);
        double t1 = now_ns();
        region_end(id, "dostep", steps);
        check(status, "fmi2DoStep");
        best = fmin(best, (t1 - t0) / (double)steps);
        stop(f, c);
    }
    printf("time\t%s\tdostep\t%.3f\n", id, best);
}

/* (c), (d) every output (get) and every input (set) of one type, in one call */
typedef struct {
    var_kind kind;
    const char *name;
} kind_name;

static const kind_name kinds[] = {
    {KIND_REAL, "Real"}, {KIND_INTEGER, "Integer"}, {KIND_BOOLEAN, "Boolean"}};

static fmi2Status get_or_set(fmu *f, fmi2Component c, bool set, var_kind kind,
                             const fmi2ValueReference *vr, size_t n, fmi2Real *real,
                             fmi2Integer *integer, fmi2Boolean *boolean)
{
    switch (kind) {
    case KIND_REAL: return set ? f->api.SetReal(c, vr, n, real) : f->api.GetReal(c, vr, n, real);
    case KIND_INTEGER:
        return set ? f->api.SetInteger(c, vr, n, integer) : f->api.GetInteger(c, vr, n, integer);
    default:
        return set ? f->api.SetBoolean(c, vr, n, boolean) : f->api.GetBoolean(c, vr, n, boolean);
    }
}

/* (d') the plain C set of the same rule (docs/behaviour.md §1.4, §1.7), written from the
 * documentation, not from the FMU's code: the instance and its mode are checked, then every
 * value (a known value reference, of the function's type, settable now, within the range of the
 * modelDescription, NaN never), and only then are they stored, so that a refused call changes
 * nothing. Its table is built from the modelDescription, a row per value reference. What it
 * leaves out, the FMU must do beyond it (e.g. a REAL's rounding to float32, the cycle's µs). */
#define PLAIN_VRS 4096

typedef struct {
    bool settable; /* an input or a tunable parameter: settable in step mode */
    var_kind kind;
    double min, max;
} plain_row;

typedef struct {
    int mode; /* 1: step mode, where inputs may be set */
    uint32_t count;
    plain_row rows[PLAIN_VRS];
    double values[PLAIN_VRS];
} plain_instance;

static plain_instance plain;

static void plain_setup(const fmu *f)
{
    memset(&plain, 0, sizeof plain);
    plain.mode = 1;
    for (size_t i = 0; i < f->md.count; i++) {
        const md_variable *v = &f->md.variables[i];
        if (v->vr >= PLAIN_VRS) continue;
        plain_row *row = &plain.rows[v->vr];
        row->settable = v->causality == CAUS_INPUT || (v->causality == CAUS_PARAMETER && !v->fixed);
        row->kind = v->kind;
        row->min = v->has_min ? v->min : v->kind == KIND_BOOLEAN ? 0 : -INFINITY;
        row->max = v->has_max ? v->max : v->kind == KIND_BOOLEAN ? 1 : INFINITY;
        if (v->vr >= plain.count) plain.count = v->vr + 1;
    }
}

static double plain_value(var_kind kind, const fmi2Real *real, const fmi2Integer *integer,
                          const fmi2Boolean *boolean, size_t i)
{
    return kind == KIND_REAL      ? real[i]
           : kind == KIND_INTEGER ? integer[i]
                                  : (double)(boolean[i] != fmi2False);
}

/* Called through a pointer, as an importer calls the FMU's fmi2Set*. */
static fmi2Status plain_set(plain_instance *inst, var_kind kind, const fmi2ValueReference *vr,
                            size_t n, const fmi2Real *real, const fmi2Integer *integer,
                            const fmi2Boolean *boolean)
{
    if (!inst || inst->mode != 1 || (n > 0 && !vr)) return fmi2Error;
    for (size_t i = 0; i < n; i++) {
        if (vr[i] >= inst->count) return fmi2Error;
        const plain_row *row = &inst->rows[vr[i]];
        double value = plain_value(kind, real, integer, boolean, i);
        if (!row->settable || row->kind != kind || !(value >= row->min && value <= row->max))
            return fmi2Error;
    }
    for (size_t i = 0; i < n; i++)
        inst->values[vr[i]] = plain_value(kind, real, integer, boolean, i);
    return fmi2OK;
}

static fmi2Status (*volatile plain_setter)(plain_instance *, var_kind, const fmi2ValueReference *,
                                           size_t, const fmi2Real *, const fmi2Integer *,
                                           const fmi2Boolean *) = plain_set;

static void measure_access(fmu *f, const scenario *s, const char *id)
{
    fmi2Component c = start(f, s);
    if (s) {
        const double h = CYCLE_US / 1e6;
        for (int n = 0; n < 10; n++) check(f->api.DoStep(c, n * h, h, fmi2True), "fmi2DoStep");
    }
    for (int set = 0; set <= 1; set++) {
        for (size_t k = 0; k < sizeof kinds / sizeof kinds[0]; k++) {
            fmi2ValueReference vr[MAX_VALUES];
            char names[2048] = "";
            size_t n = 0, used = 0;
            for (size_t i = 0; i < f->md.count && n < MAX_VALUES; i++) {
                const md_variable *v = &f->md.variables[i];
                if (v->kind != kinds[k].kind || v->causality != (set ? CAUS_INPUT : CAUS_OUTPUT))
                    continue;
                vr[n++] = v->vr;
                used +=
                    (size_t)snprintf(names + used, used < sizeof names ? sizeof names - used : 0,
                                     "%s%s", n > 1 ? "," : "", v->name);
            }
            if (n == 0) continue;
            fmi2Real real[MAX_VALUES] = {0};
            fmi2Integer integer[MAX_VALUES] = {0};
            fmi2Boolean boolean[MAX_VALUES] = {0};
            /* a set writes back the values the inputs hold, so it is always valid */
            check(get_or_set(f, c, false, kinds[k].kind, vr, n, real, integer, boolean), "fmi2Get");
            char figure[32];
            snprintf(figure, sizeof figure, "%s.%s", set ? "set" : "get", kinds[k].name);
            double best = INFINITY;
            for (int r = 0; r < repeats; r++) {
                fmi2Status status = fmi2OK;
                region_begin(id, figure);
                double t0 = now_ns();
                for (long i = 0; i < accesses; i++)
                    status |= get_or_set(f, c, set, kinds[k].kind, vr, n, real, integer, boolean);
                double t1 = now_ns();
                region_end(id, figure, accesses);
                check(status, figure);
                best = fmin(best, (t1 - t0) / (double)accesses);
            }
            sink_real = real[0] + integer[0] + boolean[0];
            printf("time\t%s\t%s\t%.3f\t%zu\t%s\n", id, figure, best, n, names);
            if (!set) continue;
            /* the plain set of the same values, which must accept them as the FMU did */
            snprintf(figure, sizeof figure, "plainset.%s", kinds[k].name);
            plain_setup(f);
            best = INFINITY;
            for (int r = 0; r < repeats; r++) {
                fmi2Status status = fmi2OK;
                region_begin(id, figure);
                double t0 = now_ns();
                for (long i = 0; i < accesses; i++)
                    status |= plain_setter(&plain, kinds[k].kind, vr, n, real, integer, boolean);
                double t1 = now_ns();
                region_end(id, figure, accesses);
                check(status, figure);
                best = fmin(best, (t1 - t0) / (double)accesses);
            }
            printf("time\t%s\t%s\t%.3f\t%zu\t%s\n", id, figure, best, n, names);
        }
    }
    stop(f, c);
}

/* (e) FMU states. Once first: a state taken after 10 doSteps, serialized, deserialized into
 * another state (taken later, so that it differs) and set into the instance must run the next
 * doSteps to the outputs the instance ran them to after it was taken. Both states exist before
 * the loops, so that neither the get nor the deserialize allocates. */
typedef enum { STATE_GET, STATE_SET, STATE_SERIALIZE, STATE_DESERIALIZE } state_op;

static const char *const state_figures[] = {"state.get", "state.set", "state.serialize",
                                            "state.deserialize"};

static fmi2Status state_call(fmu *f, fmi2Component c, state_op op, fmi2FMUstate *state,
                             fmi2FMUstate *restored, fmi2Byte *bytes, size_t size)
{
    switch (op) {
    case STATE_GET: return f->api.GetFMUstate(c, state);
    case STATE_SET: return f->api.SetFMUstate(c, *state);
    case STATE_SERIALIZE: return f->api.SerializeFMUstate(c, *state, bytes, size);
    default: return f->api.DeSerializeFMUstate(c, bytes, size, restored);
    }
}

/* The outputs after `count` doSteps of one cycle from the instance's time t = first·h; returns
 * how many there are. */
static int run_on(fmu *f, fmi2Component c, int first, int count, double *outputs)
{
    const double h = CYCLE_US / 1e6;
    for (int n = first; n < first + count; n++)
        check(f->api.DoStep(c, n * h, h, fmi2True), "fmi2DoStep");
    int k = 0;
    for (size_t i = 0; i < f->md.count && k < MAX_VALUES; i++)
        if (f->md.variables[i].causality == CAUS_OUTPUT && f->md.variables[i].kind <= KIND_BOOLEAN)
            outputs[k++] = get_value(f, c, f->md.variables[i].name);
    return k;
}

static void measure_state(fmu *f, const scenario *s, const char *id)
{
    enum { TAKEN = 10, ON = 1000 };
    fmi2Component c = start(f, s);
    double unused[MAX_VALUES], first[MAX_VALUES], again[MAX_VALUES];
    run_on(f, c, 0, TAKEN, unused);
    fmi2FMUstate state = NULL, restored = NULL;
    size_t size = 0;
    check(f->api.GetFMUstate(c, &state), "fmi2GetFMUstate");
    check(f->api.SerializedFMUstateSize(c, state, &size), "fmi2SerializedFMUstateSize");
    fmi2Byte *bytes = malloc(size);
    if (!bytes) fail("out of memory");
    check(f->api.SerializeFMUstate(c, state, bytes, size), "fmi2SerializeFMUstate");
    run_on(f, c, TAKEN, ON, first);
    /* taken later, so that the bytes must overwrite it */
    check(f->api.GetFMUstate(c, &restored), "fmi2GetFMUstate");
    check(f->api.DeSerializeFMUstate(c, bytes, size, &restored), "fmi2DeSerializeFMUstate");
    check(f->api.SetFMUstate(c, restored), "fmi2SetFMUstate");
    int count = run_on(f, c, TAKEN, ON, again);
    bool same = true;
    for (int i = 0; i < count; i++) same = same && first[i] == again[i];
    printf("check\t%s\tstate\t%s\ttaken after %d doSteps, serialized, deserialized, set: "
           "%d output%s after the next %d doSteps\n",
           id, same ? "ok" : "MISMATCH", TAKEN, count, count == 1 ? "" : "s", ON);
    printf("meta\t%s\tserialized\t%zu\n", id, size);

    for (int op = STATE_GET; op <= STATE_DESERIALIZE; op++) {
        double best = INFINITY;
        for (int r = 0; r < repeats; r++) {
            fmi2Status status = fmi2OK;
            region_begin(id, state_figures[op]);
            double t0 = now_ns();
            for (long i = 0; i < state_ops; i++)
                status |= state_call(f, c, (state_op)op, &state, &restored, bytes, size);
            double t1 = now_ns();
            region_end(id, state_figures[op], state_ops);
            check(status, state_figures[op]);
            best = fmin(best, (t1 - t0) / (double)state_ops);
        }
        printf("time\t%s\t%s\t%.3f\n", id, state_figures[op], best);
    }
    free(bytes);
    f->api.FreeFMUstate(c, &state);
    f->api.FreeFMUstate(c, &restored);
    stop(f, c);
}

/* ---- main ---- */

static void usage(void)
{
    fprintf(stderr, "usage: bench [--repeats N] [--callgrind] <unpacked FMU directory>\n");
    exit(2);
}

int main(int argc, char **argv)
{
    const char *directory = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--repeats") && i + 1 < argc) {
            repeats = atoi(argv[++i]);
            if (repeats < 1) usage();
        } else if (!strcmp(argv[i], "--callgrind")) {
            callgrind = true;
        } else if (argv[i][0] == '-' || directory) {
            usage();
        } else {
            directory = argv[i];
        }
    }
    if (!directory) usage();
    if (callgrind) {
        if (!HAVE_CALLGRIND)
            fail("built without valgrind/callgrind.h: --callgrind is not available");
        /* instructions do not depend on the load: one shorter run of each figure suffices */
        repeats = 1;
        calls_per_step = 100000;
        steps = 20000;
        accesses = 20000;
        state_ops = 10000;
    }

    static fmu f;
    char error[512], path[4200];
    snprintf(path, sizeof path, "%s/modelDescription.xml", directory);
    if (!md_read(&f.md, path, error, sizeof error)) fail("%s", error);
    snprintf(path, sizeof path, "%s/binaries/linux64/%s.so", directory, f.md.identifier);
    if (!api_load(&f.api, path, error, sizeof error)) fail("%s", error);
    snprintf(f.resources, sizeof f.resources, "file://%s/resources", directory);

    const char *id = f.md.identifier;
    const scenario *s = NULL;
    for (size_t i = 0; i < sizeof scenarios / sizeof scenarios[0]; i++)
        if (!strcmp(scenarios[i].identifier, id)) s = &scenarios[i];
    printf("meta\t%s\tscenario\t%s\n", id, s ? s->description : "start values (no scenario)");
    printf("meta\t%s\tcounts\t%ld calls in one doStep, %ld doSteps, %ld gets or sets, "
           "%ld state operations of each kind, best of %d\n",
           id, calls_per_step, steps, accesses, state_ops, repeats);
    fflush(stdout);
    if (s) {
        measure_calls(&f, s);
        fflush(stdout);
        measure_steps(&f, s);
        fflush(stdout);
    }
    measure_access(&f, s, id);
    fflush(stdout);
    if (s) measure_state(&f, s, id);
    api_unload(&f.api);
    md_free(&f.md);
    return 0;
}
