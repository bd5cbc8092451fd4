/* Drives the S7 IEC timers of src/iec/timer.h (docs/behaviour.md §1.12) for
 * tests/test_iec_timers.py: one timer, one execution per input line
 * "<TON|TOF|TP> <time in µs> <IN 0|1> <PT in ms>", one output line "<Q 0|1> <ET in ms>".
 * The kinds "QTON", "QTOF" and "QTP" do not execute the timer: they read its Q and ET at that
 * time, as a program's read of inst.Q and inst.ET does (IN and PT are ignored). */
#include <stdio.h>
#include <string.h>

#include "iec/timer.h"

int main(void)
{
    iec_timer timer = {0};
    char kind[5];
    long long now_us;
    int in;
    long pt;
    while (scanf("%4s %lld %d %ld", kind, &now_us, &in, &pt) == 4) {
        plc_call call = {.now_us = now_us, .cycle_us = 0};
        bool q = !strcmp(kind, "TON")    ? iec_ton(&timer, in, (iec_time)pt, &call)
                 : !strcmp(kind, "TOF")  ? iec_tof(&timer, in, (iec_time)pt, &call)
                 : !strcmp(kind, "TP")   ? iec_tp(&timer, in, (iec_time)pt, &call)
                 : !strcmp(kind, "QTON") ? iec_ton_q(&timer, &call)
                 : !strcmp(kind, "QTOF") ? iec_tof_q(&timer, &call)
                                         : iec_tp_q(&timer, &call);
        printf("%d %ld\n", q, (long)iec_timer_et(&timer, &call));
    }
    return 0;
}
