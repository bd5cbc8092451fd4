"""Runs of LGF_SinusCI worked out by hand from docs/behaviour.md §6 (not by running the model),
for the FMU tests (test_sinus_ci.py) and the model tests (test_model_sinus_ci.py).

Per call without reset: counter := (counter + Ts) MOD periode, P := REAL(periode),
    x := fl(fl(fl(REAL(counter) · T) / P) + fl(fl(phaseShift · T) / P)),
    value := fl(fl(SIN(x) · amplitude) + offset),
T the REAL literal 6.283185, i.e. float32 6.283185005187988 (= 6588397 · 2^-20), each operation
rounded to float32 (fl). E.g. counter 100, periode 1000: fl(100 · T) = fl(628.3185005187988) =
628.3184814453125 (ulp 2^-14), / 1000 -> x = 0.6283184885978699.
The arguments x were worked out on paper with exact binary fractions; SIN(x) is the correctly
rounded float32 of the sine of that float32 x (a 60-digit reference), which the FMU must meet
within one float32 ulp (docs/behaviour.md §6). With amplitude a power of two and offset 0 that
ulp is one ulp of `value`; check_run(..., ulps=1) compares so.
"""

import math

from tests.signal_generators import run

ULPS = 1


# --- cycleTime 0.1 s, periode 1000, amplitude 1, offset 0, phaseShift 0 ---
# counter  x                      SIN(x)
#   100    0.6283184885978699     0.5877852439880371
#   200    1.2566369771957397     0.9510564804077148
#   300    1.8849554061889648     0.9510565996170044
#   400    2.5132739543914795     0.5877853631973267
#   500    3.141592502593994      1.5099580252808664e-07   (x is the float32 below π: π − x)
#   600    3.7699108123779297    -0.5877849459648132
#   700    4.398229598999023     -0.9510564804077148
#   800    5.026547908782959     -0.9510565996170044
#   900    5.654866695404053     -0.5877853035926819
#     0    0.0                    0.0 (exactly)
#   100    (as above)             0.5877852439880371
TYPICAL_VALUES = [
    0.5877852439880371,
    0.9510564804077148,
    0.9510565996170044,
    0.5877853631973267,
    1.5099580252808664e-07,
    -0.5877849459648132,
    -0.9510564804077148,
    -0.9510565996170044,
    -0.5877853035926819,
    0.0,
    0.5877852439880371,
]
TYPICAL = run(0.1, {}, TYPICAL_VALUES)

# --- the first computed sample is at counter = Ts (not SIN(0) = 0): cycleTime 0.05 s ---
# counter 50: x = fl(fl(50 · T) / 1000) = 0.31415924429893494, SIN = 0.30901697278022766;
# then 100, 150, 200, 250 (x = 1.570796251296997: SIN = 1.0), 300
FIRST_SAMPLE = run(
    0.05,
    {},
    [
        0.30901697278022766,
        0.5877852439880371,
        0.8090169429779053,
        0.9510564804077148,
        1.0,
        0.9510565996170044,
    ],
)

# --- reset: counter := 0, value := 0.0 (not the offset); amplitude 2, offset 5 ---
# counter 100: fl(2 · 0.5877852439880371) = 1.1755704879760742, + 5 -> 6.175570487976074
# (ulp 2^-21 in [4, 8), more than twice one ulp of SIN: one ulp of SIN is at most one of value)
# counter 200: fl(2 · 0.9510564804077148 + 5) = 6.90211296081543
RESET = run(
    0.1,
    {"amplitude": 2.0, "offset": 5.0},
    [6.175570487976074, 0.0, 0.0, 6.175570487976074, 6.90211296081543],
    {1: {"reset": True}, 3: {"reset": False}},
)

# --- phaseShift 250 ms (a quarter of 1000): shift = fl(fl(250 · T) / 1000) = 1.570796251296997 ---
# counter  x = fl(rad + shift)    SIN(x)
#   100    2.1991147994995117     0.80901700258255
#   200    2.8274331092834473     0.30901727080345154
#   300    3.455751657485962     -0.30901673436164856
#   400    4.084070205688477     -0.8090168237686157
#   500    4.71238899230957      -1.0
#   600    5.340706825256348     -0.8090174198150635
#   700    5.969025611877441     -0.3090173900127411
#   800    6.597344398498535      0.3090168237686157
#   900    7.225663185119629      0.8090170621871948
#     0    1.570796251296997      1.0
PHASE_250 = run(
    0.1,
    {"phaseShift": 250.0},
    [
        0.80901700258255,
        0.30901727080345154,
        -0.30901673436164856,
        -0.8090168237686157,
        -1.0,
        -0.8090174198150635,
        -0.3090173900127411,
        0.3090168237686157,
        0.8090170621871948,
        1.0,
        0.80901700258255,
    ],
)

# --- a fractional phaseShift enters as the REAL (no REAL_TO_UDINT, which would give 0) ---
# phaseShift 0.5: shift = fl(fl(0.5 · T) / 1000) = 0.003141592489555478
# counter 100: x = fl(0.6283184885978699 + 0.003141592489555478) = 0.6314600706100464, ...
# counter 0: x = shift, SIN = 0.0031415873672813177 (not 0)
PHASE_FRACTION = run(
    0.1,
    {"phaseShift": 0.5},
    [
        0.5903239250183105,
        0.9520226120948792,
        0.9500810503959656,
        0.5852408409118652,
        -0.0031414853874593973,
        -0.5903236865997314,
        -0.9520225524902344,
        -0.9500811696052551,
        -0.5852409601211548,
        0.0031415873672813177,
    ],
)

# --- a huge phaseShift: SIN of a large argument, reduced accurately ---
# phaseShift 4294967040: shift = fl(fl(4294967040 · T) / 1000) = 26986072.0 (float32 ulp 2 there)
# counter 100: x = fl(0.6283184885978699 + 26986072) = 26986072.0; 200, 300, 400: 26986074.0;
# 500: 26986076.0
HUGE_PHASE = run(
    0.1,
    {"phaseShift": 4294967040.0},
    [
        -0.9997672438621521,
        0.43566668033599854,
        0.43566668033599854,
        0.43566668033599854,
        0.6371646523475647,
    ],
)

# --- cycleTime 1.5 ms runs on Ts = 1 ms, periode 10: counter 1, 2, ..., 9, 0, 1 ---
# P = 10: counter 1: x = fl(fl(1 · T) / 10) = 0.6283184885978699 (as above), counter 3: x =
# fl(18.849555015563965 / 10) = 1.884955644607544 (not the 1.8849554061889648 of 300/1000)
TRUNCATED_CYCLE = run(
    0.0015,
    {"periode": 10},
    [
        0.5877852439880371,
        0.9510564804077148,
        0.9510564804077148,
        0.5877853631973267,
        1.5099580252808664e-07,
        -0.5877853631973267,
        -0.9510564804077148,
        -0.9510565996170044,
        -0.5877857208251953,
        0.0,
        0.5877852439880371,
    ],
)

# --- amplitude 4 (a power of two: the product is exact) ---
AMPLITUDE_4 = run(
    0.1, {"amplitude": 4.0}, [2.3511409759521484, 3.8042259216308594, 3.8042263984680176]
)

# --- infinities: amplitude -Inf gives -Inf where SIN > 0, +Inf where SIN < 0, NaN at SIN(0) = 0 ---
INFINITE_AMPLITUDE = run(
    0.1, {"amplitude": -math.inf}, [-math.inf] * 5 + [math.inf] * 4 + [math.nan]
)
# offset +Inf: +Inf, but reset gives 0.0
INFINITE_OFFSET = run(
    0.1, {"offset": math.inf}, [math.inf, 0.0, math.inf], {1: {"reset": True}, 2: {"reset": False}}
)
