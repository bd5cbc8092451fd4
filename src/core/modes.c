/* The FMI mode machine both front-ends share (FMI 2.0, 3.2.3 and 4.2.4; FMI 3.0, 3.2 and 4.2):
 * whether a function of one interface may be called in the instance's mode, the modes a
 * restored state may bring, and the entry points whose rules do not depend on the FMI version.
 * The front-ends keep only their signatures, each naming its kind of call (core_call). */
#include "core/core.h"

static const char *const core_mode_names[] = {"instantiated",
                                              "initialization mode",
                                              "step mode",
                                              "event mode",
                                              "continuous-time mode",
                                              "terminated",
                                              "the error state of a failed PLC call"};

static bool core_mode_allows(const instance *inst, const char *function, unsigned modes)
{
    if (modes & MODE_BIT(inst->image->mode)) return true;
    core_log(inst, STATUS_ERROR, "%s must not be called in %s.", function,
             core_mode_names[inst->image->mode]);
    return false;
}

/* Which interfaces a kind of call belongs to, and the modes it may be called in. */
static const struct {
    unsigned interfaces; /* FOR_* */
    unsigned modes;      /* MODE_BIT()s */
} core_rules[] = {
    [CALL_SETUP] = {FOR_BOTH, MODE_BIT(MODE_INSTANTIATED)},
    [CALL_EXIT_INITIALIZATION] = {FOR_BOTH, MODE_BIT(MODE_INITIALIZATION)},
    [CALL_TERMINATE] = {FOR_BOTH, MODES_RUNNING},
    [CALL_SET] = {FOR_BOTH, MODES_SETTABLE},
    [CALL_GET] = {FOR_BOTH, MODES_READABLE},
    [CALL_ANY_MODE] = {FOR_BOTH, MODES_ANY},
    [CALL_DO_STEP] = {FOR_CS, MODE_BIT(MODE_STEP)},
    [CALL_STATUS] = {FOR_CS, MODE_BIT(MODE_STEP) | MODE_BIT(MODE_TERMINATED)},
    [CALL_EXCHANGE] = {FOR_ME, MODES_EXCHANGE},
    [CALL_EVENT] = {FOR_ME, MODE_BIT(MODE_EVENT)},
    [CALL_CONTINUOUS] = {FOR_ME, MODE_BIT(MODE_CONTINUOUS)},
    [CALL_EXCHANGE_GET] = {FOR_ME, MODES_READABLE},
    [CALL_EXCHANGE_ANY_MODE] = {FOR_ME, MODES_ANY},
};

/* The log line of a call core_allowed refuses on an instance. */
static void core_refuse_call(const instance *inst, const char *function, core_call call)
{
    unsigned interfaces = core_rules[call].interfaces;
    if (!(interfaces & FOR(inst->interface))) {
        core_log(inst, STATUS_ERROR, "%s is a %s function; this instance is for %s.", function,
                 interfaces == FOR_CS ? "co-simulation" : "Model Exchange",
                 inst->interface == INTERFACE_CS ? "co-simulation" : "Model Exchange");
        return;
    }
    core_mode_allows(inst, function, core_rules[call].modes);
}

/* Inline, the message apart: every get and set passes here, and an allowed call should cost
 * the two tests, not a function call. */
static inline instance *core_allowed(instance *inst, const char *function, core_call call)
{
    if (inst && (core_rules[call].interfaces & FOR(inst->interface)) &&
        (core_rules[call].modes & MODE_BIT(inst->image->mode)))
        return inst;
    if (inst) core_refuse_call(inst, function, call);
    return NULL;
}

static lgf_status core_enter_mode(instance *inst, const char *function, core_call call,
                                  fmu_mode mode)
{
    if (!core_allowed(inst, function, call)) return STATUS_ERROR;
    inst->image->mode = mode;
    return STATUS_OK;
}

static unsigned core_modes_of(const instance *inst)
{
    unsigned common = MODES_BEFORE_INIT | MODE_BIT(MODE_TERMINATED);
    return common | (inst->interface == INTERFACE_CS ? MODE_BIT(MODE_STEP) : MODES_EXCHANGE);
}

/* Model Exchange goes on in event mode (FMI 2.0, 3.2.3; FMI 3.0, 3.2.1), co-simulation in step
 * mode; the first call runs on the way (docs/behaviour.md §1.2). */
static lgf_status core_exit_initialization(instance *inst, const char *function)
{
    int32_t mode = inst->image->mode;
    inst->image->mode = inst->interface == INTERFACE_CS ? MODE_STEP : MODE_EVENT;
    lgf_status status = core_first_call(inst, function);
    if (status == STATUS_ERROR && inst->image->mode != MODE_ERROR) inst->image->mode = mode;
    return status;
}

/* Where the standard requires pointer arguments, a NULL one is refused with one sentence,
 * `rule` saying which must be given. */
static bool core_given(const instance *inst, const char *function, bool given, const char *rule)
{
    if (given) return true;
    core_log(inst, STATUS_ERROR, "%s: %s.", function, rule);
    return false;
}

/* The event update of Model Exchange (docs/behaviour.md §1.11): the call due at the time event
 * runs once, any other event iteration runs none; the next event is the next call. */
static lgf_status core_update_discrete_states(instance *inst, const char *function, double *next)
{
    lgf_status status = core_calls_due(inst, function);
    *next = core_next_call_time(inst->image);
    return status;
}

/* The functions of continuous states and event indicators: the FMU has none of either, so they
 * take arrays of 0 elements (which may be NULL). */
static lgf_status core_none(instance *inst, const char *function, core_call call, size_t n,
                            const char *what)
{
    if (!core_allowed(inst, function, call)) return STATUS_ERROR;
    if (n == 0) return STATUS_OK;
    core_log(inst, STATUS_ERROR, "%s: %s is %llu, but %s has none (it must be 0).", function, what,
             (unsigned long long)n, lgf_model.identifier);
    return STATUS_ERROR;
}

/* What the FMU does not provide (see the capability flags in its XML). */
static lgf_status core_unsupported(instance *inst, const char *function, const char *why)
{
    if (inst) core_log(inst, STATUS_ERROR, "%s is not supported: %s.", function, why);
    return STATUS_ERROR;
}
