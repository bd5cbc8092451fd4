/* What the C harness needs to drive an FMU the way an importer does: the library opened with
 * dlopen and every fmi2 function of both interfaces looked up with dlsym (the fmi3 functions:
 * fmi3.h), the callbacks (loggers that record what they are told, an allocator that counts and
 * can be made to fail) and the variables of the FMU's modelDescription.xml, FMI 2.0 or 3.0,
 * read with a small ad-hoc scanner. */
#ifndef LGF_HARNESS_IMPORTER_H
#define LGF_HARNESS_IMPORTER_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#include "fmi2FunctionTypes.h"

/* Every function of an FMI 2.0 co-simulation FMU (FMI 2.0.x, 2.1.2 and 4.2). */
/* One X() per function, in the order of the standard; laid out by hand. */
/* clang-format off */
#define FMI2_CS_FUNCTIONS(X)    \
    X(GetTypesPlatform)         \
    X(GetVersion)               \
    X(SetDebugLogging)          \
    X(Instantiate)              \
    X(FreeInstance)             \
    X(SetupExperiment)          \
    X(EnterInitializationMode)  \
    X(ExitInitializationMode)   \
    X(Terminate)                \
    X(Reset)                    \
    X(GetReal)                  \
    X(GetInteger)               \
    X(GetBoolean)               \
    X(GetString)                \
    X(SetReal)                  \
    X(SetInteger)               \
    X(SetBoolean)               \
    X(SetString)                \
    X(GetFMUstate)              \
    X(SetFMUstate)              \
    X(FreeFMUstate)             \
    X(SerializedFMUstateSize)   \
    X(SerializeFMUstate)        \
    X(DeSerializeFMUstate)      \
    X(GetDirectionalDerivative) \
    X(SetRealInputDerivatives)  \
    X(GetRealOutputDerivatives) \
    X(DoStep)                   \
    X(CancelStep)               \
    X(GetStatus)                \
    X(GetRealStatus)            \
    X(GetIntegerStatus)         \
    X(GetBooleanStatus)         \
    X(GetStringStatus)
/* clang-format on */

/* The functions only Model Exchange has (FMI 2.0, 3.2.1). */
/* One X() per function, in the order of the standard; laid out by hand. */
/* clang-format off */
#define FMI2_ME_FUNCTIONS(X)         \
    X(EnterEventMode)                \
    X(NewDiscreteStates)             \
    X(EnterContinuousTimeMode)       \
    X(CompletedIntegratorStep)       \
    X(SetTime)                       \
    X(SetContinuousStates)           \
    X(GetDerivatives)                \
    X(GetEventIndicators)            \
    X(GetContinuousStates)           \
    X(GetNominalsOfContinuousStates)
/* clang-format on */

typedef struct {
    void *handle;
#define FMI2_DECLARE_POINTER(name) fmi2##name##TYPE *name;
    FMI2_CS_FUNCTIONS(FMI2_DECLARE_POINTER)
    FMI2_ME_FUNCTIONS(FMI2_DECLARE_POINTER)
#undef FMI2_DECLARE_POINTER
} fmi2_api;

/* Opens the library and looks up every function; on failure writes why into error. */
bool api_load(fmi2_api *api, const char *library, char *error, size_t size);
void api_unload(fmi2_api *api);

/* ---- the variables of modelDescription.xml ---- */

/* The class of a variable's values, the same in both versions (FMI 2.0's types are these). */
typedef enum { KIND_REAL, KIND_INTEGER, KIND_BOOLEAN, KIND_STRING, KIND_OTHER } var_kind;
typedef enum { CAUS_PARAMETER, CAUS_INPUT, CAUS_OUTPUT, CAUS_OTHER } var_causality;

/* The variable types of FMI 3.0, in the order of fmi3_type_names. */
typedef enum {
    T3_FLOAT32,
    T3_FLOAT64,
    T3_INT8,
    T3_UINT8,
    T3_INT16,
    T3_UINT16,
    T3_INT32,
    T3_UINT32,
    T3_INT64,
    T3_UINT64,
    T3_BOOLEAN,
    T3_STRING,
    T3_BINARY,
    T3_CLOCK,
    T3_TYPES
} fmi3_type;

extern const char *const fmi3_type_names[T3_TYPES]; /* "Float32", ... as the XML elements */

typedef struct {
    char name[96];
    uint32_t vr;
    var_kind kind; /* the class */
    int type;      /* FMI 2.0: the var_kind; FMI 3.0: the fmi3_type */
    var_causality causality;
    bool fixed; /* variability="fixed" */
    bool
        is_time; /* an IEC TIME: a Real with unit "s" other than cycleTime (docs/behaviour.md §1.4) */
    bool single; /* FMI 3.0 Float32 (an IEC REAL) */
    bool is_cycle;
    bool has_min, has_max, has_start;
    double min, max, start;
} md_variable;

typedef struct {
    int version;             /* 2 or 3, from fmiVersion */
    char identifier[64];     /* CoSimulation modelIdentifier */
    char me_identifier[64];  /* ModelExchange modelIdentifier, empty if there is none */
    double event_indicators; /* FMI 2.0: numberOfEventIndicators, -1 if absent; FMI 3.0: the
                                <EventIndicator> elements */
    char guid[64];           /* FMI 3.0: instantiationToken */
    char fmi_version[16];
    md_variable *variables;
    size_t count;
} model_description;

/* Either version; the independent variable of FMI 3.0 (time) is left out. */
bool md_read(model_description *md, const char *path, char *error, size_t size);
void md_free(model_description *md);

/* ---- callbacks ---- */

#define LOG_KEEP 8 /* messages kept per environment; older ones are only counted */

typedef struct {
    fmi2Status status;
    char category[48];
    char instance[64];
    char text[640];
} log_entry;

/* One per instance (the componentEnvironment), so threads never share one. */
typedef struct {
    int total;
    log_entry kept[LOG_KEEP];
} log_record;

const log_entry *log_get(const log_record *log, int index); /* NULL when no longer kept */

void harness_logger(fmi2ComponentEnvironment env, fmi2String instance, fmi2Status status,
                    fmi2String category, fmi2String message, ...);
void *harness_allocate(size_t count, size_t size);
void harness_free(void *memory);

long live_allocations(void);          /* blocks allocated through the callbacks and not freed */
long total_log_messages(void);        /* over all environments, including NULL ones */
long malformed_log_messages(void);    /* with a '#' an FMI Library based importer cannot read */
long hash_log_messages(void);         /* FMI 3.0: messages holding a '#' */
long doubled_hash_log_messages(void); /* FMI 3.0: ... holding "##", an FMI 2.0 escape */
void fail_allocation_after(long n);   /* this thread: the n-th next allocation fails (0: never) */

fmi2CallbackFunctions harness_callbacks(log_record *log);

/* Records a message of FMI 3.0's logMessage (harness_logger3 in fmi3.c) into log (may be NULL):
 * there is no instance name, and the text is plain, so nothing is unescaped. */
void log_store3(log_record *log, int status, const char *category, const char *message);

#endif
