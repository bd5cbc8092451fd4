/* Get and set for every block, driven by the block's interface table: the type rules of
 * docs/behaviour.md §1.4, and the validation of §1.7 (a rejected set changes nothing). Messages
 * are formatted only when one is written: the success path does no string work. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core/core.h"

static size_t core_size_of(var_type type)
{
    switch (type) {
    case VAR_LREAL: return sizeof(double);
    case VAR_INT: return sizeof(iec_int);
    case VAR_WORD: return sizeof(iec_word);
    case VAR_REAL: return sizeof(float);
    case VAR_UDINT:
    case VAR_DWORD: return sizeof(uint32_t);
    case VAR_UINT: return sizeof(uint16_t);
    case VAR_SINT: return sizeof(int8_t);
    case VAR_USINT:
    case VAR_BYTE: return sizeof(uint8_t);
    case VAR_BOOL: return sizeof(bool);
    case VAR_STRING:
    case VAR_WSTRING: return sizeof(core_string);
    default: return sizeof(int32_t); /* VAR_CYCLE (µs), VAR_TIME (ms) */
    }
}

/* A variable, or one element of an array variable. */
typedef struct {
    const model_variable *var;
    uint32_t index;
} core_element;

/* The FMI name of e, for messages. */
static const char *core_name_of(const core_element *e, char *text, size_t size)
{
    if (!e->var->member) return e->var->name;
    snprintf(text, size, "%s[%u]%s", e->var->name, (unsigned)e->index, e->var->member);
    return text;
}

#define CORE_MAX_VR 4096u /* the interface tables (interface.c) number their variables below this */

static bool core_index_variables(instance *inst)
{
    uint32_t count = 0;
    for (size_t i = 0; i < lgf_model.variable_count; i++) {
        const model_variable *v = &lgf_model.variables[i];
        if (v->vr + v->count > count) count = v->vr + v->count;
    }
    if (count > CORE_MAX_VR) return false;
    inst->vr_variables = core_allocate(inst, count * sizeof *inst->vr_variables);
    if (!inst->vr_variables) return false;
    for (uint32_t k = 0; k < count; k++) inst->vr_variables[k] = NULL;
    for (size_t i = 0; i < lgf_model.variable_count; i++) {
        const model_variable *v = &lgf_model.variables[i];
        for (uint32_t k = 0; k < v->count; k++) inst->vr_variables[v->vr + k] = v;
    }
    inst->vr_count = count;
    return true;
}

/* The variable of vr, NULL if there is none. */
static inline const model_variable *core_variable(const instance *inst, uint32_t vr)
{
    return vr < inst->vr_count ? inst->vr_variables[vr] : NULL;
}

static bool core_find(const instance *inst, uint32_t vr, core_element *e)
{
    e->var = core_variable(inst, vr);
    if (!e->var) return false;
    e->index = vr - e->var->vr;
    return true;
}

static void *core_field(const fmu_image *image, const core_element *e)
{
    if (e->var->type == VAR_CYCLE) return (void *)&image->cycle_us;
    return (unsigned char *)image->data + e->var->offset + e->index * e->var->stride;
}

/* Looks up vr for a get or set of the given kind; logs and fails when there is no such
 * variable or it has another type. */
static bool core_resolve(const instance *inst, const char *function, const fmi_types *types,
                         int kind, uint32_t vr, core_element *e)
{
    if (!core_find(inst, vr, e)) {
        core_log(inst, STATUS_ERROR, "%s: unknown value reference %u in %s.", function,
                 (unsigned)vr, lgf_model.identifier);
        return false;
    }
    if (types->kind_of[e->var->type] != kind) {
        char name[64];
        core_log(inst, STATUS_ERROR, "%s: %s (value reference %u) is an %s variable.", function,
                 core_name_of(e, name, sizeof name), (unsigned)vr,
                 types->kind_names[types->kind_of[e->var->type]]);
        return false;
    }
    return true;
}

static double core_read_number(const fmu_image *image, const core_element *e)
{
    const void *p = core_field(image, e);
    switch (e->var->type) {
    case VAR_CYCLE: return image->cycle_us / 1e6;
    case VAR_LREAL: return *(const double *)p;
    case VAR_TIME: return *(const iec_time *)p / 1000.0;
    case VAR_INT: return *(const iec_int *)p;
    case VAR_WORD: return *(const iec_word *)p;
    case VAR_REAL: return *(const float *)p;
    case VAR_UDINT:
    case VAR_DWORD: return *(const uint32_t *)p;
    case VAR_DINT: return *(const int32_t *)p;
    case VAR_UINT: return *(const uint16_t *)p;
    case VAR_SINT: return *(const int8_t *)p;
    case VAR_USINT:
    case VAR_BYTE: return *(const uint8_t *)p;
    case VAR_BOOL: return *(const bool *)p;
    case VAR_STRING:
    case VAR_WSTRING: break; /* no number: core/strings.c */
    }
    return 0;
}

#define CORE_REAL_LIMIT                                                                            \
    3.4028235e38 /* the REAL range as IEC 61131-3 writes it (docs/behaviour.md §1.4) */

/* NaN is never in range. A finite REAL must lie within the REAL range; ±Inf is a REAL, in range
 * where the table's limits are infinite (docs/behaviour.md §1.4). */
static bool core_in_range(const model_variable *v, double value)
{
    if (v->type == VAR_REAL && !isinf(value) && fabs(value) > CORE_REAL_LIMIT) return false;
    return value >= v->min && value <= v->max;
}

/* One sentence: "<name> = <value> is outside the allowed range (<range>)" and, for cycleTime,
 * the original's status codes it stands for (docs/behaviour.md §1.7). The range is the one the
 * host's modelDescription declares: a UDINT or DWORD stops at udint_max (FMI 2.0: 2147483647). */
static void core_describe_refusal(const core_element *e, double value, double udint_max, char *text,
                                  size_t size)
{
    const model_variable *v = e->var;
    char name[64], range[96];
    if (var_is_integer(v->type))
        snprintf(range, sizeof range, "%.0f to %.0f", v->min,
                 v->type == VAR_UDINT || v->type == VAR_DWORD ? fmin(v->max, udint_max) : v->max);
    else if (v->type == VAR_REAL && isinf(v->min) && isinf(v->max))
        snprintf(range, sizeof range, "a REAL: ±Inf or -3.4028235e38 to 3.4028235e38");
    else if (isinf(v->min) && isinf(v->max))
        snprintf(range, sizeof range, "any number but NaN");
    else
        snprintf(range, sizeof range, "%.10g to %.10g%s", v->min, v->max,
                 v->type == VAR_LREAL ? "" : " s");
    int n = snprintf(text, size, "%s = %.17g is outside the allowed range (%s)",
                     core_name_of(e, name, sizeof name), value, range);
    if (v->type == VAR_CYCLE && lgf_model.cycle_codes && n >= 0 && (size_t)n < size)
        snprintf(text + n, size - (size_t)n,
                 "; it is the period of the calling OB, and an invalid period is what the "
                 "original reports as %s, codes this FMU never outputs",
                 lgf_model.cycle_codes);
}

/* cycleTime in whole µs; whether that is another period than the one given, or the block
 * truncates it (to whole ms, LGF_RampCI and the signal generators). */
static bool core_store_cycle(fmu_image *image, double value)
{
    int32_t us = (int32_t)llround(value * 1e6);
    image->cycle_us = us;
    return us / 1e6 != value || us % lgf_model.cycle_granularity_us != 0;
}

/* Stores a checked value; returns whether the PLC runs on another value than the one given (a
 * cycleTime rounded to whole µs, or truncated to whole ms by LGF_RampCI, docs/behaviour.md §1.1,
 * §4.2). Inline, the cycle's rounding apart: what is left for a value is its store. */
static inline bool core_store(fmu_image *image, const core_element *e, double value)
{
    void *p = core_field(image, e);
    switch (e->var->type) {
    case VAR_CYCLE: return core_store_cycle(image, value);
    case VAR_LREAL: *(double *)p = value; break;
    case VAR_TIME: *(iec_time *)p = (iec_time)llround(value * 1000.0); break; /* halves away */
    case VAR_INT: *(iec_int *)p = (iec_int)value; break;
    case VAR_WORD: *(iec_word *)p = (iec_word)value; break;
    case VAR_REAL: *(float *)p = (float)value; break; /* the nearest float32, ties to even */
    case VAR_UDINT:
    case VAR_DWORD: *(uint32_t *)p = (uint32_t)value; break;
    case VAR_DINT: *(int32_t *)p = (int32_t)value; break;
    case VAR_UINT: *(uint16_t *)p = (uint16_t)value; break;
    case VAR_SINT: *(int8_t *)p = (int8_t)value; break;
    case VAR_USINT:
    case VAR_BYTE: *(uint8_t *)p = (uint8_t)value; break;
    case VAR_BOOL: *(bool *)p = value != 0; break;
    case VAR_STRING:
    case VAR_WSTRING: break; /* no number: core/strings.c */
    }
    return false;
}

static void core_warn_cycle(const instance *inst, const char *function, double value)
{
    int32_t us = inst->image->cycle_us, grain = lgf_model.cycle_granularity_us;
    if (us % grain == 0)
        core_log(inst, STATUS_WARNING,
                 "%s: cycleTime = %.17g s is not a whole number of µs; "
                 "the block runs on %d µs.",
                 function, value, (int)us);
    else
        core_log(inst, STATUS_WARNING,
                 "%s: cycleTime = %.17g s is not a whole number of ms; "
                 "like the PLC, %s runs on the truncated period of %d ms.",
                 function, value, lgf_model.identifier, (int)(us / grain));
}

static double core_value_at(carrier c, const void *values, size_t i)
{
    switch (c) {
    case CARRIER_DOUBLE: return ((const double *)values)[i];
    case CARRIER_INT32: return ((const int32_t *)values)[i];
    case CARRIER_INT_BOOL: return ((const int *)values)[i] != 0;
    case CARRIER_INT16: return ((const int16_t *)values)[i];
    case CARRIER_UINT16: return ((const uint16_t *)values)[i];
    case CARRIER_BOOL: return ((const bool *)values)[i];
    case CARRIER_FLOAT: return ((const float *)values)[i];
    case CARRIER_UINT32: return ((const uint32_t *)values)[i];
    case CARRIER_INT8: return ((const int8_t *)values)[i];
    case CARRIER_UINT8: return ((const uint8_t *)values)[i];
    }
    return 0;
}

static void core_put_value(carrier c, void *values, size_t i, double value)
{
    switch (c) {
    case CARRIER_DOUBLE: ((double *)values)[i] = value; break;
    case CARRIER_INT32: ((int32_t *)values)[i] = (int32_t)value; break;
    case CARRIER_INT_BOOL: ((int *)values)[i] = value != 0; break;
    case CARRIER_INT16: ((int16_t *)values)[i] = (int16_t)value; break;
    case CARRIER_UINT16: ((uint16_t *)values)[i] = (uint16_t)value; break;
    case CARRIER_BOOL: ((bool *)values)[i] = value != 0; break;
    case CARRIER_FLOAT: ((float *)values)[i] = (float)value; break;
    case CARRIER_UINT32: ((uint32_t *)values)[i] = (uint32_t)value; break;
    case CARRIER_INT8: ((int8_t *)values)[i] = (int8_t)value; break;
    case CARRIER_UINT8: ((uint8_t *)values)[i] = (uint8_t)value; break;
    }
}

/* Why e may not be set now with value, or SET_ALLOWED. Inline and free of messages, so that an
 * accepted value costs a few compares; only a refusal goes on to core_refuse_set. */
typedef enum { SET_ALLOWED, SET_OUTPUT, SET_FIXED, SET_OUT_OF_RANGE } set_refusal;

static inline set_refusal core_set_refusal(const instance *inst, const model_variable *v,
                                           double value)
{
    if (var_is_computed(v->role)) return SET_OUTPUT; /* an output or a local */
    if (v->role == ROLE_FIXED_PARAMETER && inst->image->mode != MODE_INSTANTIATED &&
        inst->image->mode != MODE_INITIALIZATION)
        return SET_FIXED;
    return core_in_range(v, value) ? SET_ALLOWED : SET_OUT_OF_RANGE;
}

/* The one log line of a set of value to vr that core_set refused, saying why. Apart from
 * core_set, so that its loop over accepted values carries no message. */
static void core_refuse_set(const instance *inst, const char *function, const fmi_types *types,
                            int kind, uint32_t vr, double value)
{
    core_element e;
    if (!core_resolve(inst, function, types, kind, vr, &e)) return;
    set_refusal why = core_set_refusal(inst, e.var, value);
    char name[64];
    if (why == SET_OUTPUT) {
        core_log(inst, STATUS_ERROR, "%s: %s is %s and cannot be set.", function,
                 core_name_of(&e, name, sizeof name),
                 e.var->role == ROLE_OUTPUT ? "an output" : "a local variable (a static)");
    } else if (why == SET_FIXED) {
        core_log(inst, STATUS_ERROR,
                 "%s: %s is a fixed parameter and can only be set until initialization "
                 "mode ends.",
                 function, core_name_of(&e, name, sizeof name));
    } else {
        char text[384];
        core_describe_refusal(&e, value, inst->host->udint_max, text, sizeof text);
        core_log(inst, STATUS_ERROR, "%s: %s; the value was not applied.", function, text);
    }
}

/* Copies e's value from one image to the other: of a fixed size in each case, so that it is
 * a load and a store, not a call of memcpy (core_set saves and restores the values it sets). */
static inline void core_copy_field(fmu_image *to, const fmu_image *from, const core_element *e)
{
    void *p = core_field(to, e);
    const void *q = core_field(from, e);
    switch (core_size_of(e->var->type)) {
    case 1: memcpy(p, q, 1); break;
    case 2: memcpy(p, q, 2); break;
    case 4: memcpy(p, q, 4); break;
    case 8: memcpy(p, q, 8); break;
    default: memcpy(p, q, core_size_of(e->var->type)); break;
    }
}

/* vr and values may be NULL only with nvr = 0. */
static inline bool core_arrays_given(instance *inst, const char *function, const uint32_t vr[],
                                     size_t nvr, const void *values)
{
    if (nvr == 0 || (vr && values)) return true;
    core_log(inst, STATUS_ERROR, "%s: vr or value is NULL with nvr = %llu.", function,
             (unsigned long long)nvr);
    return false;
}

/* The fields of vr[0 .. nvr-1] copied from one image to the other. */
static inline void core_copy_fields(instance *inst, fmu_image *to, const fmu_image *from,
                                    const uint32_t vr[], size_t nvr)
{
    core_element e = {NULL, 0};
    for (size_t i = 0; i < nvr; i++) {
        core_find(inst, vr[i], &e);
        core_copy_field(to, from, &e);
    }
}

/* The block's rules across variables (model.check) after a set of vr[0 .. nvr-1], whose old
 * values the set kept in the scratch image: refused, they are put back and the error logged. */
static inline bool core_check_set(instance *inst, const char *function, const uint32_t vr[],
                                  size_t nvr)
{
    char why[256];
    if (!lgf_model.check || !lgf_model.check(inst->image->data, why, sizeof why)) return true;
    core_copy_fields(inst, inst->image, inst->scratch, vr, nvr);
    core_log(inst, STATUS_ERROR, "%s: %s; the values were not applied.", function, why);
    return false;
}

/* Every value is checked before any is stored; the rules of the block that involve more than
 * one variable are checked after, and a refusal puts the old values back (they were saved in
 * the scratch image). So a rejected call leaves the instance as it was. */
static CORE_ALWAYS_INLINE lgf_status core_set(instance *inst, const char *function,
                                              const fmi_types *types, int kind, carrier c,
                                              const uint32_t vr[], size_t nvr, const void *values)
{
    if (!core_arrays_given(inst, function, vr, nvr, values)) return STATUS_ERROR;
    for (size_t i = 0; i < nvr; i++) {
        const model_variable *v = core_variable(inst, vr[i]);
        double value = core_value_at(c, values, i);
        if (!v || types->kind_of[v->type] != kind ||
            core_set_refusal(inst, v, value) != SET_ALLOWED) {
            core_refuse_set(inst, function, types, kind, vr[i], value);
            return STATUS_ERROR;
        }
    }
    core_element e = {NULL, 0}; /* core_find fills it: every vr was found above */
    fmu_image *image = inst->image, *saved = inst->scratch;
    if (lgf_model.check) core_copy_fields(inst, saved, image, vr, nvr);
    bool rounded = false;
    double cycle = 0;
    for (size_t i = 0; i < nvr; i++) {
        core_find(inst, vr[i], &e);
        if (core_store(image, &e, core_value_at(c, values, i)))
            rounded = true, cycle = core_value_at(c, values, i);
    }
    if (!core_check_set(inst, function, vr, nvr)) return STATUS_ERROR;
    if (image->mode == MODE_CONTINUOUS && !inst->told_continuous_set && nvr > 0) {
        inst->told_continuous_set = true;
        core_log(inst, STATUS_WARNING,
                 "%s: an input set in continuous-time mode is taken; the next PLC call, at the "
                 "next time event, reads it (this is said once).",
                 function);
    }
    if (!rounded) return STATUS_OK;
    core_warn_cycle(inst, function, cycle);
    return STATUS_WARNING;
}

/* The image a get of nvr values reads outputs and locals from: in Initialization Mode those the
 * first call will compute from the inputs set so far (docs/behaviour.md §1.2), as a master that
 * connects FMUs during initialization passes on the values at t0, not those before the first
 * call; else the instance's. */
static inline const fmu_image *core_outputs_to_get(instance *inst, size_t nvr)
{
    if (inst->image->mode == MODE_INITIALIZATION && nvr > 0) return core_preview_first_call(inst);
    return inst->image;
}

static lgf_status core_get(instance *inst, const char *function, const fmi_types *types, int kind,
                           carrier c, const uint32_t vr[], size_t nvr, void *values)
{
    if (!core_arrays_given(inst, function, vr, nvr, values)) return STATUS_ERROR;
    const fmu_image *outputs = core_outputs_to_get(inst, nvr);
    for (size_t i = 0; i < nvr; i++) {
        core_element e;
        if (!core_resolve(inst, function, types, kind, vr[i], &e)) return STATUS_ERROR;
        const fmu_image *image = var_is_computed(e.var->role) ? outputs : inst->image;
        /* A NaN (of ±Inf arithmetic) is given as the positive quiet NaN: processors make NaNs
         * of either sign (x86-64 negative, aarch64 positive), the FMU the same bits on every
         * platform (docs/behaviour.md §1.4). */
        double value = core_read_number(image, &e);
        core_put_value(c, values, i, isnan(value) ? (double)NAN : value);
    }
    return STATUS_OK;
}

/* ---- the checks of a restored state (docs/behaviour.md §1.7) ---- */

static bool core_static_is_valid(const fmu_image *image, const model_static *s)
{
    const unsigned char *p = (const unsigned char *)image->data + s->offset;
    if (s->type == FIELD_BOOL) return *p <= 1;
    if (s->type == FIELD_REAL) return !isnan(*(const double *)p);
    return true;
}

static bool core_image_is_valid(const instance *inst, const fmu_image *image, const char *function)
{
    if (!core_clock_is_valid(image)) {
        core_log(inst, STATUS_ERROR, "%s: the state's clock is corrupt.", function);
        return false;
    }
    for (size_t i = 0; i < lgf_model.variable_count; i++) {
        const model_variable *v = &lgf_model.variables[i];
        for (uint32_t k = 0; k < v->count; k++) {
            core_element e = {v, k};
            bool valid = var_is_string(v->type) ? core_string_is_valid(v, core_field(image, &e))
                         : v->type == VAR_BOOL  ? iec_bool_is_valid(core_field(image, &e))
                         : (v->type == VAR_UDINT || v->type == VAR_DWORD) &&
                                 core_read_number(image, &e) > inst->host->udint_max
                             ? false
                         : var_is_computed(v->role) ? true
                                                    : core_in_range(v, core_read_number(image, &e));
            if (valid) continue;
            char why[384];
            if (v->type == VAR_BOOL || var_is_string(v->type)) {
                char name[64];
                snprintf(why, sizeof why, "it holds no valid %s for %s",
                         v->type == VAR_BOOL ? "Boolean" : "string",
                         core_name_of(&e, name, sizeof name));
            } else {
                core_describe_refusal(&e, core_read_number(image, &e), inst->host->udint_max, why,
                                      sizeof why);
            }
            core_log(inst, STATUS_ERROR, "%s: the state is invalid: %s.", function, why);
            return false;
        }
    }
    for (size_t i = 0; i < lgf_model.static_count; i++) {
        const model_static *s = &lgf_model.statics[i];
        if (core_static_is_valid(image, s)) continue;
        core_log(inst, STATUS_ERROR, "%s: the state is invalid: the static %s holds %s.", function,
                 s->name, s->type == FIELD_BOOL ? "neither FALSE nor TRUE" : "NaN");
        return false;
    }
    char why[256];
    if ((lgf_model.check && lgf_model.check(image->data, why, sizeof why)) ||
        (lgf_model.state_check && lgf_model.state_check(image->data, why, sizeof why))) {
        core_log(inst, STATUS_ERROR, "%s: the state is invalid: %s.", function, why);
        return false;
    }
    return true;
}
