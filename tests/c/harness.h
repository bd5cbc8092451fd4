/* The C harness: a block under test, the standard scenario that drives it, and the checks. */
#ifndef LGF_HARNESS_H
#define LGF_HARNESS_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "importer.h"

/* ---- the block under test ---- */

typedef struct {
    int index; /* into md.variables */
    size_t offset; /* of its storage in the serialized payload */
    int width;     /* bytes: 8 LREAL, 4 TIME, 2 INT/WORD, 1 BOOL */
} located_variable;

typedef struct {
    const char *library;
    fmi2_api api;
    model_description md;
    char guid[64]; /* as given on the command line */
    int *inputs, n_inputs;   /* indices into md.variables */
    int *outputs, n_outputs;
    int *parameters, n_parameters;
    double cycle;            /* start value of cycleTime */
    /* where the variables live in a serialized state, found by experiment (state_layout) */
    located_variable *located;
    int n_located;
    bool layout_known;
} block;

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

enum { PHASE_INSTANTIATED, PHASE_INITIALIZATION, PHASE_STEP, PHASE_TERMINATED,
       PHASE_CONTINUOUS, PHASES };
/* PHASE_STEP is, in Model Exchange, event mode right after the event iteration of call
 * STEP_PHASE_AT; PHASE_CONTINUOUS (Model Exchange only) continuous-time mode right after it. */

/* The modes of the FMU's state machine as its serialized clock holds them (fmu_mode,
 * src/core/core.h). */
enum { MODE_INSTANTIATED, MODE_INITIALIZATION, MODE_STEP, MODE_EVENT, MODE_CONTINUOUS,
       MODE_TERMINATED };

extern int STEPS;        /* doSteps (co-simulation) or calls after call 0 (Model Exchange) */
extern int STEP_PHASE_AT; /* doSteps or calls done when a case in PHASE_STEP is applied */

typedef struct {
    const block *b;
    fmi2Component c;
    log_record log;
    char name[32];
    fmi2Type type; /* fmi2CoSimulation or fmi2ModelExchange */
    bool uniform;  /* co-simulation: every step one cycle (the frame of the ME comparison) */
    int variant; /* shifts the input patterns, so that parallel runs differ */
    int phase;
    int k;       /* doSteps done, or (Model Exchange) the last call executed */
    double t;    /* the current communication point, or (Model Exchange) the FMU's time */
    bool in_event; /* Model Exchange: in event mode (else continuous-time mode) */
    double next_event; /* Model Exchange: nextEventTime of the last fmi2NewDiscreteStates */
    uint64_t *trace; /* (STEPS + 1) rows of n_outputs */
    int rows;
    char failure[256]; /* the first thing that went wrong, empty if none */
} sim;

bool sim_open(sim *s, const block *b, int variant); /* co-simulation */
bool sim_open_as(sim *s, const block *b, int variant, fmi2Type type);
const char *interface_name(fmi2Type type);
const char *phase_name(fmi2Type type, int phase);
double call_time(const block *b, int64_t k); /* t0 + k·cycle as the FMU computes it */
double me_stop_time(const block *b);         /* the stopTime of the Model Exchange scenario */
void sim_close(sim *s);
bool sim_advance(sim *s, int phase); /* runs the scenario until the phase is reached */
bool sim_step(sim *s);
bool sim_read_outputs(sim *s, uint64_t *row);
bool sim_run_to_end(sim *s);         /* remaining steps and terminate */
bool sim_state_bytes(sim *s, unsigned char **bytes, size_t *size); /* serialized, malloc'ed */
void sim_set_inputs_for(sim *s, int k);
double step_size(const sim *s, int k);

/* What a scenario without any misuse gives, per variant. */
typedef struct {
    uint64_t *trace;
    int rows;
    unsigned char *final_state; /* serialized after terminate */
    size_t final_size;
    unsigned char *state_at[PHASES]; /* serialized at each phase (PHASE_STEP: after STEP_PHASE_AT) */
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
typedef int op_fn(sim *s, const misuse *m); /* returns the fmi2Status of the call (or -1) */

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
    int expect;              /* fmi2Status */
    int logs;                /* messages logged by the call */
    int log_status;          /* fmi2Status of each */
    const char *function;    /* each message starts with it */
    char contains[100];      /* and contains this, if not empty */
    bool changes_state;      /* a warning case: the value is applied */
};

typedef struct {
    misuse *items;
    size_t count, capacity;
} misuse_list;

misuse *misuse_add(misuse_list *list, const char *group, int phase, op_fn *op);
void build_misuses(const block *b, const block *other, misuse_list *list);
/* The Model Exchange cases: the ME state machine, its functions' arguments, the functions of
 * one interface on an instance of the other. */
void build_me_misuses(const block *b, misuse_list *list);
void sort_misuses(misuse_list *list);
/* ref: the reference of the case's interface (variant 0) */
void run_misuse(const block *b, const reference *ref, const misuse *m);

/* Shared with the state cases: the other block's state and serialized state, if given. */
typedef struct {
    const block *other;
    fmi2Component other_instance;
    log_record other_log;
    fmi2FMUstate other_state;
    unsigned char *other_bytes;
    size_t other_size;
} foreign_states;

extern foreign_states FOREIGN;

/* FNV-1a 64, the checksum of the serialized format (src/fmi2/fmu_state.c). */
uint64_t fnv1a64(const unsigned char *bytes, size_t size);

#define HEADER_SIZE 104u /* serialized header (src/fmi2/fmu_state.c) */
/* The clock at the start of the payload (fmu_image in src/fmi2/instance.h). */
#define CLOCK_MODE 0u
#define CLOCK_CYCLE_US 4u
#define CLOCK_START 8u
#define CLOCK_TIME 16u
#define CLOCK_CALLS 24u
#define CLOCK_SIZE 41u /* the clock's bytes; the block's data follow (STATE_CLOCK_SIZE) */

#endif
