"""Reference model of LGF_SawTooth (docs/behaviour.md §2, seed 000)."""
from .iec import int16, check_int, time_s_to_ms


class SawTooth:
    def __init__(self, cycle_us: int, plcTiming: bool = False):
        self.cycle_us = int(cycle_us)       # §1.1 (not used by the logic: times come as now_us)
        self.plcTiming = bool(plcTiming)    # docs/behaviour.md §2.4, §2.5
        self.first = True
        # latched parameters (docs/behaviour.md §2.2)
        self.startValue = 0
        self.timeRange_ms = 0
        self.increment = 0
        self.numberSteps = 0
        self.endless = False
        # state
        self.value = 0
        self.count = 0        # steps within the current tooth (non-endless)
        self.t_ref_us = 0     # documented timing: time of the last latching call
        self.m = 0            # documented timing: steps since the last latching call
        # PLC-exact timing: IEC TON + the TON output remembered from the previous call
        self.q_prev = False
        self.ton_in = False
        self.ton_start_us = 0
        self.ton_q = False

    def _latch(self, now_us: int, inputs: dict) -> None:
        # §2.2: copy the five parameter inputs, value = startValue, step count restarts.
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
        # docs/behaviour.md §2.3.
        if self.endless:
            self.value = int16(self.value + self.increment)       # wraps 32767 -> -32768
        elif self.count < self.numberSteps:
            self.count += 1
            self.value = int16(self.value + self.increment)
        else:                                                      # numberSteps <= 0: constant
            self.count = 0
            self.value = self.startValue

    def _ton(self, now_us: int, in_: bool, pt_ms: int) -> bool:
        # IEC on-delay timer measured in simulation time (us); PT < 0 behaves like 0.
        if not in_:
            self.ton_in = False
            self.ton_q = False
            return False
        if not self.ton_in:                  # rising IN: start timing now
            self.ton_in = True
            self.ton_start_us = now_us
        self.ton_q = (now_us - self.ton_start_us) >= max(pt_ms, 0) * 1000
        return self.ton_q

    def call(self, now_us: int, inputs: dict) -> dict:
        now_us = int(now_us)
        latching = self.first or bool(inputs["reset"])
        self.first = False

        if self.plcTiming:
            # §2.5, plcTiming true: (a) latch or step on the TON output of the previous call,
            # (b) TON with IN := NOT q_prev, PT := latched timeRange, (c) remember Q.
            # A reset does not restart the timer.
            if latching:
                self._latch(now_us, inputs)
            elif self.q_prev:
                self._step()
            self.q_prev = self._ton(now_us, not self.q_prev, self.timeRange_ms)
        else:
            # §2.4, plcTiming false: step m at the first call with now >= t_ref + m*timeRange,
            # at most one step per call; m counts from the last latching call.
            if latching:
                self._latch(now_us, inputs)
            elif now_us >= self.t_ref_us + (self.m + 1) * self.timeRange_ms * 1000:
                self.m += 1
                self._step()

        return {"value": self.value}
