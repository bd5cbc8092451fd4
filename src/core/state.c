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

static bool is_ours(const instance *inst, const void *pointer)
{
    for (const saved_state *s = inst->states; s; s = s->next)
        if ((const void *)s == pointer) return true;
    return false;
}

static saved_state *new_state(instance *inst, const char *function)
{
    saved_state *state = allocate(inst, sizeof *state + inst->image_size);
    if (!state) {
        log_message(inst, STATUS_ERROR, "%s: out of memory.", function);
        return NULL;
    }
    state->next = inst->states;
    inst->states = state;
    return state;
}

/* Unlinks a state of inst's list and gives its memory back. */
static void drop_state(instance *inst, saved_state *state)
{
    for (saved_state **link = &inst->states; *link; link = &(*link)->next) {
        if (*link == state) {
            *link = state->next;
            release(inst, state);
            return;
        }
    }
}

static void refuse_state(const instance *inst, const char *function, const char *argument)
{
    log_message(inst, STATUS_ERROR,
                "%s: %s is not a state that this instance of %s made and has not freed; it was "
                "not read.",
                function, argument, lgf_model.identifier);
}

static lgf_status core_get_state(instance *inst, const char *function, void **FMUstate)
{
    if (!FMUstate) {
        log_message(inst, STATUS_ERROR, "%s: FMUstate must not be NULL.", function);
        return STATUS_ERROR;
    }
    saved_state *state = *FMUstate;
    if (state && !is_ours(inst, state)) {
        refuse_state(inst, function, "*FMUstate (neither NULL nor a state)");
        return STATUS_ERROR;
    }
    if (!state && !(state = new_state(inst, function))) return STATUS_ERROR;
    memcpy(state->image, inst->image, inst->image_size);
    *FMUstate = state;
    return STATUS_OK;
}

static bool fits(const instance *inst, const char *function, const fmu_image *image,
                 unsigned modes)
{
    if (IN(image->mode) & modes) return true;
    log_message(inst, STATUS_ERROR,
                "%s: the state was taken from an instance of the other interface (co-simulation "
                "or Model Exchange) of %s.",
                function, lgf_model.identifier);
    return false;
}

static lgf_status core_set_state(instance *inst, const char *function, void *FMUstate,
                                 unsigned modes)
{
    const saved_state *state = FMUstate;
    if (!state || !is_ours(inst, state)) {
        refuse_state(inst, function, "FMUstate");
        return STATUS_ERROR;
    }
    if (!fits(inst, function, (const fmu_image *)state->image, modes)) return STATUS_ERROR;
    memcpy(inst->image, state->image, inst->image_size);
    return STATUS_OK;
}

static lgf_status core_free_state(instance *inst, const char *function, void **FMUstate)
{
    if (!FMUstate) {
        log_message(inst, STATUS_ERROR, "%s: FMUstate must not be NULL.", function);
        return STATUS_ERROR;
    }
    saved_state *state = *FMUstate;
    if (!state) return STATUS_OK;
    if (!is_ours(inst, state)) {
        refuse_state(inst, function, "*FMUstate");
        return STATUS_ERROR;
    }
    drop_state(inst, state); /* a copy of the pointer kept by mistake is refused from now on */
    *FMUstate = NULL;
    return STATUS_OK;
}

/* ---- serialized form ----
 * offset  size  content
 *      0     8  "LGF-FMU\0"
 *      8     4  format version, little endian
 *     12    32  modelIdentifier, NUL padded
 *     44    40  guid, NUL padded
 *     84     4  payload size, little endian
 *     88     8  FNV-1a 64 of the payload, little endian
 *     96     8  layout identity: FNV-1a 64 of the names and types of the payload's fields
 *    104     n  payload: each field of walk() in little endian, at an offset (from the start
 *               of the payload) aligned to its size, padding bytes zero */

#define FORMAT_VERSION 2u
static const char format_magic[8] = "LGF-FMU";

static uint64_t fnv1a(uint64_t hash, const void *bytes, size_t size)
{
    const unsigned char *b = bytes;
    for (size_t i = 0; i < size; i++) hash = (hash ^ b[i]) * 0x100000001b3u;
    return hash;
}

#define FNV_OFFSET 0xcbf29ce484222325u

static void put_le(unsigned char *to, uint64_t value, size_t size)
{
    for (size_t i = 0; i < size; i++) to[i] = (unsigned char)(value >> (8 * i));
}

static uint64_t get_le(const unsigned char *from, size_t size)
{
    uint64_t value = 0;
    for (size_t i = 0; i < size; i++) value |= (uint64_t)from[i] << (8 * i);
    return value;
}

static void put_text(unsigned char *to, const char *text, size_t field)
{
    memset(to, 0, field);
    for (size_t i = 0; i + 1 < field && text[i]; i++) to[i] = (unsigned char)text[i];
}

static size_t field_size(field_type type)
{
    switch (type) {
    case FIELD_BOOL: return 1;
    case FIELD_INT16:
    case FIELD_UINT16: return 2;
    case FIELD_INT32:
    case FIELD_UINT32:
    case FIELD_FLOAT32: return 4;
    default: return 8;
    }
}

static field_type field_of(var_type type)
{
    switch (type) {
    case VAR_LREAL: return FIELD_REAL;
    case VAR_INT: return FIELD_INT16;
    case VAR_WORD: return FIELD_UINT16;
    case VAR_REAL: return FIELD_FLOAT32;
    case VAR_UDINT: return FIELD_UINT32;
    case VAR_BOOL: return FIELD_BOOL;
    default: return FIELD_INT32; /* VAR_TIME in ms (VAR_CYCLE is in the clock) */
    }
}

/* A pass over the payload: writes the image's fields into bytes, reads them from bytes, or
 * only counts them (bytes NULL). */
typedef struct {
    unsigned char *bytes;
    bool reading;
    size_t at;      /* the payload's size so far */
    bool padding_ok; /* reading: every padding byte was zero */
} pass;

static void visit(pass *p, void *value, field_type type)
{
    size_t size = field_size(type);
    size_t start = (p->at + size - 1) / size * size;
    if (p->bytes) {
        for (size_t i = p->at; i < start; i++) {
            if (p->reading) p->padding_ok &= p->bytes[i] == 0;
            else p->bytes[i] = 0;
        }
        unsigned char *at = p->bytes + start;
        uint64_t bits = 0;
        if (p->reading) {
            bits = get_le(at, size);
            /* a Boolean byte is copied as it is: image_is_valid refuses any but 0 and 1 */
            if (size == 1) *(unsigned char *)value = (unsigned char)bits;
            else if (size == 2) { uint16_t v = (uint16_t)bits; memcpy(value, &v, 2); }
            else if (size == 4) { uint32_t v = (uint32_t)bits; memcpy(value, &v, 4); }
            else memcpy(value, &bits, 8);
        } else {
            if (size == 1) bits = *(const unsigned char *)value;
            else if (size == 2) { uint16_t v; memcpy(&v, value, 2); bits = v; }
            else if (size == 4) { uint32_t v; memcpy(&v, value, 4); bits = v; }
            else memcpy(&bits, value, 8);
            put_le(at, bits, size);
        }
    }
    p->at = start + size;
}

/* Every field of the payload, in the order of the format: the clock, every element of every
 * variable but cycleTime (which the clock holds), every static. */
static void walk(fmu_image *image, pass *p)
{
    visit(p, &image->mode, FIELD_INT32);
    visit(p, &image->cycle_us, FIELD_INT32);
    visit(p, &image->start_time, FIELD_REAL);
    visit(p, &image->time, FIELD_REAL);
    visit(p, &image->calls, FIELD_INT64);
    visit(p, &image->stop_time, FIELD_REAL);
    visit(p, &image->stop_defined, FIELD_BOOL);
    unsigned char *data = (unsigned char *)image->data;
    for (size_t i = 0; i < lgf_model.variable_count; i++) {
        const model_variable *v = &lgf_model.variables[i];
        if (v->type == VAR_CYCLE) continue;
        for (uint32_t k = 0; k < v->count; k++)
            visit(p, data + v->offset + k * v->stride, field_of(v->type));
    }
    for (size_t i = 0; i < lgf_model.static_count; i++)
        visit(p, data + lgf_model.statics[i].offset, lgf_model.statics[i].type);
}

static size_t payload_size(const instance *inst)
{
    pass p = {0};
    walk(inst->image, &p); /* with bytes NULL, walk only adds up sizes */
    return p.at;
}

/* The identity of the payload's layout: what a rebuilt FMU must agree on to read old bytes. */
static uint64_t layout_identity(void)
{
    static const char clock[] = "mode:i32 cycle_us:i32 start_time:f64 time:f64 calls:i64 "
                                "stop_time:f64 stop_defined:bool";
    uint64_t hash = fnv1a(FNV_OFFSET, clock, sizeof clock);
    for (size_t i = 0; i < lgf_model.variable_count; i++) {
        const model_variable *v = &lgf_model.variables[i];
        if (v->type == VAR_CYCLE) continue;
        unsigned char type = (unsigned char)field_of(v->type);
        hash = fnv1a(hash, v->name, strlen(v->name) + 1);
        if (v->member) hash = fnv1a(hash, v->member, strlen(v->member) + 1);
        hash = fnv1a(hash, &type, 1);
        hash = fnv1a(hash, &v->count, sizeof v->count);
    }
    for (size_t i = 0; i < lgf_model.static_count; i++) {
        const model_static *s = &lgf_model.statics[i];
        unsigned char type = (unsigned char)s->type;
        hash = fnv1a(hash, s->name, strlen(s->name) + 1);
        hash = fnv1a(hash, &type, 1);
    }
    return hash;
}

static lgf_status core_state_size(instance *inst, const char *function, void *FMUstate,
                                  size_t *size)
{
    if (!size) {
        log_message(inst, STATUS_ERROR, "%s: size must not be NULL.", function);
        return STATUS_ERROR;
    }
    if (!is_ours(inst, FMUstate)) {
        refuse_state(inst, function, "FMUstate");
        return STATUS_ERROR;
    }
    *size = STATE_HEADER_SIZE + payload_size(inst);
    return STATUS_OK;
}

static lgf_status core_serialize(instance *inst, const char *function, void *FMUstate,
                                 unsigned char *out, size_t size)
{
    saved_state *state = FMUstate;
    if (!out) {
        log_message(inst, STATUS_ERROR, "%s: serializedState must not be NULL.", function);
        return STATUS_ERROR;
    }
    if (!is_ours(inst, state)) {
        refuse_state(inst, function, "FMUstate");
        return STATUS_ERROR;
    }
    size_t payload = payload_size(inst);
    if (size < STATE_HEADER_SIZE + payload) {
        log_message(inst, STATUS_ERROR,
                    "%s: size is %llu but the state needs %llu bytes (see the function for the "
                    "serialized size).",
                    function, (unsigned long long)size,
                    (unsigned long long)(STATE_HEADER_SIZE + payload));
        return STATUS_ERROR;
    }
    memcpy(out, format_magic, sizeof format_magic);
    put_le(out + 8, FORMAT_VERSION, 4);
    put_text(out + 12, lgf_model.identifier, 32);
    put_text(out + 44, lgf_model.guid, 40);
    put_le(out + 84, payload, 4);
    put_le(out + 96, layout_identity(), 8);
    pass p = {.bytes = out + STATE_HEADER_SIZE};
    walk((fmu_image *)state->image, &p);
    put_le(out + 88, fnv1a(FNV_OFFSET, out + STATE_HEADER_SIZE, payload), 8);
    return STATUS_OK;
}

static const char *header_problem(const unsigned char *in, size_t size, size_t payload)
{
    unsigned char expected[32 + 40];
    put_text(expected, lgf_model.identifier, 32);
    put_text(expected + 32, lgf_model.guid, 40);
    if (size < STATE_HEADER_SIZE || memcmp(in, format_magic, sizeof format_magic))
        return "the bytes are not a serialized state of this library";
    if (get_le(in + 8, 4) != FORMAT_VERSION) return "the state has another format version";
    if (memcmp(in + 12, expected, 32)) return "the state belongs to another block";
    if (memcmp(in + 44, expected + 32, 40)) return "the state belongs to another version of the block";
    if (get_le(in + 96, 8) != layout_identity())
        return "the state was written by a build of the block with other statics (its layout "
               "identity differs)";
    if (get_le(in + 84, 4) != payload || size != STATE_HEADER_SIZE + payload)
        return "the state has the wrong size (truncated or padded)";
    if (get_le(in + 88, 8) != fnv1a(FNV_OFFSET, in + STATE_HEADER_SIZE, payload))
        return "the state's checksum does not match (corrupt bytes)";
    return NULL;
}

static lgf_status core_deserialize(instance *inst, const char *function,
                                   const unsigned char *in, size_t size, void **FMUstate,
                                   unsigned modes)
{
    if (!in || !FMUstate) {
        log_message(inst, STATUS_ERROR, "%s: serializedState and FMUstate must not be NULL.",
                    function);
        return STATUS_ERROR;
    }
    if (*FMUstate && !is_ours(inst, *FMUstate)) {
        refuse_state(inst, function, "*FMUstate (neither NULL nor a state)");
        return STATUS_ERROR;
    }
    const char *problem = header_problem(in, size, payload_size(inst));
    if (problem) {
        log_message(inst, STATUS_ERROR, "%s: %s; expected %s format %u.", function, problem,
                    lgf_model.identifier, FORMAT_VERSION);
        return STATUS_ERROR;
    }
    /* The payload is read into the scratch image and checked before anything is allocated or
     * replaced. */
    fmu_image *image = inst->scratch;
    image_reset(image);
    pass p = {.bytes = (unsigned char *)in + STATE_HEADER_SIZE, .reading = true, .padding_ok = true};
    walk(image, &p);
    if (!p.padding_ok) {
        log_message(inst, STATUS_ERROR, "%s: the state is invalid: a padding byte is not zero.",
                    function);
        return STATUS_ERROR;
    }
    if (!image_is_valid(inst, image, function) || !fits(inst, function, image, modes))
        return STATUS_ERROR;
    saved_state *state = *FMUstate;
    if (!state && !(state = new_state(inst, function))) return STATUS_ERROR;
    memcpy(state->image, image, inst->image_size);
    *FMUstate = state;
    return STATUS_OK;
}
