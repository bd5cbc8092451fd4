/* The IEC timers of an S7-1200/1500 CPU, TON, TOF and TP (docs/behaviour.md §1.12), as every
 * block uses them. The time is the simulated time of the call (plc_call.now_us), so a timer
 * elapses on the call grid.
 *
 * What makes them S7 timers rather than textbook IEC ones: the instruction writes PT into its
 * instance at the edge of IN that starts the timer and keeps it while the timer runs ("Changing
 * PT has no effect while the timer runs"), and a negative PT counts as 0 ("Negative PT values
 * are set to zero when the timer instruction is executed"), both from Siemens' description of
 * the timer instructions. A PT of 0 at the edge gives Q (TON) or ends the pulse (TP, TOF) in
 * that same call. ET never exceeds the PT taken, so no TIME sum can pass 2^31 - 1 ms.
 *
 * An S7-1200/1500 timer is also updated whenever the program reads its Q or ET ("A timer
 * update is performed when and only when: a timer instruction is executed; the ELAPSED member
 * ... is referenced directly by an instruction; the Q member ... is referenced directly",
 * S7-1200 System Manual V4.2, §8.2). The iec_*_q readers below are that read: Q at the time
 * of the reading call, from the IN, PT and start of the last execution, without an edge. A
 * block that reads inst.Q before (or instead of) calling inst uses them, never a Q it kept. */
#ifndef LGF_IEC_TIMER_H
#define LGF_IEC_TIMER_H

#include "iec/iec.h"

typedef struct {
    bool in;          /* IN of the previous execution, for the edges */
    bool running;     /* started and not yet reset: ET counts from start_us up to pt */
    iec_time pt;      /* PT as taken at the starting edge, >= 0 */
    int64_t start_us; /* the call of the starting edge */
} iec_timer;

static inline void iec_timer_start(iec_timer *timer, iec_time pt, const plc_call *call)
{
    timer->running = true;
    timer->pt = pt < 0 ? 0 : pt;
    timer->start_us = call->now_us;
}

/* Whether the time taken at the start has passed (measured in µs, so a cycle that is not a
 * whole number of ms elapses when the PLC's would). */
static inline bool iec_timer_elapsed(const iec_timer *timer, const plc_call *call)
{
    return call->now_us - timer->start_us >= (int64_t)timer->pt * 1000;
}

/* ET: the whole ms since the start, at most PT; 0 when the timer is not running. */
static inline iec_time iec_timer_et(const iec_timer *timer, const plc_call *call)
{
    if (!timer->running) return 0;
    int64_t ms = (call->now_us - timer->start_us) / 1000;
    return ms >= timer->pt ? timer->pt : (iec_time)ms;
}

/* TON: Q once IN has been TRUE for PT; IN FALSE resets it. */
static inline bool iec_ton(iec_timer *timer, bool in, iec_time pt, const plc_call *call)
{
    if (in && !timer->in) iec_timer_start(timer, pt, call);
    timer->in = in;
    timer->running = in;
    return in && iec_timer_elapsed(timer, call);
}

/* TOF: Q while IN is TRUE and for PT after IN falls; IN TRUE again resets it. */
static inline bool iec_tof(iec_timer *timer, bool in, iec_time pt, const plc_call *call)
{
    if (!in && timer->in) iec_timer_start(timer, pt, call);
    if (in) timer->running = false;
    timer->in = in;
    return in || (timer->running && !iec_timer_elapsed(timer, call));
}

/* TP: a pulse of PT from a rising edge of IN; edges during the pulse are ignored. After the
 * pulse ET stays at PT until IN is FALSE. */
static inline bool iec_tp(iec_timer *timer, bool in, iec_time pt, const plc_call *call)
{
    bool pulsing = timer->running && !iec_timer_elapsed(timer, call);
    if (in && !timer->in && !pulsing) iec_timer_start(timer, pt, call);
    timer->in = in;
    bool q = timer->running && !iec_timer_elapsed(timer, call);
    if (!q && !in) timer->running = false;
    return q;
}

/* Q as a read of inst.Q in the call `call` sees it, the timer last executed earlier (update on
 * read, above). ET read so is iec_timer_et, which is already computed at the reading call. */
static inline bool iec_ton_q(const iec_timer *timer, const plc_call *call)
{
    return timer->in && iec_timer_elapsed(timer, call);
}

static inline bool iec_tof_q(const iec_timer *timer, const plc_call *call)
{
    return timer->in || (timer->running && !iec_timer_elapsed(timer, call));
}

static inline bool iec_tp_q(const iec_timer *timer, const plc_call *call)
{
    return timer->running && !iec_timer_elapsed(timer, call);
}

/* Whether a timer read from untrusted bytes (a deserialized FMU state) is one a run can leave:
 * its bools 0 or 1, PT >= 0 and a start between the first call and `latest_us`. */
static inline bool iec_timer_is_valid(const iec_timer *timer, int64_t latest_us)
{
    return iec_bool_is_valid(&timer->in) && iec_bool_is_valid(&timer->running) && timer->pt >= 0 &&
           timer->start_us >= 0 && timer->start_us <= latest_us;
}

#endif
