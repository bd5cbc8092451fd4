"""Runs of LGF_SawToothCI worked out by hand from docs/behaviour.md §6 (not by running the
model), for the FMU tests (test_saw_tooth_ci.py) and the model tests (test_model_saw_tooth_ci.py).

value := ((((2.0 · amplitude) / P) · p) − amplitude) + offset, every operation rounded to
float32 (written fl(...)). With amplitude 1 and periode 1000:
    c := fl(2.0 / 1000.0) = 0.0020000000949949026   (float32 0x3B03126F)
and each value is fl(fl(c · p) − 1.0). The products were rounded on paper with exact binary
fractions: the float32 ulp is 2^-24 in [0.5, 1), 2^-23 in [1, 2). The subtraction of 1.0 is
then exact in all of them but p = 200 (a tie, to even).
"""

import math

from tests.signal_generators import FLT_MAX, Run, run

# --- the worked example of docs/behaviour.md §6 ---
# cycleTime 0.1 s, periode 1000, amplitude 1, offset 0
# call  counter = p   fl(c·p)                       value = fl(fl(c·p) − 1)     §6
#  0     100     0.20000000949949026 -> 0.20000000298023224   -0.800000011920929    −0.8
#  1     200     0.4000000189989805  -> 0.4000000059604645    -0.6000000238418579   −0.6
#                                                             (tie -0.59999999403953552 -> even)
#  2     300     0.6000000284984708  -> 0.6000000238418579    -0.3999999761581421   −0.4
#  3     400     0.800000037997961   -> 0.800000011920929     -0.19999998807907104  −0.2
#  4     500     1.0000000474974513  -> 1.0                    0.0                   0.0
#  5     600     1.2000000569969416  -> 1.2000000476837158     0.20000004768371582   0.2
#  6     700     1.4000000664964318  -> 1.4000000953674316     0.40000009536743164   0.4
#  7     800     1.600000075995922   -> 1.600000023841858      0.6000000238418579    0.6
#  8     900     1.8000000854954123  -> 1.8000000715255737     0.8000000715255737    0.8
#  9       0     0                                            -1.0                   −1.0
# 10     100     (as call 0)                                  -0.800000011920929    −0.8
# 11     200     (as call 1)                                  -0.6000000238418579
WORKED = [
    -0.800000011920929,
    -0.6000000238418579,
    -0.3999999761581421,
    -0.19999998807907104,
    0.0,
    0.20000004768371582,
    0.40000009536743164,
    0.6000000238418579,
    0.8000000715255737,
    -1.0,
    -0.800000011920929,
    -0.6000000238418579,
]
WORKED_EXAMPLE = run(0.1, {}, WORKED)

# --- reset: counter := 0, value := 0.0 + offset; the next call samples counter = Ts again ---
# offset 0.25: fl(-0.800000011920929 + 0.25) = -0.550000011920929 (exact: 9227469 · 2^-24),
# fl(-0.6000000238418579 + 0.25) = -0.3500000238418579 (exact: 5872026 · 2^-24).
RESET = Run(
    0.1,
    [
        ({"offset": 0.25}, -0.550000011920929),  # counter 100
        ({"reset": True}, 0.25),  # counter 0, value 0.0 + offset
        ({}, 0.25),  # reset still TRUE: the same again
        ({"reset": False}, -0.550000011920929),  # counter 0 + 100: the first sample again
        ({}, -0.3500000238418579),  # counter 200
    ],
)

# --- the first computed sample is at counter = Ts: cycleTime 0.25 s ---
# p = 250: fl(c·250) = fl(0.50000002374872565) = 0.5 (ulp 2^-24 above 0.5), value -0.5
# p = 750: fl(c·750) = fl(1.500000071246177) = 1.5000001192092896 (the nearer of 1.5 and
#          1.5 + 2^-23), value 0.5000001192092896
FIRST_SAMPLE = Run(0.25, [({}, -0.5), ({}, 0.0), ({}, 0.5000001192092896), ({}, -1.0), ({}, -0.5)])

# --- counter + REAL_TO_UDINT(phaseShift) is a UDINT sum and wraps modulo 2^32 ---
# phaseShift 4294967040.0 (a float32 value, 2^32 - 256; REAL_TO_UDINT gives the same):
# counter 100: 4294967140 MOD 1000 = 140; 200: 4294967240 -> 240; 300: 4294967340 wraps to 44
# (without the wrap 340); 400: 4294967440 -> 144; 500: 4294967540 -> 244.
#   p = 140: fl(c·140) = fl(0.28000001329928637) = 0.2800000011920929  -> -0.7200000286102295
#   p = 240: fl(c·240) = fl(0.4800000227987766)  = 0.48000001907348633 -> -0.5199999809265137
#   p =  44: fl(c·44)  = fl(0.08800000417977571) = 0.08800000697374344 -> -0.9120000004768372
#   p = 144: fl(c·144) = fl(0.288000013679266)   = 0.2880000174045563  -> -0.7120000123977661
#   p = 244: fl(c·244) = fl(0.48800002317875624) = 0.4880000352859497  -> -0.5119999647140503
UDINT_WRAP = Run(
    0.1,
    [
        ({"phaseShift": 4294967040.0}, -0.7200000286102295),
        ({}, -0.5199999809265137),
        ({}, -0.9120000004768372),
        ({}, -0.7120000123977661),
        ({}, -0.5119999647140503),
    ],
)
WITHOUT_WRAP_AT_CALL_2 = -0.3199999928474426  # p = 340: what a 64-bit sum would give

# --- cycleTime 1.5 ms runs on Ts = 1 ms (truncated), periode 10 ---
# c10 := fl(2.0 / 10.0) = 0.20000000298023224; p = counter = 1, 2, ..., 9, 0:
#   fl(c10·p) = 0.20000000298023224, 0.4000000059604645, 0.6000000238418579, 0.800000011920929,
#   1.0, 1.2000000476837158, 1.399999976158142, 1.600000023841858, 1.8000000715255737, 0
# minus 1.0 (exact except p = 2, a tie to even):
TRUNCATED = [
    -0.800000011920929,
    -0.6000000238418579,
    -0.3999999761581421,
    -0.19999998807907104,
    0.0,
    0.20000004768371582,
    0.3999999761581421,
    0.6000000238418579,
    0.8000000715255737,
    -1.0,
    -0.800000011920929,
]
TRUNCATED_CYCLE = run(0.0015, {"periode": 10}, TRUNCATED)

# --- a new periode applies at the next call: counter := (900 + 100) MOD 300 = 100 ---
# c300 := fl(2.0 / 300.0) = 0.006666666828095913; p = 100: fl(c300·100) = 0.6666666865348816,
# value -0.3333333134651184; p = 200: 1.3333333730697632 -> 0.3333333730697632; p = 0: -1.0.
NEW_PERIODE = Run(
    0.1,
    [({}, v) for v in WORKED[:9]]
    + [({"periode": 300}, -0.3333333134651184), ({}, 0.3333333730697632), ({}, -1.0)],
)

# --- infinities and overflow follow IEEE float32 ---
# offset +Inf: every value +Inf. amplitude +Inf: 2·Inf/P·p − Inf is Inf − Inf = NaN (and
# Inf·0 = NaN at p = 0). amplitude FLT_MAX: fl(2·FLT_MAX) overflows to +Inf in float32 (not in
# double!), so p > 0 gives Inf − FLT_MAX = +Inf and p = 0 gives Inf·0 = NaN.
INFINITE_OFFSET = Run(0.1, [({"offset": math.inf}, math.inf)] + [({}, math.inf)] * 10)
INFINITE_AMPLITUDE = Run(0.1, [({"amplitude": math.inf}, math.nan)] + [({}, math.nan)] * 10)
OVERFLOW = Run(
    0.1,
    [({"amplitude": FLT_MAX}, math.inf)] + [({}, math.inf)] * 8 + [({}, math.nan), ({}, math.inf)],
)
