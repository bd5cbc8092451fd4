"""The values at t0 are one set of values (docs/behaviour.md §1.2): an output read in
Initialization Mode is what call 0 computes from the inputs set so far, evaluated on a copy that
commits nothing; call 0 itself runs once, in fmi2ExitInitializationMode /
fmi3ExitInitializationMode, with the final inputs. For every block, FMI 2.0 and 3.0,
co-simulation and Model Exchange (§1.11, §7):

- the outputs read in Initialization Mode equal, bit for bit, those read after the exit, and
  are the values of the first call by the contract (not the values before it);
- a get commits nothing: after the inputs change, a get returns the new inputs' values, the
  exit computes call 0 from the final inputs, and the following calls show that call 0 ran once;
- a master that connects FMUs during initialization (libcosim) passes on the values at t0 and
  so equals, sample for sample, the README's FMPy master, which exits the source first.
"""

from __future__ import annotations

import csv
import math
import shutil
import struct
import tempfile
from dataclasses import dataclass, field

import numpy as np
import pytest
from fmpy import extract, read_model_description
from fmpy.fmi3 import FMU3Model, FMU3Slave

from tests.harness import FMU_DIR, Slave, fmu_path, status_of
from tests.lgf_blocks import names
from tests.test_libcosim import after_initialization, libcosim

CYCLE = 0.1  # s; Ts = 100 ms
CYCLE_US = 100_000


def f32(x: float) -> float:
    """The float32 nearest to x, widened: a REAL output of the signal generators (§1.4)."""
    return float(np.float32(x))


@dataclass(frozen=True)
class Near:
    """A SinusCI/CosinusCI sample by docs/behaviour.md §6.2, in float32: rad := REAL(counter) ·
    6.283185 / P; shift := (phaseShift · 6.283185) / P; SIN|COS(rad + shift) · amplitude +
    offset. SIN|COS is the correctly rounded float32 value or one float32 ulp off it (the FMU's
    routine is within one ulp, §6.2): the sample is any of the three results."""

    function: object  # math.sin or math.cos
    counter: int
    periode: int = 1000
    phase_shift: float = 0.0
    amplitude: float = 1.0
    offset: float = 0.0

    def allowed(self) -> set[float]:
        r = np.float32
        rad = r(self.counter) * r(6.283185) / r(self.periode)
        shift = (r(self.phase_shift) * r(6.283185)) / r(self.periode)
        exact = r(self.function(float(rad + shift)))
        return {
            float(s * r(self.amplitude) + r(self.offset))
            for s in (np.nextafter(exact, r(-2.0)), exact, np.nextafter(exact, r(2.0)))
        }

    def __eq__(self, other):
        return isinstance(other, float) and other in self.allowed()

    def __repr__(self):
        return f"one of {sorted(self.allowed())}"


@dataclass(frozen=True)
class Case:
    """Inputs set in Initialization Mode in two phases, with the outputs the contract gives.

    first:  parameters and inputs set first, `at_first` the outputs call 0 computes from them;
    change: inputs changed after a get, `at_exit` call 0's outputs from the final inputs;
    `next_call`: call 1's outputs, the final inputs held. The values are chosen so that call 0
    changes the outputs from those before it, and so that a get that committed something, or
    a call 0 run twice, would give other values."""

    block: str
    parameters: dict
    first: dict
    at_first: dict
    change: dict
    at_exit: dict
    next_call: dict
    extra: list[tuple[str, dict, dict]] = field(default_factory=list)  # (label, inputs, outputs)


GENERATOR_OK = {"error": False, "status": 0, "subFunctionStatus": 0}
RAMP_TIMES = {
    "setpoints[0].outputValue": 12.5,
    "setpoints[0].time": 0.3,
    "setpoints[1].outputValue": 30.0,
    "setpoints[1].time": 0.2,
    "setpoints[2].outputValue": 30.0,
    "setpoints[2].time": 0.25,
    "setpoints[3].outputValue": 0.0,
    "setpoints[3].time": 0.0,
}


def history_case(block, output, value, delta_t=None, enabled_delta_t=None) -> Case:
    """The case of LGF_SimpleSmoothingFB and LGF_DifferenceQuotientFB (with deltaT), which start
    alike: disabled with insert TRUE at t0, then enabled."""
    extra = {} if delta_t is None else {"deltaT": delta_t}
    enabled_extra = {} if enabled_delta_t is None else {"deltaT": enabled_delta_t}

    def outputs(status):
        return {output: 0.0, "error": False, "status": status}

    return Case(
        block,
        {"cycleTime": CYCLE},
        {"enable": False, "insert": True, "value": value, **extra},
        outputs(0x7000),
        {"enable": True, **enabled_extra},
        outputs(0x7001),
        outputs(0x7001),
        [("enabled_no_insert", {"enable": True, "insert": False, "value": value}, outputs(0x7001))],
    )


CASES = [
    # §3.2 rule 2: a pre-assignment jumps to defaultOutValue in the first call (7.5, not the
    # 0.0 before it); released, the first call ramps from p = 0.0 by 15·0.1 (1.5: had the get
    # committed p = 7.5, it would be 9.0), the next one from 1.5 (3.0: had call 0 run twice,
    # 4.5).
    Case(
        "LGF_LimRateOfChangeCI",
        {"cycleTime": CYCLE},
        {"value": 100.0, "setChangeRate": 15.0, "enDefaultOutValue": True, "defaultOutValue": 7.5},
        {"delayedValue": 7.5, "error": False, "status": 0, "subFunctionStatus": 0},
        {"enDefaultOutValue": False},
        {"delayedValue": 1.5, "error": False, "status": 0, "subFunctionStatus": 0},
        {"delayedValue": 3.0, "error": False, "status": 0, "subFunctionStatus": 0},
        # §3.2 rule 1, §3.5: a negative rate is a block error in the first call.
        [
            (
                "negative_rate",
                {"value": 100.0, "setChangeRate": -1.0},
                {"delayedValue": 0.0, "error": True, "status": 0x8200, "subFunctionStatus": 0},
            )
        ],
    ),
    # §2.2: the first call latches, value = startValue (7, then -5: had the get latched 7, the
    # exit would not latch again); timeRange 0 steps in every later call (§2.4): -5 + 3.
    Case(
        "LGF_SawTooth",
        {"cycleTime": CYCLE},
        {"startValue": 7, "incrementRange": 3, "timeRange": 0.0, "numberSteps": 4},
        {"value": 7},
        {"startValue": -5},
        {"value": -5},
        {"value": -2},
    ),
    # §4.3: the rising edge of start (the edge memory starts FALSE) gives 16#7001 and step 3 a)
    # in the first call; a pre-assigned output overrides the output only (step 5), and the
    # edge is still there after a get. Call 1 interpolates underneath (remainTime 0.3 - Ts:
    # had call 0 run twice, 0.1) with the status 16#7000.
    Case(
        "LGF_RampCI",
        {"cycleTime": CYCLE, **RAMP_TIMES},
        {"start": True, "cyclicOP": True, "defaultOutValue": 3.25},
        {
            "outputValue": 12.5,
            "actTimeTable": True,
            "stepNumber": 1,
            "remainTime": 0.3,
            "totalTime": 0.75,
            "remainTotalTime": 0.75,
            "error": False,
            "status": 0x7001,
            "subFunctionStatus": 0,
        },
        {"enDefaultOutValue": True},
        {
            "outputValue": 3.25,
            "actTimeTable": False,
            "stepNumber": 1,
            "remainTime": 0.3,
            "totalTime": 0.75,
            "remainTotalTime": 0.75,
            "error": False,
            "status": 0x7001,
            "subFunctionStatus": 0,
        },
        {
            "outputValue": 3.25,
            "actTimeTable": False,
            "stepNumber": 1,
            "remainTime": 0.2,
            "totalTime": 0.75,
            "remainTotalTime": 0.65,
            "error": False,
            "status": 0x7000,
            "subFunctionStatus": 0,
        },
    ),
    # §6.2: the first sample is at counter = Ts = 100. SawToothCI: p = (100 + 500) MOD 2000,
    # 2·2.5/2000·600 - 2.5 + 0.25; then the worked example: -0.8, -0.6 (had the get counted,
    # -0.6 at the exit; had call 0 run twice, -0.4 after it).
    Case(
        "LGF_SawToothCI",
        {"cycleTime": CYCLE},
        {"amplitude": 2.5, "offset": 0.25, "periode": 2000, "phaseShift": 500.0},
        {"value": f32(-0.75), **GENERATOR_OK},
        {"amplitude": 1.0, "offset": 0.0, "periode": 1000, "phaseShift": 0.0},
        {"value": f32(-0.8), **GENERATOR_OK},
        {"value": f32(-0.6), **GENERATOR_OK},
    ),
    # ABS((4/1000·100 - 2)·2) - 2 + 1 = 2.2; then the worked example, 0.6 and 0.2 (0.2 is
    # 0.20000004768371582 in the block's float32 arithmetic, not the float32 nearest 0.2).
    Case(
        "LGF_TriangleCI",
        {"cycleTime": CYCLE},
        {"amplitude": 2.0, "offset": 1.0},
        {"value": f32(2.2), **GENERATOR_OK},
        {"amplitude": 1.0, "offset": 0.0},
        {"value": f32(0.6), **GENERATOR_OK},
        {"value": 0.20000004768371582, **GENERATOR_OK},
    ),
    # High (offset + amplitude) while ps <= counter < 500 + ps: counter 100 is high with ps 0,
    # low with ps 200; counter 200 is high (had call 0 run twice, high at the exit).
    Case(
        "LGF_RectangleCI",
        {"cycleTime": CYCLE},
        {"amplitude": 3.0, "offset": -1.0},
        {"value": 2.0, **GENERATOR_OK},
        {"phaseShift": 200.0},
        {"value": -4.0, **GENERATOR_OK},
        {"value": 2.0, **GENERATOR_OK},
    ),
    # SIN(2π·100/1000 + 2π·250/1000)·2 + 0.5 (about 2.118); with periode 3000 the samples
    # at 12° and 24° (about 0.208 and 0.407: they rise, so a call too many shows).
    Case(
        "LGF_SinusCI",
        {"cycleTime": CYCLE},
        {"amplitude": 2.0, "offset": 0.5, "phaseShift": 250.0},
        {"value": Near(math.sin, 100, 1000, 250.0, 2.0, 0.5), **GENERATOR_OK},
        {"amplitude": 1.0, "offset": 0.0, "phaseShift": 0.0, "periode": 3000},
        {"value": Near(math.sin, 100, 3000), **GENERATOR_OK},
        {"value": Near(math.sin, 200, 3000), **GENERATOR_OK},
    ),
    # COS: about -0.676, then 0.978 and 0.914.
    Case(
        "LGF_CosinusCI",
        {"cycleTime": CYCLE},
        {"amplitude": 2.0, "offset": 0.5, "phaseShift": 250.0},
        {"value": Near(math.cos, 100, 1000, 250.0, 2.0, 0.5), **GENERATOR_OK},
        {"amplitude": 1.0, "offset": 0.0, "phaseShift": 0.0, "periode": 3000},
        {"value": Near(math.cos, 100, 3000), **GENERATOR_OK},
        {"value": Near(math.cos, 200, 3000), **GENERATOR_OK},
    ),
    # §8.2: call 0 is a rising edge of in for the TON. With timeOnDelay 0 its Q is TRUE in
    # that call, the TOF's IN TRUE, out TRUE. With 0.1 s the TON starts at t0 (0 < 100 ms:
    # Q FALSE; the TOF, IN FALSE and never started, Q FALSE): out FALSE; had the get committed
    # the TON's start with PT 0, the exit would see no edge and an elapsed TON (out TRUE).
    # Call 1 at 0.1 s: 100 - 0 >= 100 ms, the TON's Q TRUE, out TRUE.
    Case(
        "LGF_IecTimerOnOff",
        {"cycleTime": CYCLE},
        {"in": True, "timeOnDelay": 0.0, "timeOffDelay": 0.2},
        {"out": True},
        {"timeOnDelay": 0.1},
        {"out": False},
        {"out": True},
    ),
    # §9.2: frequency 1.0: P = T#1000s / TRUNC(1.0 · 1000) = 1000 ms. The TOF never ran, so
    # its Q reads FALSE and impulse = NOT Q = TRUE (the block begins with a pulse); the TOF runs
    # with IN TRUE: countdown 1000 - 0 ms. frequency 2.0: P = 500 ms: TRUE, 0.5 s. Call 1: Q
    # reads TRUE, impulse FALSE, IN FALSE: the falling edge starts the TOF at 0.1 s (ET 0):
    # FALSE, 500 - 0 ms = 0.5 s (had the get committed, or call 0 run twice, impulse would be
    # FALSE in call 0 and the TOF started at t0).
    Case(
        "LGF_Impulse",
        {"cycleTime": CYCLE},
        {"frequency": 1.0},
        {"impulse": True, "countdown": 1.0},
        {"frequency": 2.0},
        {"impulse": True, "countdown": 0.5},
        {"impulse": False, "countdown": 0.5},
    ),
    # §10.2: new settings in call 0. Ratio 1.0: pulseRate 1/2 = 0.5, Pp = Pz = 500 ms; pauseQ
    # FALSE, so the pulse TOF's IN TRUE (Q TRUE): clock TRUE, countdown 500 - 0 ms. Ratio 3.0:
    # pulseRate 3/4 = 0.75, pauseRate 0.25, Pp = 1000·0.75/1 = 750 ms, Pz = 250 ms: TRUE,
    # 0.75 s. Call 1: IN = NOT pauseQ = FALSE, the falling edge starts the pulse TOF at 0.1 s
    # (Q TRUE, ET 0): TRUE, 0.75 s (had call 0 run twice: started at t0, 750 - 100 = 0.65 s).
    # (A committed get would not show: the new ratio resets both TOFs, step 2.1.)
    Case(
        "LGF_Frequency",
        {"cycleTime": CYCLE},
        {"frequency": 1.0, "pulsePauseRatio": 1.0},
        {"clock": True, "countdown": 0.5},
        {"pulsePauseRatio": 3.0},
        {"clock": True, "countdown": 0.75},
        {"clock": True, "countdown": 0.75},
    ),
    # §11.2: the edge memories start FALSE, so trigger and reset TRUE in call 0 both rise: the
    # toggle gives TRUE, the reset FALSE. reset released: trigger's rising edge alone, TRUE (had
    # the get committed triggerOld TRUE, no edge at the exit: FALSE). Call 1: no edge, TRUE.
    Case(
        "LGF_PulseRelay",
        {"cycleTime": CYCLE},
        {"trigger": True, "reset": True},
        {"out": False},
        {"reset": False},
        {"out": True},
        {"out": True},
    ),
    # §12.2: trigger TRUE in call 0 is an edge, edges 1. monitorTime 0: the TP gives no pulse
    # (q FALSE), trigger TRUE and edges 1: long, noOfEdges 1. monitorTime 0.1 s: the TP starts
    # at t0 (q TRUE): no result. Call 1 at 0.1 s: the TP's Q, read without running it, is
    # FALSE (100 >= 100 ms) with one edge counted and trigger TRUE: long, 1. (Had the get
    # committed triggerPrevious TRUE and the TP started with PT 0, the exit would see no edge,
    # q FALSE: long at the exit.)
    Case(
        "LGF_CountBooleanEdges",
        {"cycleTime": CYCLE},
        {"trigger": True, "monitorTime": 0.0},
        {"single": False, "double": False, "long": True, "severalEdges": False, "noOfEdges": 1},
        {"monitorTime": 0.1},
        {"single": False, "double": False, "long": False, "severalEdges": False, "noOfEdges": 0},
        {"single": False, "double": False, "long": True, "severalEdges": False, "noOfEdges": 1},
    ),
    # §13.2, absolute tolerances: high = 50 + 5 = 55, low = 50 - 5 = 45, low <= high: status 0.
    # Call 0 sees a setpoint change (50 != 0.0). value 52 is within: 6.1 then 6.2 leave
    # wasWithinTolerance TRUE, setpointChangeActive FALSE: inLimits TRUE, no setpointChange.
    # value 60 is above: the change leaves setpointChangeActive TRUE, the change TON starts
    # (0 < 100 ms), nothing monitored: only setpointChange TRUE (had the get committed
    # setpointPrevious 50 and wasWithinTolerance TRUE, the exit would see no change and time
    # the violation at once, PT 0: overHighLimit TRUE). Call 1 at 0.1 s: the change TON's Q,
    # read before it runs, is TRUE (100 >= 100 ms): monitored; the high TON rises with PT 0:
    # overHighLimit TRUE, inLimits FALSE (never within since the change); as in the original
    # code, the change time's end does not end setpointChange, which waits for the value to
    # come within (§13.2): still TRUE.
    Case(
        "LGF_IsValueInToleranceByTime",
        {"cycleTime": CYCLE},
        {
            "value": 52.0,
            "setpoint": 50.0,
            "lowerMinimum": 5.0,
            "upperMaximum": 5.0,
            "configuration.toleranceAsAbsoluteValues": True,
            "configuration.upperLimitMonitoringTime": 0.0,
            "configuration.lowerLimitMonitoringTime": 1.0,
            "configuration.setpointChangeMonitoringTime": 0.1,
        },
        {
            "overHighLimit": False,
            "belowLowLimit": False,
            "inLimits": True,
            "setpointChange": False,
            "error": False,
            "status": 0,
        },
        {"value": 60.0},
        {
            "overHighLimit": False,
            "belowLowLimit": False,
            "inLimits": False,
            "setpointChange": True,
            "error": False,
            "status": 0,
        },
        {
            "overHighLimit": True,
            "belowLowLimit": False,
            "inLimits": False,
            "setpointChange": True,
            "error": False,
            "status": 0,
        },
    ),
    # §14.2, from the reset values (+1.7976931348623157e308, -1.7976931348623157e308): +Inf is
    # not < the minimum, > the maximum (§14.3); then -3.0 is both (had the get committed the
    # maximum +Inf, it would stay +Inf). Call 1: -3.0 changes nothing.
    Case(
        "LGF_StoreMinMax",
        {"cycleTime": CYCLE},
        {"value": math.inf},
        {"minValue": 1.7976931348623157e308, "maxValue": math.inf},
        {"value": -3.0},
        {"minValue": -3.0, "maxValue": -3.0},
        {"minValue": -3.0, "maxValue": -3.0},
    ),
    # ---- B: LGF_FloatingAverage ----
    # §15.2, LREAL, as the original code: the remembered window size starts at 0, so windowSize
    # 0 in call 0 is no change but invalid: error, 16#8200, nothing read in. windowSize 3 is a
    # change: a restart that returns without reading in, every output 0, no error (had the get
    # committed the remembered size 0 ... it is 0 anyway; the exit still sees 3 as a change).
    # Call 1: no change, cyclicExecution reads 6.0 in: 6.0 / 1 = 6.0, count 1 < 3 (had call 0
    # run twice, the second run would have read 6.0 in already: count 2, still 6.0; a committed
    # get cannot show here). Extras: a window of 1 is a change too, so its first call reads
    # nothing in; reset held hides an invalid size.
    Case(
        "LGF_FloatingAverage",
        {"cycleTime": CYCLE},
        {"cyclicExecution": True, "windowSize": 0, "value": 6.0},
        {"average": 0.0, "windowSizeReached": False, "error": True, "status": 0x8200},
        {"windowSize": 3},
        {"average": 0.0, "windowSizeReached": False, "error": False, "status": 0},
        {"average": 6.0, "windowSizeReached": False, "error": False, "status": 0},
        [
            (
                "window_of_one",
                {"cyclicExecution": True, "windowSize": 1, "value": 0.1},
                {"average": 0.0, "windowSizeReached": False, "error": False, "status": 0},
            ),
            (
                "reset_hides_an_invalid_size",
                {"reset": True, "windowSize": 0, "value": 6.0},
                {"average": 0.0, "windowSizeReached": False, "error": False, "status": 0},
            ),
        ],
    ),
    # ---- B: LGF_SimpleSmoothingFB ----
    # §16.2, as the original code: enable FALSE: disabled, 16#7000, smoothedValue 0.0 (the edge
    # memories follow the inputs in every call). enable TRUE: its rising edge only starts the
    # block (16#7001); insert's edge in the same call is not read in and, its memory updated at
    # the end of the call, is lost. Call 1, the inputs held: no edge, 16#7001 held. (A get that
    # committed insert's memory, or call 0 run twice, cannot show here: the insert is lost
    # either way.)
    history_case("LGF_SimpleSmoothingFB", "smoothedValue", 3.0),
    # ---- B: LGF_DifferenceQuotientFB ----
    # §17.2, as §16.2: enable FALSE with insert TRUE: 16#7000, derivatedValue 0.0. enable TRUE
    # (with deltaT 0.0): enable's edge only starts (16#7001), insert's edge is lost; deltaT is
    # looked at only when a derivative is due (§17.4), so no 16#8200. Call 1: no edge, 16#7001.
    history_case("LGF_DifferenceQuotientFB", "derivatedValue", 2.0, 0.5, 0.0),
    # ---- B: LGF_Integration ----
    # §18.2: the first integrating call measures d = 0 (last time cleared, §18.3), dt = 0.0:
    # value +Inf gives ((+Inf + 0.0) × 0.0) / 2.0 = NaN, statIntegral 0.0 + NaN = NaN (the
    # positive quiet NaN, §1.4). value 3.0: ((3.0 + 0.0) × 0.0) / 2.0 = 0.0, integral 0.0
    # (had the get committed the NaN, it would stay NaN). Call 1: c = 100000 µs / 1000 = 100,
    # d = 100 − 0, dt = 100.0 / 1000.0 = 0.1; ((3.0 + 3.0) × 0.1) / 2.0 = 0.6000000000000001
    # / 2.0 = 0.30000000000000004, 0.0 + that (a second call 0 at t0 would measure d = 0 and
    # add nothing, so only a call at another time shows here: 0.6000000000000001 after two
    # cycles). Extras: reset and disabled give 0.0 whatever value is (steps 1, 2: nothing is
    # integrated).
    Case(
        "LGF_Integration",
        {"cycleTime": CYCLE},
        {"enable": True, "value": math.inf},
        {"integral": math.nan, "error": False, "status": 0, "subFunctionStatus": 0},
        {"value": 3.0},
        {"integral": 0.0, "error": False, "status": 0, "subFunctionStatus": 0},
        {"integral": 0.30000000000000004, "error": False, "status": 0, "subFunctionStatus": 0},
        [
            (
                "reset",
                {"reset": True, "value": math.inf},
                {"integral": 0.0, "error": False, "status": 0, "subFunctionStatus": 0},
            ),
            (
                "disabled",
                {"enable": False, "value": math.inf},
                {"integral": 0.0, "error": False, "status": 0, "subFunctionStatus": 0},
            ),
        ],
    ),
    # ---- B: LGF_ScaleLinear ----
    # §19.2, 4 … 20 to 0 … 100: s = 100.0 − 0.0 = 100.0, d = 20.0 − 4.0 = 16.0, m = 6.25;
    # x = 12.3: x − x1 = 8.3 (the double 12.3 − 4.0 = 8.3000000000000007), × 6.25 =
    # 51.87500000000001, + 0.0: within 0 … 100, status 0. x = 2.5: 6.25 × (2.5 − 4.0) =
    # −9.375 < yMin: 0.0, 16#6001; call 1 the same (an FC has no memory). Extras: yMin > yMax
    # is the error (y 0.0); |x2 − x1| = 0 ≤ 1e-6 gives y1 = 120.0, limited to yMax, 16#6002.
    Case(
        "LGF_ScaleLinear",
        {"cycleTime": CYCLE},
        {"x": 12.3, "x1": 4.0, "y1": 0.0, "x2": 20.0, "y2": 100.0, "yMin": 0.0, "yMax": 100.0},
        {"y": 51.87500000000001, "error": False, "status": 0},
        {"x": 2.5},
        {"y": 0.0, "error": False, "status": 0x6001},
        {"y": 0.0, "error": False, "status": 0x6001},
        [
            (
                "limits_crossed",
                {"x": 12.3, "x1": 4.0, "x2": 20.0, "yMin": 50.0, "yMax": 40.0},
                {"y": 0.0, "error": True, "status": 0x8200},
            ),
            (
                "same_points",
                {"x": 12.3, "x1": 5.0, "x2": 5.0, "y1": 120.0, "yMin": 0.0, "yMax": 100.0},
                {"y": 100.0, "error": False, "status": 0x6002},
            ),
        ],
    ),
    # ---- B: LGF_NonLinearInterpolation ----
    # §20.3, the default table with point 3 at (80, 90.5): (0, 0), (20, 5), (50, 30),
    # (80, 90.5), (100, 100). value 90: statIndex 0 → 1, search up 2, 3, 4 (90 > 80); segment
    # 4: slope = (100 − 90.5) / (100 − 80) = 9.5 / 20 = 0.475, 0.475 × 90 = 42.75, 0.475 × 80 =
    # 38.0, 90.5 − 38.0 = 52.5, 42.75 + 52.5 = 95.25. value 80 (on point 3): from segment 1
    # the search stops at 3 (80 > 80 is false): slope = 60.5 / 30 = 2.0166666666666666,
    # × 80 = 161.33333333333331, × 50 = 100.83333333333333, 30 − that = −70.83333333333333,
    # sum 90.49999999999999; had the get committed statIndex 4, segment 4 would stay
    # (80 < 80 is false): 38.0 + 52.5 = 90.5 (§20.4, hysteresis). Call 1 keeps segment 3.
    # Extras: below the table, segment 1: slope 5 / 20 = 0.25, 0.25 × −10 + (0 − 0.25 × 0) =
    # −2.5; track gives value; reset 0.0; the pre-assignment before reset (§20.2).
    Case(
        "LGF_NonLinearInterpolation",
        {"cycleTime": CYCLE, "setpoints[3].outputValue": 90.5},
        {"value": 90.0},
        {"outputValue": 95.25},
        {"value": 80.0},
        {"outputValue": 90.49999999999999},
        {"outputValue": 90.49999999999999},
        [
            ("below_the_table", {"value": -10.0}, {"outputValue": -2.5}),
            ("track", {"value": 90.0, "track": True}, {"outputValue": 90.0}),
            ("reset", {"value": 90.0, "reset": True}, {"outputValue": 0.0}),
            (
                "default_before_reset",
                {"value": 90.0, "reset": True, "enDefaultOutValue": True, "defaultOutValue": 7.25},
                {"outputValue": 7.25},
            ),
        ],
    ),
    # ---- B: LGF_LimRateOfChangeAdvancedCI ----
    # §21.2, dt = 100000.0 / 1e6 = 0.1. track outputs autoValue 5.0 (within −80 … 80, no flag).
    # Released, autoValue −50, setNegUpRateLim 3: from p = 0.0 (t < p, p ≤ 0, §21.3)
    # c = 0.0 − 3.0 × 0.1 = −0.30000000000000004 > t: out = c, negUpRateLim (had the get
    # committed p = 5.0: t < p, p > 0, c = 5.0 − 40 × 0.1 = 1.0, no crossing: 1.0 with
    # posDownRateLim). Call 1: −0.30000000000000004 − 0.30000000000000004 =
    # −0.6000000000000001 (had call 0 run twice, −0.9000000000000001). Extras: the limits
    # checked first (16#8200), a negative rate (16#8202), both freezing the values before the
    # first call; manual mode beyond the limits, uncut; a restart brings defaultOutValue 95
    # to the limit, 80.0, and sets highLim (the original checks the limits in a restart too,
    # at >=); a pre-assignment of 95 is cut, highLim.
    Case(
        "LGF_LimRateOfChangeAdvancedCI",
        {"cycleTime": CYCLE},
        {"track": True, "autoValue": 5.0},
        {
            "outputValue": 5.0,
            "posUpRateLim": False,
            "posDownRateLim": False,
            "negUpRateLim": False,
            "negDownRateLim": False,
            "highLim": False,
            "lowLim": False,
            "error": False,
            "status": 0,
            "subFunctionStatus": 0,
        },
        {"track": False, "autoValue": -50.0, "setNegUpRateLim": 3.0},
        {
            "outputValue": -0.30000000000000004,
            "posUpRateLim": False,
            "posDownRateLim": False,
            "negUpRateLim": True,
            "negDownRateLim": False,
            "highLim": False,
            "lowLim": False,
            "error": False,
            "status": 0,
            "subFunctionStatus": 0,
        },
        {
            "outputValue": -0.6000000000000001,
            "posUpRateLim": False,
            "posDownRateLim": False,
            "negUpRateLim": True,
            "negDownRateLim": False,
            "highLim": False,
            "lowLim": False,
            "error": False,
            "status": 0,
            "subFunctionStatus": 0,
        },
        [
            (
                "limits_crossed",
                {"setHighLim": -1.0, "setLowLim": 1.0, "setPosUpRateLim": -1.0},
                {"outputValue": 0.0, "posUpRateLim": False, "error": True, "status": 0x8200},
            ),
            (
                "negative_rate",
                {"setPosDownRateLim": -1.0},
                {"outputValue": 0.0, "posUpRateLim": False, "error": True, "status": 0x8202},
            ),
            (
                "manual_beyond_the_limits",
                {"manOp": True, "manualValue": -90.0},
                {"outputValue": -90.0, "lowLim": False, "error": False, "status": 0},
            ),
            (
                "restart_within_the_limits",
                {"reset": True, "enDefaultOutValue": True, "defaultOutValue": 95.0},
                {"outputValue": 80.0, "highLim": True, "error": False, "status": 0},
            ),
            (
                "default_cut",
                {"enDefaultOutValue": True, "defaultOutValue": 95.0},
                {"outputValue": 80.0, "highLim": True, "error": False, "status": 0},
            ),
        ],
    ),
]


def test_every_block_has_a_case():
    assert sorted(c.block for c in CASES) == sorted(names())


# ---- one instance of either FMI version and interface --------------------------------------

_unzipped3: dict[str, tuple] = {}


def fmi3_unpacked(block: str):
    if block not in _unzipped3:
        directory = extract(
            str(fmu_path(block, FMU_DIR / "fmi3")), tempfile.mkdtemp(prefix=f"{block}-fmi3-")
        )
        _unzipped3[block] = (read_model_description(directory), directory)
    return _unzipped3[block]


@pytest.fixture(scope="module", autouse=True)
def _fmi3_cleanup():
    yield
    for _, directory in _unzipped3.values():
        shutil.rmtree(directory, ignore_errors=True)
    _unzipped3.clear()


def python_type(fmi_type: str):
    return (
        bool if fmi_type == "Boolean" else float if fmi_type.startswith(("Real", "Float")) else int
    )


class Instance:
    """A block's FMU (fmi_version 2 or 3, co-simulation or Model Exchange), instantiated and
    in Initialization Mode at t0 = 0. Getters and setters by the variable's type (getReal,
    getFloat32, getUInt16, ...); the outputs are read with one get per type, as an importer
    reads them."""

    def __init__(self, block: str, fmi_version: int, model_exchange: bool):
        self.version, self.model_exchange = fmi_version, model_exchange
        self.log: list[str] = []
        if fmi_version == 2:
            self.slave = Slave(block, initialize=False, model_exchange=model_exchange)
            self.md, self.fmu = self.slave.md, self.slave.fmu
            self.fmu.setupExperiment(startTime=0.0)
        else:
            self.md, directory = fmi3_unpacked(block)
            kind = FMU3Model if model_exchange else FMU3Slave
            self.fmu = kind(
                guid=self.md.instantiationToken,
                unzipDirectory=directory,
                modelIdentifier=block,
                instanceName="test",
            )
            self.fmu.instantiate(
                logMessage=lambda env, status, category, message: self.log.append(message.decode())
            )
        self.fmu.enterInitializationMode(**({"startTime": 0.0} if fmi_version == 3 else {}))
        self.variables = {v.name: v for v in self.md.modelVariables}
        self.output_names = [v.name for v in self.md.modelVariables if v.causality == "output"]
        self.calls = 0
        self.initial_iteration_pending = False

    def set(self, values: dict) -> None:
        for name, value in values.items():
            v = self.variables[name]
            getattr(self.fmu, f"set{v.type}")([v.valueReference], [python_type(v.type)(value)])

    def outputs(self) -> dict:
        by_type: dict[str, list[str]] = {}
        for name in self.output_names:
            by_type.setdefault(self.variables[name].type, []).append(name)
        values = {}
        for fmi_type, group in by_type.items():
            got = getattr(self.fmu, f"get{fmi_type}")(
                [self.variables[n].valueReference for n in group]
            )
            if fmi_type == "Boolean":  # FMPy gives an fmi2Boolean as the int it is
                assert all(b in (0, 1) for b in got), (group, got)
                got = [bool(b) for b in got]
            values.update(zip(group, got))
        return {name: values[name] for name in self.output_names}

    def exit(self) -> None:
        """Call 0. A Model Exchange instance is in Event Mode after it (§1.11)."""
        self.fmu.exitInitializationMode()
        self.initial_iteration_pending = self.model_exchange

    def next_call(self) -> dict:
        """Runs call k + 1, as a co-simulation step of one cycle or at its time event, with the
        inputs as they are; returns the outputs after it."""
        self.calls += 1
        if not self.model_exchange:
            self.fmu.doStep((self.calls - 1) * CYCLE, CYCLE)
            return self.outputs()
        update = self.fmu.newDiscreteStates if self.version == 2 else self.fmu.updateDiscreteStates
        if self.initial_iteration_pending:  # the event iteration of the exit: no call
            *_, defined, self.next_event = update()
            assert defined
            self.initial_iteration_pending = False
        assert self.next_event == self.calls * CYCLE_US / 1e6  # from the integer call count
        self.fmu.enterContinuousTimeMode()
        self.fmu.setTime(self.next_event)
        self.fmu.enterEventMode()
        needed, terminate, *_, defined, self.next_event = update()  # call k at its time event
        assert (needed, terminate, defined) == (False, False, True)
        return self.outputs()

    def free(self) -> None:
        if self.version == 2:
            self.slave.free()
        else:
            status_of(self.fmu.terminate)
            self.fmu.freeInstance()


def bits(values: dict) -> dict:
    """Each value with its Python type, Reals as their IEEE bits (tells -0.0 from 0.0)."""
    return {
        n: (type(v).__name__, struct.pack("<d", v).hex() if isinstance(v, float) else v)
        for n, v in values.items()
    }


def assert_contract(got: dict, expected: dict, when: str) -> None:
    """The outputs of `expected` have their contract values (types as FMPy returns them)."""
    wrong = {}
    for name, want in expected.items():
        value = got[name]
        if isinstance(want, Near):
            ok = want == value
        else:
            ok = type(value) is type(want) and bits({0: value}) == bits({0: want})
        if not ok:
            wrong[name] = (value, want)
    assert not wrong, f"{when}: output (FMU, contract): {wrong}"


VERSIONS = [pytest.param(2, id="fmi2"), pytest.param(3, id="fmi3")]
INTERFACES = [pytest.param(False, id="co_simulation"), pytest.param(True, id="model_exchange")]


def init_cases() -> list:
    """(block, parameters and inputs, the contract's outputs of call 0), with ids."""
    cases = []
    for c in CASES:
        cases.append(
            pytest.param(c.block, {**c.parameters, **c.first}, c.at_first, id=f"{c.block}-first")
        )
        cases.append(
            pytest.param(
                c.block, {**c.parameters, **c.first, **c.change}, c.at_exit, id=f"{c.block}-changed"
            )
        )
        cases += [
            pytest.param(c.block, {**c.parameters, **inputs}, outputs, id=f"{c.block}-{label}")
            for label, inputs, outputs in c.extra
        ]
    return cases


# ---- 1. the outputs in Initialization Mode are those after the exit -------------------------


@pytest.mark.parametrize("model_exchange", INTERFACES)
@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("block, values, expected", init_cases())
def test_outputs_in_initialization_mode_are_those_of_call_0(
    block, values, expected, version, model_exchange
):
    s = Instance(block, version, model_exchange)
    s.set(values)
    before = s.outputs()
    assert_contract(before, expected, "read in Initialization Mode")
    s.exit()
    after = s.outputs()
    assert bits(before) == bits(after), "Initialization Mode and after the exit differ"
    assert list(after) == s.output_names
    assert_contract(after, expected, "after the exit")
    s.free()


# ---- 2. a get commits nothing; call 0 runs once, at the exit -------------------------------


def reference_run(case: Case, version: int, model_exchange: bool, calls: int) -> list[dict]:
    """The outputs after the exit and after each of `calls` calls, with the final inputs set
    at once and no get in Initialization Mode."""
    s = Instance(case.block, version, model_exchange)
    s.set({**case.parameters, **case.first, **case.change})
    s.exit()
    rows = [s.outputs()] + [s.next_call() for _ in range(calls)]
    s.free()
    return rows


@pytest.mark.parametrize("model_exchange", INTERFACES)
@pytest.mark.parametrize("version", VERSIONS)
@pytest.mark.parametrize("case", CASES, ids=lambda c: c.block)
def test_a_get_in_initialization_mode_commits_nothing(case, version, model_exchange):
    s = Instance(case.block, version, model_exchange)
    s.set({**case.parameters, **case.first})
    first = s.outputs()
    assert_contract(first, case.at_first, "read with the first inputs")
    assert bits(s.outputs()) == bits(first), "a second get differs from the first"
    s.set(case.change)
    changed = s.outputs()
    assert_contract(changed, case.at_exit, "read after the inputs changed")
    assert bits(changed) != bits(first), "the change of inputs must show"
    s.exit()
    rows = [s.outputs()]
    assert bits(rows[0]) == bits(changed), "the exit differs from the last get before it"
    rows += [s.next_call() for _ in range(10)]
    assert_contract(rows[1], case.next_call, "after call 1")
    s.free()
    reference = reference_run(case, version, model_exchange, 10)
    assert [bits(r) for r in rows] == [bits(r) for r in reference], (
        "the gets in Initialization Mode changed the run"
    )


# ---- 3. a chain through libcosim's connection equals the README's FMPy master --------------

SOURCE, TARGET = "LGF_SawToothCI", "LGF_LimRateOfChangeCI"
CHAIN_PARAMETERS = {
    SOURCE: {"cycleTime": CYCLE},
    TARGET: {"cycleTime": CYCLE, "setChangeRate": 5.0},
}  # 0.5 per call
CHAIN_CYCLES = 30
NS = 1_000_000_000


def fmpy_chain(passed_at_t0: float | None = None) -> list[dict]:
    """The README's master ("Two FMUs chained"): exit the source's initialization, read its
    value, set it into the target, exit the target; then per step: read, set, doStep both.
    Returns {(block, output): value} after the exits and after every step. passed_at_t0, if
    given, is set into the target in Initialization Mode instead of the source's value, as
    libcosim passed on the value the FMU returned there before docs/behaviour.md §1.2 (0.0,
    the value before call 0); from the first step on it passed on the source's values."""
    source, target = (Instance(b, 2, False) for b in (SOURCE, TARGET))
    for s in (source, target):
        s.set(CHAIN_PARAMETERS[s.md.modelName])
    source.exit()
    value = source.outputs()["value"]
    target.set({"value": value if passed_at_t0 is None else passed_at_t0})
    target.exit()

    def sample():
        return {(s.md.modelName, n): v for s in (source, target) for n, v in s.outputs().items()}

    rows = [sample()]
    for n in range(CHAIN_CYCLES):
        value = source.outputs()["value"]
        target.set({"value": value})
        source.next_call()
        target.next_call()
        rows.append(sample())
    for s in (source, target):
        s.free()
    return rows


def libcosim_chain(log_dir) -> list[dict]:
    """The chain in libcosim (run_libcosim_chain), with the Boolean outputs at t = 0 read
    from the file observer's CSVs, complete once the execution is gone."""
    rows, outputs = run_libcosim_chain(log_dir)
    for block, variables in outputs.items():
        rows[0].update(booleans_at_t0(log_dir, block, variables))
    return rows


def run_libcosim_chain(log_dir) -> tuple[list[dict], dict]:
    """The chain in libcosim with a connection SawToothCI.value -> LimRateOfChangeCI.value (both
    fmi2Real): libcosim reads the source's outputs in Initialization Mode and sets them into
    the target before it ends the initialization, then transfers them after each step. The
    values at t = 0 come from the observers' records, as in tests/test_libcosim.py (the Booleans
    are left to the caller); also returns each block's outputs."""
    CosimEnums, CosimExecution, _, CosimObserver, CosimSlave = libcosim()
    execution = CosimExecution.CosimExecution.from_step_size(round(CYCLE * NS))
    last = CosimObserver.CosimObserver.create_last_value()
    series = CosimObserver.CosimObserver.create_time_series()
    files = CosimObserver.CosimObserver.create_to_dir(str(log_dir))
    assert all(execution.add_observer(o) for o in (last, series, files))
    slaves = {}
    for block in (SOURCE, TARGET):
        index = execution.add_local_slave(CosimSlave.CosimLocalSlave(str(fmu_path(block)), block))
        assert index >= 0, f"libcosim could not add {block}.fmu"
        md = read_model_description(str(fmu_path(block)))
        variables = {v.name: v for v in md.modelVariables}
        outputs = [v for v in md.modelVariables if v.causality == "output"]
        slaves[block] = (index, variables, outputs)
        for name, value in CHAIN_PARAMETERS[block].items():
            assert execution.real_initial_value(index, variables[name].valueReference, value)
        for v in outputs:
            if v.type != "Boolean":  # the time series holds no Booleans
                kind = CosimEnums.CosimVariableType[v.type.upper()]
                assert series.start_time_series(index, v.valueReference, kind), v.name
    (i, vs, _), (j, vt, _) = slaves[SOURCE], slaves[TARGET]
    assert (
        execution.connect_real_variables(
            i, vs["value"].valueReference, j, vt["value"].valueReference
        )
        == 0
    )

    def sample():
        return {
            (block, v.name): getattr(last, f"last_{v.type.lower()}_values")(
                index, [v.valueReference]
            )[0]
            for block, (index, _, outputs) in slaves.items()
            for v in outputs
        }

    rows = []
    for n in range(CHAIN_CYCLES):
        assert execution.step(), f"libcosim step {n} failed"
        assert execution.status().current_time == (n + 1) * round(CYCLE * NS)
        rows.append(sample())
    at_t0 = {}
    for block, (index, _, outputs) in slaves.items():
        numeric = [v for v in outputs if v.type != "Boolean"]
        at_t0.update(
            {(block, n): v for n, v in after_initialization(series, index, numeric).items()}
        )
    return [at_t0] + rows, {block: outputs for block, (_, _, outputs) in slaves.items()}


def booleans_at_t0(log_dir, block: str, outputs) -> dict:
    """The Boolean outputs of one slave at t = 0 from the file observer's CSV (step 0)."""
    [csv_file] = log_dir.glob(f"{block}*.csv")
    with open(csv_file) as f:
        first = next(csv.DictReader(f), None)
    assert first is not None and first["StepCount"] == "0", f"{csv_file.name}: no row of step 0"
    return {(block, v.name): first[v.name] == "1" for v in outputs if v.type == "Boolean"}


def test_a_chain_through_libcosim_equals_the_readme_master(tmp_path):
    libcosim()  # fails here, with its message, when libcosim cannot be used
    fmpy = fmpy_chain()
    cosim = libcosim_chain(tmp_path)
    assert len(fmpy) == len(cosim) == CHAIN_CYCLES + 1
    assert all(set(r) == set(fmpy[0]) for r in fmpy + cosim)  # every output of both FMUs
    # The first values by the contract: the source's first sample -0.8 (§6.2), towards which
    # the limiter's first call ramps from 0.0 by 5·0.1 (§3.2), then lands on -0.8.
    assert fmpy[0][SOURCE, "value"] == f32(-0.8)
    assert [r[TARGET, "delayedValue"] for r in fmpy[:3]] == [-0.5, f32(-0.8), f32(-0.6)]
    mismatches = [
        f"t = {k * CYCLE:.1f} s: {name}: FMPy {fmpy[k][name]!r}, libcosim {cosim[k][name]!r}"
        for k in range(len(fmpy))
        for name in fmpy[k]
        if bits({0: fmpy[k][name]}) != bits({0: cosim[k][name]})
    ]
    assert not mismatches, "\n".join(mismatches[:10])
    # The comparison would have failed before §1.2: libcosim then passed on the 0.0 the source
    # returned in Initialization Mode, so the limiter's call 0 saw 0.0, not -0.8: it stayed at
    # 0.0 and ramped to -0.5 only in call 1; from call 2 on the chains agree again. (This
    # master with 0.0 at t0 gives, sample for sample, libcosim's chain of the FMU before.)
    before = fmpy_chain(passed_at_t0=0.0)
    assert [r[TARGET, "delayedValue"] for r in before[:3]] == [0.0, -0.5, f32(-0.6)]
    assert [bits(r) for r in before[2:]] == [bits(r) for r in cosim[2:]]
    assert [bits(r) for r in before[:2]] != [bits(r) for r in cosim[:2]]
