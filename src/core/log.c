/* Instances, their memory and their log (docs/behaviour.md §1.8). */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "core/core.h"

#define DEFAULT_CYCLE_US 100000 /* 100 ms, a default OB35 (docs/behaviour.md §1.1) */

static void *allocate(const instance *inst, size_t size) { return inst->host->allocate(inst, size); }

static void release(const instance *inst, void *memory)
{
    if (memory) inst->host->release(inst, memory);
}

static void image_reset(fmu_image *image)
{
    memset(image, 0, sizeof(fmu_image) + lgf_model.data_size);
    image->mode = MODE_INSTANTIATED;
    image->cycle_us = DEFAULT_CYCLE_US;
    lgf_model.init(image->data);
}

static bool index_variables(instance *inst);

static bool core_create(instance *inst, const char *name, bool logging_on)
{
    inst->categories = logging_on ? LOG_EVERY : 0;
    inst->image_size = sizeof(fmu_image) + lgf_model.data_size;
    inst->name = allocate(inst, strlen(name) + 1);
    inst->image = allocate(inst, inst->image_size);
    inst->scratch = allocate(inst, inst->image_size);
    if (!inst->name || !inst->image || !inst->scratch || !index_variables(inst)) {
        core_destroy(inst);
        return false;
    }
    strcpy(inst->name, name);
    image_reset(inst->image);
    return true;
}

static void core_destroy(instance *inst)
{
    while (inst->states) drop_state(inst, inst->states); /* states the importer did not free */
    release(inst, inst->image);
    release(inst, inst->scratch);
    release(inst, inst->vr_index);
    release(inst, inst->name);
    inst->image = inst->scratch = NULL;
    inst->vr_index = NULL;
    inst->name = NULL;
}

static const char *const category_names[] = {"logAll", "logStatusWarning", "logStatusDiscard",
                                             "logStatusError"};

static unsigned category_bit(const char *name)
{
    for (unsigned i = 0; name && i < sizeof category_names / sizeof category_names[0]; i++)
        if (!strcmp(name, category_names[i])) return 1u << i;
    return 0;
}

static void log_message(const instance *inst, lgf_status status, const char *fmt, ...)
{
    unsigned category = status == STATUS_OK        ? 0
                        : status == STATUS_WARNING ? 1
                        : status == STATUS_DISCARD ? 2
                                                   : 3;
    if (category == 0 && !trace_on(inst)) return;
    char text[512], escaped[2 * sizeof text];
    va_list args;
    va_start(args, fmt);
    vsnprintf(text, sizeof text, fmt, args);
    va_end(args);
    size_t n = 0;
    for (const char *c = text; *c; c++) {
        if (*c == '#' && inst->host->escape_hash) escaped[n++] = '#';
        escaped[n++] = *c;
    }
    escaped[n] = '\0';
    inst->host->log(inst, status, category_names[category], escaped);
}

/* Without categories, on switches every category; with categories, on = true logs only those,
 * false switches those off (FMI 2.0, 2.1.5; FMI 3.0 alike). Warnings, discards and errors are
 * logged whatever the switches say, as the standards allow: only the logAll trace is optional. */
static lgf_status core_set_debug_logging(instance *inst, const char *function, bool on, size_t n,
                                         const char *const categories[])
{
    if (n > 0 && !categories) {
        log_message(inst, STATUS_ERROR, "%s: categories is NULL but nCategories is %llu.",
                    function, (unsigned long long)n);
        return STATUS_ERROR;
    }
    unsigned listed = n ? 0 : LOG_EVERY;
    for (size_t i = 0; i < n; i++) {
        unsigned bit = category_bit(categories[i]);
        if (!bit) {
            log_message(inst, STATUS_ERROR,
                        "%s: unknown log category \"%s\"; allowed are logAll, logStatusWarning, "
                        "logStatusDiscard and logStatusError.",
                        function, categories[i] ? categories[i] : "(null)");
            return STATUS_ERROR;
        }
        listed |= bit;
    }
    if (on) inst->categories = listed;
    else inst->categories &= ~listed;
    return STATUS_OK;
}

/* The functions of continuous states and event indicators: the FMU has none of either, so they
 * take arrays of 0 elements (which may be NULL). */
static lgf_status core_none(instance *inst, const char *function, size_t n, const char *what)
{
    if (n == 0) return STATUS_OK;
    log_message(inst, STATUS_ERROR, "%s: %s is %llu, but %s has none (it must be 0).", function,
                what, (unsigned long long)n, lgf_model.identifier);
    return STATUS_ERROR;
}

static const char *const mode_names[] = {"instantiated", "initialization mode", "step mode",
                                         "event mode", "continuous-time mode", "terminated"};

static bool mode_allows(const instance *inst, const char *function, unsigned modes)
{
    if (modes & IN(inst->image->mode)) return true;
    log_message(inst, STATUS_ERROR, "%s must not be called in %s.", function,
                mode_names[inst->image->mode]);
    return false;
}
