"""Reference model of LGF_RampCI (docs/behaviour.md §4, seed 004), written from
docs/behaviour.md only.

All times are integer milliseconds inside (docs/behaviour.md §1.4: IEC TIME); the FMI side uses
float seconds, converted by the shared TIME helpers of tests/models/iec.py.
One call() is one PLC call and follows docs/behaviour.md §4.3 steps 1..6 in order.
"""

import math
import re

import numpy as np

from tests.models.iec import TIME_MS_MAX, TIME_MS_MIN, time_ms_to_s, time_s_to_ms

MAX_SETPOINTS = 64  # docs/behaviour.md §4.1: numberOfSetpoints 2 .. 64

STATUS_WORKING = 0x7000  # docs/behaviour.md §4.3: working status at the start of each call
STATUS_START = 0x7001  # step 1: rising edge of start
STATUS_CYCLIC = 0x7002  # step 3e: cyclic wrap call
STATUS_DONE = 0x0000  # step 2 (reset) and step 3e (last point reached)


def _real(ms: int) -> float:
    """REAL(x) of a TIME/UDINT count of ms: the nearest float32 (halves to even), widened to
    double for the LREAL arithmetic (docs/behaviour.md §4.3 c); exact up to 2^24 ms)."""
    return float(np.float32(ms))


def _sat(ms: int) -> int:
    """Sums of times are computed without overflow and saturate at the largest TIME (§4.3)."""
    return max(TIME_MS_MIN, min(TIME_MS_MAX, ms))


# --- the block -----------------------------------------------------------------------------------


class RampCI:
    def __init__(self, cycle_us: int, params: dict | None = None):
        # docs/behaviour.md §4.2: cycleTime 1 ms .. 60 s; Ts = cycle in whole ms, truncated.
        cycle_us = int(cycle_us)
        if not 1000 <= cycle_us <= 60_000_000:
            raise ValueError(f"cycleTime {cycle_us} us outside 1 ms .. 60 s")
        self.ts = cycle_us // 1000

        # docs/behaviour.md §4.1: default table 0 -> 100 in 5 s, hold 10 s, -> 0 in 5 s.
        self.n = 4
        self.values = [0.0] * MAX_SETPOINTS
        self.times = [0] * MAX_SETPOINTS
        for i, (v, t) in enumerate([(0.0, 5000), (100.0, 10000), (100.0, 5000), (0.0, 0)]):
            self.values[i], self.times[i] = v, t
        for name, value in (params or {}).items():
            self.set(name, value)

        # Statics of the block.
        self.prev_out = 0.0  # previous output (step 6)
        self.target = 0.0
        self.step_number = 0
        self.remain_time = 0  # ms
        self.total_time = 0  # ms
        self.remain_total_time = 0  # ms
        self.act_time_table = False
        self.init_run = False  # "initialise run" mark
        self.blocked = False  # "blocked" mark (step 2)
        # docs/behaviour.md §4.3: edge memories start FALSE.
        self.start_mem = False
        self.reset_mem = False
        self.update_mem = False

    # Tunable parameters (docs/behaviour.md §4.1), FMI names. Invalid values raise ValueError, not
    # applied (§4.6).
    def set(self, name: str, value) -> None:
        if name == "numberOfSetpoints":
            value = int(value)
            if not 2 <= value <= MAX_SETPOINTS:
                raise ValueError(f"numberOfSetpoints {value} outside 2 .. {MAX_SETPOINTS}")
            self.n = value
            return
        m = re.fullmatch(r"setpoints\[(\d+)\]\.(outputValue|time)", name)
        if not m or int(m.group(1)) >= MAX_SETPOINTS:
            raise KeyError(name)
        i = int(m.group(1))
        if m.group(2) == "outputValue":
            value = float(value)
            if math.isnan(value):
                raise ValueError(f"{name}: NaN")
            self.values[i] = value
        else:
            ms = time_s_to_ms(value)
            if ms < 0:
                raise ValueError(f"{name}: negative time {value}")
            self.times[i] = ms

    # --- helpers ---
    @property
    def last(self) -> int:
        return self.n - 1

    def _sum_times(self, first: int) -> int:
        """Sum of the times of table entries first .. last, unbounded (Python int)."""
        return sum(self.times[first : self.n])

    # --- one PLC call (docs/behaviour.md §4.3) ---
    def call(self, now_us: int, inputs: dict) -> dict:
        default_out = float(inputs["defaultOutValue"])
        cont_step_nbr = int(inputs["contStepNbr"])
        cont_step_time = time_s_to_ms(inputs["contStepTime"])
        en_default = bool(inputs["enDefaultOutValue"])
        start = bool(inputs["start"])
        hold = bool(inputs["hold"])
        cont = bool(inputs["continue"])
        cyclic = bool(inputs["cyclicOP"])
        update_time = bool(inputs["updateTime"])
        reset = bool(inputs["reset"])
        # docs/behaviour.md §4.6: invalid inputs are rejected by the FMU, so they cannot reach the
        # block.
        if not 0 <= cont_step_nbr <= self.last:
            raise ValueError(f"contStepNbr {cont_step_nbr} outside 0 .. {self.last}")
        if cont_step_time < 0:
            raise ValueError(f"contStepTime {inputs['contStepTime']} < 0")

        ts = self.ts
        status = STATUS_WORKING
        # Edge detection; memories are updated every call.
        start_edge = start and not self.start_mem
        reset_edge = reset and not self.reset_mem
        update_edge = update_time and not self.update_mem
        self.start_mem, self.reset_mem, self.update_mem = start, reset, update_time

        out = self.prev_out

        # Step 1: rising edge of start.
        if start_edge:
            status = STATUS_START
            self.init_run = True
            self.total_time = _sat(self._sum_times(0))
            self.remain_total_time = self.total_time
            self.blocked = False

        # Step 2: rising edge of reset.
        if reset_edge:
            status = STATUS_DONE
            self.total_time = _sat(self._sum_times(0))
            out = 0.0
            self.remain_total_time = self.total_time
            self.target = 0.0
            self.step_number = 0
            self.remain_time = 0
            self.init_run = True
            self.act_time_table = False
            self.blocked = True

        # Step 3: operation only if start AND NOT blocked.
        if start and not self.blocked:
            if self.init_run:
                # a) initialise run (clears the mark).
                self.init_run = False
                out = self.values[0]
                self.target = self.values[1]
                self.remain_time = self.times[0]
                self.remain_total_time = self.total_time
                self.step_number = 1
                self.act_time_table = True
            elif hold:
                # b) hold: output frozen at the previous output, times frozen.
                self.act_time_table = False
                out = self.prev_out
                if cont:
                    self.target = self.values[cont_step_nbr]
                    self.remain_time = cont_step_time
                    self.step_number = cont_step_nbr
                    self.remain_total_time = _sat(cont_step_time + self._sum_times(cont_step_nbr))
            elif self.remain_time > ts:
                # c) interpolate: prev + (target - prev) / REAL(remainTime_ms) * REAL(Ts), in
                # this order; the rest time and the cycle are rounded to float32 first, the
                # arithmetic is LREAL (visible once remainTime exceeds 2^24 ms).
                out = self.prev_out + (self.target - self.prev_out) / _real(
                    self.remain_time
                ) * _real(ts)
                self.remain_time -= ts
                self.remain_total_time = _sat(self.remain_total_time - ts)
            elif self.step_number < self.last:
                # d) snap onto the reached point, head for the next one.
                out = self.values[self.step_number]
                self.target = self.values[self.step_number + 1]
                self.remain_time = self.times[self.step_number]
                self.step_number += 1
                self.act_time_table = True
                self.remain_total_time = _sat(self.remain_total_time - ts)
            else:
                # e) last point reached (remainTime := 0 as in the 4.3 worked example).
                status = STATUS_DONE
                self.remain_total_time = 0
                self.remain_time = 0
                out = self.values[self.last]
                if cyclic:
                    self.init_run = True
                    status = STATUS_CYCLIC
                else:
                    self.act_time_table = False
        else:
            out = 0.0
            self.act_time_table = False

        # Step 4: rising edge of updateTime.
        if update_edge:
            self.total_time = _sat(self._sum_times(0))
            self.remain_total_time = _sat(self.remain_time + self._sum_times(self.step_number))

        # Step 5: default output value; time processing went on underneath.
        if en_default:
            out = default_out
            self.act_time_table = False

        # Step 6: write outputs.
        self.prev_out = out
        return {
            "outputValue": out,
            "actTimeTable": self.act_time_table,
            "stepNumber": self.step_number,
            "remainTime": time_ms_to_s(self.remain_time),
            "totalTime": time_ms_to_s(self.total_time),
            "remainTotalTime": time_ms_to_s(self.remain_total_time),
            "error": False,
            "status": status,
            "subFunctionStatus": 0,
        }
