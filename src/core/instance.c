/* Instances: their memory, their image and its reset (docs/behaviour.md §1.10). */
#include <string.h>

#include "core/core.h"

#ifndef CORE_DEFAULT_CYCLE_US /* a compiled program's interface.c gives its tick (docs/scl.md §3.10) */
#define CORE_DEFAULT_CYCLE_US 100000 /* 100 ms, a default OB35 (docs/behaviour.md §1.1) */
#endif

static void *core_allocate(const instance *inst, size_t size)
{
    return inst->host->allocate(inst, size);
}

static void core_release(const instance *inst, void *memory)
{
    if (memory) inst->host->release(inst, memory);
}

static void core_image_reset(fmu_image *image)
{
    memset(image, 0, sizeof(fmu_image) + lgf_model.data_size);
    image->mode = MODE_INSTANTIATED;
    image->cycle_us = CORE_DEFAULT_CYCLE_US;
    lgf_model.init(image->data);
}

static bool core_index_variables(instance *inst);

static bool core_create(instance *inst, const char *name, bool logging_on)
{
    inst->categories = logging_on ? LOG_EVERY : 0;
    inst->image_size = sizeof(fmu_image) + lgf_model.data_size;
    inst->name = core_allocate(inst, strlen(name) + 1);
    inst->image = core_allocate(inst, inst->image_size);
    inst->scratch = core_allocate(inst, inst->image_size);
    if (!inst->name || !inst->image || !inst->scratch || !core_index_variables(inst)) {
        core_destroy(inst);
        return false;
    }
    strcpy(inst->name, name);
    core_image_reset(inst->image);
    return true;
}

static void core_destroy(instance *inst)
{
    while (inst->states) core_drop_state(inst, inst->states); /* states the importer did not free */
    core_release(inst, inst->image);
    core_release(inst, inst->scratch);
    core_release(inst, inst->vr_variables);
    core_release(inst, inst->name);
    core_release(inst, inst->text);
    inst->image = inst->scratch = NULL;
    inst->vr_variables = NULL;
    inst->name = inst->text = NULL;
    inst->text_count = 0;
}

static void *core_instantiate(const instance *probe, size_t size, const char *function,
                              const char *refusal, bool logging_on)
{
    if (refusal) {
        core_log(probe, STATUS_ERROR, "%s: %s (%s).", function, refusal, lgf_model.identifier);
        return NULL;
    }
    instance *inst = core_allocate(probe, size);
    if (inst) {
        memcpy(inst, probe, size);
        if (core_create(inst, probe->name, logging_on)) return inst;
        core_release(probe, inst);
    }
    core_log(probe, STATUS_ERROR, "%s: out of memory.", function);
    return NULL;
}

static void core_free_instance(instance *inst)
{
    if (!inst) return;
    core_destroy(inst);
    core_release(inst, inst); /* the host reads its release before it frees */
}
