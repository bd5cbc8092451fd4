"""Reference model of LGF_SawTooth (docs/behaviour.md §2, seed 000), written from the behaviour
contract only.

One call, as docs/behaviour.md §2 describes it:

Latching ("Latching"). On the first call and on every call in which `reset` is TRUE (a level,
not an edge) the five parameter inputs startValue, timeRange, incrementRange, numberSteps and
endlessSteps are copied into the block; value := startValue and the step count restarts (:= 0).
Input changes at other times have no effect.

A step ("Steps", "Step counter"). The step count is an INT:
    count := count + 1                 (INT arithmetic: 32767 + 1 = -32768, docs/behaviour.md §1.4)
    if not endless and count > numberSteps:
        value := startValue; count := 0              (the tooth starts again)
    else:
        value := value + incrementRange  (INT arithmetic, wraps 32767 -> -32768)
So the levels are startValue, startValue+inc, ..., startValue+numberSteps*inc, then startValue
again; numberSteps <= 0 gives a constant output (the first step already has count 1 > numberSteps);
numberSteps = 32766 returns after 32767 steps (count 32767 > 32766); numberSteps = 32767 never
returns, because the count wraps from 32767 to -32768 and no INT exceeds 32767: the tooth is
endless, and value goes on adding incrementRange with INT wrap-around.

When a step happens ("When steps happen", parameter plcTiming):
- plcTiming false (documented timing): t_ref is the time of the last latching call; step m
  (m = 1, 2, ... counted from that call) happens at the first call at or after
  t_ref + m*timeRange, at most one step per call. A latching call never steps.
  timeRange = 0 steps on every (non-latching) call; a negative timeRange is treated like 0
  (the contract is silent; t_ref + m*timeRange <= now always holds).
- plcTiming true (PLC-exact): an IEC TON in simulation time, in the original's order:
    (1) latch if first call or reset;
    (2) if the TON's Q of the previous call is TRUE and reset is FALSE: step, and the TON's IN
        is FALSE in this call;
    (3) run the TON with IN (TRUE in every other call, including every reset call) and
        PT = the latched timeRange (read in this call, after a latch); its Q is used next call.
  So a reset call never steps and never stops/restarts the timer; if the timer elapses while
  reset is held, the first call after reset is released steps at once.
  The TON is an S7-1200/1500 IEC timer (docs/behaviour.md §2.5): it takes PT over at the rising
  edge of IN and keeps that PT until IN falls, so a timeRange latched by a reset while the timer
  runs reaches the timer only at its next start (the call after the next step; the step in
  progress keeps the old time). A negative PT is taken as 0, and a PT <= 0 at the edge gives Q
  in that same call. A reset call that is itself the call of a rising edge (the call right after
  a step) latches first, so that start already takes the new timeRange.
"""

from tests.models.iec import check_int, int16, time_s_to_ms


class SawTooth:
    def __init__(self, cycle_us: int, plcTiming: bool = False):
        self.cycle_us = int(
            cycle_us
        )  # docs/behaviour.md §1.1 (not used by the logic: times come as now_us)
        self.plcTiming = bool(plcTiming)  # §2 "When steps happen"
        self.first = True
        # latched parameters (§2 "Latching")
        self.startValue = 0
        self.timeRange_ms = 0
        self.increment = 0
        self.numberSteps = 0
        self.endless = False
        # state
        self.value = 0
        self.count = 0  # §2 "Step counter": an INT, steps within the current tooth
        self.t_ref_us = 0  # documented timing: time of the last latching call
        self.m = 0  # documented timing: steps since the last latching call
        # PLC-exact timing: IEC TON (IN memory, start time, PT taken over at the start, Q) + Q
        # remembered from the previous call
        self.q_prev = False
        self.ton_in = False
        self.ton_start_us = 0
        self.ton_pt_ms = 0
        self.ton_q = False

    def _latch(self, now_us: int, inputs: dict) -> None:
        # §2 Latching: copy the five parameter inputs, value = startValue, step count restarts.
        self.startValue = check_int("startValue", inputs["startValue"])
        self.timeRange_ms = time_s_to_ms(inputs["timeRange"])
        self.increment = check_int("incrementRange", inputs["incrementRange"])
        self.numberSteps = check_int("numberSteps", inputs["numberSteps"])
        self.endless = bool(inputs["endlessSteps"])
        self.value = self.startValue
        self.count = 0
        self.t_ref_us = now_us
        self.m = 0

    def _step(self) -> None:
        # §2 Steps + Step counter: the INT count is incremented (with wrap) and compared
        # afterwards; "returns to startValue when the count exceeds numberSteps".
        self.count = int16(self.count + 1)
        if not self.endless and self.count > self.numberSteps:
            self.count = 0
            self.value = self.startValue
        else:
            self.value = int16(self.value + self.increment)  # wraps 32767 -> -32768

    def _ton(self, now_us: int, in_: bool, pt_ms: int) -> bool:
        # IEC on-delay timer measured in simulation time (us), docs/behaviour.md §2.5.
        # IN FALSE: Q FALSE and the timer stops; rising IN: timing starts at this call and the
        # timer takes PT over (a negative PT is set to 0); while IN stays TRUE the PT of that
        # edge is kept whatever pt_ms is now, and Q = elapsed >= that PT (so PT 0: Q at the edge).
        if not in_:
            self.ton_in = False
            self.ton_q = False
            return False
        if not self.ton_in:  # rising IN: start timing now with this call's PT
            self.ton_in = True
            self.ton_start_us = now_us
            self.ton_pt_ms = max(pt_ms, 0)
        self.ton_q = (now_us - self.ton_start_us) >= self.ton_pt_ms * 1000
        return self.ton_q

    def call(self, now_us: int, inputs: dict) -> dict:
        now_us = int(now_us)
        reset = bool(inputs["reset"])
        latching = self.first or reset
        self.first = False

        if self.plcTiming:
            # docs/behaviour.md §2, plcTiming true, in the original's order (1) (2) (3).
            if latching:  # (1)
                self._latch(now_us, inputs)
            stepping = self.q_prev and not reset  # (2)
            if stepping:
                self._step()
            # (3) IN is FALSE only in a call that stepped; PT = the latched timeRange, which the
            # TON takes over only at a rising IN.
            self.q_prev = self._ton(now_us, not stepping, self.timeRange_ms)
        else:
            # docs/behaviour.md §2, plcTiming false: step m at the first call with
            # now >= t_ref + m*timeRange, at most one step per call; m counts from the last
            # latching call.
            if latching:
                self._latch(now_us, inputs)
            elif now_us >= self.t_ref_us + (self.m + 1) * self.timeRange_ms * 1000:
                self.m += 1
                self._step()

        return {"value": self.value}
