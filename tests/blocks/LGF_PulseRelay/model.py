"""Independent model of LGF_PulseRelay (docs/behaviour.md §11), written from that section only,
never from the C.

Statics (§11.1): statOut and the edge memories triggerOld, setOld, resetOld, all FALSE before
the first call. One call (§11.2):
1. rising `trigger`: statOut := NOT statOut;
2. rising `set`: statOut := TRUE;
3. rising `reset`: statOut := FALSE (so reset > set > trigger, §11.3);
4. the edge memories := the inputs;
5. `out` := statOut.
No error can occur; cycleTime only sets when calls happen (§11).
"""

from tests.models.iec import cycle_us_of


class PulseRelay:
    def __init__(self, cycle_us: int):
        self.cycle_us = cycle_us_of(cycle_us)  # §11.1: not used by the logic
        self.stat_out = False
        self.trigger_old = self.set_old = self.reset_old = False

    def call(self, now_us: int, inputs: dict) -> dict:
        trigger, set_, reset = bool(inputs["trigger"]), bool(inputs["set"]), bool(inputs["reset"])
        if trigger and not self.trigger_old:  # step 1
            self.stat_out = not self.stat_out
        if set_ and not self.set_old:  # step 2
            self.stat_out = True
        if reset and not self.reset_old:  # step 3
            self.stat_out = False
        self.trigger_old, self.set_old, self.reset_old = trigger, set_, reset  # step 4
        return {"out": self.stat_out}  # step 5
