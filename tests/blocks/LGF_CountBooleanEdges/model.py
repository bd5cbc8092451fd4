"""Independent model of LGF_CountBooleanEdges, written from the original block's program (the LGF
SCL of 2021, executed statement by statement) and docs/behaviour.md §1.4 (TIME, USINT), §1.12
(the S7 IEC timers, with the update on read) and §12 (the interface); never from the C.

Statics: the trigger of the previous call (FALSE at first), the edge counter (USINT, 0), the
"time elapsed" flag that marks a shown result (FALSE), and an S7 TP (tests/models/timers.py).
One call, in the original's order; the outputs are computed in temporaries, which start FALSE
and 0 in every call (docs/scl.md §3.4, docs/behaviour.md §12.2 Decision):

1. edge := trigger AND NOT the previous trigger; the previous trigger := trigger.
2. Only at an edge: the TP is executed with IN TRUE and PT := monitorTime, and the counter is
   incremented (USINT: 255 + 1 wraps to 0). The TP gets IN FALSE only when a result is cleared
   (3.1), so the first edge after the start or after a clear is a rising IN that starts the
   monitoring time and takes PT (a negative one as 0); every later edge finds IN TRUE already
   and starts nothing, also in the call in which the pulse ends: that edge counts into the
   window that ends.
3. The TP's Q is read (not executed): with the update on read it is the pulse at this call's
   time (§1.12), so the window ends in the first call at or after its start + PT, whether or
   not the TP runs in that call. If Q is FALSE, the first that applies:
   1. trigger FALSE and the flag set: the temporaries stay FALSE, noOfEdges and the counter
      := 0, the flag := FALSE, and the TP is executed with IN FALSE and PT := monitorTime.
   2. counter <> 0: long if trigger and counter = 1, else single if counter = 1, else double if
      counter = 2, else severalEdges; noOfEdges := counter; the flag := TRUE. So an edge right
      after a result (before a call with trigger FALSE cleared it) counts into the old window
      and the result is shown again with the new count.
4. The outputs are the temporaries.

`monitorTime` is a TIME (§1.4: the value in s rounded to whole ms; NaN or beyond ±2147483.647 s
refused by the FMU, ValueError here).
"""

from tests.models.iec import cycle_us_of, time_s_to_ms
from tests.models.timers import TP

USINT_MOD = 256


class CountBooleanEdges:
    def __init__(self, cycle_us: int):
        self.cycle_us = cycle_us_of(cycle_us)  # the TP measures the call times
        self.trigger_previous = False
        self.time_elapsed_flag = False
        self.edges = 0  # the edge counter, USINT
        self.tp = TP()

    def call(self, now_us: int, inputs: dict) -> dict:
        trigger = bool(inputs["trigger"])
        monitor_ms = time_s_to_ms(inputs["monitorTime"])
        single = double = long = several = False  # the temporaries, 4.
        n = 0
        edge = trigger and not self.trigger_previous  # 1.
        self.trigger_previous = trigger
        if edge:  # 2.
            self.tp(now_us, True, monitor_ms)
            self.edges = (self.edges + 1) % USINT_MOD
        if not self.tp.q_at(now_us):  # 3.: a read, updated to this call's time
            if not trigger and self.time_elapsed_flag:  # 3.1 clear
                n = self.edges = 0
                self.time_elapsed_flag = False
                self.tp(now_us, False, monitor_ms)
            elif self.edges != 0:  # 3.2 result
                if trigger and self.edges == 1:
                    long = True
                elif self.edges == 1:
                    single = True
                elif self.edges == 2:
                    double = True
                else:
                    several = True
                n = self.edges
                self.time_elapsed_flag = True
        return {
            "single": single,
            "double": double,
            "long": long,
            "severalEdges": several,
            "noOfEdges": n,
        }
