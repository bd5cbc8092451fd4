"""What the five LGF signal generators' folders share (tests/blocks/LGF_{SawTooth,Triangle,
Rectangle,Sinus,Cosinus}CI/, docs/behaviour.md §6): for spec.py the Hypothesis strategies of their
cycle times and inputs, ACTIVE, ORIGINAL_NAMES and the comparison of model and FMU for the sine and
cosine; for cross.py their fixed cross scenario; for the hand-traced tests the runs (Run, driven
on the model or the FMU) and the checks of the values the FMU must refuse or accept.

The generic suites compare outputs with ==, which a NaN never passes. So the strategies give each
block ±Inf only where no combination of the other inputs can make `value` NaN:
- SawToothCI, TriangleCI: amplitude finite with |a| <= 1e38 (an infinite amplitude always gives
  Inf - Inf; a finite one up to 1e38 cannot overflow in 2·a or (4/P·p - 2)·a); offset may be ±Inf.
- SinusCI: amplitude finite (SIN(0) = 0 and 0 · Inf is NaN), offset may be ±Inf.
- RectangleCI, CosinusCI: amplitude may be ±Inf (COS of a float32 is never 0), offset finite.
NaN results of infinite inputs are covered by the blocks' hand-traced tests instead.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from hypothesis import strategies as st

from tests.block_spec import BlockSpec, exact, rarely_true

FLT_MAX = float(np.finfo(np.float32).max)  # 3.4028234663852886e38
LARGEST_PHASE_SHIFT = 4294967040.0  # the largest float32 <= 4294967295 (2^32 - 256)
FMI2_PERIODE_MAX = 2**31 - 1  # FMI 2.0 Integer

# Whole ms and not (1.5 ms runs on Ts = 1 ms, 33.3 ms on 33 ms, 1.234567 s on 1234 ms).
CYCLES_US = st.sampled_from(
    [1000, 2000, 10000, 100000, 250000, 1000000, 1500, 2500, 33300, 1234567]
)

_moderate = st.one_of(
    st.integers(-100, 100).map(float),
    st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False),
    st.sampled_from([0.0, -0.0, 1.0, -1.0, 0.1, 2.5, 1e-3, 1e-40, 16777217.0]),
)


def finite_reals(limit: float = FLT_MAX) -> st.SearchStrategy:
    """Finite REAL inputs within ±limit: moderate ones, large ones, and any float32."""
    width32 = np.float32(limit)  # Hypothesis wants float32 bounds here
    if float(width32) > limit:
        width32 = np.nextafter(width32, np.float32(0))
    return st.one_of(
        _moderate,
        _moderate,
        _moderate,
        st.sampled_from([limit, -limit, limit / 3, 1e30, -1e30]),
        st.floats(-float(width32), float(width32), allow_nan=False, allow_infinity=False, width=32),
    )


def with_infinities(strategy: st.SearchStrategy) -> st.SearchStrategy:
    """The strategy, and sometimes +Inf or -Inf."""
    return st.one_of(strategy, strategy, strategy, strategy, st.sampled_from([math.inf, -math.inf]))


PERIODE = st.one_of(
    st.sampled_from([1, 2, 3, 7, 10, 999, 1000, 1001, 2000, 65536, 16777217, FMI2_PERIODE_MAX]),
    st.integers(1, 5000),
    st.integers(1, FMI2_PERIODE_MAX),
)

PHASE_SHIFT = st.one_of(
    st.sampled_from(
        [
            0.0,
            0.0,
            -0.0,
            0.5,
            1.5,
            2.5,
            100.0,
            250.0,
            499.5,
            500.0,
            600.0,
            999.0,
            1000.0,
            1500.0,
            2500.5,
            123456.789,
            4294967000.0,
            LARGEST_PHASE_SHIFT,
        ]
    ),
    st.integers(0, 5000).map(float),
    st.floats(0.0, 1e4, allow_nan=False),
    st.floats(0.0, LARGEST_PHASE_SHIFT, allow_nan=False),
)


def inputs(amplitude: st.SearchStrategy, offset: st.SearchStrategy) -> dict:
    """Every input of a signal generator with its strategy."""
    return {
        "amplitude": amplitude,
        "offset": offset,
        "periode": PERIODE,
        "phaseShift": PHASE_SHIFT,
        "reset": rarely_true,
    }


def spec(model_class, amplitude: st.SearchStrategy, offset: st.SearchStrategy, same=exact):
    """A signal generator's BlockSpec: its model, no parameters, every input (amplitude and
    offset with the block's strategies), compared by `same`."""
    return BlockSpec(
        make_model=lambda cycle_us, parameters: model_class(cycle_us, parameters),
        cycles_us=CYCLES_US,
        inputs=inputs(amplitude=amplitude, offset=offset),
        same=same,
    )


# Under these the block visibly works with the default periode (1000 ms) and cycleTime (0.1 s).
# Only REAL inputs: the generic FMI 3.0 test sets an int as Int16, and periode is a UInt32 there.
ACTIVE = {"amplitude": 2.0, "offset": 0.5, "phaseShift": 250.0}

# The original's callOB is replaced by cycleTime (docs/behaviour.md §1.1–1.3, §6).
ORIGINAL_NAMES = ["callOB"]


# --- model against FMU for SinusCI / CosinusCI ---


def _float32_ordinal(x: float) -> int:
    """Position of a float32 on the line of all float32 values (-0.0 and +0.0 both 0)."""
    bits = int(np.float32(x).view(np.uint32))
    return bits if bits < 0x80000000 else -(bits - 0x80000000)


def float32_ulps(a: float, b: float) -> float:
    """How many float32 steps lie between a and b (both float32 values); inf when either is NaN
    or not a float32 value."""
    a, b = float(a), float(b)
    if math.isnan(a) or math.isnan(b) or float(np.float32(a)) != a or float(np.float32(b)) != b:
        return math.inf
    return abs(_float32_ordinal(a) - _float32_ordinal(b))


def _same_real(want: float, got: float) -> bool:
    return got == want or (math.isnan(want) and math.isnan(got))


def same_within_trig_ulp(want: dict, got: dict) -> bool:
    """The BlockSpec comparison (tests/block_spec.py) of SinusCI and CosinusCI: `want` (the
    model's outputs) and `got` (the FMU's) agree when every output but `value` is equal and
    `value` is the model's, or differs from it by at most one float32 ulp, or is one of the
    values that a SIN/COS one float32 ulp off gives (want['value'].allowed, a TrigValue of
    tests/models/signal_ci.py): docs/behaviour.md §6, SIN/COS "tested within 1 float32 ulp of a
    correctly rounded value"."""
    if set(want) != set(got) or "value" not in want:
        return False
    if any(got[name] != want[name] for name in want if name != "value"):
        return False
    w, g = want["value"], got["value"]
    return (
        _same_real(w, g)
        or float32_ulps(w, g) <= 1
        or any(_same_real(a, g) for a in getattr(w, "allowed", ()))
    )


# --- the fixed cross scenario (tests/cross/scenario_runner.c: test_win64.py, test_aarch64.py) ---


def cross_script(md, name: str) -> str:
    """One fixed scenario for a signal generator, the same rules for all five: a whole-ms cycle
    with changes of every input, a UDINT wrap of counter + phaseShift, huge SIN/COS arguments,
    ±Inf, refused values (periode 0, negative, too large or NaN inputs), resets, and state save,
    restore and reserialize; then a cycle of 1.5 ms that runs on Ts = 1 ms."""
    from tests.cross.scripts import Script

    s = Script(md)
    s.start(
        name,
        0.0,
        {
            "cycleTime": 0.01,
            "amplitude": 1.0,
            "offset": 0.0,
            "periode": 250,
            "phaseShift": 0.0,
            "reset": False,
        },
    )
    s.run(
        400,
        [0.01, 0.01, 0.03, 0.005, 0.005, 0.02],
        {
            20: {"amplitude": 2.5, "offset": -0.75},
            40: {"phaseShift": 100.0},
            60: {"phaseShift": 187.5},  # beyond periode / 2
            80: {"phaseShift": 2.5, "periode": 7},  # halves to even; tiny periode
            100: {"periode": 1000, "phaseShift": LARGEST_PHASE_SHIFT},  # counter + ps wraps
            120: {"reset": True},
            123: {"reset": False, "amplitude": 1.0 / 3.0, "offset": 1e-3},
            140: [
                {"periode": 0},
                {"phaseShift": -1.0},
                {"phaseShift": 4294967295.0},
                {"amplitude": math.nan},
                {"offset": 1e39},
            ],  # all refused
            150: {"phaseShift": 123456.789, "periode": 333},  # large SIN/COS arguments
            170: {"offset": math.inf},
            180: {"offset": 0.5, "amplitude": -math.inf},
            190: [{"amplitude": FLT_MAX, "offset": -FLT_MAX, "periode": FMI2_PERIODE_MAX}, "save"],
            220: {"periode": 16777217, "phaseShift": 16777216.0},
            250: {"reset": True, "periode": 40},
            252: {"reset": False},
            300: "restore",
            350: "reserialize",
        },
    )
    s.finish()
    s.start(
        name + "_1_5ms",
        0.0,
        {
            "cycleTime": 0.0015,
            "amplitude": 4.0,
            "offset": 1.0,
            "periode": 10,
            "phaseShift": 0.0,
            "reset": False,
        },
    )
    s.run(60, [0.0015, 0.003, 0.00075, 0.00075], {30: {"phaseShift": 3.5}})
    s.finish()
    return s.text()


# --- hand-traced runs (tests/blocks/<Block>/traces.py), on the model and on the FMU ---

# The start values of the inputs (docs/behaviour.md §6): the inputs of a run that does not set them.
START = {"amplitude": 1.0, "offset": 0.0, "periode": 1000, "phaseShift": 0.0, "reset": False}


@dataclass
class Run:
    """A run worked out by hand: cycleTime in s, and per call k the inputs set before it (for
    call 0, in initialization mode, over START) and `value` after it. Call k happens at
    k·cycleTime; in co-simulation the inputs set before the step that ends there reach it."""

    cycle: float
    calls: list[tuple[dict, float]]

    @property
    def expected(self) -> list[float]:
        return [value for _, value in self.calls]


def run(cycle: float, first_inputs: dict, values: list, changes: dict | None = None) -> Run:
    """A Run of `values`, with first_inputs set before call 0 and changes[k] before call k."""
    changes = changes or {}
    return Run(
        cycle, [(first_inputs if k == 0 else changes.get(k, {}), v) for k, v in enumerate(values)]
    )


def runs(traces) -> list[str]:
    """The names of the Runs a block's traces module defines, in their order there."""
    return [name for name, value in vars(traces).items() if isinstance(value, Run)]


def model_values(model_class, run: Run) -> list[float]:
    """`value` after each call of the run, on the model (every call also has error FALSE,
    status 0, subFunctionStatus 0)."""
    cycle_us = round(run.cycle * 1e6)
    model = model_class(cycle_us, {})
    inputs, values = dict(START), []
    for k, (changes, _) in enumerate(run.calls):
        inputs.update(changes)
        out = model.call(k * cycle_us, dict(inputs))
        assert (out["error"], out["status"], out["subFunctionStatus"]) == (False, 0, 0)
        values.append(out["value"])
    return values


def fmu_values(block: str, run: Run) -> list[float]:
    """`value` after each call of the run, on the FMU, one doStep of one cycle per call."""
    from tests.harness import Slave

    s = Slave(block, {"cycleTime": run.cycle}, run.calls[0][0])
    values = []
    for k, (changes, _) in enumerate(run.calls):
        if k:
            s.set(changes)
            s.step(run.cycle)
        out = s.outputs()
        assert (out["error"], out["status"], out["subFunctionStatus"]) == (False, 0, 0), k
        values.append(out["value"])
    s.free()
    return values


def same_values(got: list[float], want: list[float], ulps: int = 0) -> bool:
    """Equal value by value (NaN equals NaN), or within `ulps` float32 ulps."""
    return len(got) == len(want) and all(
        _same_real(w, g) or (ulps and float32_ulps(w, g) <= ulps) for g, w in zip(got, want)
    )


def check_run(values: list[float], run: Run, ulps: int = 0) -> None:
    assert same_values(values, run.expected, ulps), "\n".join(
        f"call {k}: {g!r} expected {w!r}"
        for k, (g, w) in enumerate(zip(values, run.expected))
        if not same_values([g], [w], ulps)
    )


# --- values the FMU must refuse (docs/behaviour.md §1.4, §6) ---

REFUSED = [
    ("periode", 0),  # "`periode` = 0 is refused"
    ("periode", -1),  # below the FMI 2.0 minimum 1
    ("phaseShift", -1.0),  # "≥ 0"
    ("phaseShift", -0.5),
    ("phaseShift", 4294967295.0),  # float32 4294967296 > 4294967295
    ("phaseShift", 5e9),
    ("phaseShift", math.inf),
    ("phaseShift", math.nan),
    ("amplitude", math.nan),  # "NaN and finite values beyond ±3.4028235e38"
    ("amplitude", 1e39),
    ("amplitude", -3.5e38),
    ("offset", math.nan),
    ("offset", 1e300),
]

ACCEPTED = [
    ("periode", 1),
    ("periode", FMI2_PERIODE_MAX),
    ("phaseShift", 0.0),
    ("phaseShift", LARGEST_PHASE_SHIFT),
    ("phaseShift", 4294967100.0),
    ("amplitude", math.inf),
    ("amplitude", -math.inf),
    ("amplitude", FLT_MAX),
    ("offset", -math.inf),
    ("offset", -FLT_MAX),
]


def check_refused(block: str, name: str, value) -> None:
    """Setting `value` is fmi2Error with a message naming the variable, the value is not
    applied and the block runs on as if it had not been tried."""
    from fmpy.fmi2 import fmi2Error

    from tests.harness import Slave

    plain = Slave(block, {"cycleTime": 0.1}, ACTIVE)
    expected = [plain.step(0.1) for _ in range(3)]
    plain.free()
    s = Slave(block, {"cycleTime": 0.1}, ACTIVE)
    before = s.get([name])[name]
    v = s.variables[name]
    setter = s.fmu.setInteger if v.type == "Integer" else s.fmu.setReal
    assert s.status_of(setter, [v.valueReference], [value]) == fmi2Error
    assert s.log and s.log[-1][0] == fmi2Error and name in s.log[-1][2], s.log[-1:]
    after = s.get([name])[name]
    assert after == before
    assert [s.step(0.1) for _ in range(3)] == expected
    s.free()


def check_accepted(block: str, name: str, value) -> None:
    from fmpy.fmi2 import fmi2OK

    from tests.harness import Slave

    s = Slave(block, {"cycleTime": 0.1}, ACTIVE)
    v = s.variables[name]
    setter = s.fmu.setInteger if v.type == "Integer" else s.fmu.setReal
    assert s.status_of(setter, [v.valueReference], [value]) == fmi2OK
    s.step(0.1)
    s.free()


def check_cycle_time_refused(block: str, cycle: float) -> None:
    """cycleTime below 1 ms: fmi2Error naming cycleTime and the original codes it replaces
    (docs/behaviour.md §6: 16#8600 OB unavailable, 16#8601 QRY_CINT)."""
    from fmpy.fmi2 import fmi2Error

    from tests.harness import Slave

    s = Slave(block, initialize=False)
    s.fmu.setupExperiment(startTime=0.0)
    s.fmu.enterInitializationMode()
    assert s.status_of(s.fmu.setReal, [s.vr("cycleTime")], [cycle]) == fmi2Error
    status, _, text = s.log[-1]
    assert status == fmi2Error and "cycleTime" in text, text
    assert "16#8600" in text and "16#8601" in text, text
    assert s.get(["cycleTime"])["cycleTime"] == 0.1
    s.fmu.exitInitializationMode()
    s.free()


def check_truncated_cycle_warns(block: str, cycle: float) -> None:
    """A cycleTime that is not whole ms is accepted with fmi2Warning and a warning in the log
    (docs/behaviour.md §4.2: "the block runs on the truncated period")."""
    from fmpy.fmi2 import fmi2Real, fmi2ValueReference, fmi2Warning

    from tests.harness import Slave

    s = Slave(block, initialize=False)
    s.fmu.setupExperiment(startTime=0.0)
    s.fmu.enterInitializationMode()
    vr, value = (fmi2ValueReference * 1)(s.vr("cycleTime")), (fmi2Real * 1)(cycle)
    assert s.fmu.fmi2SetReal(s.fmu.component, vr, 1, value) == fmi2Warning
    assert any(status == fmi2Warning and "cycleTime" in text for status, _, text in s.log)
    s.fmu.exitInitializationMode()
    s.free()
