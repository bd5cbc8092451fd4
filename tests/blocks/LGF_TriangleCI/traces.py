"""Runs of LGF_TriangleCI worked out by hand from docs/behaviour.md §6 (not by running the
model), for the FMU tests (test_triangle_ci.py) and the model tests (test_model_triangle_ci.py).

value := (ABS((((4.0 / P) · p) − 2.0) · amplitude) − amplitude) + offset, every operation
rounded to float32 (fl(...)). With periode 1000:
    d := fl(4.0 / 1000.0) = 0.004000000189989805   (float32 0x3B83126F)
and, with amplitude 1, each value is fl(|fl(fl(d · p) − 2.0)| − 1.0); the products were rounded
on paper with exact binary fractions (float32 ulp 2^-24 in [0.5, 1), 2^-23 in [1, 2), 2^-22 in
[2, 4)); the subtractions are then exact.
"""

import math

from tests.signal_generators import Run

# --- the worked example of docs/behaviour.md §6 ---
# cycleTime 0.1 s, periode 1000, amplitude 1, offset 0
# call p   fl(d·p)                                − 2.0                  |·| − 1.0              §6
#  0  100  0.4000000189989805 -> 0.4000000059604645  -1.600000023841858   0.6000000238418579    0.6
#  1  200  0.800000037997961  -> 0.800000011920929   -1.2000000476837158  0.20000004768371582   0.2
#  2  300  1.2000000569969416 -> 1.2000000476837158  -0.7999999523162842  -0.20000004768371582 −0.2
#  3  400  1.600000075995922  -> 1.600000023841858   -0.3999999761581421  -0.6000000238418579  −0.6
#  4  500  2.0000000949949026 -> 2.0                  0.0                 -1.0                  −1.0
#  5  600  2.400000113993883  -> 2.4000000953674316   0.40000009536743164 -0.5999999046325684  −0.6
#  6  700  2.8000001329928637 -> 2.8000001907348633   0.8000001907348633  -0.19999980926513672 −0.2
#  7  800  3.200000151991844  -> 3.200000047683716    1.2000000476837158  0.20000004768371582   0.2
#  8  900  3.6000001709908247 -> 3.6000001430511475   1.6000001430511475  0.6000001430511475    0.6
#  9    0  0                                         -2.0                 1.0                   1.0
# 10  100  (as call 0)                                                    0.6000000238418579    0.6
# 11  200  (as call 1)                                                    0.20000004768371582
WORKED = [
    0.6000000238418579,
    0.20000004768371582,
    -0.20000004768371582,
    -0.6000000238418579,
    -1.0,
    -0.5999999046325684,
    -0.19999980926513672,
    0.20000004768371582,
    0.6000001430511475,
    1.0,
    0.6000000238418579,
    0.20000004768371582,
]
WORKED_EXAMPLE = Run(0.1, [({}, v) for v in WORKED])

# --- reset: counter := 0, value := 0.0 + offset; amplitude 2, offset 10 ---
# p = 100: fl(0.4000000059604645 − 2) · 2 = -3.200000047683716, |·| − 2 = 1.2000000476837158,
#          + 10 = fl(11.2000000476837158) = 11.199999809265137 (ulp 2^-20 in [8, 16))
# p = 200: -2.4000000953674316 -> 0.40000009536743164 -> fl(10.40000009536743164)
#          = 10.399999618530273
RESET = Run(
    0.1,
    [
        ({"amplitude": 2.0, "offset": 10.0}, 11.199999809265137),
        ({"reset": True}, 10.0),
        ({}, 10.0),
        ({"reset": False}, 11.199999809265137),  # counter 0 + 100: the first sample again
        ({}, 10.399999618530273),
    ],
)

# --- the first computed sample is at counter = Ts: cycleTime 0.25 s ---
# p = 250: fl(d·250) = fl(1.0000000474974513) = 1.0 -> -1.0 -> 0.0
# p = 750: fl(d·750) = fl(3.000000142492354) = 3.000000238418579 (3 + 2^-22 is nearer than 3)
#          -> 1.000000238418579 -> 2.384185791015625e-07 (2^-22, where exact arithmetic gives 0)
FIRST_SAMPLE = Run(0.25, [({}, 0.0), ({}, -1.0), ({}, 2.384185791015625e-07), ({}, 1.0), ({}, 0.0)])

# --- counter + REAL_TO_UDINT(phaseShift) wraps modulo 2^32 ---
# phaseShift 4294967040.0: p = 140, 240, 44 (wrapped; 340 without), 144, 244
#   p = 140: fl(d·140) = 0.5600000023841858 -> -1.440000057220459  -> 0.440000057220459
#   p = 240: fl(d·240) = 0.9600000381469727 -> -1.0399999618530273 -> 0.039999961853027344
#   p =  44: fl(d·44)  = 0.17600001394748688 -> -1.8240000009536743 -> 0.8240000009536743
#   p = 144: fl(d·144) = 0.5760000348091125 -> -1.4240000247955322 -> 0.4240000247955322
#   p = 244: fl(d·244) = 0.9760000705718994 -> -1.0239999294281006 -> 0.023999929428100586
UDINT_WRAP = Run(
    0.1,
    [
        ({"phaseShift": 4294967040.0}, 0.440000057220459),
        ({}, 0.039999961853027344),
        ({}, 0.8240000009536743),
        ({}, 0.4240000247955322),
        ({}, 0.023999929428100586),
    ],
)

# --- a phase shift beyond the periode: 1250 acts as 250 (the sum is taken MOD periode) ---
# counter 100 ... 900, 0 -> p = 350, 450, 550, 650, 750, 850, 950, 50, 150, 250
#   e.g. p = 350: fl(d·350) = fl(1.4000000664964318) = 1.4000000953674316 -> -0.5999999046325684
#        -> -0.40000009536743164; p = 250: 1.0 -> -1.0 -> 0.0
PHASE_BEYOND_PERIODE_VALUES = [
    -0.40000009536743164,
    -0.8000000715255737,
    -0.7999999523162842,
    -0.39999985694885254,
    2.384185791015625e-07,
    0.40000009536743164,
    0.8000001907348633,
    0.7999999523162842,
    0.3999999761581421,
    0.0,
]
PHASE_BEYOND_PERIODE = Run(
    0.1,
    [({"phaseShift": 1250.0}, PHASE_BEYOND_PERIODE_VALUES[0])]
    + [({}, v) for v in PHASE_BEYOND_PERIODE_VALUES[1:]],
)
PHASE_250 = Run(
    0.1,
    [({"phaseShift": 250.0}, PHASE_BEYOND_PERIODE_VALUES[0])]
    + [({}, v) for v in PHASE_BEYOND_PERIODE_VALUES[1:]],
)

# --- cycleTime 1.5 ms runs on Ts = 1 ms, periode 10 ---
# d10 := fl(4.0 / 10.0) = 0.4000000059604645; p = 1, 2, ..., 9, 0, 1:
#   fl(d10·p) = 0.4000000059604645, 0.800000011920929, 1.2000000476837158, 1.600000023841858,
#   2.0, 2.4000000953674316, 2.799999952316284, 3.200000047683716, 3.6000001430511475, 0
TRUNCATED = [
    0.6000000238418579,
    0.20000004768371582,
    -0.20000004768371582,
    -0.6000000238418579,
    -1.0,
    -0.5999999046325684,
    -0.20000004768371582,
    0.20000004768371582,
    0.6000001430511475,
    1.0,
    0.6000000238418579,
]
TRUNCATED_CYCLE = Run(0.0015, [({"periode": 10}, TRUNCATED[0])] + [({}, v) for v in TRUNCATED[1:]])

# --- infinities follow IEEE float32 ---
# amplitude +Inf: |x · Inf| − Inf is Inf − Inf = NaN (or 0 · Inf = NaN); offset -Inf: -Inf.
INFINITE_AMPLITUDE = Run(0.1, [({"amplitude": math.inf}, math.nan)] + [({}, math.nan)] * 10)
INFINITE_OFFSET = Run(0.1, [({"offset": -math.inf}, -math.inf)] + [({}, -math.inf)] * 10)

# The runs tests/test_signal_generator_blocks.py checks on the FMU and on the model.
RUNS = [
    "WORKED_EXAMPLE",
    "RESET",
    "FIRST_SAMPLE",
    "UDINT_WRAP",
    "PHASE_BEYOND_PERIODE",
    "PHASE_250",
    "TRUNCATED_CYCLE",
    "INFINITE_AMPLITUDE",
    "INFINITE_OFFSET",
]
