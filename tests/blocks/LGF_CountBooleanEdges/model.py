"""Independent model of LGF_CountBooleanEdges (docs/behaviour.md §12), written from that section,
§1.4 and §1.12 only, never from the C.

Statics (§12.1): triggerPrevious (FALSE), edges (USINT, 0), the TP of tests/models/timers.py
and qPrevious (FALSE). One call (§12.2):
1. edge := trigger AND NOT triggerPrevious; triggerPrevious := trigger.
2. q := TP(IN := trigger, PT := monitorTime) (S7 TP: PT taken at the starting edge, a negative PT
   as 0, edges during the pulse ignored, PT 0 gives no pulse; elapsed in simulated µs).
3. edge: edges := edges + 1 (USINT: 255 + 1 = 0); every edge counts.
4. Outputs FALSE, noOfEdges 0; if q is FALSE and (qPrevious or trigger): the first matching
   case: edges = 0: none; trigger and edges = 1: long; edges = 1: single; edges = 2: double;
   otherwise severalEdges; and noOfEdges := edges.
5. q FALSE and trigger FALSE: edges := 0.
6. qPrevious := q.
`monitorTime` is a TIME (§1.4: rounded to whole ms, NaN or beyond ±2147483.647 s refused).
"""

from tests.models.iec import time_s_to_ms
from tests.models.timers import TP


class CountBooleanEdges:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §12.1: 1 µs … 60 s; the TP measures the call times
        if not 1 <= self.cycle_us <= 60_000_000:
            raise ValueError(f"cycleTime {self.cycle_us} µs outside 1 µs … 60 s")
        self.trigger_previous = False
        self.edges = 0
        self.tp = TP()
        self.q_previous = False

    def call(self, now_us: int, inputs: dict) -> dict:
        trigger = bool(inputs["trigger"])
        pt_ms = time_s_to_ms(inputs["monitorTime"])
        edge = trigger and not self.trigger_previous  # step 1
        self.trigger_previous = trigger
        q = self.tp(now_us, trigger, pt_ms)  # step 2
        if edge:  # step 3
            self.edges = (self.edges + 1) % 256
        out = {"single": False, "double": False, "long": False, "severalEdges": False}
        n = 0
        if not q and (self.q_previous or trigger):  # step 4
            if self.edges == 0:
                pass
            elif trigger and self.edges == 1:
                out["long"] = True
            elif self.edges == 1:
                out["single"] = True
            elif self.edges == 2:
                out["double"] = True
            else:
                out["severalEdges"] = True
            n = self.edges
        if not q and not trigger:  # step 5
            self.edges = 0
        self.q_previous = q  # step 6
        return {**out, "noOfEdges": n}
