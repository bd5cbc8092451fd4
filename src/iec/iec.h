/* PLC semantics shared by the LGF blocks (docs/behaviour.md §1.4): 16-bit INT arithmetic,
 * TIME as a signed count of milliseconds, edge memories, the IEC on-delay timer and
 * the cyclic call that a block performs. Nothing here knows about FMI. */
#ifndef LGF_IEC_H
#define LGF_IEC_H

#include <stdbool.h>
#include <stdint.h>

typedef int16_t iec_int;   /* INT  */
typedef uint16_t iec_word; /* WORD */
typedef int32_t iec_time;  /* TIME, milliseconds */

#define IEC_TIME_MAX INT32_MAX

/* One call of a block by its organisation block: when it happens, measured from the first
 * call, and the period of the OB (what QRY_CINT returns to a CI block), in µs and, as the
 * LREAL the original divides it into, in s (µs / 1e6, computed once, not per call). */
typedef struct {
    int64_t now_us;
    int32_t cycle_us;
    double cycle_s;
} plc_call;

/* INT + INT wraps in 16-bit two's complement on the PLC (32767 + 1 = -32768). */
static inline iec_int iec_int_add(iec_int a, iec_int b)
{
    uint16_t sum = (uint16_t)((uint16_t)a + (uint16_t)b);
    return (iec_int)(sum <= INT16_MAX ? (int32_t)sum : (int32_t)sum - 65536);
}

/* A TIME sum that saturates at the largest TIME instead of wrapping (docs/behaviour.md §4.3). */
static inline iec_time iec_time_saturate(int64_t ms)
{
    if (ms > IEC_TIME_MAX) return IEC_TIME_MAX;
    if (ms < INT32_MIN) return INT32_MIN;
    return (iec_time)ms;
}

/* R_TRIG: TRUE in the call where clk goes from FALSE to TRUE. The memory starts FALSE, so a
 * signal that is TRUE in the very first call is a rising edge. */
static inline bool iec_rising_edge(bool *memory, bool clk)
{
    bool rising = clk && !*memory;
    *memory = clk;
    return rising;
}

/* TON, with the elapsed time read from the simulation clock of the call. */
typedef struct {
    bool in;          /* IN of the previous execution, to see a rising IN */
    int64_t start_us; /* when IN last rose */
} iec_ton;

static inline bool iec_ton_run(iec_ton *timer, bool in, iec_time preset, const plc_call *call)
{
    if (in && !timer->in) timer->start_us = call->now_us;
    timer->in = in;
    return in && call->now_us - timer->start_us >= (int64_t)preset * 1000;
}

/* A bool read from untrusted bytes (a deserialized FMU state) must be 0 or 1 before it is
 * used as a bool; reading any other byte as bool is undefined behaviour. */
static inline bool iec_bool_is_valid(const bool *value)
{
    return *(const unsigned char *)value <= 1;
}

#endif
