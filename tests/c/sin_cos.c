/* Compares iec_sin_cos of src/iec/sin_cos.h with the version it replaced, which took the
 * quadrant as fmod(k, 4.0), kept here as the oracle (tests/test_sin_cos.py): SIN and COS of
 * the float32 arguments whose bit patterns run from <first> to <last> in steps of <stride>
 * (all three as numbers, e.g. 0x7f7fffff; all 2^32 patterns: 0 0xffffffff 1). Prints
 * "<arguments> <mismatches>", then one line per mismatch (at most 10): the argument's bits,
 * "sin" or "cos", the bits of both results. Compiled as the FMUs are: numerics.h first. With
 * -DSIN_COS_DEFECT the oracle has a defect, so that the test sees the comparison fail. */
#include "core/numerics.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "iec/sin_cos.h"

static float oracle(float x, bool cosine)
{
    static const double half_pi[] = {1.5707931518554688,     3.1749368645250797e-06,
                                     2.5633384304057927e-12, 5.721178163110765e-18,
                                     1.05629611168797e-23,   3.7950107727212256e-29};
    if (isnan(x) || isinf(x)) return NAN;
    double k = nearbyint((double)x * 0.6366197723675814), r = x;
    for (size_t i = 0; i < sizeof half_pi / sizeof half_pi[0]; i++) r -= k * half_pi[i];
    int quadrant = (int)fmod(k, 4.0) + (cosine ? 1 : 0);
    quadrant = ((quadrant % 4) + 4) % 4;
#ifdef SIN_COS_DEFECT
    /* a defect the comparison must find: the wrong sign for k = 5 only (x near 7.85) */
    if (k == 5) quadrant = (quadrant + 2) % 4;
#endif
    double y = quadrant == 0   ? lgf_sin_poly(r)
               : quadrant == 1 ? lgf_cos_poly(r)
               : quadrant == 2 ? -lgf_sin_poly(r)
                               : -lgf_cos_poly(r);
    return (float)y;
}

static uint32_t bits_of(float x)
{
    uint32_t b;
    memcpy(&b, &x, sizeof b);
    return b;
}

int main(int argc, char **argv)
{
    if (argc != 4) {
        fprintf(stderr, "usage: sin_cos <first bits> <last bits> <stride>\n");
        return 2;
    }
    uint64_t first = strtoull(argv[1], NULL, 0), last = strtoull(argv[2], NULL, 0),
             stride = strtoull(argv[3], NULL, 0);
    if (last > UINT32_MAX || first > last || stride == 0) {
        fprintf(stderr, "sin_cos: need first <= last <= 0xffffffff and stride >= 1\n");
        return 2;
    }
    uint64_t arguments = 0, mismatches = 0;
    char report[10][96];
    for (uint64_t b = first; b <= last; b += stride) {
        uint32_t pattern = (uint32_t)b;
        float x;
        memcpy(&x, &pattern, sizeof x);
        for (int cosine = 0; cosine <= 1; cosine++) {
            uint32_t got = bits_of(iec_sin_cos(x, cosine)), want = bits_of(oracle(x, cosine));
            if (got == want) continue;
            if (mismatches < 10)
                snprintf(report[mismatches], sizeof report[0],
                         "0x%08" PRIx32 " %s 0x%08" PRIx32 " 0x%08" PRIx32, pattern,
                         cosine ? "cos" : "sin", got, want);
            mismatches++;
        }
        arguments++;
    }
    printf("%" PRIu64 " %" PRIu64 "\n", arguments, mismatches);
    for (uint64_t i = 0; i < mismatches && i < 10; i++) puts(report[i]);
    return 0;
}
