"""For each block: its independent model and Hypothesis strategies for its parameters, inputs
and cycle times, used by the property tests."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

from hypothesis import strategies as st

from models.lim_rate_of_change_ci import LimRateOfChangeCI
from models.ramp_ci import RampCI
from models.saw_tooth import SawTooth


@dataclass
class BlockSpec:
    make_model: Callable[[int, dict], object]  # (cycle_us, parameters) -> model
    cycles_us: st.SearchStrategy
    parameters: Callable[[], st.SearchStrategy]  # -> dict of fixed/tunable parameters
    inputs: dict[str, st.SearchStrategy]         # every input with a strategy for its values
    tunables: Callable[[dict], dict[str, st.SearchStrategy]] = lambda parameters: {}


def time_ms(lo: int, hi: int) -> st.SearchStrategy:
    """TIME inputs as seconds, sometimes off the ms grid to exercise rounding."""
    return st.one_of(st.integers(lo, hi).map(lambda ms: ms / 1000),
                     st.floats(lo / 1000, hi / 1000, allow_nan=False))


reals = st.one_of(st.integers(-100, 100).map(float),
                  st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False),
                  st.sampled_from([0.0, -0.0, 1e300, -1e300]))
ints = st.one_of(st.integers(-20, 20), st.integers(-32768, 32767),
                 st.sampled_from([-32768, -1, 0, 1, 32767]))
rarely_true = st.sampled_from([False, False, False, True])

LIM_RATE = BlockSpec(
    make_model=lambda cycle_us, parameters: LimRateOfChangeCI(cycle_us),
    cycles_us=st.sampled_from([1000, 10000, 100000, 1000000, 3300, 7]),
    parameters=lambda: st.just({}),
    inputs={
        "value": reals,
        "setChangeRate": st.one_of(st.sampled_from([0.0, 10.0, 0.5, -1.0, 1e6]),
                                   st.floats(-10, 1e4, allow_nan=False, allow_infinity=False)),
        "defaultOutValue": reals,
        "enDefaultOutValue": rarely_true,
    },
)

SAW_TOOTH = BlockSpec(
    make_model=lambda cycle_us, parameters: SawTooth(cycle_us, parameters["plcTiming"]),
    cycles_us=st.sampled_from([1000, 10000, 100000, 250000, 3300]),
    parameters=lambda: st.fixed_dictionaries({"plcTiming": st.booleans()}),
    inputs={
        "startValue": ints,
        "timeRange": time_ms(-50, 1200),
        "incrementRange": ints,
        "numberSteps": st.one_of(st.integers(-2, 8), ints),
        "endlessSteps": st.booleans(),
        "reset": rarely_true,
    },
)


def _ramp_parameters():
    def table(n):
        return st.fixed_dictionaries({
            "numberOfSetpoints": st.just(n),
            **{f"setpoints[{i}].outputValue": reals for i in range(n)},
            **{f"setpoints[{i}].time": time_ms(0, 1500) for i in range(n)},
        })
    return st.integers(2, 6).flatmap(table)


def _ramp_tunables(parameters):
    n = parameters["numberOfSetpoints"]
    return {**{f"setpoints[{i}].outputValue": reals for i in range(n)},
            **{f"setpoints[{i}].time": time_ms(0, 1500) for i in range(n)}}


RAMP = BlockSpec(
    make_model=lambda cycle_us, parameters: RampCI(cycle_us, parameters),
    cycles_us=st.sampled_from([1000, 10000, 100000, 250000, 1500, 33300]),
    parameters=_ramp_parameters,
    inputs={
        "defaultOutValue": reals,
        "contStepNbr": st.integers(0, 1),  # valid for every table (numberOfSetpoints >= 2)
        "contStepTime": time_ms(0, 1000),
        "enDefaultOutValue": rarely_true,
        "start": st.sampled_from([True, True, True, False]),
        "hold": rarely_true,
        "continue": rarely_true,
        "cyclicOP": st.booleans(),
        "updateTime": rarely_true,
        "reset": st.sampled_from([False] * 7 + [True]),
    },
    tunables=_ramp_tunables,
)

SPECS = {"LGF_LimRateOfChangeCI": LIM_RATE, "LGF_SawTooth": SAW_TOOTH, "LGF_RampCI": RAMP}

# Inputs under which each block visibly works, for the generic interface tests.
ACTIVE = {
    "LGF_LimRateOfChangeCI": {"value": 100.0, "setChangeRate": 10.0},
    "LGF_SawTooth": {"startValue": 5, "timeRange": 0.2, "incrementRange": 3, "numberSteps": 4},
    "LGF_RampCI": {"start": True, "cyclicOP": True},
}
