/* What the C that lgf_fmus.scl generates from an SCL block calls (docs/scl.md §3): S7 integer
 * wrap, division, the S7 conversions and functions (SIN and COS: iec/sin_cos.h), and the system
 * FB instances (TON, TOF, TP onto iec/timer.h; R_TRIG, F_TRIG onto iec/iec.h). Part of every compiled FMU's sources/. */
#ifndef LGF_SCL_H
#define LGF_SCL_H

#include <math.h>
#include <stdbool.h>
#include <stdint.h>

#include "iec/iec.h"
#include "iec/sin_cos.h"
#include "iec/timer.h"

/* An integer result wraps to its type's width in two's complement, as on the S7 CPU
 * (docs/behaviour.md §1.4: 32767 + 1 = -32768); computed in 64 bits, then wrapped. */
static inline int64_t scl_wrap(int64_t value, int bits)
{
    uint64_t mask = bits == 64 ? UINT64_MAX : (UINT64_C(1) << bits) - 1;
    uint64_t sign = UINT64_C(1) << (bits - 1);
    uint64_t low = (uint64_t)value & mask;
    return (int64_t)(low ^ sign) - (int64_t)sign;
}

static inline uint64_t scl_wrap_unsigned(uint64_t value, int bits)
{
    return bits == 64 ? value : value & ((UINT64_C(1) << bits) - 1);
}

/* Integer division and MOD truncate towards zero (the MOD has the dividend's sign); a divisor of
 * 0 gives 0 (docs/scl.md §3.3: Decision). The operands are at most 32 bits wide, so the
 * quotient of the most negative value by -1 fits and then wraps. */
static inline int64_t scl_div(int64_t a, int64_t b) { return b == 0 ? 0 : a / b; }
static inline int64_t scl_mod(int64_t a, int64_t b) { return b == 0 ? 0 : a % b; }

/* REAL_TO_<integer>, LREAL_TO_<integer>: the nearest integer, halves to even
 * (docs/behaviour.md §6.2); NaN gives 0 and a value beyond the target's range its limit
 * (docs/scl.md §3.3: Decision). TRUNC: towards zero, the same limits. */
static inline int64_t scl_limit_round(double value, int64_t low, int64_t high, bool truncate)
{
    if (isnan(value)) return 0;
    double whole = truncate ? trunc(value) : nearbyint(value);
    if (whole <= (double)low) return low;
    if (whole >= (double)high) return high;
    return (int64_t)whole;
}

/* 64-bit division (LINT, ULINT, LWORD): as scl_div, and the most negative LINT by -1 wraps to
 * itself as on the CPU instead of trapping in C. */
static inline int64_t scl_div64(int64_t a, int64_t b)
{
    if (b == 0) return 0;
    if (b == -1) return (int64_t)(UINT64_C(0) - (uint64_t)a);
    return a / b;
}
static inline int64_t scl_mod64(int64_t a, int64_t b) { return b == 0 || b == -1 ? 0 : a % b; }
static inline uint64_t scl_udiv64(uint64_t a, uint64_t b) { return b == 0 ? 0 : a / b; }
static inline uint64_t scl_umod64(uint64_t a, uint64_t b) { return b == 0 ? 0 : a % b; }

/* REAL/LREAL to ULINT: as scl_limit_round, up to 2^64 - 1. */
static inline uint64_t scl_limit_round_u64(double value, bool truncate)
{
    if (isnan(value)) return 0;
    double whole = truncate ? trunc(value) : nearbyint(value);
    if (whole <= 0.0) return 0;
    if (whole >= 18446744073709551616.0) return UINT64_MAX;
    return (uint64_t)whole;
}

/* An ARRAY index at run time (docs/scl.md §3.8): whether it lies in lo..hi. Decision: a read
 * outside gives 0 and a write outside is ignored (the CPU stops with an access error). */
static inline bool scl_in(int64_t index, int64_t lo, int64_t hi)
{
    return index >= lo && index <= hi;
}

/* The offset of an element from the low bound, index kept in lo..hi: the conditions of scl_in
 * decide whether the element is read or written, this keeps the subscript inside the array
 * even where the compiler cannot see them (and would warn of a write outside). */
static inline int64_t scl_at(int64_t index, int64_t lo, int64_t hi)
{
    return (index < lo ? lo : index > hi ? hi : index) - lo;
}

/* The elements of an ARRAY[*] table the block sees: its numberOf<Name>, kept in 1 .. capacity
 * whatever the data holds (the FMU refuses other values when they are set). */
static inline int64_t scl_count(int64_t count, int64_t capacity)
{
    return count < 1 ? 1 : count > capacity ? capacity : count;
}

/* MIN, MAX, LIMIT of numbers: ties give the first argument; a NaN argument loses to a number
 * (docs/scl.md §3.5). */
static inline int64_t scl_min_i(int64_t a, int64_t b) { return b < a ? b : a; }
static inline int64_t scl_max_i(int64_t a, int64_t b) { return b > a ? b : a; }
static inline uint64_t scl_min_u(uint64_t a, uint64_t b) { return b < a ? b : a; }
static inline uint64_t scl_max_u(uint64_t a, uint64_t b) { return b > a ? b : a; }
static inline double scl_min_d(double a, double b) { return isnan(a) || b < a ? b : a; }
static inline double scl_max_d(double a, double b) { return isnan(a) || b > a ? b : a; }
static inline float scl_min_f(float a, float b) { return isnan(a) || b < a ? b : a; }
static inline float scl_max_f(float a, float b) { return isnan(a) || b > a ? b : a; }

/* A TON, TOF or TP instance: its parameters and outputs as the instance holds them, and the
 * S7 timer of iec/timer.h (PT taken at the starting edge, docs/behaviour.md §1.12). */
typedef struct {
    bool IN;
    iec_time PT;
    bool Q;
    iec_time ET;
    iec_timer timer;
} scl_timer;

static inline void scl_ton(scl_timer *t, const plc_call *call)
{
    t->Q = iec_ton(&t->timer, t->IN, t->PT, call);
    t->ET = iec_timer_et(&t->timer, call);
}

static inline void scl_tof(scl_timer *t, const plc_call *call)
{
    t->Q = iec_tof(&t->timer, t->IN, t->PT, call);
    t->ET = iec_timer_et(&t->timer, call);
}

static inline void scl_tp(scl_timer *t, const plc_call *call)
{
    t->Q = iec_tp(&t->timer, t->IN, t->PT, call);
    t->ET = iec_timer_et(&t->timer, call);
}

/* R_TRIG and F_TRIG: the edge memory starts FALSE (iec/iec.h), so a CLK TRUE in the first call
 * is a rising edge. */
typedef struct {
    bool CLK;
    bool Q;
    bool memory;
} scl_trig;

static inline void scl_r_trig(scl_trig *t) { t->Q = iec_rising_edge(&t->memory, t->CLK); }

static inline void scl_f_trig(scl_trig *t)
{
    t->Q = !t->CLK && t->memory;
    t->memory = t->CLK;
}

/* QRY_CINT: the period of the calling cyclic-interrupt OB in µs is the FMU's cycleTime
 * (docs/behaviour.md §1.1); phase 0; it cannot fail, so STATUS and the return value are 0. */
static inline int16_t scl_qry_cint(const plc_call *call, uint32_t *cycle, uint32_t *phase,
                                   uint32_t *status)
{
    if (cycle) *cycle = (uint32_t)call->cycle_us;
    if (phase) *phase = 0;
    if (status) *status = 0;
    return 0;
}

/* Whether an instance read from untrusted bytes (a deserialized FMU state) is one a run can
 * leave (docs/behaviour.md §1.9). */
#define SCL_LATEST_CALL_US (INT64_C(1) << 62)
static inline bool scl_timer_is_valid(const scl_timer *t)
{
    return iec_bool_is_valid(&t->IN) && iec_bool_is_valid(&t->Q) && t->ET >= 0 &&
           iec_timer_is_valid(&t->timer, SCL_LATEST_CALL_US);
}

static inline bool scl_trig_is_valid(const scl_trig *t)
{
    return iec_bool_is_valid(&t->CLK) && iec_bool_is_valid(&t->Q) && iec_bool_is_valid(&t->memory);
}

#endif
