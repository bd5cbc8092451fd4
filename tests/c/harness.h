/* The C harness: a block under test, the FMI version behind it (one table of operations per
 * version: fmi2.c, fmi3.c), the standard scenario that drives it, and the checks. */
#ifndef LGF_HARNESS_H
#define LGF_HARNESS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "importer.h"

/* ---- the FMI version: what the version-neutral code calls ---- */

typedef struct block block;

#define OTHER_RESULT 99 /* an op or driver call saw something wrong besides the status */

/* The functions the version-neutral cases name in their messages: FMI 2.0 and FMI 3.0 spell
 * them differently (and FMI 3.0 has no fmi2SetupExperiment: fmi3EnterInitializationMode
 * takes the experiment's times). */
typedef enum {
    FN_SETUP,
    FN_ENTER_INIT,
    FN_EXIT_INIT,
    FN_TERMINATE,
    FN_RESET,
    FN_DO_STEP,
    FN_SET_DEBUG_LOGGING,
    FN_GET_STATE,
    FN_SET_STATE,
    FN_FREE_STATE,
    FN_STATE_SIZE,
    FN_SERIALIZE,
    FN_DESERIALIZE,
    /* the Model Exchange functions, in the order of the ME_* ops of cases.c */
    FN_ENTER_EVENT,
    FN_UPDATE_DISCRETE,
    FN_ENTER_CONTINUOUS,
    FN_COMPLETED,
    FN_SET_TIME,
    FN_SET_STATES,
    FN_GET_DERIVATIVES,
    FN_GET_INDICATORS,
    FN_GET_STATES,
    FN_GET_NOMINALS,
    FN_COUNT
} fn_id;

/* A variable type of the version (FMI 2.0: fmi2Real ... fmi2String; FMI 3.0: Float32 ...
 * Clock): its functions, the class of its values and the values its C type can carry. */
typedef struct {
    const char *setter, *getter;
    var_kind kind;
    double lo, hi;  /* integers: the range of the C type */
    bool single;    /* Float32 */
    bool has_table; /* the FMU has variables of this type class: a mismatch names the variable
                         (else it names the value reference) */
} type_info;

/* The event iteration's results, as the FMU wrote them (fmi2EventInfo; the out-pointers of
 * fmi3UpdateDiscreteStates): a flag the FMU did not write keeps the driver's sentinel. */
typedef struct {
    int needed, terminate, nominals_changed, values_changed, next_defined;
    double next;
} event_info;

/* The calls of the scenario and the cases, for one version. Every call returns the FMI status
 * (both versions number them alike), or OTHER_RESULT where the driver saw a broken promise
 * (e.g. fmi3DoStep asking for event handling). `values` are doubles, converted to and from
 * the version's C types; NULL passes NULL. */
typedef struct {
    int version;                /* 2 or 3 */
    const char *version_string; /* what fmiXGetVersion returns */
    const char *const *names;   /* FN_COUNT function names */
    const type_info *types;     /* indexed by md_variable.type */
    int n_types;
    int string_type; /* the String type (no variables of it) */
    bool (*load)(block *b, char *error, size_t size);
    void (*unload)(block *b);
    const char *(*get_version)(const block *b);
    /* NULL when refused */
    void *(*instantiate)(const block *b, const char *name, fmi2Type type, log_record *log);
    void (*free_instance)(const block *b, void *c);
    /* into initialization mode with the experiment's times (FMI 2.0: fmi2SetupExperiment and
     * fmi2EnterInitializationMode) */
    int (*begin)(const block *b, void *c, double start, bool stop_defined, double stop);
    int (*setup)(const block *b, void *c, double start, bool stop_defined,
                 double stop);                  /* FN_SETUP */
    int (*enter_init)(const block *b, void *c); /* FN_ENTER_INIT without arguments */
    int (*exit_init)(const block *b, void *c);
    int (*terminate)(const block *b, void *c);
    int (*reset)(const block *b, void *c);
    int (*do_step)(const block *b, void *c, double t, double h);
    /* the time: FMI 2.0 fmi2LastSuccessfulTime, FMI 3.0 the independent variable */
    int (*now)(const block *b, void *c, double *t);
    int (*set)(const block *b, void *c, int type, const uint32_t *vr, size_t nvr,
               const double *values, size_t n_values);
    int (*get)(const block *b, void *c, int type, const uint32_t *vr, size_t nvr, double *values,
               size_t n_values);
    int (*set_debug_logging)(const block *b, void *c, bool on, size_t n,
                             const char *const *categories);
    int (*get_state)(const block *b, void *c, void **state);
    int (*set_state)(const block *b, void *c, void *state);
    int (*free_state)(const block *b, void *c, void **state);
    int (*state_size)(const block *b, void *c, void *state, size_t *size);
    int (*serialize)(const block *b, void *c, void *state, unsigned char *bytes, size_t size);
    int (*deserialize)(const block *b, void *c, const unsigned char *bytes, size_t size,
                       void **state);
    /* Model Exchange. update_discrete: info NULL passes NULL (FMI 3.0: every out-pointer) */
    int (*enter_event)(const block *b, void *c);
    int (*update_discrete)(const block *b, void *c, event_info *info);
    int (*enter_continuous)(const block *b, void *c);
    /* enter, terminate NULL pass NULL; written as 0/1 */
    int (*completed)(const block *b, void *c, bool no_set_prior, int *enter, int *terminate);
    int (*set_time)(const block *b, void *c, double t);
    /* FN_SET_STATES ... FN_GET_NOMINALS (fn - FN_SET_STATES) with an array of n */
    int (*no_states)(const block *b, void *c, int which, double *array, size_t n);
} fmu_ops;

/* The operations of fmu_ops but begin, which each front-end (fmi2.c, fmi3.c) defines as static
 * functions of these names: its fmu_ops lists them so. */
#define FMU_OPERATIONS                                                                             \
    .load = load, .unload = unload, .get_version = get_version, .instantiate = instantiate,        \
    .free_instance = free_instance, .setup = setup, .enter_init = enter_init,                      \
    .exit_init = exit_init, .terminate = terminate, .reset = reset, .do_step = do_step,            \
    .now = now, .set = set, .get = get, .set_debug_logging = set_debug_logging,                    \
    .get_state = get_state, .set_state = set_state, .free_state = free_state,                      \
    .state_size = state_size, .serialize = serialize, .deserialize = deserialize,                  \
    .enter_event = enter_event, .update_discrete = update_discrete,                                \
    .enter_continuous = enter_continuous, .completed = completed, .set_time = set_time,            \
    .no_states = no_states

extern const fmu_ops fmi2_ops, fmi3_ops;

/* A call through the block's version: FMU(b, do_step, c, t, h). */
#define FMU(b, op, ...) ((b)->ops->op((b), __VA_ARGS__))
#define FN(b, id) ((b)->ops->names[id])

/* ---- the block under test ---- */

typedef struct {
    int index;     /* into md.variables */
    size_t offset; /* of its storage in the serialized payload */
    int width;     /* bytes: 8 LREAL, 4 TIME and REAL, 2 INT/WORD, 1 BOOL */
} located_variable;

struct block {
    const char *library;
    const fmu_ops *ops;
    fmi2_api api;          /* FMI 2.0 */
    struct fmi3_api *api3; /* FMI 3.0 (fmi3.h) */
    model_description md;
    char guid[64];         /* as given on the command line */
    int *inputs, n_inputs; /* indices into md.variables */
    int *outputs, n_outputs;
    int *parameters, n_parameters;
    double cycle; /* start value of cycleTime */
    /* where the variables live in a serialized state, found by experiment (state_layout) */
    located_variable *located;
    int n_located;
    bool layout_known;
    const block *fmi2; /* FMI 3.0: the same block's FMI 2.0 library, to compare with (or NULL) */
};

bool load_block(block *b, const char *library, const char *xml, const char *guid);
void unload_block(block *b);

/* ---- the standard scenario ----
 * Co-simulation: instantiate, setupExperiment(t0 = 0), enterInitializationMode, every
 * parameter set to its start value, the inputs of call 0, exitInitializationMode, then STEPS
 * doSteps with inputs changed before each and step sizes that vary (1, 2, 0.5, 1.5 cycles; all
 * one cycle when `uniform`), then terminate. After every call that produces outputs, all
 * outputs are read into one row of the trace.
 * Model Exchange: the same setup (with a stopTime two cycles after the last call), then
 * exitInitializationMode (call 0) and the event iteration at t0 (no call), then STEPS time
 * events, one per PLC call k at t_k = k·cycleTime: the inputs of call k are set before the
 * fmi2NewDiscreteStates that executes it, and the outputs are read into row k. Between the
 * events the importer varies what it does (sim_step_me): continuous-time mode with or without
 * an intermediate time and fmi2CompletedIntegratorStep, a state event at a time that is no
 * call time, Real inputs set in continuous-time mode, staying in event mode, a second event
 * iteration at the same instant. With the inputs of call k fed to co-simulation before the
 * doStep that executes call k (uniform steps), both interfaces give the same rows bit for bit. */

enum {
    PHASE_INSTANTIATED,
    PHASE_INITIALIZATION,
    PHASE_STEP,
    PHASE_TERMINATED,
    PHASE_CONTINUOUS,
    PHASES
};
/* PHASE_STEP is, in Model Exchange, event mode right after the event iteration of call
 * STEP_PHASE_AT; PHASE_CONTINUOUS (Model Exchange only) continuous-time mode right after it. */

/* The modes of the FMU's state machine as its serialized clock holds them (fmu_mode,
 * src/core/core.h). */
enum {
    MODE_INSTANTIATED,
    MODE_INITIALIZATION,
    MODE_STEP,
    MODE_EVENT,
    MODE_CONTINUOUS,
    MODE_TERMINATED
};

extern int STEPS;         /* doSteps (co-simulation) or calls after call 0 (Model Exchange) */
extern int STEP_PHASE_AT; /* doSteps or calls done when a case in PHASE_STEP is applied */

typedef struct {
    const block *b;
    void *c; /* the instance */
    log_record log;
    char name[32];
    fmi2Type type; /* fmi2CoSimulation or fmi2ModelExchange */
    bool uniform;  /* co-simulation: every step one cycle (the frame of the ME comparison) */
    int variant;   /* shifts the input patterns, so that parallel runs differ */
    int phase;
    int k;             /* doSteps done, or (Model Exchange) the last call executed */
    double t;          /* the current communication point, or (Model Exchange) the FMU's time */
    bool in_event;     /* Model Exchange: in event mode (else continuous-time mode) */
    double next_event; /* Model Exchange: nextEventTime of the last fmi2NewDiscreteStates */
    uint64_t *trace;   /* (STEPS + 1) rows of n_outputs */
    int rows;
    char failure[256]; /* the first thing that went wrong, empty if none */
} sim;

bool sim_open(sim *s, const block *b, int variant); /* co-simulation */
void sim_fail(sim *s, const char *fmt, ...)         /* records the first failure */
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
bool sim_open_as(sim *s, const block *b, int variant, fmi2Type type);
const char *interface_name(fmi2Type type);
const char *phase_name(fmi2Type type, int phase);
double call_time(const block *b, int64_t k); /* t0 + k·cycle as the FMU computes it */
double me_stop_time(const block *b);         /* the stopTime of the Model Exchange scenario */
void sim_close(sim *s);
bool sim_advance(sim *s, int phase); /* runs the scenario until the phase is reached */
bool sim_step(sim *s);
bool sim_read_outputs(sim *s, uint64_t *row);
bool sim_run_to_end(sim *s); /* remaining steps and terminate */
bool sim_state_bytes(sim *s, unsigned char **bytes, size_t *size); /* serialized, malloc'ed */
void sim_set_inputs_for(sim *s, int k);
double step_size(const sim *s, int k);

/* What a scenario without any misuse gives, per variant. */
typedef struct {
    uint64_t *trace;
    int rows;
    unsigned char *final_state; /* serialized after terminate */
    size_t final_size;
    unsigned char
        *state_at[PHASES]; /* serialized at each phase (PHASE_STEP: after STEP_PHASE_AT) */
    size_t size_at[PHASES];
} reference;

bool reference_run(const block *b, int variant, reference *ref); /* co-simulation */
/* fmi2CoSimulation (uniform: one cycle a step) or fmi2ModelExchange */
bool reference_run_as(const block *b, int variant, fmi2Type type, bool uniform, reference *ref);
void reference_free(reference *ref);

/* ---- checks ---- */

void group_begin(const char *name);
void group_end(void);
bool check(bool condition, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;

/* ---- the misuse cases of docs/behaviour.md §1.7 ---- */

typedef struct misuse misuse;
typedef int op_fn(sim *s, const misuse *m); /* returns the status of the call (or -1) */

typedef struct {
    size_t offset; /* in the payload */
    int width;
    uint64_t bits;
} patch;

struct misuse {
    char label[200];
    const char *group;
    fmi2Type type; /* the interface of the instance (misuse_add: co-simulation) */
    int phase;
    op_fn *op;
    /* arguments of the op */
    uint32_t vr, vr2;
    double r, r2;
    long i, i2;
    patch patches[3];
    int n_patches;
    /* what must happen */
    int expect;           /* status */
    int logs;             /* messages logged by the call */
    int log_status;       /* status of each */
    const char *function; /* each message starts with it */
    char contains[100];   /* and contains this, if not empty */
    bool changes_state;   /* a warning case: the value is applied */
};

typedef struct {
    misuse *items;
    size_t count, capacity;
} misuse_list;

misuse *misuse_add(misuse_list *list, const char *group, int phase, op_fn *op);
void misuse_label(misuse *m, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* The cases of both versions, through the driver (names from FN()). */
void build_misuses(const block *b, const block *other, misuse_list *list);
/* Only FMI 2.0 has them: its status functions, fmi2CancelStep, its NULL-component list, the
 * allocator callbacks. */
void build_fmi2_misuses(const block *b, misuse_list *list);
/* Only FMI 3.0 (fmi3.c): nValues, the types without variables, time, the functions it
 * refuses, its own mode tables. */
void build_fmi3_misuses(const block *b, misuse_list *list);
/* The Model Exchange cases: the ME state machine, its functions' arguments, the functions of
 * one interface on an instance of the other. */
void build_me_misuses(const block *b, misuse_list *list);
void sort_misuses(misuse_list *list);
/* ref: the reference of the case's interface (variant 0) */
void run_misuse(const block *b, const reference *ref, const misuse *m);

/* The ops of both versions (cases.c); m->i is mostly the type (md_variable.type). */
op_fn op_set, op_get, op_null_array, op_setup, op_enter, op_exit, op_terminate, op_dostep,
    op_debug_logging, op_me, op_get_free_state, op_me_null_component;

/* The functions of op_me (i), in the order of FN_ENTER_EVENT ... FN_GET_NOMINALS. */
enum {
    ME_ENTER_EVENT,
    ME_NEW_DISCRETE,
    ME_ENTER_CONTINUOUS,
    ME_COMPLETED,
    ME_SET_TIME,
    ME_SET_STATES,
    ME_GET_DERIVATIVES,
    ME_GET_INDICATORS,
    ME_GET_STATES,
    ME_GET_NOMINALS,
    ME_FUNCTIONS
};

/* One row of a table of calls in every mode: the case is added for each phase in which the
 * call is refused, and for each in which it is allowed and changes nothing (`made`): there it
 * must return fmi2OK (or, `discard`, fmi2Discard with one message) and log nothing. */
typedef struct {
    const char *function, *what;
    op_fn *op;
    long i, i2;
    const md_variable *v;   /* op_get, op_set: the variable (no row without one) */
    unsigned allowed, made; /* bits 1 << PHASE_* */
    const char *contains;   /* the refusal's message contains this (NULL: anything) */
    bool discard;
} mode_row;

void add_mode_cases(const block *b, misuse_list *list, const char *group, fmi2Type type,
                    const mode_row *rows, size_t n_rows, const int *phases, size_t n_phases);

/* Variables for the cases */
const md_variable *first_of(const block *b, var_kind kind, bool (*fits)(const md_variable *));
bool is_input(const md_variable *v);
bool is_output(const md_variable *v);
bool is_settable(const md_variable *v);
bool is_any(const md_variable *v);
bool known_vr(const block *b, uint32_t vr);
/* A type of the block's version that has variables, and one of them (NULL: none). */
const md_variable *first_of_type(const block *b, int type);

/* Shared with the state cases: the other block's state and serialized state, if given. */
typedef struct {
    const block *other;
    void *other_instance;
    log_record other_log;
    void *other_state;
    unsigned char *other_bytes;
    size_t other_size;
} foreign_states;

extern foreign_states FOREIGN;

/* The GUIDs (instantiation tokens) an instantiation must refuse: another block's, this one's
 * without its last character, and this one's with one character changed. */
typedef struct {
    char other[64], prefix[64], changed[64];
} wrong_guids;
void make_wrong_guids(const block *b, wrong_guids *w);

/* FNV-1a 64, the checksum of the serialized format (src/core/state.c). */
uint64_t fnv1a64(const unsigned char *bytes, size_t size);

#define HEADER_SIZE 104u /* serialized header (src/core/state.c) */
/* The clock at the start of the payload (fmu_image in src/core/core.h). */
#define CLOCK_MODE 0u
#define CLOCK_CYCLE_US 4u
#define CLOCK_START 8u
#define CLOCK_TIME 16u
#define CLOCK_CALLS 24u
#define CLOCK_SIZE 41u /* the clock's bytes; the block's data follow (STATE_CLOCK_SIZE) */

/* ---- shared by the groups of harness.c and fmi3.c ---- */

extern long CYCLES;
extern int THREADS;

bool same_trace(const sim *s, const reference *ref, int from, char *why, size_t size);
bool same_bytes(const unsigned char *a, size_t na, const unsigned char *b, size_t nb, char *why,
                size_t size, const char *what);
bool takes_own_state(sim *s, char *why, size_t size);
/* The trace and states of two references (e.g. FMI 3.0 against FMI 2.0), into why. */
bool same_reference(const block *b, const reference *x, const reference *y, char *why, size_t size);

/* Runs fn(arg) in a child process, so that a crash or a sanitizer's abort of a known bug is one
 * failed check instead of the end of the run; returns fn's result, false if the child died.
 * why: what fn wrote there, or how the child died. */
bool isolated(bool (*fn)(void *arg, char *why, size_t size), void *arg, char *why, size_t size);

/* The FMI 3.0 groups (fmi3.c); refs: FMI 3.0 references (co-simulation and Model Exchange) */
void fmi3_groups_before_cases(const block *b, const reference *refs, const reference *me_refs);
void fmi3_groups_after_cases(const block *b);

#endif
