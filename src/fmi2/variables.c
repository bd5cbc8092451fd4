/* fmi2Get and fmi2Set for every block, driven by the block's variable table: type rules of
 * BLOCKS.md 1.2, and the validation of 1.4 (a rejected set changes nothing). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "fmi2/instance.h"

typedef enum { FMI_REAL, FMI_INTEGER, FMI_BOOLEAN } fmi_kind;

static const char *const kind_names[] = {"Real", "Integer", "Boolean"};

static fmi_kind kind_of(var_type type)
{
    switch (type) {
    case VAR_INT:
    case VAR_WORD: return FMI_INTEGER;
    case VAR_BOOL: return FMI_BOOLEAN;
    default: return FMI_REAL;
    }
}

/* A variable, or one element of an array variable. */
typedef struct {
    const model_variable *var;
    uint32_t index;
    char name[64];
} element;

static element element_of(const model_variable *v, uint32_t index)
{
    element e = {.var = v, .index = index};
    if (v->member)
        snprintf(e.name, sizeof e.name, "%s[%u]%s", v->name, (unsigned)index, v->member);
    else
        snprintf(e.name, sizeof e.name, "%s", v->name);
    return e;
}

static bool find(fmi2ValueReference vr, element *e)
{
    for (size_t i = 0; i < lgf_model.variable_count; i++) {
        const model_variable *v = &lgf_model.variables[i];
        if (vr >= v->vr && vr - v->vr < v->count) {
            *e = element_of(v, vr - v->vr);
            return true;
        }
    }
    return false;
}

static void *field(const fmu_image *image, const element *e)
{
    return (unsigned char *)image->data + e->var->offset + e->index * e->var->stride;
}

/* Looks up vr for an fmi2Get/fmi2Set of the given kind; logs and fails when there is no such
 * variable or it has another type. */
static bool resolve(const instance *inst, const char *function, fmi2ValueReference vr,
                    fmi_kind kind, element *e)
{
    if (!find(vr, e)) {
        log_message(inst, fmi2Error, "%s: unknown value reference %u in %s.", function,
                    (unsigned)vr, lgf_model.identifier);
        return false;
    }
    if (kind_of(e->var->type) != kind) {
        log_message(inst, fmi2Error, "%s: %s (value reference %u) is an fmi2%s variable.",
                    function, e->name, (unsigned)vr, kind_names[kind_of(e->var->type)]);
        return false;
    }
    return true;
}

static double read_number(const fmu_image *image, const element *e)
{
    const void *p = field(image, e);
    switch (e->var->type) {
    case VAR_CYCLE: return image->cycle_us / 1e6;
    case VAR_LREAL: return *(const double *)p;
    case VAR_TIME: return *(const iec_time *)p / 1000.0;
    case VAR_INT: return *(const iec_int *)p;
    case VAR_WORD: return *(const iec_word *)p;
    case VAR_BOOL: return *(const bool *)p;
    }
    return 0;
}

/* Range text for messages, in the variable's own units. */
static void describe_range(const model_variable *v, char *text, size_t size)
{
    if (kind_of(v->type) == FMI_INTEGER)
        snprintf(text, size, "%.0f to %.0f", v->min, v->max);
    else if (isinf(v->min) && isinf(v->max))
        snprintf(text, size, "any number but NaN");
    else
        snprintf(text, size, "%.10g to %.10g%s", v->min, v->max,
                 v->type == VAR_LREAL ? "" : " s");
}

/* Whether value may be stored in e; else one sentence into why. */
static bool acceptable(const element *e, double value, char *why, size_t size)
{
    char range[96];
    describe_range(e->var, range, sizeof range);
    if (isnan(value) || value < e->var->min || value > e->var->max) {
        snprintf(why, size, "%s = %.17g is outside the allowed range (%s)", e->name, value, range);
        return false;
    }
    return true;
}

/* Stores a checked value. Returns a warning (or NULL) for values the PLC would round. */
static const char *store(const instance *inst, fmu_image *image, const element *e, double value,
                         char *note, size_t size)
{
    void *p = field(image, e);
    switch (e->var->type) {
    case VAR_CYCLE: {
        double us = value * 1e6;
        int32_t rounded = (int32_t)llround(us);
        bool off_us = fabs(us - rounded) > 1e-6 * fmax(1.0, us);
        bool off_grain = rounded % lgf_model.cycle_granularity_us != 0;
        image->cycle_us = rounded;
        if (!off_us && !off_grain) return NULL;
        int length = snprintf(note, size, "%s = %.17g s", e->name, value);
        if (off_us && length >= 0 && (size_t)length < size)
            length += snprintf(note + length, size - (size_t)length,
                               " is rounded to %d µs", (int)rounded);
        if (off_grain && length >= 0 && (size_t)length < size)
            snprintf(note + length, size - (size_t)length,
                     "%s; like the PLC, %s runs on the truncated period of %d ms", off_us ? "" : " is not a whole number of ms",
                     lgf_model.identifier, (int)(rounded / lgf_model.cycle_granularity_us));
        return note;
    }
    case VAR_LREAL: *(double *)p = value; break;
    case VAR_TIME: *(iec_time *)p = (iec_time)llround(value * 1000.0); break;
    case VAR_INT: *(iec_int *)p = (iec_int)value; break;
    case VAR_WORD: *(iec_word *)p = (iec_word)value; break;
    case VAR_BOOL: *(bool *)p = value != 0; break;
    }
    (void)inst;
    return NULL;
}

static const char *const set_names[] = {"fmi2SetReal", "fmi2SetInteger", "fmi2SetBoolean"};

/* All values are tried on a copy of the image, which replaces the image only when every one of
 * them and the block's own rules pass: a rejected call leaves the instance as it was. */
static fmi2Status set_values(instance *inst, fmi_kind kind, const fmi2ValueReference vr[],
                             size_t nvr, const void *values)
{
    const char *function = set_names[kind];
    if (!inst) return fmi2Error;
    if (!mode_allows(inst, function,
                     IN(MODE_INSTANTIATED) | IN(MODE_INITIALIZATION) | IN(MODE_STEP)))
        return fmi2Error;
    if (nvr > 0 && (!vr || !values)) {
        log_message(inst, fmi2Error, "%s: vr or value is NULL with nvr = %llu.", function,
                    (unsigned long long)nvr);
        return fmi2Error;
    }
    fmu_image *candidate = inst->scratch;
    memcpy(candidate, inst->image, inst->image_size);
    bool initialized = inst->image->mode >= MODE_STEP;
    char warnings[2][256];
    int warning_count = 0;
    for (size_t i = 0; i < nvr; i++) {
        element e;
        if (!resolve(inst, function, vr[i], kind, &e)) return fmi2Error;
        if (e.var->role == ROLE_OUTPUT) {
            log_message(inst, fmi2Error, "%s: %s is an output and cannot be set.", function,
                        e.name);
            return fmi2Error;
        }
        if (e.var->role == ROLE_FIXED_PARAMETER && initialized) {
            log_message(inst, fmi2Error,
                        "%s: %s is a fixed parameter and can only be set before "
                        "fmi2ExitInitializationMode.",
                        function, e.name);
            return fmi2Error;
        }
        double value = kind == FMI_REAL      ? ((const fmi2Real *)values)[i]
                       : kind == FMI_INTEGER ? ((const fmi2Integer *)values)[i]
                                             : ((const fmi2Boolean *)values)[i] != fmi2False;
        char why[256];
        if (!acceptable(&e, value, why, sizeof why)) {
            log_message(inst, fmi2Error, "%s: %s; the value was not applied.", function, why);
            return fmi2Error;
        }
        const char *warning = store(inst, candidate, &e, value, warnings[warning_count % 2],
                                    sizeof warnings[0]);
        if (warning) warning_count++;
    }
    char why[256];
    if (lgf_model.check && lgf_model.check(candidate->data, why, sizeof why)) {
        log_message(inst, fmi2Error, "%s: %s; the values were not applied.", function, why);
        return fmi2Error;
    }
    inst->scratch = inst->image;
    inst->image = candidate;
    for (int w = 0; w < warning_count && w < 2; w++)
        log_message(inst, fmi2Warning, "%s: %s.", function, warnings[w]);
    return warning_count ? fmi2Warning : fmi2OK;
}

static const char *const get_names[] = {"fmi2GetReal", "fmi2GetInteger", "fmi2GetBoolean"};

static fmi2Status get_values(instance *inst, fmi_kind kind, const fmi2ValueReference vr[],
                             size_t nvr, void *values)
{
    const char *function = get_names[kind];
    if (!inst) return fmi2Error;
    if (!mode_allows(inst, function,
                     IN(MODE_INITIALIZATION) | IN(MODE_STEP) | IN(MODE_TERMINATED)))
        return fmi2Error;
    if (nvr > 0 && (!vr || !values)) {
        log_message(inst, fmi2Error, "%s: vr or value is NULL with nvr = %llu.", function,
                    (unsigned long long)nvr);
        return fmi2Error;
    }
    for (size_t i = 0; i < nvr; i++) {
        element e;
        if (!resolve(inst, function, vr[i], kind, &e)) return fmi2Error;
        double value = read_number(inst->image, &e);
        if (kind == FMI_REAL) ((fmi2Real *)values)[i] = value;
        else if (kind == FMI_INTEGER) ((fmi2Integer *)values)[i] = (fmi2Integer)value;
        else ((fmi2Boolean *)values)[i] = value != 0 ? fmi2True : fmi2False;
    }
    return fmi2OK;
}

bool image_is_valid(const instance *inst, const fmu_image *image, const char *function)
{
    if (!clock_is_valid(image)) {
        log_message(inst, fmi2Error, "%s: the state's clock is corrupt.", function);
        return false;
    }
    for (size_t i = 0; i < lgf_model.variable_count; i++) {
        const model_variable *v = &lgf_model.variables[i];
        for (uint32_t k = 0; k < v->count; k++) {
            element e = element_of(v, k);
            if (v->type == VAR_BOOL && !iec_bool_is_valid(field(image, &e))) {
                log_message(inst, fmi2Error, "%s: the state holds no valid Boolean for %s.",
                            function, e.name);
                return false;
            }
            char why[256];
            if (v->role != ROLE_OUTPUT && !acceptable(&e, read_number(image, &e), why, sizeof why)) {
                log_message(inst, fmi2Error, "%s: the state is invalid: %s.", function, why);
                return false;
            }
        }
    }
    char why[256];
    if (lgf_model.check && lgf_model.check(image->data, why, sizeof why)) {
        log_message(inst, fmi2Error, "%s: the state is invalid: %s.", function, why);
        return false;
    }
    return true;
}

fmi2Status fmi2SetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       const fmi2Real value[])
{
    return set_values(c, FMI_REAL, vr, nvr, value);
}

fmi2Status fmi2SetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Integer value[])
{
    return set_values(c, FMI_INTEGER, vr, nvr, value);
}

fmi2Status fmi2SetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          const fmi2Boolean value[])
{
    return set_values(c, FMI_BOOLEAN, vr, nvr, value);
}

fmi2Status fmi2GetReal(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                       fmi2Real value[])
{
    return get_values(c, FMI_REAL, vr, nvr, value);
}

fmi2Status fmi2GetInteger(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Integer value[])
{
    return get_values(c, FMI_INTEGER, vr, nvr, value);
}

fmi2Status fmi2GetBoolean(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                          fmi2Boolean value[])
{
    return get_values(c, FMI_BOOLEAN, vr, nvr, value);
}

/* This FMU has no String variables: any value reference is unknown. */
fmi2Status fmi2SetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         const fmi2String value[])
{
    instance *inst = c;
    (void)value;
    if (!inst || !mode_allows(inst, "fmi2SetString",
                              IN(MODE_INSTANTIATED) | IN(MODE_INITIALIZATION) | IN(MODE_STEP)))
        return fmi2Error;
    if (nvr == 0) return fmi2OK;
    log_message(inst, fmi2Error, "fmi2SetString: %s has no String variables (value reference %u).",
                lgf_model.identifier, vr ? (unsigned)vr[0] : 0u);
    return fmi2Error;
}

fmi2Status fmi2GetString(fmi2Component c, const fmi2ValueReference vr[], size_t nvr,
                         fmi2String value[])
{
    instance *inst = c;
    (void)value;
    if (!inst || !mode_allows(inst, "fmi2GetString",
                              IN(MODE_INITIALIZATION) | IN(MODE_STEP) | IN(MODE_TERMINATED)))
        return fmi2Error;
    if (nvr == 0) return fmi2OK;
    log_message(inst, fmi2Error, "fmi2GetString: %s has no String variables (value reference %u).",
                lgf_model.identifier, vr ? (unsigned)vr[0] : 0u);
    return fmi2Error;
}
