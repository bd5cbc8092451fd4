/* What the LGF signal generators share (docs/behaviour.md §6): LGF_SawToothCI, LGF_TriangleCI,
 * LGF_RectangleCI, LGF_SinusCI and LGF_CosinusCI have one interface, one static (the counter)
 * and one clock; each block's block.c adds its reset rule and its waveform. REAL arithmetic is
 * float32, evaluated in the original's order (the build turns off FMA contraction, so that
 * every product is rounded as the PLC rounds it). */
#ifndef LGF_SIGNAL_GENERATOR_H
#define LGF_SIGNAL_GENERATOR_H

#include <math.h>
#include <string.h>

#include "core/model.h"
#include "iec/iec.h"
#include "iec/sin_cos.h"

typedef uint32_t iec_udint; /* UDINT */

typedef struct {
    /* inputs */
    float amplitude;
    float offset;
    iec_udint periode; /* ms; the original's spelling */
    float phaseShift;  /* ms, a REAL */
    bool reset;
    /* outputs */
    float value;
    bool error;
    iec_word status;
    iec_word subFunctionStatus; /* capital F in these blocks' originals */
    /* static */
    iec_udint statCounter; /* ms within the period */
} lgf_signal;

static inline void lgf_signal_init(lgf_signal *block)
{
    memset(block, 0, sizeof *block);
    block->amplitude = 1.0f; /* the LGF defaults */
    block->periode = 1000;
}

/* REAL_TO_UDINT: to the nearest integer, halves to even, as the CPU converts. The interface
 * keeps phaseShift within 0 ... 4294967040, the largest REAL whose conversion is valid (the
 * doubles up to 4294967167.9999995 round to it). */
static inline iec_udint iec_real_to_udint(float x) { return (iec_udint)rintf(x); }

/* The cycle of the calling OB in whole ms, truncated as the original divides the µs of
 * QRY_CINT (docs/behaviour.md §4.2, §6). */
static inline iec_udint lgf_signal_ts(const plc_call *call)
{
    return (iec_udint)(call->cycle_us / 1000);
}

/* counter := (counter + Ts) MOD periode: the UDINT sum wraps modulo 2^32 first. */
static inline void lgf_signal_advance(lgf_signal *block, const plc_call *call)
{
    block->statCounter = (iec_udint)(block->statCounter + lgf_signal_ts(call)) % block->periode;
}

/* p := REAL((counter + REAL_TO_UDINT(phaseShift)) MOD periode), the UDINT sum wrapping. */
static inline float lgf_signal_position(const lgf_signal *block)
{
    iec_udint sum = block->statCounter + iec_real_to_udint(block->phaseShift);
    return (float)(sum % block->periode);
}

/* No block-level error can occur (docs/behaviour.md §6). */
static inline void lgf_signal_no_error(lgf_signal *block)
{
    block->error = false;
    block->status = 0;
    block->subFunctionStatus = 0;
}

/* One call, in the original's order (docs/behaviour.md §6.2): the reset rule, counter :=
 * reset_counter and value := reset_value while reset is TRUE, else the counter advances and
 * value := wave(block); then the outputs of no block-level error. */
static inline void lgf_signal_call(lgf_signal *block, const plc_call *call, iec_udint reset_counter,
                                   float reset_value, float (*wave)(const lgf_signal *block))
{
    if (block->reset) {
        block->statCounter = reset_counter;
        block->value = reset_value;
    } else {
        lgf_signal_advance(block, call);
        block->value = wave(block);
    }
    lgf_signal_no_error(block);
}

/* LGF_SinusCI and LGF_CosinusCI, after the reset rule: rad := REAL(counter) · 6.283185 / P;
 * shift := (phaseShift · 6.283185) / P; value := SIN|COS(rad + shift) · amplitude + offset. */
static inline float lgf_signal_harmonic(const lgf_signal *block, bool cosine)
{
    float P = (float)block->periode;
    float rad = (float)block->statCounter * 6.283185f;
    rad = rad / P;
    float shift = block->phaseShift * 6.283185f;
    shift = shift / P;
    return iec_sin_cos(rad + shift, cosine) * block->amplitude + block->offset;
}

/* ---- the interface table of every signal generator ---- */

#define LGF_SIGNAL_CYCLE_CODES "status 16#8600 (OB unavailable) or 16#8601 (QRY_CINT failed)"

static const model_variable lgf_signal_variables[] = {
    /* The original counts its cycle in whole ms: below 1 ms it would never advance. */
    CYCLE_TIME_ROW(
        0.001, "none: replaces callOB",
        "Period of the calling cyclic-interrupt OB (replaces callOB); the block "
        "counts whole ms, so 1 ms to 60 s, and a period that is not a whole number of ms runs "
        "truncated (with a warning)"),
    {.vr = 1,
     .name = "amplitude",
     .type = VAR_REAL,
     .role = ROLE_INPUT,
     AT(lgf_signal, amplitude),
     .min = -INFINITY,
     .max = INFINITY,
     .description = "REAL: amplitude of the signal (stored as the nearest float32)"},
    {.vr = 2,
     .name = "offset",
     .type = VAR_REAL,
     .role = ROLE_INPUT,
     AT(lgf_signal, offset),
     .min = -INFINITY,
     .max = INFINITY,
     .description = "REAL: offset added to the signal"},
    {.vr = 3,
     .name = "periode",
     .type = VAR_UDINT,
     .role = ROLE_INPUT,
     AT(lgf_signal, periode),
     .min = 1,
     .max = 4294967295.0,
     .description = "UDINT: period of the signal in ms (the original's spelling); 0 is refused, "
                    "the original would divide by it"},
    {.vr = 4,
     .name = "phaseShift",
     .type = VAR_REAL,
     .role = ROLE_INPUT,
     AT(lgf_signal, phaseShift),
     .min = 0,
     .max = 4294967167.9999995,
     .unit = "ms",
     .description = "REAL: phase shift in ms; its REAL must convert to a UDINT, so at most "
                    "4294967040 (the value set up to 4294967167.9999995, which rounds to it)"},
    {.vr = 5,
     .name = "reset",
     .type = VAR_BOOL,
     .role = ROLE_INPUT,
     AT(lgf_signal, reset),
     .min = 0,
     .max = 1,
     .description = "TRUE: restart the signal"},
    {.vr = 6,
     .name = "value",
     .type = VAR_REAL,
     .role = ROLE_OUTPUT,
     AT(lgf_signal, value),
     .min = -INFINITY,
     .max = INFINITY,
     .description = "REAL: the signal (an exact float32 value)"},
    {.vr = 7,
     .name = "error",
     .type = VAR_BOOL,
     .role = ROLE_OUTPUT,
     AT(lgf_signal, error),
     .min = 0,
     .max = 1,
     .description = "Always FALSE: no block-level error can occur; invalid inputs are refused "
                    "when they are set"},
    {.vr = 8,
     .name = "status",
     .type = VAR_WORD,
     .role = ROLE_OUTPUT,
     AT(lgf_signal, status),
     .min = 0,
     .max = 65535,
     .description = "WORD: always 0 = 16#0000 (the cycle errors 16#8600/16#8601 of the original "
                    "are replaced by the check of cycleTime)"},
    {.vr = 9,
     .name = "subFunctionStatus",
     .type = VAR_WORD,
     .role = ROLE_OUTPUT,
     AT(lgf_signal, subFunctionStatus),
     .min = 0,
     .max = 65535,
     .description = "WORD: status of called system functions; always 0 in the FMU"},
};

static const model_static lgf_signal_statics[] = {
    STATIC(lgf_signal, statCounter, FIELD_UINT32),
};

static void lgf_signal_init_data(void *data) { lgf_signal_init(data); }

/* The lgf_model of a signal generator whose call is prefix_##_call: its modelIdentifier and
 * GUID, then its description; the rest all five share. */
#define LGF_SIGNAL_MODEL(prefix_, identifier_, guid_, ...)                                         \
    BLOCK_CALL(prefix_)                                                                            \
    static const model lgf_model = {                                                               \
        .identifier = (identifier_),                                                               \
        .guid = (guid_),                                                                           \
        .stop_time = 3,                                                                            \
        .variables = lgf_signal_variables,                                                         \
        .variable_count = sizeof lgf_signal_variables / sizeof lgf_signal_variables[0],            \
        .statics = lgf_signal_statics,                                                             \
        .static_count = sizeof lgf_signal_statics / sizeof lgf_signal_statics[0],                  \
        .data_size = sizeof(lgf_signal),                                                           \
        CI_CYCLE(1000, LGF_SIGNAL_CYCLE_CODES),                                                    \
        .init = lgf_signal_init_data,                                                              \
        .call = call,                                                                              \
        .description = __VA_ARGS__}

#endif
