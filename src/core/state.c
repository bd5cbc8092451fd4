/* FMU states (docs/behaviour.md §1.9): in memory a copy of the instance image; serialized, a versioned
 * byte format, written field by field in little endian, with a header naming the block, the
 * format version and an identity of the block's state layout, so that bytes from another
 * block, another format, a rebuilt block whose statics changed or a damaged buffer are refused
 * instead of being run. */
#include <string.h>

#include "core/core.h"

/* The states an instance made, in a list it keeps (instance.states). A pointer an importer
 * passes is looked up there before anything is read through it, so a freed pointer, one of
 * another instance or any other address is refused with a message instead of being
 * dereferenced (docs/behaviour.md §1.9). */
struct saved_state {
    saved_state *next;
    lgf_aligned image[]; /* image_size() bytes */
};

static bool core_is_ours(const instance *inst, const void *pointer)
{
    for (const saved_state *s = inst->states; s; s = s->next)
        if ((const void *)s == pointer) return true;
    return false;
}

static saved_state *core_new_state(instance *inst, const char *function)
{
    saved_state *state = core_allocate(inst, sizeof *state + inst->image_size);
    if (!state) {
        core_log(inst, STATUS_ERROR, "%s: out of memory.", function);
        return NULL;
    }
    state->next = inst->states;
    inst->states = state;
    return state;
}

/* Unlinks a state of inst's list and gives its memory back. */
static void core_drop_state(instance *inst, saved_state *state)
{
    for (saved_state **link = &inst->states; *link; link = &(*link)->next) {
        if (*link == state) {
            *link = state->next;
            core_release(inst, state);
            return;
        }
    }
}

/* Whether `pointer`, the argument named `argument` of `function`, is a state this instance made
 * and has not freed; else a log line saying it was not read. */
static bool core_owns(const instance *inst, const char *function, const void *pointer,
                      const char *argument)
{
    if (core_is_ours(inst, pointer)) return true;
    core_log(inst, STATUS_ERROR,
             "%s: %s is not a state that this instance of %s made and has not freed; it was "
             "not read.",
             function, argument, lgf_model.identifier);
    return false;
}

static lgf_status core_get_state(instance *inst, const char *function, void **FMUstate)
{
    if (!core_given(inst, function, FMUstate, "FMUstate must not be NULL")) return STATUS_ERROR;
    if (inst->image->mode == MODE_ERROR) { /* FMI: a state is taken in a state without error */
        core_log(inst, STATUS_ERROR,
                 "%s must not be called in the error state of a failed PLC call.", function);
        return STATUS_ERROR;
    }
    saved_state *state = *FMUstate;
    if (state && !core_owns(inst, function, state, "*FMUstate (neither NULL nor a state)"))
        return STATUS_ERROR;
    if (!state && !(state = core_new_state(inst, function))) return STATUS_ERROR;
    memcpy(state->image, inst->image, inst->image_size);
    *FMUstate = state;
    return STATUS_OK;
}

static bool core_fits(const instance *inst, const char *function, const fmu_image *image,
                      unsigned modes)
{
    if (MODE_BIT(image->mode) & modes) return true;
    core_log(inst, STATUS_ERROR,
             "%s: the state was taken from an instance of the other interface (co-simulation "
             "or Model Exchange) of %s.",
             function, lgf_model.identifier);
    return false;
}

static lgf_status core_set_state(instance *inst, const char *function, void *FMUstate,
                                 unsigned modes)
{
    const saved_state *state = FMUstate;
    if (!core_owns(inst, function, state, "FMUstate")) return STATUS_ERROR;
    if (!core_fits(inst, function, (const fmu_image *)state->image, modes)) return STATUS_ERROR;
    memcpy(inst->image, state->image, inst->image_size);
    return STATUS_OK;
}

static lgf_status core_free_state(instance *inst, const char *function, void **FMUstate)
{
    if (!core_given(inst, function, FMUstate, "FMUstate must not be NULL")) return STATUS_ERROR;
    saved_state *state = *FMUstate;
    if (!state) return STATUS_OK;
    if (!core_owns(inst, function, state, "*FMUstate")) return STATUS_ERROR;
    core_drop_state(inst, state); /* a copy of the pointer kept by mistake is refused from now on */
    *FMUstate = NULL;
    return STATUS_OK;
}

/* ---- serialized form ----
 * The header of STATE_HEADER_SIZE bytes, its fields at the STATE_AT_* offsets of core.h, then
 * the payload: each field of core_walk() in little endian, at an offset (from the start of the
 * payload) aligned to its size, padding bytes zero. */

#define CORE_FORMAT_VERSION 2u
static const char core_format_magic[8] = "LGF-FMU";

static uint64_t core_fnv1a(uint64_t hash, const void *bytes, size_t size)
{
    const unsigned char *b = bytes;
    for (size_t i = 0; i < size; i++) hash = (hash ^ b[i]) * 0x100000001b3u;
    return hash;
}

#define CORE_FNV_OFFSET 0xcbf29ce484222325u

static void core_put_le(unsigned char *to, uint64_t value, size_t size)
{
    for (size_t i = 0; i < size; i++) to[i] = (unsigned char)(value >> (8 * i));
}

static uint64_t core_get_le(const unsigned char *from, size_t size)
{
    uint64_t value = 0;
    for (size_t i = 0; i < size; i++) value |= (uint64_t)from[i] << (8 * i);
    return value;
}

static void core_put_text(unsigned char *to, const char *text, size_t width)
{
    memset(to, 0, width);
    for (size_t i = 0; i + 1 < width && text[i]; i++) to[i] = (unsigned char)text[i];
}

static size_t core_field_size(field_type type)
{
    switch (type) {
    case FIELD_BOOL:
    case FIELD_INT8:
    case FIELD_UINT8: return 1;
    case FIELD_INT16:
    case FIELD_UINT16: return 2;
    case FIELD_INT32:
    case FIELD_UINT32:
    case FIELD_FLOAT32: return 4;
    default: return 8;
    }
}

static field_type core_field_of(var_type type)
{
    switch (type) {
    case VAR_LREAL: return FIELD_REAL;
    case VAR_INT: return FIELD_INT16;
    case VAR_WORD: return FIELD_UINT16;
    case VAR_REAL: return FIELD_FLOAT32;
    case VAR_UDINT:
    case VAR_DWORD: return FIELD_UINT32;
    case VAR_UINT: return FIELD_UINT16;
    case VAR_SINT: return FIELD_INT8;
    case VAR_USINT:
    case VAR_BYTE: return FIELD_UINT8;
    case VAR_BOOL: return FIELD_BOOL;
    case VAR_STRING:
    case VAR_WSTRING: return FIELD_UINT16; /* each of its lengths and characters */
    default: return FIELD_INT32;           /* VAR_TIME in ms (VAR_CYCLE is in the clock) */
    }
}

/* A pass over the payload: writes the image's fields into bytes, reads them from bytes, or
 * only counts them (bytes NULL). */
typedef struct {
    unsigned char *bytes;
    bool reading;
    size_t at;       /* the payload's size so far */
    bool padding_ok; /* reading: every padding byte was zero */
} core_pass;

static void core_visit(core_pass *p, void *value, field_type type)
{
    size_t size = core_field_size(type);
    size_t start = (p->at + size - 1) / size * size;
    if (p->bytes) {
        for (size_t i = p->at; i < start; i++) {
            if (p->reading)
                p->padding_ok &= p->bytes[i] == 0;
            else
                p->bytes[i] = 0;
        }
        unsigned char *at = p->bytes + start;
        uint64_t bits = 0;
        if (p->reading) {
            bits = core_get_le(at, size);
            /* a Boolean byte is copied as it is: image_is_valid refuses any but 0 and 1 */
            if (size == 1)
                *(unsigned char *)value = (unsigned char)bits;
            else if (size == 2) {
                uint16_t v = (uint16_t)bits;
                memcpy(value, &v, 2);
            } else if (size == 4) {
                uint32_t v = (uint32_t)bits;
                memcpy(value, &v, 4);
            } else
                memcpy(value, &bits, 8);
        } else {
            if (size == 1)
                bits = *(const unsigned char *)value;
            else if (size == 2) {
                uint16_t v;
                memcpy(&v, value, 2);
                bits = v;
            } else if (size == 4) {
                uint32_t v;
                memcpy(&v, value, 4);
                bits = v;
            } else
                memcpy(&bits, value, 8);
            core_put_le(at, bits, size);
        }
    }
    p->at = start + size;
}

/* Every field of the payload, in the order of the format: the clock, every element of every
 * variable but cycleTime (which the clock holds), every static. */
static void core_walk(fmu_image *image, core_pass *p)
{
    core_visit(p, &image->mode, FIELD_INT32);
    core_visit(p, &image->cycle_us, FIELD_INT32);
    core_visit(p, &image->start_time, FIELD_REAL);
    core_visit(p, &image->time, FIELD_REAL);
    core_visit(p, &image->calls, FIELD_INT64);
    core_visit(p, &image->stop_time, FIELD_REAL);
    core_visit(p, &image->stop_defined, FIELD_BOOL);
    unsigned char *data = (unsigned char *)image->data;
    for (size_t i = 0; i < lgf_model.variable_count; i++) {
        const model_variable *v = &lgf_model.variables[i];
        if (v->type == VAR_CYCLE) continue;
        for (uint32_t k = 0; k < v->count; k++) {
            unsigned char *at = data + v->offset + k * v->stride;
            if (!var_is_string(v->type)) {
                core_visit(p, at, core_field_of(v->type));
                continue;
            }
            core_string *s = (core_string *)(void *)at; /* its lengths, its characters */
            core_visit(p, &s->max, FIELD_UINT16);
            core_visit(p, &s->len, FIELD_UINT16);
            for (unsigned c = 0; c < CORE_STRING_CAPACITY; c++)
                core_visit(p, &s->data[c], FIELD_UINT16);
        }
    }
    for (size_t i = 0; i < lgf_model.static_count; i++)
        core_visit(p, data + lgf_model.statics[i].offset, lgf_model.statics[i].type);
}

static size_t core_payload_size(const instance *inst)
{
    core_pass p = {0};
    core_walk(inst->image, &p); /* with bytes NULL, walk only adds up sizes */
    return p.at;
}

/* The identity of the payload's layout: what a rebuilt FMU must agree on to read old bytes. */
static uint64_t core_layout_identity(void)
{
    static const char clock[] = "mode:i32 cycle_us:i32 start_time:f64 time:f64 calls:i64 "
                                "stop_time:f64 stop_defined:bool";
    uint64_t hash = core_fnv1a(CORE_FNV_OFFSET, clock, sizeof clock);
    for (size_t i = 0; i < lgf_model.variable_count; i++) {
        const model_variable *v = &lgf_model.variables[i];
        if (v->type == VAR_CYCLE) continue;
        unsigned char type = (unsigned char)core_field_of(v->type);
        hash = core_fnv1a(hash, v->name, strlen(v->name) + 1);
        if (v->member) hash = core_fnv1a(hash, v->member, strlen(v->member) + 1);
        hash = core_fnv1a(hash, &type, 1);
        hash = core_fnv1a(hash, &v->count, sizeof v->count);
    }
    for (size_t i = 0; i < lgf_model.static_count; i++) {
        const model_static *s = &lgf_model.statics[i];
        unsigned char type = (unsigned char)s->type;
        hash = core_fnv1a(hash, s->name, strlen(s->name) + 1);
        hash = core_fnv1a(hash, &type, 1);
    }
    return hash;
}

static lgf_status core_state_size(instance *inst, const char *function, void *FMUstate,
                                  size_t *size)
{
    if (!core_given(inst, function, size, "size must not be NULL") ||
        !core_owns(inst, function, FMUstate, "FMUstate"))
        return STATUS_ERROR;
    *size = STATE_HEADER_SIZE + core_payload_size(inst);
    return STATUS_OK;
}

static lgf_status core_serialize(instance *inst, const char *function, void *FMUstate,
                                 unsigned char *out, size_t size)
{
    saved_state *state = FMUstate;
    if (!core_given(inst, function, out, "serializedState must not be NULL") ||
        !core_owns(inst, function, state, "FMUstate"))
        return STATUS_ERROR;
    size_t payload = core_payload_size(inst);
    if (size < STATE_HEADER_SIZE + payload) {
        core_log(inst, STATUS_ERROR,
                 "%s: size is %llu but the state needs %llu bytes (see the function for the "
                 "serialized size).",
                 function, (unsigned long long)size,
                 (unsigned long long)(STATE_HEADER_SIZE + payload));
        return STATUS_ERROR;
    }
    memcpy(out + STATE_AT_MAGIC, core_format_magic, sizeof core_format_magic);
    core_put_le(out + STATE_AT_VERSION, CORE_FORMAT_VERSION, 4);
    core_put_text(out + STATE_AT_IDENTIFIER, lgf_model.identifier, STATE_IDENTIFIER_SIZE);
    core_put_text(out + STATE_AT_GUID, lgf_model.guid, STATE_GUID_SIZE);
    core_put_le(out + STATE_AT_PAYLOAD_SIZE, payload, 4);
    core_put_le(out + STATE_AT_LAYOUT, core_layout_identity(), 8);
    core_pass p = {.bytes = out + STATE_HEADER_SIZE};
    core_walk((fmu_image *)state->image, &p);
    core_put_le(out + STATE_AT_CHECKSUM,
                core_fnv1a(CORE_FNV_OFFSET, out + STATE_HEADER_SIZE, payload), 8);
    return STATUS_OK;
}

static const char *core_header_problem(const unsigned char *in, size_t size, size_t payload)
{
    unsigned char expected[STATE_IDENTIFIER_SIZE + STATE_GUID_SIZE];
    core_put_text(expected, lgf_model.identifier, STATE_IDENTIFIER_SIZE);
    core_put_text(expected + STATE_IDENTIFIER_SIZE, lgf_model.guid, STATE_GUID_SIZE);
    if (size < STATE_HEADER_SIZE || memcmp(in, core_format_magic, sizeof core_format_magic))
        return "the bytes are not a serialized state of this library";
    if (core_get_le(in + STATE_AT_VERSION, 4) != CORE_FORMAT_VERSION)
        return "the state has another format version";
    if (memcmp(in + STATE_AT_IDENTIFIER, expected, STATE_IDENTIFIER_SIZE))
        return "the state belongs to another block";
    if (memcmp(in + STATE_AT_GUID, expected + STATE_IDENTIFIER_SIZE, STATE_GUID_SIZE))
        return "the state belongs to another version of the block";
    if (core_get_le(in + STATE_AT_LAYOUT, 8) != core_layout_identity())
        return "the state was written by a build of the block with other statics (its layout "
               "identity differs)";
    if (core_get_le(in + STATE_AT_PAYLOAD_SIZE, 4) != payload ||
        size != STATE_HEADER_SIZE + payload)
        return "the state has the wrong size (truncated or padded)";
    if (core_get_le(in + STATE_AT_CHECKSUM, 8) !=
        core_fnv1a(CORE_FNV_OFFSET, in + STATE_HEADER_SIZE, payload))
        return "the state's checksum does not match (corrupt bytes)";
    return NULL;
}

static lgf_status core_deserialize(instance *inst, const char *function, const unsigned char *in,
                                   size_t size, void **FMUstate, unsigned modes)
{
    if (!core_given(inst, function, in && FMUstate,
                    "serializedState and FMUstate must not be NULL") ||
        (*FMUstate &&
         !core_owns(inst, function, *FMUstate, "*FMUstate (neither NULL nor a state)")))
        return STATUS_ERROR;
    const char *problem = core_header_problem(in, size, core_payload_size(inst));
    if (problem) {
        core_log(inst, STATUS_ERROR, "%s: %s; expected %s format %u.", function, problem,
                 lgf_model.identifier, CORE_FORMAT_VERSION);
        return STATUS_ERROR;
    }
    /* The payload is read into the scratch image and checked before anything is allocated or
     * replaced. */
    fmu_image *image = inst->scratch;
    core_image_reset(image);
    core_pass p = {
        .bytes = (unsigned char *)in + STATE_HEADER_SIZE, .reading = true, .padding_ok = true};
    core_walk(image, &p);
    if (!p.padding_ok) {
        core_log(inst, STATUS_ERROR, "%s: the state is invalid: a padding byte is not zero.",
                 function);
        return STATUS_ERROR;
    }
    if (!core_image_is_valid(inst, image, function) || !core_fits(inst, function, image, modes))
        return STATUS_ERROR;
    saved_state *state = *FMUstate;
    if (!state && !(state = core_new_state(inst, function))) return STATUS_ERROR;
    memcpy(state->image, image, inst->image_size);
    *FMUstate = state;
    return STATUS_OK;
}
