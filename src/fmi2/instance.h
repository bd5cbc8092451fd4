/* The instance of an FMU, private to the FMI layer. */
#ifndef LGF_INSTANCE_H
#define LGF_INSTANCE_H

#include <stddef.h>

#include "fmi2Functions.h"
#include "fmi2/model.h"

typedef enum { MODE_INSTANTIATED, MODE_INITIALIZATION, MODE_STEP, MODE_TERMINATED } fmu_mode;

/* Everything an FMU state holds: the clock and the block's data (inputs, parameters, outputs,
 * statics). It is one allocation so that a state is one memcpy. */
typedef struct {
    int32_t mode;      /* fmu_mode */
    int32_t cycle_us;  /* cycleTime in whole µs */
    double start_time; /* t0 of fmi2SetupExperiment */
    double time;       /* the current communication point */
    int64_t calls;     /* PLC calls executed; call k happens at t0 + k * cycle */
    max_align_t data[]; /* lgf_model.data_size bytes */
} fmu_image;

typedef struct {
    fmi2CallbackFunctions callbacks;
    char *name;
    bool debug_logging;
    size_t image_size;
    fmu_image *image;
    fmu_image *scratch; /* where a set is tried before it is committed */
} instance;

/* One sentence to the importer's logger. Errors and warnings are always logged: they are
 * what the user must see. The message is passed through "%s", never as a format. */
void log_message(const instance *inst, fmi2Status status, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 3, 4)))
#endif
    ;

/* fmi2Error plus a log line naming the function, unless the instance is in one of the
 * modes of the mask. */
#define IN(mode) (1u << (mode))
bool mode_allows(const instance *inst, const char *function, unsigned mask);

void *allocate(const instance *inst, size_t size);
void release(const instance *inst, void *memory);

size_t image_size(void);
void image_reset(fmu_image *image);

/* Whether the clock of an image read from outside is one this FMU can have reached: a mode,
 * and a call counter that fits the mode and stays within what fmi2DoStep can count. */
bool clock_is_valid(const fmu_image *image);

/* Whether an image read from outside (a deserialized state) is one this FMU can run. */
bool image_is_valid(const instance *inst, const fmu_image *image, const char *function);

#endif
