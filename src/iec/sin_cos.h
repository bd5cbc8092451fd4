/* SIN and COS of a REAL (docs/behaviour.md §6.2), the same bits on every platform: what the
 * signal generators (iec/signal_generator.h) and SCL's SIN and COS (docs/scl.md §3.5) compute. */
#ifndef LGF_IEC_SIN_COS_H
#define LGF_IEC_SIN_COS_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* SIN and COS of a REAL, the same bits on every platform: the PLC's routine is not public and
 * the C libraries' sinf differ, so the float32 argument is reduced and evaluated in double by
 * plain arithmetic (no library call), and the result rounded to float32 (within 1 float32 ulp
 * of the correctly rounded value; docs/behaviour.md §6). */

/* The polynomial c[0] + c[1]·r2 + ... + c[n - 1]·r2^(n - 1) in Horner's form, the innermost
 * product first: both series below, evaluated alike. */
static inline double lgf_horner(const double *c, size_t n, double r2)
{
    double p = c[n - 1];
    for (size_t i = n - 1; i-- > 0;) p = c[i] + r2 * p;
    return p;
}

static inline double lgf_sin_poly(double r) /* |r| <= pi/4: Taylor to r^17, error < 1e-18 */
{
    static const double c[] = {1.0,
                               -1.0 / 6,
                               1.0 / 120,
                               -1.0 / 5040,
                               1.0 / 362880,
                               -1.0 / 39916800,
                               1.0 / 6227020800.0,
                               -1.0 / 1307674368000.0,
                               1.0 / 355687428096000.0};
    return r * lgf_horner(c, sizeof c / sizeof c[0], r * r);
}

static inline double lgf_cos_poly(double r) /* |r| <= pi/4: Taylor to r^18 */
{
    static const double c[] = {1.0,
                               -1.0 / 2,
                               1.0 / 24,
                               -1.0 / 720,
                               1.0 / 40320,
                               -1.0 / 3628800,
                               1.0 / 479001600,
                               -1.0 / 87178291200.0,
                               1.0 / 20922789888000.0,
                               -1.0 / 6402373705728000.0};
    return lgf_horner(c, sizeof c / sizeof c[0], r * r);
}

/* sin (cosine false) or cos (cosine true) of x, in float32: r = x - k·pi/2 with pi/2 in five
 * parts of 18 bits and a tail (Cody-Waite), so that k times a part is exact for |k| < 2^35,
 * i.e. for every argument these blocks form (at most 2pi·4294967040, about 2.7e10).
 * The quadrant is k mod 4 (plus 1 for the cosine), taken from the two low bits of k as a 64-bit
 * integer instead of fmod(k, 4), a library call that was 23 % of LGF_SinusCI's run. Both give
 * the same quadrant for every float x: k is a whole number (nearbyint), so for |k| < 2^63 its
 * conversion to int64_t is exact and fmod(k, 4) (always exact) is its C remainder n % 4, whose
 * sum with 1 or 0, taken to 0 ... 3, is (n + cosine) mod 4, the two low bits of n + cosine in
 * two's complement; and a double of magnitude 2^63 or more (|x| above about 1.4e19, which
 * SCL's SIN and COS can be given) is a multiple of 2^11, so that fmod gives 0.
 * tests/test_sin_cos.py compares the two over the float32 arguments. */
static inline float iec_sin_cos(float x, bool cosine)
{
    static const double half_pi[] = {1.5707931518554688,     3.1749368645250797e-06,
                                     2.5633384304057927e-12, 5.721178163110765e-18,
                                     1.05629611168797e-23,   3.7950107727212256e-29};
    if (isnan(x) || isinf(x)) return NAN; /* SIN(±Inf) is invalid: NaN, as IEEE */
    double k = nearbyint((double)x * 0.6366197723675814), r = x;
    for (size_t i = 0; i < sizeof half_pi / sizeof half_pi[0]; i++) r -= k * half_pi[i];
    uint64_t n = fabs(k) < 0x1p63 ? (uint64_t)(int64_t)k : 0u;
    unsigned quadrant = (unsigned)((n + (cosine ? 1u : 0u)) & 3u);
    double y = quadrant == 0   ? lgf_sin_poly(r)
               : quadrant == 1 ? lgf_cos_poly(r)
               : quadrant == 2 ? -lgf_sin_poly(r)
                               : -lgf_cos_poly(r);
    return (float)y;
}

#endif
