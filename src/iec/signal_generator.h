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

/* SIN and COS of a REAL, the same bits on every platform: the PLC's routine is not public and
 * the C libraries' sinf differ, so the float32 argument is reduced and evaluated in double by
 * plain arithmetic (no library call), and the result rounded to float32 (within 1 float32 ulp
 * of the correctly rounded value; docs/behaviour.md §6). */
static inline double lgf_sin_poly(double r) /* |r| <= pi/4: Taylor to r^17, error < 1e-18 */
{
    double r2 = r * r;
    return r *
           (1.0 + r2 * (-1.0 / 6 +
                        r2 * (1.0 / 120 +
                              r2 * (-1.0 / 5040 +
                                    r2 * (1.0 / 362880 +
                                          r2 * (-1.0 / 39916800 +
                                                r2 * (1.0 / 6227020800.0 +
                                                      r2 * (-1.0 / 1307674368000.0 +
                                                            r2 * (1.0 / 355687428096000.0)))))))));
}

static inline double lgf_cos_poly(double r) /* |r| <= pi/4: Taylor to r^18 */
{
    double r2 = r * r;
    return 1.0 +
           r2 * (-1.0 / 2 +
                 r2 * (1.0 / 24 +
                       r2 * (-1.0 / 720 +
                             r2 * (1.0 / 40320 +
                                   r2 * (-1.0 / 3628800 +
                                         r2 * (1.0 / 479001600 +
                                               r2 * (-1.0 / 87178291200.0 +
                                                     r2 * (1.0 / 20922789888000.0 +
                                                           r2 * (-1.0 / 6402373705728000.0)))))))));
}

/* sin (cosine false) or cos (cosine true) of x, in float32: r = x - k·pi/2 with pi/2 in five
 * parts of 18 bits and a tail (Cody-Waite), so that k times a part is exact for |k| < 2^35,
 * i.e. for every argument these blocks form (at most 2pi·4294967040, about 2.7e10). */
static inline float iec_sin_cos(float x, bool cosine)
{
    static const double half_pi[] = {1.5707931518554688,     3.1749368645250797e-06,
                                     2.5633384304057927e-12, 5.721178163110765e-18,
                                     1.05629611168797e-23,   3.7950107727212256e-29};
    if (isnan(x) || isinf(x)) return NAN; /* SIN(±Inf) is invalid: NaN, as IEEE */
    double k = nearbyint((double)x * 0.6366197723675814), r = x;
    for (size_t i = 0; i < sizeof half_pi / sizeof half_pi[0]; i++) r -= k * half_pi[i];
    int quadrant = (int)fmod(k, 4.0) + (cosine ? 1 : 0);
    quadrant = ((quadrant % 4) + 4) % 4;
    double y = quadrant == 0   ? lgf_sin_poly(r)
               : quadrant == 1 ? lgf_cos_poly(r)
               : quadrant == 2 ? -lgf_sin_poly(r)
                               : -lgf_cos_poly(r);
    return (float)y;
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

/* The fields of `lgf_model` all five share. */
#define LGF_SIGNAL_MODEL                                                                           \
    .stop_time = 3, .variables = lgf_signal_variables,                                             \
    .variable_count = sizeof lgf_signal_variables / sizeof lgf_signal_variables[0],                \
    .statics = lgf_signal_statics,                                                                 \
    .static_count = sizeof lgf_signal_statics / sizeof lgf_signal_statics[0],                      \
    .data_size = sizeof(lgf_signal), .cycle_granularity_us = 1000,                                 \
    .cycle_codes = LGF_SIGNAL_CYCLE_CODES, .init = lgf_signal_init_data

#endif
