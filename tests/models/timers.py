"""Independent models of the S7 IEC timers TON, TOF and TP (docs/behaviour.md §1.12), for the
models of the blocks that time something (tests/blocks/<Block>/model.py). Written from
docs/behaviour.md §1.12 and the timer rules the block sections repeat (§8.2, §9.2, §10.2, §12.2,
§13.2), never from the C.

Rules (the docs/behaviour.md sentence behind each in quotes):

T1  Time. "Their elapsed time is the simulated time of the calls, measured in µs, so a timer
    elapses in the first call at or after its start + PT." A timer is executed with the call
    time `now_us` (an integer) and elapsed means now_us − start_us ≥ PT · 1000 (§8.2: "with
    the call time t_k in µs and PT in ms × 1000").
T2  PT. "The instruction writes PT into its instance at the edge of IN that starts the timer
    (the rising edge for TON and TP, the falling edge for TOF) and keeps it while the timer
    runs." "Negative PT values are set to zero": PT taken = max(PT, 0), in whole ms (a TIME).
T3  Edges. Each timer keeps the IN of its previous execution, FALSE before its first execution
    (§8.2: "each keeps the IN of its previous execution (FALSE before the first call)"). A
    timer that is not executed in a call (§9.2 step 1, §10.2 step 1) keeps everything.
T4  TON: "Q once IN has been TRUE for PT; IN FALSE resets Q and ET." Q = IN AND elapsed (§8.2);
    a PT of 0 gives Q in the rising call itself (§1.12 Decisions).
T5  TOF: "Q while IN is TRUE and for PT after it falls; IN TRUE again resets the timer." A falling
    edge starts it; IN TRUE stops it; Q = IN OR (it runs AND NOT elapsed) (§8.2, §9.2). A PT of
    0 gives no pulse beyond the edge. Before its first falling edge it does not run: IN FALSE
    then gives Q FALSE.
T6  TP: "a pulse of PT from a rising edge of IN, edges during the pulse are ignored, ET stays at
    PT after the pulse until IN is FALSE." Q is TRUE from the starting call until the first call
    at or after start + PT, exclusive (§12.2). A rising edge in the call in which the pulse ends
    starts the next pulse at once (§12.3: "the TP restarts, q stays TRUE"): the model first ends
    an elapsed pulse, then looks at the edge. A PT of 0 gives no pulse at all.
T7  ET: "ET counts whole ms up to PT and stays there": ET = min((now_us − start_us) DIV 1000,
    PT taken) while it counts; TON: 0 while IN is FALSE; TOF: 0 while IN is TRUE (§9.2: "0 while
    it does not run (IN TRUE), else the whole ms since its start, at most the PT it took"), and
    0 before its first start; TP: 0 once the pulse is over and IN is FALSE.
T8  RESET_TIMER (§10.2 step 2.1): "not running, IN memory FALSE, PT 0, ET 0".

T9  Update on read (§1.12): "A timer is updated when its instruction is executed *and*
    whenever the program reads its `Q` or `ET`"; "Within one PLC call every read sees that
    call's time". `q_at(now_us)` and `et_at(now_us)` are such reads: what Q and ET would be
    at `now_us` with the IN of the timer's last execution (its IN memory, T3), changing
    nothing (every later read or execution recomputes from the same start and the time, so a
    read that ends a pulse is the same as the next execution ending it).

Decision where §1.12 leaves room: "whole ms since its start" (T7) is taken as the elapsed µs
truncated to ms (a cycle of 3300 µs gives ET 3 ms after one call, 6 ms after two).
"""

from __future__ import annotations


def _pt(pt_ms: int) -> int:
    """T2: the PT taken at a starting edge, a negative one as 0."""
    return max(int(pt_ms), 0)


class _Timer:
    def __init__(self):
        self.reset()

    def reset(self) -> None:
        """T8 (and the state before the first call, T3): not running, IN memory FALSE, PT 0."""
        self.in_prev = False  # T3
        self.running = False
        self.pt_ms = 0  # PT taken at the last start (T2)
        self.start_us = 0
        self.q = False
        self.et_ms = 0

    def _elapsed(self, now_us: int) -> bool:
        return now_us - self.start_us >= self.pt_ms * 1000  # T1

    def _et(self, now_us: int) -> int:
        return min((now_us - self.start_us) // 1000, self.pt_ms)  # T7

    def _start(self, now_us: int, pt_ms: int) -> None:
        self.running = True
        self.start_us = int(now_us)
        self.pt_ms = _pt(pt_ms)


class TON(_Timer):
    """T4: on delay."""

    def __call__(self, now_us: int, in_: bool, pt_ms: int) -> bool:
        in_ = bool(in_)
        if in_ and not self.in_prev:
            self._start(now_us, pt_ms)  # rising edge: start, take PT (T2)
        if in_:
            self.q = self._elapsed(now_us)
            self.et_ms = self._et(now_us)
        else:
            self.running = False  # IN FALSE resets Q and ET
            self.q = False
            self.et_ms = 0
        self.in_prev = in_
        return self.q

    def q_at(self, now_us: int) -> bool:
        """T9: Q read at `now_us` between executions: IN (memory) AND elapsed."""
        return self.in_prev and self._elapsed(now_us)

    def et_at(self, now_us: int) -> int:
        """T9: ET read at `now_us`: 0 while IN (memory) is FALSE."""
        return self._et(now_us) if self.in_prev else 0


class TOF(_Timer):
    """T5: off delay."""

    def __call__(self, now_us: int, in_: bool, pt_ms: int) -> bool:
        in_ = bool(in_)
        if in_:
            self.running = False  # IN TRUE stops it
            self.q = True
            self.et_ms = 0
        else:
            if self.in_prev:
                self._start(now_us, pt_ms)  # falling edge: start, take PT (T2)
            if self.running:
                self.q = not self._elapsed(now_us)
                self.et_ms = self._et(now_us)
            else:
                self.q = False  # never started since IN was last TRUE (or reset)
                self.et_ms = 0
        self.in_prev = in_
        return self.q

    def q_at(self, now_us: int) -> bool:
        """T9: Q read at `now_us` between executions: IN (memory) OR (runs AND NOT elapsed)."""
        return self.in_prev or (self.running and not self._elapsed(now_us))

    def et_at(self, now_us: int) -> int:
        """T9: ET read at `now_us`: 0 while IN (memory) is TRUE or it never started."""
        return self._et(now_us) if self.running and not self.in_prev else 0


class TP(_Timer):
    """T6: pulse."""

    def __call__(self, now_us: int, in_: bool, pt_ms: int) -> bool:
        in_ = bool(in_)
        if self.running and self._elapsed(now_us):
            self.running = False  # the pulse ends in this call
        if in_ and not self.in_prev and not self.running:
            self._start(now_us, pt_ms)  # rising edge while no pulse runs (T2)
            if self._elapsed(now_us):
                self.running = False  # PT 0: no pulse at all
        if self.running:
            self.q = True
            self.et_ms = self._et(now_us)
        else:
            # T7: after a pulse ET stays at PT until IN is FALSE. With IN TRUE and no pulse
            # running, a pulse has run since IN rose (the rising edge started one, or a pulse was
            # running then and has ended), so ET is the PT it took.
            self.q = False
            self.et_ms = self.pt_ms if in_ else 0
        self.in_prev = in_
        return self.q

    def q_at(self, now_us: int) -> bool:
        """T9: Q read at `now_us` between executions: the pulse runs and has not elapsed."""
        return self.running and not self._elapsed(now_us)

    def et_at(self, now_us: int) -> int:
        """T9: ET read at `now_us`: counting during the pulse, then PT while IN (memory) is
        TRUE, 0 once IN is FALSE (T7)."""
        if self.q_at(now_us):
            return self._et(now_us)
        return self.pt_ms if self.in_prev else 0
