"""Independent model of LGF_FloatingAverage, written from the original block's logic (the Siemens
LGF V3.0.1 FB), never from the C. docs/behaviour.md §15 describes the block; where the two
disagree the original wins.

The original's value, window, running sum and average are LREAL (Python float, IEEE double;
the old model, from the manual, used REAL), each operation rounded on its own in its order.

The original, in order, in every call:
1. the edge of trigger, and its memory updated (in every call, before anything can end it);
2. reset, or windowSize different from the previous call's: the counter, the sum and the
   average cleared, the outputs 0.0 / FALSE / FALSE / 16#0000, the size remembered, and the
   call ENDS: no value is read in that call (the old model read one in);
3. else windowSize outside 1 ... 100: the same clearing, error TRUE and status 16#8200, and
   the call ends. A size that becomes invalid is a change first (step 2, no error), so the
   error shows one call later; a size invalid from the first call on that equals the start
   value 0 of the remembered size errors at once;
4. a read-in (cyclicExecution, or the trigger edge), index := counter MOD windowSize:
   filling (counter < windowSize): sum := sum + value, the slot := value, counter + 1,
   average := sum / counter;
   sliding: windowSizeReached's static set TRUE (so it rises with the first read-in that
   replaces a value, the (windowSize + 1)-th, not with the windowSize-th), sum := sum +
   (value - oldest), the slot := value, average := sum / windowSize, and the counter steps on
   (to windowSize + 1 after the slot 0, else + 1: it cycles through windowSize ... 2 windowSize);
5. the outputs: average and windowSizeReached from the statics, error FALSE, status 16#0000.
The window's slots are not cleared by a restart: the filling overwrites each before it is
read as the oldest.
"""

import math

STATUS_OK = 0x0000
STATUS_WRONG_WINDOW_SIZE = 0x8200  # the original's ERR_WRONG_WINDOW_SIZE
MAX_WINDOW_SIZE = 100


class FloatingAverage:
    def __init__(self, cycle_us: int):
        self.cycle_us = int(cycle_us)  # §15: only the period of the calls
        # the original's statics and their start values
        self.statValues = [0.0] * (MAX_WINDOW_SIZE + 1)  # Array[0..100] of LREAL
        self.statValuesSum = 0.0
        self.statArithmeticAverage = 0.0
        self.statWindowSizeOld = 0
        self.statCounter = 0
        self.statwindowSizeReached = False
        self.statTriggerOld = False

    @staticmethod
    def _outputs(average: float, reached: bool, error: bool, status: int) -> dict:
        if math.isnan(average):
            average = math.nan  # §1.4: got as the positive quiet NaN
        return {
            "average": average,
            "windowSizeReached": reached,
            "error": error,
            "status": status,
        }

    def _clear(self, window: int) -> None:
        self.statWindowSizeOld = window
        self.statCounter = 0
        self.statValuesSum = 0.0
        self.statArithmeticAverage = 0.0
        self.statwindowSizeReached = False

    def call(self, now_us: int, inputs: dict) -> dict:
        cyclic = bool(inputs["cyclicExecution"])
        trigger = bool(inputs["trigger"])
        value = float(inputs["value"])
        window = int(inputs["windowSize"])
        reset = bool(inputs["reset"])

        trigger_edge = trigger and not self.statTriggerOld
        self.statTriggerOld = trigger

        if reset or window != self.statWindowSizeOld:
            self._clear(window)
            return self._outputs(0.0, False, False, STATUS_OK)  # nothing read in this call
        if window <= 0 or window > MAX_WINDOW_SIZE:
            self._clear(window)
            return self._outputs(0.0, False, True, STATUS_WRONG_WINDOW_SIZE)

        if cyclic or trigger_edge:
            index = self.statCounter % window  # counter >= 0, window >= 1: MOD as in S7
            if self.statCounter < window:
                self.statValuesSum = self.statValuesSum + value
                self.statValues[index] = value
                self.statCounter += 1
                self.statArithmeticAverage = self.statValuesSum / float(self.statCounter)
            else:
                self.statwindowSizeReached = True
                self.statValuesSum = self.statValuesSum + (value - self.statValues[index])
                self.statValues[index] = value
                self.statArithmeticAverage = self.statValuesSum / float(window)
                if index == 0:
                    self.statCounter = window + 1
                else:
                    self.statCounter += 1

        return self._outputs(
            self.statArithmeticAverage, self.statwindowSizeReached, False, STATUS_OK
        )
