/* The log: one sentence per message, under the categories of modelDescription.xml
 * (docs/behaviour.md §1.8). */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "core/core.h"

static const char *const core_category_names[] = {"logAll", "logStatusWarning", "logStatusDiscard",
                                                  "logStatusError"};

static unsigned core_category_bit(const char *name)
{
    for (unsigned i = 0; name && i < sizeof core_category_names / sizeof core_category_names[0];
         i++)
        if (!strcmp(name, core_category_names[i])) return 1u << i;
    return 0;
}

static void core_log(const instance *inst, lgf_status status, const char *fmt, ...)
{
    unsigned category = status == STATUS_OK        ? 0
                        : status == STATUS_WARNING ? 1
                        : status == STATUS_DISCARD ? 2
                                                   : 3;
    if (category == 0 && !core_trace_on(inst)) return;
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
    inst->host->log(inst, status, core_category_names[category], escaped);
}

/* Without categories, on switches every category; with categories, on = true logs only those,
 * false switches those off (FMI 2.0, 2.1.5; FMI 3.0 alike). Warnings, discards and errors are
 * logged whatever the switches say, as the standards allow: only the logAll trace is optional. */
static lgf_status core_set_debug_logging(instance *inst, const char *function, bool on, size_t n,
                                         const char *const categories[])
{
    if (n > 0 && !categories) {
        core_log(inst, STATUS_ERROR, "%s: categories is NULL but nCategories is %llu.", function,
                 (unsigned long long)n);
        return STATUS_ERROR;
    }
    unsigned listed = n ? 0 : LOG_EVERY;
    for (size_t i = 0; i < n; i++) {
        unsigned bit = core_category_bit(categories[i]);
        if (!bit) {
            core_log(inst, STATUS_ERROR,
                     "%s: unknown log category \"%s\"; allowed are logAll, logStatusWarning, "
                     "logStatusDiscard and logStatusError.",
                     function, categories[i] ? categories[i] : "(null)");
            return STATUS_ERROR;
        }
        listed |= bit;
    }
    if (on)
        inst->categories = listed;
    else
        inst->categories &= ~listed;
    return STATUS_OK;
}
