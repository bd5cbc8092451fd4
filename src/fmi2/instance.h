/* The instance of an FMU, private to the FMI layer. Everything here is static: the layer is
 * compiled into the one translation unit of its FMU (fmi2/fmu.c, see fmi2/model.h). */
#ifndef LGF_INSTANCE_H
#define LGF_INSTANCE_H

#include <stddef.h>

#include "fmi2Functions.h"
#include "fmi2/model.h"

typedef enum { MODE_INSTANTIATED, MODE_INITIALIZATION, MODE_STEP, MODE_TERMINATED } fmu_mode;

/* Everything an FMU state holds: the clock and the block's data (inputs, parameters, outputs,
 * statics). It is one allocation so that a state is one copy. */
typedef struct {
    int32_t mode;      /* fmu_mode */
    int32_t cycle_us;  /* cycleTime in whole µs */
    double start_time; /* t0 of fmi2SetupExperiment */
    double time;       /* the current communication point */
    int64_t calls;     /* PLC calls executed; call k happens at t0 + k * cycle */
    double stop_time;  /* of fmi2SetupExperiment, if stop_defined */
    bool stop_defined;
    max_align_t data[]; /* lgf_model.data_size bytes */
} fmu_image;

/* A serialized state: a header, then the payload, field by field (fmu_state.c). The clock comes
 * first: mode, cycle_us (4 bytes each), start_time, time, calls, stop_time (8 bytes each),
 * stop_defined (1 byte); then the block's variables and statics. */
#define STATE_HEADER_SIZE 104u
#define STATE_CLOCK_SIZE 41u

/* The log categories of modelDescription.xml, as bits of instance.categories. */
enum {
    LOG_ALL = 1u << 0,            /* logAll: a trace of what the FMU does */
    LOG_STATUS_WARNING = 1u << 1, /* logStatusWarning */
    LOG_STATUS_DISCARD = 1u << 2, /* logStatusDiscard */
    LOG_STATUS_ERROR = 1u << 3,   /* logStatusError */
    LOG_EVERY = (1u << 4) - 1
};

typedef struct {
    fmi2CallbackFunctions callbacks;
    char *name;
    unsigned categories; /* switched on by loggingOn / fmi2SetDebugLogging */
    size_t image_size;
    fmu_image *image;
    fmu_image *scratch; /* where a restored state is checked, and old values are kept */
    uint16_t *vr_index; /* value reference -> 1 + index into lgf_model.variables, 0: none */
    uint32_t vr_count;  /* entries of vr_index */
} instance;

/* One sentence to the importer's logger, under the category of its status. Errors, discards
 * and warnings are always logged (they are what the user must see); an fmi2OK message is the
 * logAll trace, logged when that category is on. The text is passed
 * through "%s", never as a format, with every '#' doubled: for the logger '#' starts a
 * variable reference and "##" is a literal '#' (FMI 2.0, 2.1.5). */
static void log_message(const instance *inst, fmi2Status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

static bool trace_on(const instance *inst) { return (inst->categories & LOG_ALL) != 0; }

static void *allocate(const instance *inst, size_t size);
static void release(const instance *inst, void *memory);

static size_t image_size(void);
static void image_reset(fmu_image *image);

/* Whether the clock of an image read from outside is one this FMU can have reached: a mode,
 * and a call counter that fits the mode and stays within what fmi2DoStep can count. */
static bool clock_is_valid(const fmu_image *image);

/* Whether an image read from outside (a deserialized state) is one this FMU can run. */
static bool image_is_valid(const instance *inst, const fmu_image *image, const char *function);

/* The value references of the block, indexed once per instance so that a get or set finds its
 * variable without a search. */
static bool index_variables(instance *inst);

#endif
