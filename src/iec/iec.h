/* PLC semantics shared by the LGF blocks (docs/behaviour.md §1.4): 16-bit INT arithmetic,
 * TIME as a signed count of milliseconds, edge memories and the cyclic call that a block
 * performs (the timers: iec/timer.h). Nothing here knows about FMI. */
#ifndef LGF_IEC_H
#define LGF_IEC_H

#include <stdbool.h>
#include <stdint.h>

typedef int16_t iec_int;   /* INT  */
typedef uint16_t iec_word; /* WORD */
typedef int32_t iec_time;  /* TIME, milliseconds */

#define IEC_TIME_MAX INT32_MAX

/* One call of a block by its organisation block: when it happens, measured from the first
 * call, and the period of the OB in µs (what QRY_CINT returns to a CI block). */
typedef struct {
    int64_t now_us;
    int32_t cycle_us;
} plc_call;

/* UDINT_TO_REAL: the nearest REAL (float32), halves to even, as the CPU converts (an integer
 * above 2^24 loses its low bits: 16777217 becomes 16777216). */
static inline float iec_udint_to_real(uint32_t value) { return (float)value; }
/* DINT_TO_REAL (a TIME's ms count included), rounded in the same way. */
static inline float iec_dint_to_real(int32_t value) { return (float)value; }

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

/* A bool read from untrusted bytes (a deserialized FMU state) must be 0 or 1 before it is
 * used as a bool; reading any other byte as bool is undefined behaviour. */
static inline bool iec_bool_is_valid(const bool *value)
{
    return *(const unsigned char *)value <= 1;
}

#endif
