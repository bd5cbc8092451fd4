"""Runs of LGF_RectangleCI worked out by hand from docs/behaviour.md §6 (not by running the
model), for the FMU tests (test_rectangle_ci.py) and the model tests (test_model_rectangle_ci.py).

Per call without reset: counter := (counter + Ts) MOD periode; ps := REAL_TO_UDINT(phaseShift)
MOD periode; value := offset + amplitude if ps <= counter < periode DIV 2 + ps, else
offset − amplitude (float32 sums). With reset: counter := ps, value := 0.0.
"""

import math

from tests.signal_generators import run

H, L = 1.0, -1.0  # amplitude 1, offset 0: offset + amplitude, offset − amplitude


# --- cycleTime 0.1 s, periode 1000, phaseShift 0: high for counter 0 ... 499 ---
# counter: 100 200 300 400 500 600 700 800 900   0 100
TYPICAL = run(0.1, {}, [H, H, H, H, L, L, L, L, L, H, H])  # 5 of 10 calls high: 50 %

# --- phaseShift beyond half a periode: the high window [ps, periode DIV 2 + ps) is not wrapped ---
# ps 700: high for counter 700 ... 999 only (1200 is never reached): 3 of 10 calls, 30 %
# counter: 100 200 300 400 500 600 700 800 900   0 100
PHASE_700 = run(0.1, {"phaseShift": 700.0}, [L, L, L, L, L, L, H, H, H, L, L])
PHASE_1700 = run(0.1, {"phaseShift": 1700.0}, PHASE_700.expected)  # 1700 MOD 1000 = 700
# ps 600: high for 600 ... 999: 4 of 10, 40 %; ps 500 = periode / 2: 500 ... 999, 50 %
PHASE_600 = run(0.1, {"phaseShift": 600.0}, [L, L, L, L, L, H, H, H, H, L, L])
PHASE_500 = run(0.1, {"phaseShift": 500.0}, [L, L, L, L, H, H, H, H, H, L, L])
# ps 200 (below half): high for 200 ... 699, 50 %
PHASE_200 = run(0.1, {"phaseShift": 200.0}, [L, H, H, H, H, H, L, L, L, L, L])

# --- reset: counter := REAL_TO_UDINT(phaseShift) MOD periode, value := 0.0 (not the offset) ---
# offset 5, amplitude 2, phaseShift 1700 (ps 700): high 7.0, low 3.0
# call 0: counter 100 -> 3.0; call 1 (reset): counter 700, value 0.0; call 2: counter 800 -> 7.0;
# call 3: 900 -> 7.0; call 4: 0 -> 3.0; call 5: 100 -> 3.0
RESET = run(
    0.1,
    {"offset": 5.0, "amplitude": 2.0, "phaseShift": 1700.0},
    [3.0, 0.0, 7.0, 7.0, 3.0, 3.0],
    {1: {"reset": True}, 2: {"reset": False}},
)
# reset held for two calls: counter stays 700 (it is set, not advanced), value 0.0
RESET_HELD = run(
    0.1,
    {"offset": 5.0, "amplitude": 2.0, "phaseShift": 700.0},
    [3.0, 0.0, 0.0, 7.0, 7.0, 3.0],
    {1: {"reset": True}, 3: {"reset": False}},
)

# --- REAL_TO_UDINT rounds halves to even: cycleTime 1 ms (Ts 1), periode 10 (high 5 counts) ---
# phaseShift 2.5 -> ps 2: high for counter 2 ... 6; counter: 1 2 3 4 5 6 7 8 9 0 1
HALF_TO_EVEN_DOWN = run(
    0.001, {"periode": 10, "phaseShift": 2.5}, [L, H, H, H, H, H, L, L, L, L, L]
)
# phaseShift 3.5 -> ps 4: high for counter 4 ... 8
HALF_TO_EVEN_UP = run(0.001, {"periode": 10, "phaseShift": 3.5}, [L, L, L, H, H, H, H, H, L, L, L])

# --- an odd periode: periode / 2 is an integer division, 7 DIV 2 = 3: high for counter 0, 1, 2 ---
# counter: 1 2 3 4 5 6 0 1 2
ODD_PERIODE = run(0.001, {"periode": 7}, [H, H, L, L, L, L, H, H, H])

# --- cycleTime 1.5 ms runs on Ts = 1 ms: periode 10, high for counter 0 ... 4 ---
# counter: 1 2 3 4 5 6 7 8 9 0 1   (with Ts = 2 ms it would be 2 4 6 8 0 ...)
TRUNCATED_CYCLE = run(0.0015, {"periode": 10}, [H, H, H, H, L, L, L, L, L, H, H])

# --- the sums are float32: offset 0.1, amplitude 0.2 ---
# float32(0.1) = 0.100000001490116119384765625, float32(0.2) = 0.20000000298023223876953125
# (exactly twice it); high: fl(0.30000000447034836) = 0.30000001192092896 (ulp 2^-25 in
# [0.25, 0.5)); low: 0.1f − 0.2f = -0.10000000149011612 exactly. (Double: 0.30000000000000004.)
FLOAT32_SUMS = run(
    0.1,
    {"offset": 0.1, "amplitude": 0.2},
    [0.30000001192092896] * 4 + [-0.10000000149011612] * 5 + [0.30000001192092896],
)

# --- infinities follow IEEE float32 ---
INFINITE_AMPLITUDE = run(
    0.1, {"amplitude": math.inf, "offset": 1.0}, [math.inf] * 4 + [-math.inf] * 5 + [math.inf]
)
BOTH_INFINITE = run(
    0.1, {"amplitude": math.inf, "offset": math.inf}, [math.inf] * 4 + [math.nan] * 5 + [math.inf]
)  # Inf − Inf = NaN


# --- duty cycle over many calls: cycleTime 1 ms, periode 100: ps p > 50 is high 100 − p of 100 ---
DUTY = {0.0: 50, 30.0: 50, 50.0: 50, 51.0: 49, 70.0: 30, 99.0: 1, 170.0: 30}
