/* The version-neutral core of every FMU: the instance and its image, the PLC call clock, value
 * validation and conversion, the FMU state and its serialized format, and logging. The FMI
 * front-ends (fmi2/, fmi3/) only translate their entry points onto it. Everything here is
 * static: the core is compiled into the one translation unit of its FMU (see core/model.h); it
 * reads the block through `lgf_model`, which the block's interface.c defines before this is
 * included. */
#ifndef LGF_CORE_H
#define LGF_CORE_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "core/model.h"

/* A function the compiler must inline: core_set, into each fmi2Set* and fmi3Set*, so that the
 * conversion of the importer's values is fixed for each (GCC otherwise keeps one copy for the
 * blocks with a check, which cost them a sixth more per set). */
#if defined(__GNUC__)
#define CORE_ALWAYS_INLINE __attribute__((always_inline)) inline
#elif defined(_MSC_VER)
#define CORE_ALWAYS_INLINE __forceinline
#else
#define CORE_ALWAYS_INLINE inline
#endif

/* The status codes of FMI 2.0 and 3.0 (both number them alike). */
typedef enum { STATUS_OK, STATUS_WARNING, STATUS_DISCARD, STATUS_ERROR } lgf_status;

/* The modes of the FMI state machines: co-simulation steps in MODE_STEP, Model Exchange
 * alternates between MODE_EVENT and MODE_CONTINUOUS. The core needs to know whether the first
 * call has happened and whether fixed parameters may still be set. */
typedef enum {
    MODE_INSTANTIATED,
    MODE_INITIALIZATION,
    MODE_STEP,
    MODE_EVENT,
    MODE_CONTINUOUS,
    MODE_TERMINATED,
    /* after a PLC call failed (model.fault): gets, a restored state, reset and free only; never
     * in an FMU state, so past the modes core_clock_is_valid takes */
    MODE_ERROR
} fmu_mode;

#define MODE_BIT(mode) (1u << (mode))

/* The mode sets the rules of both FMI versions are written in. */
#define MODES_BEFORE_INIT (MODE_BIT(MODE_INSTANTIATED) | MODE_BIT(MODE_INITIALIZATION))
#define MODES_RUNNING (MODE_BIT(MODE_STEP) | MODE_BIT(MODE_EVENT) | MODE_BIT(MODE_CONTINUOUS))
#define MODES_READABLE                                                                             \
    (MODE_BIT(MODE_INITIALIZATION) | MODES_RUNNING | MODE_BIT(MODE_TERMINATED) |                   \
     MODE_BIT(MODE_ERROR))
#define MODES_ANY (MODE_BIT(MODE_INSTANTIATED) | MODES_READABLE)
#define MODES_EXCHANGE (MODE_BIT(MODE_EVENT) | MODE_BIT(MODE_CONTINUOUS))
/* FMI 2.0 (3.2.3) and 3.0 let importers set discrete inputs in event mode only, yet OMSimulator
 * and the FMI Compliance Checker set Integer and Boolean inputs in continuous-time mode too. An
 * input is read by the next PLC call alone, at a time event, so such a set cannot change
 * anything before that call: the FMU takes it (core_set says so once in the log,
 * docs/behaviour.md §1.11). */
#define MODES_SETTABLE                                                                             \
    (MODES_BEFORE_INIT | MODE_BIT(MODE_STEP) | MODE_BIT(MODE_EVENT) | MODE_BIT(MODE_CONTINUOUS))

/* The interface an instance was made for, and the interfaces a function belongs to. */
typedef enum { INTERFACE_ME, INTERFACE_CS } lgf_interface;
#define FOR(interface_) (1u << (interface_))
#define FOR_ME FOR(INTERFACE_ME)
#define FOR_CS FOR(INTERFACE_CS)
#define FOR_BOTH (FOR_ME | FOR_CS)

/* What an entry point does, for the mode machine: the functions of one kind may be called in
 * the same modes of the same interfaces, whichever FMI version names them (FMI 2.0, 4.2.4 and
 * 3.2.3; FMI 3.0, 4.2 and 3.2), so core/modes.c holds the one table of both, and each entry
 * point names itself and its kind. */
typedef enum {
    CALL_SETUP, /* fmi2SetupExperiment, fmi2/fmi3EnterInitializationMode */
    CALL_EXIT_INITIALIZATION,
    CALL_TERMINATE,
    CALL_SET,      /* fmi2Set*, fmi3Set* of the types with variables */
    CALL_GET,      /* fmi2Get*, fmi3Get* of the types with variables */
    CALL_ANY_MODE, /* FMU states, fmi3Get/Set* of the types without variables */
    CALL_DO_STEP,
    CALL_STATUS,           /* fmi2Get*Status */
    CALL_EXCHANGE,         /* EnterEventMode, SetTime */
    CALL_EVENT,            /* the event update, EnterContinuousTimeMode */
    CALL_CONTINUOUS,       /* CompletedIntegratorStep, SetContinuousStates */
    CALL_EXCHANGE_GET,     /* derivatives, event indicators, continuous states */
    CALL_EXCHANGE_ANY_MODE /* nominals, fmi3GetNumberOf* */
} core_call;

/* The strictest alignment a block's data can need (C99 has no max_align_t). */
typedef union {
    long double ld;
    double d;
    int64_t i;
    void *p;
} lgf_aligned;

/* Everything an FMU state holds: the clock and the block's data (inputs, parameters, outputs,
 * statics). It is one allocation so that a state is one copy. */
typedef struct {
    int32_t mode;      /* fmu_mode */
    int32_t cycle_us;  /* cycleTime in whole µs */
    double start_time; /* t0 of the experiment */
    double time;       /* the current communication point */
    int64_t calls;     /* PLC calls executed; call k happens at t0 + k * cycle */
    double stop_time;  /* of the experiment, if stop_defined */
    bool stop_defined;
    lgf_aligned data[]; /* lgf_model.data_size bytes */
} fmu_image;

/* A serialized state: a header, then the payload, field by field (core/state.c). The clock comes
 * first: mode, cycle_us (4 bytes each), start_time, time, calls, stop_time (8 bytes each),
 * stop_defined (1 byte); then the block's variables and statics. */
enum {
    STATE_AT_MAGIC = 0,         /* 8 bytes: "LGF-FMU\0" */
    STATE_AT_VERSION = 8,       /* 4: the format version, little endian */
    STATE_AT_IDENTIFIER = 12,   /* STATE_IDENTIFIER_SIZE: modelIdentifier, NUL padded */
    STATE_AT_GUID = 44,         /* STATE_GUID_SIZE: the guid, NUL padded */
    STATE_AT_PAYLOAD_SIZE = 84, /* 4: the payload's size, little endian */
    STATE_AT_CHECKSUM = 88,     /* 8: FNV-1a 64 of the payload, little endian */
    STATE_AT_LAYOUT = 96,       /* 8: FNV-1a 64 of the names and types of the payload's fields */
    STATE_HEADER_SIZE = 104,    /* the payload follows */
    STATE_IDENTIFIER_SIZE = 32,
    STATE_GUID_SIZE = 40,
    STATE_CLOCK_SIZE = 41 /* the clock at the payload's start */
};

/* The log categories of modelDescription.xml, as bits of instance.categories. */
enum {
    LOG_ALL = 1u << 0,            /* logAll: a trace of what the FMU does */
    LOG_STATUS_WARNING = 1u << 1, /* logStatusWarning */
    LOG_STATUS_DISCARD = 1u << 2, /* logStatusDiscard */
    LOG_STATUS_ERROR = 1u << 3,   /* logStatusError */
    LOG_EVERY = (1u << 4) - 1
};

typedef struct instance instance;
typedef struct saved_state saved_state; /* an FMU state (core/state.c) */

/* What a front-end lends the core: its importer's logger and memory. */
typedef struct {
    void (*log)(const instance *inst, lgf_status status, const char *category, const char *text);
    void *(*allocate)(const instance *inst, size_t size); /* zeroed memory, or NULL */
    void (*release)(const instance *inst, void *memory);
    /* FMI 2.0's logger reads '#' as the start of a variable reference, "##" as '#' (2.1.5);
     * FMI 3.0 passes messages as they are. */
    bool escape_hash;
    /* The largest UDINT its integers carry: fmi2Integer is 32 bits signed, fmi3UInt32 not. A
     * restored state (the format is the same for both) must fit. */
    double udint_max;
} lgf_host;

struct instance {
    const lgf_host *host;
    lgf_interface interface;
    char *name;
    unsigned categories; /* switched on by loggingOn / fmi2SetDebugLogging, fmi3SetDebugLogging */
    size_t image_size;
    fmu_image *image;
    fmu_image *scratch; /* where a restored state is checked, and old values are kept */
    /* value reference -> its row of lgf_model.variables, NULL: none (a pointer, not an index,
     * as every get and set looks up each value reference) */
    const model_variable **vr_variables;
    uint32_t vr_count;        /* entries of vr_variables */
    saved_state *states;      /* the FMU states this instance made and has not freed */
    bool told_continuous_set; /* the log said that a set in continuous-time mode waits */
    char *text;               /* the values of the last get of strings (core/strings.c) */
    size_t text_count;        /* how many it holds */
};

/* ---- instances (core/instance.c) and the log (core/log.c) ---- */

/* Allocates what inst needs beside itself; false (and nothing kept) when memory runs out. */
static bool core_create(instance *inst, const char *name, bool logging_on);
static void core_destroy(instance *inst);
/* The end of fmi2Instantiate and fmi3Instantiate*: the instance, `size` bytes whose first are
 * the probe's (the front-end's instance, its instance first), in the importer's memory; NULL,
 * with a log line, when `refusal` says why the call is refused or memory runs out. */
static void *core_instantiate(const instance *probe, size_t size, const char *function,
                              const char *refusal, bool logging_on);
/* fmi2FreeInstance, fmi3FreeInstance: all the instance holds, then the instance itself. */
static void core_free_instance(instance *inst);
static void core_image_reset(fmu_image *image);
static void *core_allocate(const instance *inst, size_t size);
static void core_release(const instance *inst, void *memory);

/* One sentence to the importer's logger, under the category of its status. Errors, discards
 * and warnings are always logged (they are what the user must see); a STATUS_OK message is
 * the logAll trace, logged when that category is on. The text is never a format; for FMI 2.0
 * every '#' is doubled (see lgf_host). */
static void core_log(const instance *inst, lgf_status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static bool core_trace_on(const instance *inst) { return (inst->categories & LOG_ALL) != 0; }

/* ---- the mode machine (core/modes.c) ---- */

/* Whether the instance is in one of `modes` (MODE_BIT()s); else a log line saying that
 * `function` must not be called in its mode. */
static bool core_mode_allows(const instance *inst, const char *function, unsigned modes);

/* inst, unless it is NULL, or `function` (of kind `call`) belongs to the other interface or may
 * not be called in the instance's mode: then NULL, with a log line naming the function. */
static instance *core_allowed(instance *inst, const char *function, core_call call);
/* A function whose only effect is to put the instance into `mode`, if its kind allows. */
static lgf_status core_enter_mode(instance *inst, const char *function, core_call call,
                                  fmu_mode mode);
/* The modes an instance of inst's interface can be in, for restored states. */
static unsigned core_modes_of(const instance *inst);
static lgf_status core_exit_initialization(instance *inst, const char *function);
static bool core_given(const instance *inst, const char *function, bool given, const char *rule);
/* The event update; *next the time of the next call. */
static lgf_status core_update_discrete_states(instance *inst, const char *function, double *next);
static lgf_status core_unsupported(instance *inst, const char *function, const char *why);

/* The category bit of a category name, 0 if there is no such category. */
static unsigned core_category_bit(const char *name);

/* fmi2SetDebugLogging / fmi3SetDebugLogging. */
static lgf_status core_set_debug_logging(instance *inst, const char *function, bool on, size_t n,
                                         const char *const categories[]);

/* An array of continuous states or event indicators: the FMU has none, so n must be 0 (`what`
 * names it), if `function`, of kind `call`, may be called. */
static lgf_status core_none(instance *inst, const char *function, core_call call, size_t n,
                            const char *what);

/* ---- the PLC call clock (core/clock.c) ---- */

static lgf_status core_setup(instance *inst, const char *function, double start_time,
                             bool stop_defined, double stop_time);
/* What the first call computes from the inputs set so far, in inst->scratch, without
 * committing anything: the outputs a get in Initialization Mode returns. */
static const fmu_image *core_preview_first_call(instance *inst);
/* The first call, at t0. */
static lgf_status core_first_call(instance *inst, const char *function);
/* Every call in (t, t + h]. */
static lgf_status core_do_step(instance *inst, const char *function, double t, double h);

/* Model Exchange (docs/behaviour.md §1.11): the importer's time, which may not go back before
 * the last call; the calls due at it, executed at its time event; the time of the next call. */
static lgf_status core_set_time(instance *inst, const char *function, double t);
static lgf_status core_calls_due(instance *inst, const char *function);
static double core_next_call_time(const fmu_image *image);

/* Whether the clock of an image read from outside is one this FMU can have reached. */
static bool core_clock_is_valid(const fmu_image *image);

/* ---- values (core/values.c) ---- */

/* How a front-end names its types: the type class of each var_type (e.g. for LREAL fmi2Real in
 * FMI 2.0, fmi3Float64 in FMI 3.0) and the names of those classes for messages. */
typedef struct {
    uint8_t kind_of[VAR_BOOL + 1];
    const char *const *kind_names;
} fmi_types;

/* The C type of the values an importer passes: FMI 2.0 passes fmi2Real, fmi2Integer and
 * fmi2Boolean (an int); FMI 3.0 the native widths. */
typedef enum {
    CARRIER_DOUBLE,
    CARRIER_INT32,
    CARRIER_INT_BOOL,
    CARRIER_INT16,
    CARRIER_UINT16,
    CARRIER_BOOL,
    CARRIER_FLOAT,
    CARRIER_UINT32,
    CARRIER_INT8,
    CARRIER_UINT8
} carrier;

static lgf_status core_set(instance *inst, const char *function, const fmi_types *types, int kind,
                           carrier c, const uint32_t vr[], size_t nvr, const void *values);
static lgf_status core_get(instance *inst, const char *function, const fmi_types *types, int kind,
                           carrier c, const uint32_t vr[], size_t nvr, void *values);

/* The String variables (core/strings.c): UTF-8, a set refused beyond the maximum length. */
static lgf_status core_set_strings(instance *inst, const char *function, const fmi_types *types,
                                   int kind, const uint32_t vr[], size_t nvr,
                                   const char *const values[]);
static lgf_status core_get_strings(instance *inst, const char *function, const fmi_types *types,
                                   int kind, const uint32_t vr[], size_t nvr, const char *values[]);
static bool core_string_is_valid(const model_variable *v, const core_string *s);

/* Whether an image read from outside (a deserialized state) is one this FMU can run. */
static bool core_image_is_valid(const instance *inst, const fmu_image *image, const char *function);

/* ---- FMU states (core/state.c) ---- */

/* Unlinks one of inst->states and releases it (also for the states left at core_destroy). */
static void core_drop_state(instance *inst, saved_state *state);

static lgf_status core_get_state(instance *inst, const char *function, void **state);
/* A state is only restored into an instance that can be in its mode (`modes`, bits MODE_BIT()):
 * a co-simulation state does not fit a Model Exchange instance. */
static lgf_status core_set_state(instance *inst, const char *function, void *state, unsigned modes);
static lgf_status core_free_state(instance *inst, const char *function, void **state);
static lgf_status core_state_size(instance *inst, const char *function, void *state, size_t *size);
static lgf_status core_serialize(instance *inst, const char *function, void *state,
                                 unsigned char *bytes, size_t size);
static lgf_status core_deserialize(instance *inst, const char *function, const unsigned char *bytes,
                                   size_t size, void **state, unsigned modes);

#endif
