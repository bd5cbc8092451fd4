"""Prints how fast each FMU runs: the cost of one PLC call inside a long doStep, the cost of a
doStep with one call (dominated by the FMI call itself), and how much faster than real time a
100 ms cycle simulates. All figures come from this one run on this machine; compare ratios,
not absolute times, between machines.

    make bench
"""
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))
from blocks import ACTIVE  # noqa: E402
from harness import Slave, built_blocks  # noqa: E402


def best_of(repeats, function):
    return min(function() for _ in range(repeats))


def per_call_in_long_steps(block, calls=200_000):
    def run():
        s = Slave(block, {"cycleTime": 0.001}, ACTIVE[block])
        start = time.perf_counter()
        s.fmu.fmi2DoStep(s.fmu.component, 0.0, calls * 0.001, 1)
        elapsed = time.perf_counter() - start
        s.free()
        return elapsed / calls
    return best_of(3, run)


def per_step_of_one_call(block, steps=50_000):
    def run():
        s = Slave(block, {"cycleTime": 0.1}, ACTIVE[block])
        do_step, component = s.fmu.fmi2DoStep, s.fmu.component
        start = time.perf_counter()
        for i in range(steps):
            t = i * 0.1
            do_step(component, t, (i + 1) * 0.1 - t, 1)
        elapsed = time.perf_counter() - start
        s.free()
        return elapsed / steps
    return best_of(3, run)


def main():
    print(f"{'block':24} {'ns per PLC call':>16} {'µs per doStep':>14} {'doStep/call':>12} {'× real time @100 ms':>20}")
    for block in built_blocks():
        call = per_call_in_long_steps(block)
        step = per_step_of_one_call(block)
        print(f"{block:24} {call * 1e9:16.1f} {step * 1e6:14.2f} {step / call:12.0f} {0.1 / step:20.0f}")


if __name__ == "__main__":
    main()
