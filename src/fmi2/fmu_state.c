/* FMU states (BLOCKS.md 1.4): a copy of the instance image; serialized, a versioned byte
 * format with a header naming the block, so bytes from another block, another format version
 * or a damaged buffer are refused instead of being run. */
#include <string.h>

#include "fmi2/instance.h"

#define STATE_MAGIC 0x4c474653u /* "LGFS": marks the states this library allocated */

typedef struct {
    uint32_t magic;
    const model *owner;
    max_align_t image[]; /* image_size() bytes */
} saved_state;

static bool is_ours(const saved_state *state)
{
    return state->magic == STATE_MAGIC && state->owner == &lgf_model;
}

fmi2Status fmi2GetFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    instance *inst = c;
    if (!inst) return fmi2Error;
    if (!FMUstate) {
        log_message(inst, fmi2Error, "fmi2GetFMUstate: FMUstate must not be NULL.");
        return fmi2Error;
    }
    saved_state *state = *FMUstate;
    if (state && !is_ours(state)) {
        log_message(inst, fmi2Error,
                    "fmi2GetFMUstate: *FMUstate is neither NULL nor a state of %s.",
                    lgf_model.identifier);
        return fmi2Error;
    }
    if (!state) {
        state = allocate(inst, sizeof *state + inst->image_size);
        if (!state) {
            log_message(inst, fmi2Error, "fmi2GetFMUstate: out of memory.");
            return fmi2Error;
        }
        state->magic = STATE_MAGIC;
        state->owner = &lgf_model;
    }
    memcpy(state->image, inst->image, inst->image_size);
    *FMUstate = state;
    return fmi2OK;
}

fmi2Status fmi2SetFMUstate(fmi2Component c, fmi2FMUstate FMUstate)
{
    instance *inst = c;
    if (!inst) return fmi2Error;
    const saved_state *state = FMUstate;
    if (!state || !is_ours(state)) {
        log_message(inst, fmi2Error, "fmi2SetFMUstate: FMUstate is not a state of %s.",
                    lgf_model.identifier);
        return fmi2Error;
    }
    memcpy(inst->image, state->image, inst->image_size);
    return fmi2OK;
}

fmi2Status fmi2FreeFMUstate(fmi2Component c, fmi2FMUstate *FMUstate)
{
    instance *inst = c;
    if (!inst) return fmi2Error;
    if (!FMUstate) {
        log_message(inst, fmi2Error, "fmi2FreeFMUstate: FMUstate must not be NULL.");
        return fmi2Error;
    }
    saved_state *state = *FMUstate;
    if (!state) return fmi2OK;
    if (!is_ours(state)) {
        log_message(inst, fmi2Error, "fmi2FreeFMUstate: *FMUstate is not a state of %s.",
                    lgf_model.identifier);
        return fmi2Error;
    }
    state->magic = 0; /* no longer a state: a copy of the pointer held by mistake cannot pass as one */
    release(inst, state);
    *FMUstate = NULL;
    return fmi2OK;
}

/* ---- serialized form ----
 * offset  size  content
 *      0     8  "LGF-FMU\0"
 *      8     4  format version, little endian
 *     12    32  modelIdentifier, NUL padded
 *     44    40  guid, NUL padded
 *     84     4  payload size, little endian
 *     88     8  FNV-1a 64 of the payload, little endian
 *     96     n  payload: the instance image (clock, then the block's data) */

#define FORMAT_VERSION 1u
#define HEADER_SIZE 96u
static const char format_magic[8] = "LGF-FMU";

static uint64_t fnv1a(const unsigned char *bytes, size_t size)
{
    uint64_t hash = 0xcbf29ce484222325u;
    for (size_t i = 0; i < size; i++) hash = (hash ^ bytes[i]) * 0x100000001b3u;
    return hash;
}

static void put_le(unsigned char *to, uint64_t value, int size)
{
    for (int i = 0; i < size; i++) to[i] = (unsigned char)(value >> (8 * i));
}

static uint64_t get_le(const unsigned char *from, int size)
{
    uint64_t value = 0;
    for (int i = 0; i < size; i++) value |= (uint64_t)from[i] << (8 * i);
    return value;
}

static void put_text(unsigned char *to, const char *text, size_t field)
{
    memset(to, 0, field);
    for (size_t i = 0; i + 1 < field && text[i]; i++) to[i] = (unsigned char)text[i];
}

fmi2Status fmi2SerializedFMUstateSize(fmi2Component c, fmi2FMUstate FMUstate, size_t *size)
{
    instance *inst = c;
    if (!inst) return fmi2Error;
    if (!FMUstate || !is_ours(FMUstate) || !size) {
        log_message(inst, fmi2Error,
                    "fmi2SerializedFMUstateSize: FMUstate must be a state of %s and size "
                    "must not be NULL.",
                    lgf_model.identifier);
        return fmi2Error;
    }
    *size = HEADER_SIZE + inst->image_size;
    return fmi2OK;
}

fmi2Status fmi2SerializeFMUstate(fmi2Component c, fmi2FMUstate FMUstate, fmi2Byte serializedState[],
                                 size_t size)
{
    instance *inst = c;
    if (!inst) return fmi2Error;
    const saved_state *state = FMUstate;
    if (!state || !is_ours(state) || !serializedState) {
        log_message(inst, fmi2Error,
                    "fmi2SerializeFMUstate: FMUstate must be a state of %s and "
                    "serializedState must not be NULL.",
                    lgf_model.identifier);
        return fmi2Error;
    }
    if (size < HEADER_SIZE + inst->image_size) {
        log_message(inst, fmi2Error,
                    "fmi2SerializeFMUstate: size is %llu but the state needs %llu bytes "
                    "(fmi2SerializedFMUstateSize).",
                    (unsigned long long)size, (unsigned long long)(HEADER_SIZE + inst->image_size));
        return fmi2Error;
    }
    unsigned char *out = (unsigned char *)serializedState;
    memcpy(out, format_magic, sizeof format_magic);
    put_le(out + 8, FORMAT_VERSION, 4);
    put_text(out + 12, lgf_model.identifier, 32);
    put_text(out + 44, lgf_model.guid, 40);
    put_le(out + 84, inst->image_size, 4);
    memcpy(out + HEADER_SIZE, state->image, inst->image_size);
    put_le(out + 88, fnv1a(out + HEADER_SIZE, inst->image_size), 8);
    return fmi2OK;
}

static const char *header_problem(const unsigned char *in, size_t size, size_t image_size)
{
    unsigned char expected[32 + 40];
    put_text(expected, lgf_model.identifier, 32);
    put_text(expected + 32, lgf_model.guid, 40);
    if (size < HEADER_SIZE || memcmp(in, format_magic, sizeof format_magic))
        return "the bytes are not a serialized state of this library";
    if (get_le(in + 8, 4) != FORMAT_VERSION) return "the state has another format version";
    if (memcmp(in + 12, expected, 32)) return "the state belongs to another block";
    if (memcmp(in + 44, expected + 32, 40)) return "the state belongs to another version of the block";
    if (get_le(in + 84, 4) != image_size || size != HEADER_SIZE + image_size)
        return "the state has the wrong size (truncated or padded)";
    if (get_le(in + 88, 8) != fnv1a(in + HEADER_SIZE, image_size))
        return "the state's checksum does not match (corrupt bytes)";
    return NULL;
}

fmi2Status fmi2DeSerializeFMUstate(fmi2Component c, const fmi2Byte serializedState[], size_t size,
                                   fmi2FMUstate *FMUstate)
{
    instance *inst = c;
    if (!inst) return fmi2Error;
    if (!serializedState || !FMUstate) {
        log_message(inst, fmi2Error,
                    "fmi2DeSerializeFMUstate: serializedState and FMUstate must not be NULL.");
        return fmi2Error;
    }
    if (*FMUstate && !is_ours(*FMUstate)) {
        log_message(inst, fmi2Error,
                    "fmi2DeSerializeFMUstate: *FMUstate is neither NULL nor a state of %s.",
                    lgf_model.identifier);
        return fmi2Error;
    }
    const unsigned char *in = (const unsigned char *)serializedState;
    const char *problem = header_problem(in, size, inst->image_size);
    if (problem) {
        log_message(inst, fmi2Error, "fmi2DeSerializeFMUstate: %s; expected %s format %u.", problem,
                    lgf_model.identifier, FORMAT_VERSION);
        return fmi2Error;
    }
    /* The payload is checked in the scratch image before anything is allocated or replaced. */
    memcpy(inst->scratch, in + HEADER_SIZE, inst->image_size);
    if (!image_is_valid(inst, inst->scratch, "fmi2DeSerializeFMUstate")) return fmi2Error;
    saved_state *state = *FMUstate;
    if (!state) {
        state = allocate(inst, sizeof *state + inst->image_size);
        if (!state) {
            log_message(inst, fmi2Error, "fmi2DeSerializeFMUstate: out of memory.");
            return fmi2Error;
        }
        state->magic = STATE_MAGIC;
        state->owner = &lgf_model;
    }
    memcpy(state->image, inst->scratch, inst->image_size);
    *FMUstate = state;
    return fmi2OK;
}
