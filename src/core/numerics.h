/* The floating-point contract of every FMU (docs/behaviour.md §1.4): each REAL (float32) and
 * LREAL (double) operation is rounded on its own, in the order written, as on the S7 CPU, so
 * that an FMU rebuilt from its sources/ with any compiler flags gives the same bits as the
 * FMU as shipped. The contract is here, in the sources, and not only in the project's build:
 * an importer compiles sources/ with flags of its own. The FMU's translation unit includes
 * this file first, so that every function after it, those of the system headers too, is
 * compiled under it.
 *
 * 1. No contraction. A compiler may fuse a * b + c into one multiply-add, rounded once, where
 *    the CPU has one (x86-64 with -march=native or -mfma, aarch64, Apple silicon): GCC does so
 *    by default outside the ISO C modes, clang within one expression. That changes results in
 *    the last bit, so it is switched off for the rest of the translation unit, in each
 *    compiler's own spelling, each guarded by its compiler (another compiler's spelling would
 *    be an unknown pragma, a warning under -Wall). */
#ifndef LGF_NUMERICS_H
#define LGF_NUMERICS_H

#if defined(__clang__)
/* float_control(precise, on) undoes -funsafe-math-optimizations and its parts
 * (-fassociative-math, -freciprocal-math, -fno-signed-zeros), which clang, unlike GCC, does
 * not reveal by a macro; it also allows contraction again, so the standard pragma and clang's
 * own come after it. (Clang 11 and later know it; for an older one the diagnostic push keeps
 * the unknown pragma quiet.) Clang's -ffp-contract=fast (which -ffast-math, refused below,
 * implies) and -fno-honor-nans override all of these by design and are not supported; no
 * macro reveals them. */
#pragma clang diagnostic push
#pragma clang diagnostic ignored "-Wunknown-pragmas"
#pragma float_control(precise, on)
#pragma clang diagnostic pop
#pragma STDC FP_CONTRACT OFF
#pragma clang fp contract(off)
#elif defined(__GNUC__)
/* GCC ignores the standard pragma (and warns). This gives every function defined after it
 * -ffp-contract=off, overriding the command line, -ffp-contract=fast included. */
#pragma GCC optimize("fp-contract=off")
#elif defined(_MSC_VER)
/* MSVC's spelling (not exercised by this project's tests). */
#pragma fp_contract(off)
#else
/* Any other compiler: the standard pragma. */
#pragma STDC FP_CONTRACT OFF
#endif

/* 2. No value-changing optimisation. -ffast-math and its parts let the compiler reorder sums,
 *    replace a division by a multiplication with the reciprocal, ignore the sign of zero and
 *    assume that no infinity or NaN occurs: the results would depend on the optimiser instead
 *    of following the PLC's arithmetic, and the FMU's refusal of NaN and its IEEE arithmetic
 *    with ±Inf (docs/behaviour.md §1.4) could be optimised away. Pragmas cannot undo all of
 *    that in every compiler, so such a build is refused here, saying why, rather than giving
 *    an FMU that is silently not exact:
 *    - GCC and clang define __FAST_MATH__ for -ffast-math and -Ofast, and __FINITE_MATH_ONLY__
 *      as 1 for -ffinite-math-only (also on its own);
 *    - GCC names the parts of -funsafe-math-optimizations, and sets __GCC_IEC_559 to 0 for
 *      every option that it counts as breaking IEEE 754 arithmetic, such as
 *      -fsingle-precision-constant (a clang that defines a macro of that name makes GCC's
 *      promise no more than clang's own, so it is not read there);
 *    - MSVC defines _M_FP_FAST for /fp:fast (not exercised by this project's tests);
 *    - excess precision, FLT_EVAL_METHOD 1 or 2 (x87 arithmetic: 32-bit x86 without SSE),
 *      would evaluate float32 sums and products in a wider type, unlike the PLC. */
#if defined(__FAST_MATH__)
#error "-ffast-math (or -Ofast) is not supported: results would differ from the S7 CPU's"
#elif defined(__FINITE_MATH_ONLY__) && __FINITE_MATH_ONLY__
#error "-ffinite-math-only is not supported: the blocks compute with infinities as the S7 CPU"
#elif defined(__ASSOCIATIVE_MATH__) || defined(__RECIPROCAL_MATH__) || defined(__NO_SIGNED_ZEROS__)
#error "-funsafe-math-optimizations (or a part) is not supported: results would differ"
#elif !defined(__clang__) && defined(__GCC_IEC_559) && __GCC_IEC_559 == 0
#error "an option breaks IEEE 754 arithmetic (__GCC_IEC_559 is 0): results would differ"
#elif defined(_M_FP_FAST)
#error "/fp:fast is not supported: results would differ from the S7 CPU's"
#elif defined(__FLT_EVAL_METHOD__) && (__FLT_EVAL_METHOD__ == 1 || __FLT_EVAL_METHOD__ == 2)
#error "excess precision (FLT_EVAL_METHOD 1 or 2, x87) is not supported: use SSE2 arithmetic"
#endif

#endif
