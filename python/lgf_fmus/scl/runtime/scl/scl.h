/* What the C that lgf_fmus.scl generates from an SCL block calls (docs/scl.md §3): S7 integer
 * wrap, division, the S7 conversions and functions (SIN and COS: iec/sin_cos.h), and the system
 * FB instances (TON, TOF, TP onto iec/timer.h; R_TRIG, F_TRIG onto iec/iec.h). Part of every compiled FMU's sources/. */
#ifndef LGF_SCL_H
#define LGF_SCL_H

#include <math.h>
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "iec/iec.h"
#include "iec/sin_cos.h"
#include "iec/timer.h"
#include "scl/scl_string.h"
#include "scl/scl_number_string.h"
#include "scl/dates.h"

/* A local or parameter of the generated C that it may assign and never read (a VAR_TEMP the
 * block only writes, ENO; the context of a call that needs none): no warning of the C
 * compiler, which would fail a build with -Werror. */
#if defined(__GNUC__) || defined(__clang__)
#define SCL_UNUSED __attribute__((unused))
#else
#define SCL_UNUSED
#endif

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

/* TIA's block property "Set ENO automatically" (docs/scl.md §3.4 [S7-ENO-AUTO]): a REAL or LREAL
 * sum, difference, product or quotient that is no finite number (an overflow to an infinity, an
 * operand that is infinite or NaN) sets ENO FALSE; the value itself is the IEEE result. */
static inline float scl_real_eno_f(bool *eno, float v)
{
    if (!isfinite(v)) *eno = false;
    return v;
}
static inline double scl_real_eno_d(bool *eno, double v)
{
    if (!isfinite(v)) *eno = false;
    return v;
}
#define scl_real_eno(eno, v) _Generic((v), float: scl_real_eno_f, default: scl_real_eno_d)(eno, v)

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

/* ROUND, CEIL, FLOOR to an integer (docs/scl.md §3.5): the whole number `whole` (nearbyint,
 * ceil, floor of the value) in low .. high; NaN gives 0 and a value beyond the range its limit,
 * as scl_limit_round (docs/scl.md §3.3: Decision). */
static inline int64_t scl_limit_whole(double whole, int64_t low, int64_t high)
{
    if (isnan(whole)) return 0;
    if (whole <= (double)low) return low;
    if (whole >= (double)high) return high;
    return (int64_t)whole;
}

/* NORM_X and SCALE_X (docs/scl.md §3.5): Siemens' formulas, in double, rounded once to their
 * type by the caller; MAX <= MIN and a VALUE outside the range give what the formula gives. */
static inline double scl_norm_x(double low, double value, double high)
{
    return (value - low) / (high - low);
}
static inline double scl_scale_x(double low, double value, double high)
{
    return value * (high - low) + low;
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

/* RESET_TIMER: the timer as before its first run (not running, IN's memory FALSE); Q and ET
 * read FALSE and 0 until it runs again. */
static inline bool scl_reset_timer(scl_timer *t)
{
    t->Q = false;
    t->ET = 0;
    t->timer = (iec_timer){0};
    return false;
}

/* A read of inst.Q or inst.ET: the S7 updates the timer when the program reads them, not only
 * when it runs (docs/behaviour.md §1.12), so the value is the one at the time of the read. */
static inline bool scl_ton_q(const scl_timer *t, const plc_call *call)
{
    return iec_ton_q(&t->timer, call);
}

static inline bool scl_tof_q(const scl_timer *t, const plc_call *call)
{
    return iec_tof_q(&t->timer, call);
}

static inline bool scl_tp_q(const scl_timer *t, const plc_call *call)
{
    return iec_tp_q(&t->timer, call);
}

static inline iec_time scl_timer_et(const scl_timer *t, const plc_call *call)
{
    return iec_timer_et(&t->timer, call);
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
 * (docs/behaviour.md §1.1); phase 0. STATUS is what a CPU answers for a cyclic-interrupt OB that
 * exists and runs: bit 4 "OB loaded" and bit 2 "interrupt active" set, bits 0 and 1 ("disabled",
 * "locked by DIS_IRT") clear, i.e. 16#0014 (Siemens' table of QRY_CINT's STATUS). The LGF CI
 * blocks take a STATUS of 0 for a missing OB. It cannot fail, so the return value is 0. */
static inline int16_t scl_qry_cint(const plc_call *call, uint32_t *cycle, uint32_t *phase,
                                   uint32_t *status)
{
    if (cycle) *cycle = (uint32_t)call->cycle_us;
    if (phase) *phase = 0;
    if (status) *status = 0x0014;
    return 0;
}

/* QRY_CINT with its STATUS into a WORD: the low word of the DWORD, as TIA's implicit
 * conversion without "IEC check" gives it (docs/scl.md §3.6). */
static inline int16_t scl_qry_cint_word(const plc_call *call, uint32_t *cycle, uint32_t *phase,
                                        uint16_t *status)
{
    uint32_t word;
    int16_t ret = scl_qry_cint(call, cycle, phase, &word);
    if (status) *status = (uint16_t)word;
    return ret;
}

/* CTU, CTD, CTUD of the S7 (docs/scl.md §3.6) for a count of type T: CU and CD count at their
 * rising edge (the edge memory starts FALSE, as R_TRIG's), within the range of T: CV stops at
 * the type's limits instead of wrapping. R sets CV to 0, LD to PV (R before LD in CTUD), both
 * before counting; in CTUD a rising edge of CU and of CD in the same call leaves CV as it is.
 * CTU's Q is CV >= PV, CTD's Q is CV <= 0; CTUD's QU and QD are those two. */
#define SCL_COUNTER(T, name, low, high)                                                            \
    typedef struct {                                                                               \
        bool CU, CD, R, LD;                                                                        \
        T PV;                                                                                      \
        bool Q, QU, QD;                                                                            \
        T CV;                                                                                      \
        bool cu_memory, cd_memory;                                                                 \
    } scl_counter_##name;                                                                          \
    static inline void scl_ctu_##name(scl_counter_##name *c)                                       \
    {                                                                                              \
        bool up = iec_rising_edge(&c->cu_memory, c->CU);                                           \
        if (c->R)                                                                                  \
            c->CV = 0;                                                                             \
        else if (up && c->CV < (high))                                                             \
            c->CV = (T)(c->CV + 1);                                                                \
        c->Q = c->CV >= c->PV;                                                                     \
    }                                                                                              \
    static inline void scl_ctd_##name(scl_counter_##name *c)                                       \
    {                                                                                              \
        bool down = iec_rising_edge(&c->cd_memory, c->CD);                                         \
        if (c->LD)                                                                                 \
            c->CV = c->PV;                                                                         \
        else if (down && c->CV > (low))                                                            \
            c->CV = (T)(c->CV - 1);                                                                \
        c->Q = (int64_t)c->CV <= 0;                                                                \
    }                                                                                              \
    static inline void scl_ctud_##name(scl_counter_##name *c)                                      \
    {                                                                                              \
        bool up = iec_rising_edge(&c->cu_memory, c->CU);                                           \
        bool down = iec_rising_edge(&c->cd_memory, c->CD);                                         \
        if (c->R)                                                                                  \
            c->CV = 0;                                                                             \
        else if (c->LD)                                                                            \
            c->CV = c->PV;                                                                         \
        else if (up && !down && c->CV < (high))                                                    \
            c->CV = (T)(c->CV + 1);                                                                \
        else if (down && !up && c->CV > (low))                                                     \
            c->CV = (T)(c->CV - 1);                                                                \
        c->QU = c->CV >= c->PV;                                                                    \
        c->QD = (int64_t)c->CV <= 0;                                                               \
    }                                                                                              \
    static inline bool scl_counter_##name##_is_valid(const scl_counter_##name *c)                  \
    {                                                                                              \
        const bool *flags[] = {&c->CU, &c->CD, &c->R,         &c->LD,       &c->Q,                 \
                               &c->QU, &c->QD, &c->cu_memory, &c->cd_memory};                      \
        for (unsigned i = 0; i < sizeof flags / sizeof flags[0]; i++)                              \
            if (!iec_bool_is_valid(flags[i])) return false;                                        \
        return true;                                                                               \
    }

SCL_COUNTER(int8_t, sint, INT8_MIN, INT8_MAX)
SCL_COUNTER(int16_t, int, INT16_MIN, INT16_MAX)
SCL_COUNTER(int32_t, dint, INT32_MIN, INT32_MAX)
SCL_COUNTER(uint8_t, usint, 0, UINT8_MAX)
SCL_COUNTER(uint16_t, uint, 0, UINT16_MAX)
SCL_COUNTER(uint32_t, udint, 0, UINT32_MAX)

/* SHL, SHR, ROL, ROR (docs/scl.md §3.5) on the bit pattern of a value of `bits` bits: a shift by
 * the width or more gives 0 (SHR of a signed value: its sign in every bit), a rotation by N is
 * one by N modulo the width. */
static inline uint64_t scl_shl(uint64_t x, uint64_t n, int bits)
{
    return n >= (uint64_t)bits ? 0 : scl_wrap_unsigned(x << n, bits);
}

static inline uint64_t scl_shr(uint64_t x, uint64_t n, int bits)
{
    x = scl_wrap_unsigned(x, bits);
    return n >= (uint64_t)bits ? 0 : x >> n;
}

/* SHR of a signed value fills with its sign; written without >> of a negative value, whose
 * result C leaves to the implementation. */
static inline int64_t scl_shr_signed(int64_t x, uint64_t n)
{
    if (n > 63) n = 63;
    return x < 0 ? ~(~x >> n) : x >> n;
}

static inline uint64_t scl_rol(uint64_t x, uint64_t n, int bits)
{
    x = scl_wrap_unsigned(x, bits);
    n %= (uint64_t)bits;
    return n == 0 ? x : scl_wrap_unsigned(x << n | x >> ((uint64_t)bits - n), bits);
}

static inline uint64_t scl_ror(uint64_t x, uint64_t n, int bits)
{
    return scl_rol(x, (uint64_t)bits - n % (uint64_t)bits, bits);
}

/* SWAP: the bytes of the low `bits` bits of x in the reverse order (docs/scl.md §3.5). */
static inline uint64_t scl_swap(uint64_t x, int bits)
{
    uint64_t swapped = 0;
    for (int byte = 0; byte < bits / 8; byte++)
        swapped = swapped << 8 | ((x >> (8 * byte)) & 0xFFu);
    return swapped;
}

/* MUX: IN<K>, or INELSE (0 where none is given) for a K outside 0 .. count - 1
 * (docs/scl.md §3.5: Decision). */
static inline bool scl_mux_in_range(int64_t k, int64_t count) { return k >= 0 && k < count; }

/* The cycle watchdog (docs/scl.md §3.4 [DEC-WATCHDOG]): the budget of one PLC call, counted in
 * loop iterations, not in time, so that where a call stops never depends on the machine:
 * SCL_LOOPS_PER_MS iterations per ms of the FMU's parameter maxCycleTime. */
#define SCL_LOOPS_PER_MS 10000

typedef struct {
    int64_t left;      /* the iterations this call may still run */
    const char *where; /* the loop that found none left ("Motor.scl:14"), NULL while some are */
} scl_watchdog;

static inline scl_watchdog scl_watchdog_of(iec_time max_cycle_ms)
{
    scl_watchdog w = {(int64_t)max_cycle_ms * SCL_LOOPS_PER_MS, NULL};
    return w;
}

/* The context of a call of a compiled block, of its FBs and FCs: the PLC call (time, cycle),
 * the parameters of the date and time (docs/scl.md §3.6) and the cycle watchdog. */
typedef struct {
    const plc_call *plc;
    double start_s;    /* startDateAndTime: s since 1970-01-01 00:00 (UTC) at the first call */
    iec_time local_ms; /* localTimeOffset: local time minus system time, ms */
    void *top;         /* the data of the FB compiled into the FMU, which holds the DBs */
    scl_watchdog *watchdog;
} scl_context;

/* At the start of each iteration of a loop (FOR, WHILE, REPEAT) at `where`: false while the
 * budget lasts. Past it, true: the loop's block returns, and so does every block of the call
 * at its next loop iteration, so the call ends at once; the FMU then reports the time error
 * (model.fault) with the first loop that ran out. */
static inline bool scl_time_error(const scl_context *ctx, const char *where)
{
    scl_watchdog *w = ctx->watchdog;
    if (w->left > 0) {
        w->left--;
        return false;
    }
    if (!w->where) w->where = where;
    return true;
}

/* The sentence of model.fault for a call the watchdog stopped at `where` (NULL: none). */
static inline const char *scl_time_error_text(const char *where, iec_time max_cycle_ms, char *msg,
                                              size_t size)
{
    if (!where) return NULL;
    snprintf(msg, size,
             "time error: the loop at %s ran out of the call's budget of %lld loop iterations "
             "(maxCycleTime %d ms at %d iterations a ms, docs/scl.md §3.4); the CPU calls OB80 "
             "or goes to STOP",
             where, (long long)max_cycle_ms * SCL_LOOPS_PER_MS, (int)max_cycle_ms,
             SCL_LOOPS_PER_MS);
    return msg;
}

/* RD_SYS_T (local: RD_LOC_T): the date and time of the call, startDateAndTime plus the simulated
 * time since the first call (plus localTimeOffset), in whole ms as the FMU's clock counts them
 * (docs/behaviour.md §18.3); it cannot fail, so the return value is 0 (docs/scl.md §3.6). */
static inline int16_t scl_rd_sys_t(const scl_context *ctx, bool local, scl_dtl *out)
{
    int64_t ms = llround(ctx->start_s * 1e3) + ctx->plc->now_us / 1000;
    if (local) ms += ctx->local_ms;
    if (out) *out = scl_dtl_of(ms < 0 ? 0 : ms * 1000000);
    return 0;
}

/* RUNTIME(MEM): the simulated time since the first call, in s, minus MEM; MEM takes that time
 * (docs/scl.md §3.6: the first RUNTIME with MEM 0 gives the time since the first call). */
static inline double scl_runtime(double *mem, const plc_call *call)
{
    double now = (double)call->now_us / 1e6;
    double elapsed = now - *mem;
    *mem = now;
    return elapsed;
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
