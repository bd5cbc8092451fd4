"""Runs of LGF_CosinusCI worked out by hand from docs/behaviour.md §6 (not by running the
model), for the FMU tests (test_cosinus_ci.py) and the model tests (test_model_cosinus_ci.py).

The arguments x are those of LGF_SinusCI (tests/blocks/LGF_SinusCI/traces.py, where they are
derived): x := fl(fl(fl(REAL(counter) · T) / P) + fl(fl(phaseShift · T) / P)), T = float32
6.283185005187988; value := fl(fl(COS(x) · amplitude) + offset). COS(x) is the correctly rounded
float32 of the cosine of the float32 x (a 60-digit reference), which the FMU must meet within
one float32 ulp (docs/behaviour.md §6).
"""

import math

from tests.signal_generators import run

ULPS = 1


# --- cycleTime 0.1 s, periode 1000, amplitude 1, offset 0, phaseShift 0 ---
# counter  x                      COS(x)
#   100    0.6283184885978699     0.80901700258255
#   200    1.2566369771957397     0.3090170621871948
#   300    1.8849554061889648    -0.3090168237686157
#   400    2.5132739543914795    -0.8090168833732605
#   500    3.141592502593994     -1.0
#   600    3.7699108123779297    -0.8090172410011292
#   700    4.398229598999023     -0.3090170919895172
#   800    5.026547908782959      0.3090166747570038
#   900    5.654866695404053      0.8090169429779053
#     0    0.0                    1.0 (exactly)
TYPICAL_VALUES = [
    0.80901700258255,
    0.3090170621871948,
    -0.3090168237686157,
    -0.8090168833732605,
    -1.0,
    -0.8090172410011292,
    -0.3090170919895172,
    0.3090166747570038,
    0.8090169429779053,
    1.0,
    0.80901700258255,
]
TYPICAL = run(0.1, {}, TYPICAL_VALUES)

# --- the first computed sample is at counter = Ts (not COS(0) = 1): cycleTime 0.05 s ---
# counter 50, 100, 150, 200, 250 (x = 1.570796251296997, just below π/2:
# COS = 7.549790126404332e-08)
FIRST_SAMPLE = run(
    0.05,
    {},
    [
        0.9510565400123596,
        0.80901700258255,
        0.5877853035926819,
        0.3090170621871948,
        7.549790126404332e-08,
        -0.3090168237686157,
    ],
)

# --- reset: counter := 0, value := 0.0 (not the offset); amplitude 2, offset 5 ---
# counter 100: fl(2 · 0.80901700258255) + 5 = fl(6.6180340051651) = 6.6180338859558105
# counter 200: fl(2 · 0.3090170621871948 + 5) = 5.618034362792969
RESET = run(
    0.1,
    {"amplitude": 2.0, "offset": 5.0},
    [6.6180338859558105, 0.0, 0.0, 6.6180338859558105, 5.618034362792969],
    {1: {"reset": True}, 3: {"reset": False}},
)

# --- phaseShift 250 ms: the arguments of LGF_SinusCI's PHASE_250 ---
# counter 500: x = 4.71238899230957, COS = 1.1924880638503055e-08; counter 0: x =
# 1.570796251296997, COS = 7.549790126404332e-08
PHASE_250 = run(
    0.1,
    {"phaseShift": 250.0},
    [
        -0.5877851843833923,
        -0.9510564208030701,
        -0.9510565996170044,
        -0.5877854228019714,
        1.1924880638503055e-08,
        0.5877847075462341,
        0.9510563611984253,
        0.9510565996170044,
        0.5877851843833923,
        7.549790126404332e-08,
        -0.5877851843833923,
    ],
)

# --- a fractional phaseShift enters as the REAL: 0.5 ms, shift 0.003141592489555478 ---
PHASE_FRACTION = run(
    0.1,
    {"phaseShift": 0.5},
    [
        0.8071664571762085,
        0.30602768063545227,
        -0.31200316548347473,
        -0.8108595013618469,
        -0.9999950528144836,
        -0.8071666359901428,
        -0.30602791905403137,
        0.3120028078556061,
        0.8108594417572021,
        0.9999950528144836,
    ],
)

# --- a huge phaseShift (4294967040): x = 26986072.0, 26986074.0 (three times), 26986076.0 ---
HUGE_PHASE = run(
    0.1,
    {"phaseShift": 4294967040.0},
    [
        0.021573465317487717,
        0.9001080989837646,
        0.9001080989837646,
        0.9001080989837646,
        -0.7707276940345764,
    ],
)

# --- cycleTime 1.5 ms runs on Ts = 1 ms, periode 10: counter 1, 2, ..., 9, 0, 1 ---
TRUNCATED_CYCLE = run(
    0.0015,
    {"periode": 10},
    [
        0.80901700258255,
        0.3090170621871948,
        -0.30901703238487244,
        -0.8090168833732605,
        -1.0,
        -0.8090169429779053,
        -0.3090170919895172,
        0.3090166747570038,
        0.8090166449546814,
        1.0,
        0.80901700258255,
    ],
)

# --- amplitude 4 (a power of two: the product is exact) ---
AMPLITUDE_4 = run(
    0.1, {"amplitude": 4.0}, [3.2360680103302, 1.2360682487487793, -1.236067295074463]
)

# --- infinities: COS of a float32 is never 0, so amplitude -Inf gives ∓Inf, never NaN ---
# the signs of TYPICAL: + + − − − − − + + +
INFINITE_AMPLITUDE = run(
    0.1, {"amplitude": -math.inf}, [-math.inf] * 2 + [math.inf] * 5 + [-math.inf] * 3
)
INFINITE_OFFSET = run(
    0.1,
    {"offset": -math.inf},
    [-math.inf, 0.0, -math.inf],
    {1: {"reset": True}, 2: {"reset": False}},
)
